#include "scene/frame_worker.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <thread>

#include "scene/mujoco_model.hpp"
#include "scene/scene_error.hpp"
#include "sys/process.hpp"

namespace armstudy::scene {
namespace fs = std::filesystem;

namespace {

// the protocol: a message is a type byte and its fields; numbers in this machine's byte
// order (both ends are one machine), a string as its length (u64) and bytes
enum : char {
  kScene = 'S',  // parent: mjcf, source, width, height, shadows, margin, view box
  kWarm = 'W',   // parent: as kScene, and one frame drawn and dropped (its contexts warm)
  kReset = 'R',  // parent: mj_resetData (no answer)
  kFrame = 'F',  // parent: time, nq, qpos, nv, qvel, three labels
  kReady = 'K',  // helper: the scene is loaded
  kImage = 'I',  // helper: width, height, RGB rows
  kError = 'E',  // helper: a message
};

// how long the parent waits for the helper's next bytes before it gives up on it
constexpr int kAnswerTimeoutMs = 120000;

struct Out {
  std::string bytes;
  template <typename T>
  void put(const T& v) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    bytes += s;
  }
  void put_vector(const Eigen::VectorXd& v) {
    put<std::int32_t>(static_cast<std::int32_t>(v.size()));
    bytes.append(reinterpret_cast<const char*>(v.data()), sizeof(double) * v.size());
  }
};

// writes everything; false if the other end is gone
bool send_all(int fd, const char* p, size_t n) {
  while (n > 0) {
    const ssize_t w = ::send(fd, p, n, MSG_NOSIGNAL);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<size_t>(w);
  }
  return true;
}

// reads exactly n bytes, waiting at most timeout_ms for each part (-1: no limit); false at
// the end of the connection, on an error or when the time ran out (`timed_out` set)
bool read_all(int fd, char* p, size_t n, int timeout_ms, bool* timed_out = nullptr) {
  while (n > 0) {
    if (timeout_ms >= 0) {
      pollfd pf{fd, POLLIN, 0};
      const int r = ::poll(&pf, 1, timeout_ms);
      if (r < 0 && errno == EINTR) continue;
      if (r == 0 && timed_out) *timed_out = true;
      if (r <= 0) return false;
    }
    const ssize_t got = ::read(fd, p, n);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    p += got;
    n -= static_cast<size_t>(got);
  }
  return true;
}

struct In {
  int fd;
  int timeout_ms;
  bool timed_out = false;
  bool ok = true;
  template <typename T>
  T get() {
    T v{};
    ok = ok && read_all(fd, reinterpret_cast<char*>(&v), sizeof v, timeout_ms, &timed_out);
    return v;
  }
  std::string get_string(size_t at_most) {
    const auto n = get<std::uint64_t>();
    if (!ok || n > at_most) return ok = false, std::string();
    std::string s(n, '\0');
    ok = ok && read_all(fd, s.data(), n, timeout_ms, &timed_out);
    return s;
  }
  Eigen::VectorXd get_vector() {
    const auto n = get<std::int32_t>();
    if (!ok || n < 0 || n > 4096) return ok = false, Eigen::VectorXd();
    Eigen::VectorXd v(n);
    ok = ok && read_all(fd, reinterpret_cast<char*>(v.data()), sizeof(double) * n, timeout_ms,
                        &timed_out);
    return v;
  }
};

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

void FrameWorker::send_bytes(const std::string& bytes) {
  if (!send_all(fd_, bytes.data(), bytes.size())) {
    failed_ = true;
    throw SceneError("the frame helper (armstudy-frames) closed the connection");
  }
}

void FrameWorker::load(const ArmScene& scene, const std::string& source,
                       const RenderSettings& settings, bool warm) {
  Out o;
  o.put(warm ? kWarm : kScene);
  o.put_string(scene.mjcf);
  o.put_string(source);
  o.put<std::int32_t>(settings.frame.width);
  o.put<std::int32_t>(settings.frame.height);
  o.put<std::uint8_t>(settings.shadows ? 1 : 0);
  o.put(settings.margin);
  o.put(scene.view.x_min);
  o.put(scene.view.x_max);
  o.put(scene.view.y_min);
  o.put(scene.view.y_max);
  send_bytes(o.bytes);
  ++loads_pending_;
}

// the answers to the loads asked for, in order: an error of the last is thrown, of an
// earlier one (a scene replaced before it was drawn) dropped; false if the helper is gone
bool FrameWorker::read_loads(bool* timed_out) {
  In in{fd_, kAnswerTimeoutMs};
  while (loads_pending_ > 0) {
    const char type = in.get<char>();
    if (!in.ok) return *timed_out = in.timed_out, false;
    --loads_pending_;
    if (type == kError) {
      const std::string why = in.get_string(1 << 16);
      if (!in.ok) return *timed_out = in.timed_out, false;
      if (loads_pending_ == 0)
        throw SceneError("the frame helper (armstudy-frames) could not load the scene: " + why);
    } else if (type != kReady) {
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

void FrameWorker::reset() {
  Out o;
  o.put(kReset);
  send_bytes(o.bytes);
}

void FrameWorker::send(const WorkerPose& p) {
  Out o;
  o.put(kFrame);
  o.put(p.t);
  o.put_vector(p.qpos);
  o.put_vector(p.qvel);
  o.put_string(p.labels.top_left);
  o.put_string(p.labels.top_right);
  o.put_string(p.labels.bottom_left);
  send_bytes(o.bytes);
  ++frames_pending_;
}

Image FrameWorker::receive() {
  // any error below leaves the connection in an unknown state: this helper is not reused
  failed_ = true;
  In in{fd_, kAnswerTimeoutMs};
  const auto gone = [&] {
    return SceneError(in.timed_out ? "the frame helper (armstudy-frames) stopped answering"
                                   : "the frame helper (armstudy-frames) ended unexpectedly");
  };
  if (!read_loads(&in.timed_out)) throw gone();
  if (frames_pending_ <= 0) throw SceneError("frame helper: no frame was asked for");
  const char type = in.get<char>();
  if (in.ok && type == kError) throw SceneError(in.get_string(1 << 16));
  const auto w = in.get<std::int32_t>(), h = in.get<std::int32_t>();
  if (!in.ok || type != kImage || w <= 0 || h <= 0 || w > 1 << 14 || h > 1 << 14) throw gone();
  Image img(w, h);
  if (!read_all(fd_, reinterpret_cast<char*>(img.rgb.data()), img.rgb.size(), kAnswerTimeoutMs))
    throw gone();
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

// (over 60 lines, kept whole: one loop over the requests of the frame protocol, each read
// field by field in the order the parent's FrameWorker writes them)
int run_frame_worker(int in_fd, int out_fd) {
  install_mujoco_handlers();
  std::unique_ptr<MujocoModel> model;
  std::unique_ptr<Renderer> renderer;
  In in{in_fd, -1};
  const auto answer_error = [&](const std::string& text) {
    Out o;
    o.put(kError);
    o.put_string(text);
    return send_all(out_fd, o.bytes.data(), o.bytes.size());
  };
  while (true) {
    const char type = in.get<char>();
    if (!in.ok) return 0;  // the parent closed the connection
    if (type == kScene || type == kWarm) {
      const std::string mjcf = in.get_string(size_t{1} << 30);
      const std::string source = in.get_string(1 << 16);
      RenderSettings s;
      s.frame.width = in.get<std::int32_t>();
      s.frame.height = in.get<std::int32_t>();
      s.shadows = in.get<std::uint8_t>() != 0;
      s.margin = in.get<double>();
      ViewBox v;
      v.x_min = in.get<double>();
      v.x_max = in.get<double>();
      v.y_min = in.get<double>();
      v.y_max = in.get<double>();
      if (!in.ok) return 1;
      try {
        renderer.reset();
        model.reset();
        model = std::make_unique<MujocoModel>(mjcf, source);
        renderer = std::make_unique<Renderer>(model->model(), s, v);
        if (type == kWarm) {
          mj_forward(model->model(), model->data());
          renderer->render(model->data(), FrameLabels{"warm-up", "", ""});
        }
        const char ready = kReady;
        if (!send_all(out_fd, &ready, 1)) return 1;
      } catch (const std::exception& e) {
        if (!answer_error(e.what())) return 1;
      }
    } else if (type == kReset) {
      if (model) mj_resetData(model->model(), model->data());
    } else if (type == kFrame) {
      const auto t = in.get<double>();
      const Eigen::VectorXd qpos = in.get_vector(), qvel = in.get_vector();
      FrameLabels labels;
      labels.top_left = in.get_string(1 << 20);
      labels.top_right = in.get_string(1 << 20);
      labels.bottom_left = in.get_string(1 << 20);
      if (!in.ok) return 1;
      try {
        if (!model || !renderer) throw SceneError("frame helper: a frame before the scene");
        mjModel* m = model->model();
        mjData* d = model->data();
        if (qpos.size() != m->nq || qvel.size() != m->nv)
          throw SceneError("frame helper: a pose of " + std::to_string(qpos.size()) +
                           " coordinates for a model of " + std::to_string(m->nq));
        // set_pose's steps (replay.cpp): qpos, qvel, time, then mj_forward
        for (int k = 0; k < m->nq; ++k) d->qpos[k] = qpos[k];
        for (int k = 0; k < m->nv; ++k) d->qvel[k] = qvel[k];
        d->time = t;
        mj_forward(m, d);
        const Image img = renderer->render(d, labels);
        Out o;
        o.put(kImage);
        o.put<std::int32_t>(img.width);
        o.put<std::int32_t>(img.height);
        if (!send_all(out_fd, o.bytes.data(), o.bytes.size()) ||
            !send_all(out_fd, reinterpret_cast<const char*>(img.rgb.data()), img.rgb.size()))
          return 1;
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
