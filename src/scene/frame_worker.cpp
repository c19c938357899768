// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/frame_worker.hpp"

#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <thread>

#include "scene/frame_messages.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/scene_error.hpp"
#include "sys/process.hpp"

namespace armstudy::scene {
namespace fs = std::filesystem;

namespace wire = frame_wire;  // the messages (scene/frame_messages.hpp)

namespace {

// how long the parent waits for the helper to take or give its next bytes before it ends
// it (ARMSTUDY_HELPER_TIMEOUT_S, 120 s by default)
int answer_timeout_ms() { return static_cast<int>(sys::helper_timeout_seconds() * 1000); }

// the error of a helper that made no progress (it has been killed)
HelperStuck stuck(int pid) {
  char secs[32];
  std::snprintf(secs, sizeof secs, "%g", sys::helper_timeout_seconds());
  return HelperStuck("the frame helper (armstudy-frames, " + frame_worker_program() + ", pid " +
                     std::to_string(pid) + ") made no progress for " + secs +
                     " s (ARMSTUDY_HELPER_TIMEOUT_S) and was ended");
}

}  // namespace

std::string frame_worker_program() {
  if (const char* env = std::getenv("ARMSTUDY_FRAME_WORKER")) {
    const std::string p = env;
    return p.empty() || p == "none" || !sys::is_executable(p) ? "" : p;
  }
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && sys::is_executable(self.parent_path() / "armstudy-frames"))
    return (self.parent_path() / "armstudy-frames").string();
#if defined(ARMSTUDY_FRAME_WORKER_BUILT) && defined(ARMSTUDY_BUILD_TREE)
  // the build's helper, for the build tree's programs only (the tests in build/tests); an
  // installed armstudy never looks into the build tree
  const bool in_build = !ec && self.string().rfind(ARMSTUDY_BUILD_TREE "/", 0) == 0;
  if (in_build && sys::is_executable(ARMSTUDY_FRAME_WORKER_BUILT))
    return ARMSTUDY_FRAME_WORKER_BUILT;
#endif
  return "";
}

std::unique_ptr<FrameWorker> FrameWorker::spawn(std::string* why) {
  const auto fail = [&](const std::string& text) -> std::unique_ptr<FrameWorker> {
    if (why) *why = text;
    return nullptr;
  };
  const std::string program = frame_worker_program();
  if (program.empty()) return fail("no frame helper program (armstudy-frames)");
  int sv[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
    return fail(std::string("socketpair: ") + std::strerror(errno));
  // the helper's end as its standard input and output (dup2 clears close-on-exec); its
  // signals as new (armstudy blocks the termination signals in every thread); one
  // rasteriser thread unless the environment says otherwise (it draws beside this process)
  sys::SpawnOptions o;
  o.fds = {{sv[1], 0}, {sv[1], 1}};
  o.default_signals = {SIGPIPE, SIGINT, SIGTERM, SIGHUP};
  bool lp_set = false;
  for (std::string& e : sys::current_environment()) {
    lp_set |= e.rfind("LP_NUM_THREADS=", 0) == 0;
    o.env.push_back(std::move(e));
  }
  if (!lp_set) o.env.emplace_back("LP_NUM_THREADS=1");
  o.argv = {program, std::to_string(::getpid())};
  int error = 0;
  const pid_t pid = sys::spawn(o, &error);
  ::close(sv[1]);
  if (pid < 0) {
    ::close(sv[0]);
    return fail("cannot start " + program + ": " + std::strerror(error));
  }
  return std::unique_ptr<FrameWorker>(new FrameWorker(sv[0], pid));
}

void FrameWorker::send_message(const frame_wire::Packed& message) {
  bool timed_out = false;
  if (!wire::send(fd_, message, answer_timeout_ms(), &timed_out)) {
    failed_ = true;
    if (timed_out) {
      ::kill(pid_, SIGKILL);
      throw stuck(pid_);
    }
    throw SceneError("the frame helper (armstudy-frames) closed the connection");
  }
}

void FrameWorker::load(const ArmScene& scene, const std::string& source,
                       const RenderSettings& settings, bool warm) {
  send_message(wire::pack(warm ? wire::kWarm : wire::kScene,
                          wire::SceneMessage{scene.mjcf, source, settings, scene.view}));
  ++loads_pending_;
}

// the answers to the loads asked for, in order: an error of the last is thrown, of an
// earlier one (a scene replaced before it was drawn) dropped; false if the helper is gone
bool FrameWorker::read_loads(bool* timed_out) {
  wire::Reader in{fd_, answer_timeout_ms()};
  while (loads_pending_ > 0) {
    const char type = in.kind();
    if (!in.ok) return *timed_out = in.timed_out, false;
    --loads_pending_;
    if (type == wire::kError) {
      wire::ErrorMessage why;
      if (!wire::unpack(in, why)) return *timed_out = in.timed_out, false;
      if (loads_pending_ == 0)
        throw SceneError("the frame helper (armstudy-frames) could not load the scene: " +
                         why.text);
    } else if (type != wire::kReady) {
      return false;
    }
  }
  return true;
}

namespace {
// this thread's idle helpers (closed when the thread ends)
std::vector<std::unique_ptr<FrameWorker>>& idle_workers() {
  thread_local std::vector<std::unique_ptr<FrameWorker>> idle;
  return idle;
}
}  // namespace

std::unique_ptr<FrameWorker> FrameWorker::acquire(const ArmScene& scene, const std::string& source,
                                                  const RenderSettings& settings,
                                                  std::string* why) {
  auto& idle = idle_workers();
  std::unique_ptr<FrameWorker> w;
  if (!idle.empty()) {
    w = std::move(idle.back());
    idle.pop_back();
  } else {
    w = spawn(why);
  }
  if (!w) return nullptr;
  try {
    w->load(scene, source, settings, false);
  } catch (const SceneError& e) {
    if (why) *why = e.what();
    return nullptr;
  }
  return w;
}

void FrameWorker::release(std::unique_ptr<FrameWorker> worker) {
  if (!worker || worker->failed_ || worker->frames_pending_ != 0) return;
  // a scene it never drew (this process drew every frame first): its answer read now, so
  // that the next acquire starts clean
  bool timed_out = false;
  try {
    if (!worker->read_loads(&timed_out)) return;
  } catch (const SceneError&) {
    return;
  }
  idle_workers().push_back(std::move(worker));
}

void FrameWorker::prewarm(const ArmScene& scene, const RenderSettings& settings) {
  std::unique_ptr<FrameWorker> w = spawn(nullptr);
  if (!w) return;
  try {
    w->load(scene, "warm-up scene", settings, true);
  } catch (const SceneError&) {
    return;
  }
  idle_workers().push_back(std::move(w));
}

FrameWorker::~FrameWorker() {
  if (fd_ >= 0) ::close(fd_);  // the helper reads the end of its input and exits
  if (pid_ <= 0) return;
  if (loads_pending_ > 0 || frames_pending_ > 0) ::kill(pid_, SIGKILL);  // busy: not waited for
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  int status = 0;
  while (::waitpid(pid_, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > until) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

void FrameWorker::reset() { send_message(wire::pack(wire::kReset)); }

void FrameWorker::send(const WorkerPose& p) {
  send_message(wire::pack(wire::kFrame, p));
  ++frames_pending_;
}

Image FrameWorker::receive() {
  // any error below leaves the connection in an unknown state: this helper is not reused
  failed_ = true;
  wire::Reader in{fd_, answer_timeout_ms()};
  const auto gone = [&]() -> SceneError {
    if (!in.timed_out) return SceneError("the frame helper (armstudy-frames) ended unexpectedly");
    ::kill(pid_, SIGKILL);
    throw stuck(pid_);
  };
  if (!read_loads(&in.timed_out)) throw gone();
  if (frames_pending_ <= 0) throw SceneError("frame helper: no frame was asked for");
  const char type = in.kind();
  if (in.ok && type == wire::kError) {
    wire::ErrorMessage e;
    wire::unpack(in, e);
    throw SceneError(e.text);
  }
  Image img;
  if (!in.ok || type != wire::kImage || !wire::unpack(in, img)) throw gone();
  --frames_pending_;
  failed_ = false;
  return img;
}

std::vector<Image> FrameWorker::draw(const std::vector<WorkerPose>& poses) {
  reset();
  for (const WorkerPose& p : poses) send(p);
  std::vector<Image> out;
  out.reserve(poses.size());
  for (size_t k = 0; k < poses.size(); ++k) out.push_back(receive());
  return out;
}

namespace {

// the helper's scene: its model and renderer
struct HelperState {
  std::unique_ptr<MujocoModel> model;
  std::unique_ptr<Renderer> renderer;
};

// loads `m` (for a warm-up, draws one frame of it and drops it); throws what MuJoCo or
// OSMesa throws
void helper_load(HelperState& h, const wire::SceneMessage& m, bool warm) {
  h.renderer.reset();
  h.model.reset();
  h.model = std::make_unique<MujocoModel>(m.mjcf, m.source);
  h.renderer = std::make_unique<Renderer>(h.model->model(), m.settings, m.view);
  if (warm) {
    mj_forward(h.model->model(), h.model->data());
    h.renderer->render(h.model->data(), FrameLabels{"warm-up", "", ""});
  }
}

// the frame of pose `p`; @throws SceneError for a pose that is not the model's
Image helper_draw(HelperState& h, const WorkerPose& p) {
  if (!h.model || !h.renderer) throw SceneError("frame helper: a frame before the scene");
  mjModel* m = h.model->model();
  mjData* d = h.model->data();
  if (p.qpos.size() != m->nq || p.qvel.size() != m->nv)
    throw SceneError("frame helper: a pose of " + std::to_string(p.qpos.size()) +
                     " coordinates for a model of " + std::to_string(m->nq));
  // set_pose's steps (replay.cpp): qpos, qvel, time, then mj_forward
  for (int k = 0; k < m->nq; ++k) d->qpos[k] = p.qpos[k];
  for (int k = 0; k < m->nv; ++k) d->qvel[k] = p.qvel[k];
  d->time = p.t;
  mj_forward(m, d);
  return h.renderer->render(d, p.labels);
}

}  // namespace

int run_frame_worker(int in_fd, int out_fd) {
  install_mujoco_handlers();
  HelperState h;
  wire::Reader in{in_fd, -1};
  const auto answer_error = [&](const std::string& text) {
    return wire::send(out_fd, wire::pack(wire::kError, wire::ErrorMessage{text}));
  };
  while (true) {
    const char type = in.kind();
    if (!in.ok) return 0;  // the parent closed the connection
    if (type == wire::kScene || type == wire::kWarm) {
      wire::SceneMessage m;
      if (!wire::unpack(in, m)) return 1;
      try {
        helper_load(h, m, type == wire::kWarm);
        if (!wire::send(out_fd, wire::pack(wire::kReady))) return 1;
      } catch (const std::exception& e) {
        if (!answer_error(e.what())) return 1;
      }
    } else if (type == wire::kReset) {
      if (h.model) mj_resetData(h.model->model(), h.model->data());
    } else if (type == wire::kFrame) {
      WorkerPose p;
      if (!wire::unpack(in, p)) return 1;
      try {
        const Image img = helper_draw(h, p);
        if (!wire::send(out_fd, wire::pack(wire::kImage, img))) return 1;
      } catch (const std::exception& e) {
        if (!answer_error(e.what())) return 1;
      }
    } else {
      answer_error(std::string("frame helper: unknown request '") + type + "'");
      return 1;
    }
  }
}

}  // namespace armstudy::scene
