// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// A helper process that draws frames of a scene: its own MuJoCo model, OSMesa context and
/// llvmpipe. llvmpipe rasterises every context of one process through one queue, so a
/// second drawing thread gains little (scene_bench.cpp BM_Strip16Frames640x480); a second
/// process has a rasteriser of its own. The helper is the program armstudy-frames
/// (src/cli/frame_worker_main.cpp), spoken to over a socket: the scene once, then poses
/// (MuJoCo's qpos and qvel, already mapped from the chain) and their labels; it answers
/// each with the frame's pixels (the messages, each one typed struct and one field list:
/// scene/frame_messages.hpp). A frame is a function of its pose alone, so the helper's
/// frames are the parent's byte for byte on one machine (tests/scene/frame_worker_test.cpp).

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "scene/arm_scene.hpp"
#include "scene/image.hpp"
#include "scene/renderer.hpp"

namespace armstudy::scene {
namespace frame_wire {
struct Packed;  // scene/frame_messages.hpp
}  // namespace frame_wire

/// One frame asked of a worker: the model's state and the labels.
struct WorkerPose {
  double t = 0;          ///< s (mjData::time)
  Eigen::VectorXd qpos;  ///< (nq) rad
  Eigen::VectorXd qvel;  ///< (nv) rad/s
  FrameLabels labels;
};

class FrameWorker {
 public:
  /// A helper asked to load `scene`: one this thread gave back earlier (release), or a new
  /// one started from frame_worker_program(). It loads while the caller goes on; a scene it
  /// cannot load is an error of the first receive(). nullptr when there is no helper
  /// program or it could not start (`why`, when given, says why). A helper is kept per
  /// thread: it dies with the thread that started it (PR_SET_PDEATHSIG), and its OSMesa
  /// contexts stay warm between scenes.
  static std::unique_ptr<FrameWorker> acquire(const ArmScene& scene, const std::string& source,
                                              const RenderSettings& settings,
                                              std::string* why = nullptr);
  /// Starts a helper in this thread's pool that loads `scene` and draws one frame of it
  /// while the caller goes on, so that the next acquire on this thread finds its OSMesa
  /// context made and llvmpipe's shaders compiled. Nothing happens where none can start.
  static void prewarm(const ArmScene& scene, const RenderSettings& settings);
  /// Gives a helper back to this thread's pool, for the next acquire on this thread. A
  /// helper with answers not received, or that failed, is closed instead.
  static void release(std::unique_ptr<FrameWorker> worker);
  /// Closes the connection; the helper exits (and is killed if it has not within 2 s).
  ~FrameWorker();
  FrameWorker(const FrameWorker&) = delete;
  FrameWorker& operator=(const FrameWorker&) = delete;

  /// Asks the helper to begin a replay (mj_resetData). @throws SceneError if it is gone.
  void reset();
  /// Asks the helper to draw `pose` (answered in order by receive()). @throws SceneError if
  /// it is gone.
  void send(const WorkerPose& pose);
  /// The next frame asked for. @throws SceneError with the helper's own message (a scene
  /// it could not load, a failing frame), or if it died or stopped answering.
  Image receive();
  /// reset(), then every pose of `poses` sent and received, in order.
  std::vector<Image> draw(const std::vector<WorkerPose>& poses);
  /// The helper's process id (for tests and diagnostics).
  int pid() const { return pid_; }

 private:
  FrameWorker(int fd, int pid) : fd_(fd), pid_(pid) {}
  static std::unique_ptr<FrameWorker> spawn(std::string* why);
  void load(const ArmScene& scene, const std::string& source, const RenderSettings& settings,
            bool warm);
  bool read_loads(bool* timed_out);
  void send_message(const frame_wire::Packed& message);
  int fd_ = -1;
  int pid_ = -1;
  int loads_pending_ = 0;   // answers to load() not read yet
  int frames_pending_ = 0;  // frames sent and not received
  bool failed_ = false;     // an error was raised: not reused
};

/// The helper program: $ARMSTUDY_FRAME_WORKER when set (empty or "none": no helper), else
/// armstudy-frames beside the running program (installed: <prefix>/bin/armstudy-frames),
/// else, for a program of the build tree (the tests), the one that build tree made; "" when
/// none of them is an executable file.
std::string frame_worker_program();

/// The helper's side: reads requests from `in_fd` and answers on `out_fd` until the
/// connection closes (returns 0) or breaks (returns 1). Errors of a request (a model MuJoCo
/// rejects, a failing context) are answered with their message, not thrown.
int run_frame_worker(int in_fd, int out_fd);

}  // namespace armstudy::scene
