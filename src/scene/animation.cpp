// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/animation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <future>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "scene/phase_times.hpp"
#include "scene/png_writer.hpp"
#include "scene/replay.hpp"
#include "scene/scene_error.hpp"
#include "sys/process.hpp"

namespace armstudy::scene {
namespace fs = std::filesystem;

namespace {

// a pipe, both ends close-on-exec (spawn gives the child its end as a copy); false when
// out of descriptors
bool make_pipe(int fds[2]) { return ::pipe2(fds, O_CLOEXEC) == 0; }

// "N s" of the helper timeout, for messages
std::string timeout_text() {
  char secs[32];
  std::snprintf(secs, sizeof secs, "%g s", sys::helper_timeout_seconds());
  return secs;
}

// ffmpeg's command line: raw RGB frames of `first`'s size on stdin, H.264 MP4 into tmp
std::vector<std::string> ffmpeg_arguments(const std::string& ffmpeg, const Image& first, double fps,
                                          const fs::path& tmp) {
  const int w = first.width & ~1, h = first.height & ~1;
  char rate[64];
  std::snprintf(rate, sizeof rate, "%.6f", fps);
  return {ffmpeg,
          "-loglevel",
          "error",
          "-nostdin",
          "-y",
          "-f",
          "rawvideo",
          "-pix_fmt",
          "rgb24",
          "-s",
          std::to_string(first.width) + "x" + std::to_string(first.height),
          "-framerate",
          rate,
          "-i",
          "-",
          "-vf",
          "crop=" + std::to_string(w) + ":" + std::to_string(h) + ":0:0",
          "-c:v",
          "libx264",
          "-preset",
          "veryfast",
          "-crf",
          "20",
          "-pix_fmt",
          "yuv420p",
          "-threads",
          "1",
          "-map_metadata",
          "-1",
          "-fflags",
          "+bitexact",
          "-flags:v",
          "+bitexact",
          "-movflags",
          "+faststart",
          tmp.string()};
}

// what feeding ffmpeg came to: its messages (the last 2 kB), whether it took nothing and
// said nothing for the timeout, whether it closed its input before taking every frame
struct FeedOutcome {
  std::string said;
  bool stuck = false;
  bool write_failed = false;
};

// the frames into ffmpeg's input (non-blocking, closed at the end), its messages out, until
// it has every frame and closes its output or stays silent for timeout_ms
FeedOutcome feed_frames(const std::vector<Image>& frames, int in_write, int msg_read,
                        int timeout_ms) {
  FeedOutcome out;
  std::string& said = out.said;
  bool& stuck = out.stuck;
  bool& write_failed = out.write_failed;
  // the frames in, ffmpeg's messages out, until it has every frame and ends
  size_t frame = 0, at = 0;
  int in_fd = in_write;
  bool msg_open = true;
  while ((in_fd >= 0 || msg_open) && !stuck) {
    if (in_fd >= 0 && frame == frames.size()) {
      ::close(in_fd), in_fd = -1;
      continue;
    }
    pollfd p[2] = {{msg_open ? msg_read : -1, POLLIN, 0}, {in_fd, POLLOUT, 0}};
    const int r = ::poll(p, 2, timeout_ms);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) {
      stuck = r == 0;
      break;
    }
    if (p[0].revents) {
      char buf[4096];
      const ssize_t got = ::read(msg_read, buf, sizeof buf);
      if (got > 0) {
        said.append(buf, static_cast<size_t>(got));
        if (said.size() > 2048) said.erase(0, said.size() - 2048);
      } else if (got == 0 || errno != EINTR) {
        msg_open = false;
      }
    }
    if (in_fd >= 0 && p[1].revents) {
      const Image& f = frames[frame];
      const ssize_t put = ::write(in_fd, f.rgb.data() + at, f.rgb.size() - at);
      if (put > 0) {
        at += static_cast<size_t>(put);
        if (at == f.rgb.size()) ++frame, at = 0;
      } else if (put < 0 && errno != EINTR && errno != EAGAIN) {
        write_failed = true;  // ffmpeg closed its input (it failed: its messages say why)
        ::close(in_fd), in_fd = -1;
      }
    }
  }
  if (in_fd >= 0) ::close(in_fd);
  return out;
}

// frames as raw RGB into ffmpeg's stdin: H.264 in MP4, yuv420p (plays everywhere), one
// thread and bit-exact flags so that the same frames give the same file; x264's veryfast
// preset: about 0.6x medium's CPU on these flat-shaded scenes at the same crf, 46 dB PSNR
// against medium's 48 and a file about 5 % larger. ffmpeg is watched: when it takes no
// input, says nothing and does not end for sys::helper_timeout_seconds(), it is killed and
// the video left out (its messages, the last 2 kB, say why it failed).
bool write_video(const std::string& ffmpeg, const std::vector<Image>& frames, double fps,
                 const fs::path& out, std::string* why) {
  PhaseScope phase("video");
  const fs::path tmp = out.string() + ".tmp.mp4";
  std::error_code ec;
  fs::remove(tmp, ec);
  sys::SpawnOptions o;
  o.argv = ffmpeg_arguments(ffmpeg, frames.front(), fps, tmp);
  o.env = sys::current_environment();
  o.default_signals = {SIGPIPE, SIGINT, SIGTERM, SIGHUP};
  o.death_signal = SIGKILL;  // dies with this thread (and with armstudy)
  // close-on-exec ends: a process another thread starts meanwhile (Chromium, another
  // case's ffmpeg) must not inherit them, or ffmpeg waits for that process to end
  int in[2], msg[2];
  if (!make_pipe(in)) {
    *why = "cannot start ffmpeg: " + std::string(std::strerror(errno));
    return false;
  }
  if (!make_pipe(msg)) {
    const int err = errno;
    ::close(in[0]), ::close(in[1]);
    return *why = "cannot start ffmpeg: " + std::string(std::strerror(err)), false;
  }
  o.fds = {{in[0], 0}, {msg[1], 1}, {msg[1], 2}};
  int error = 0;
  const pid_t pid = sys::spawn(o, &error);
  ::close(in[0]), ::close(msg[1]);
  if (pid < 0) {
    ::close(in[1]), ::close(msg[0]);
    *why = "cannot start ffmpeg (" + ffmpeg + "): " + std::strerror(error);
    return false;
  }
  const int timeout_ms = static_cast<int>(sys::helper_timeout_seconds() * 1000);
  // this end never blocks: a frame goes in as far as ffmpeg takes it
  ::fcntl(in[1], F_SETFL, ::fcntl(in[1], F_GETFL) | O_NONBLOCK);
  // a write to an ffmpeg that has gone fails with EPIPE, never a SIGPIPE to this process
  // (blocked in this thread, and a pending one taken below)
  sigset_t pipe_signal, old_mask;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  ::pthread_sigmask(SIG_BLOCK, &pipe_signal, &old_mask);
  const FeedOutcome fed = feed_frames(frames, in[1], msg[0], timeout_ms);
  std::string said = fed.said;
  bool stuck = fed.stuck;
  const bool write_failed = fed.write_failed;
  const timespec now{0, 0};
  while (::sigtimedwait(&pipe_signal, nullptr, &now) == SIGPIPE) {
  }
  ::pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
  ::close(msg[0]);
  // its end: waited for at most the timeout once its output has closed
  int status = 0;
  const auto until =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(stuck ? 0 : timeout_ms);
  pid_t done = 0;
  while ((done = ::waitpid(pid, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (done == 0) {
    stuck = true;
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  while (!said.empty() && (said.back() == '\n' || said.back() == '\r')) said.pop_back();
  const auto fail = [&](const std::string& text) {
    fs::remove(tmp, ec);
    *why = text;
    return false;
  };
  if (stuck)
    return fail("ffmpeg (" + ffmpeg + ") made no progress for " + timeout_text() +
                " (ARMSTUDY_HELPER_TIMEOUT_S) and was ended");
  const bool exited_ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (exited_ok && write_failed)
    return fail("ffmpeg (" + ffmpeg + ") ended without taking every frame or writing the video");
  if (!exited_ok)
    return fail("ffmpeg failed (" +
                (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                   : "signal " + std::to_string(WTERMSIG(status))) +
                (said.empty() ? "" : ": " + said) + ")");
  if (!fs::is_regular_file(fs::symlink_status(tmp, ec)) || fs::file_size(tmp, ec) == 0)
    return fail("ffmpeg (" + ffmpeg + ") ended without writing the video");
  fs::rename(tmp, out, ec);
  if (ec) return fail("cannot rename " + tmp.string() + ": " + ec.message());
  return true;
}

}  // namespace

std::string find_ffmpeg() {
  // a name without a folder is looked for on PATH (the program is started without a shell)
  if (const char* env = std::getenv("ARMSTUDY_FFMPEG"); env && *env)
    return std::string(env).find('/') == std::string::npos ? sys::find_on_path({env}) : env;
  return sys::find_on_path({"ffmpeg"});
}

int animation_frames(double duration) {
  if (!(duration > 0)) return kAnimationMinFrames;
  const int n = static_cast<int>(std::ceil(duration * kAnimationFps)) + 1;
  return std::clamp(n, kAnimationMinFrames, kAnimationMaxFrames);
}

PendingAnimation write_animation(SceneRenderer& sr, const SampledMotion& m,
                                 const std::string& title, const fs::path& dir,
                                 const std::string& name) {
  Animation a;
  a.name = name;
  a.title = title;
  if (m.t.size() < 2) throw SceneError("animation " + name + ": fewer than 2 samples");
  a.duration_s = m.t.back() - m.t.front();
  a.frames = animation_frames(a.duration_s);
  // frame k at t0 + k / fps: the last frame is the end of the motion
  a.fps = a.duration_s > 0 ? (a.frames - 1) / a.duration_s : 1;
  const std::vector<double> at = even_times(m.t.front(), m.t.back(), a.frames);
  const std::vector<PoseSample> samples = resample(m.t, m.q, m.qd, at);
  std::vector<FrameLabels> labels(samples.size());
  for (size_t k = 0; k < samples.size(); ++k)
    labels[k].top_left = title + "\n" + time_label(samples[k].t);
  std::vector<Image> frames = sr.frames(samples, labels);
  // the sprite: frames at 3/4 size, 8 to a row
  a.columns = std::min(a.frames, 8);
  a.frame_width = frames.front().width * 3 / 4;
  a.frame_height = frames.front().height * 3 / 4;
  const int rows = (a.frames + a.columns - 1) / a.columns;
  Image sheet(a.columns * a.frame_width, rows * a.frame_height);
  std::optional<PhaseScope> sprite_phase(std::in_place, "sprite");
  for (int k = 0; k < a.frames; ++k)
    blit(downscale(frames[k], a.frame_width, a.frame_height), &sheet,
         (k % a.columns) * a.frame_width, (k / a.columns) * a.frame_height);
  sprite_phase.reset();
  a.sprite = name + "_anim.png";
  write_png(dir / a.sprite, sheet, sr.strip_threads());
  a.still = name + "_still.png";
  write_png(dir / a.still, frames.back());
  // the video on a thread of its own: ffmpeg encodes while this thread draws on (the
  // animation's get() waits for it)
  return std::async(std::launch::async, [a, dir, frames = std::move(frames)]() mutable {
    const std::string ffmpeg = find_ffmpeg();
    if (ffmpeg.empty()) {
      a.note = "no video: ffmpeg was not found (apt-get install ffmpeg)";
    } else {
      std::string why;
      if (write_video(ffmpeg, frames, a.fps, dir / (a.name + ".mp4"), &why))
        a.video = a.name + ".mp4";
      else
        a.note = "no video: " + why;
    }
    return a;
  });
}

std::vector<Animation> finish_animations(std::vector<PendingAnimation>& pending) {
  PhaseScope phase("video_wait");
  std::vector<Animation> out;
  std::exception_ptr first;
  for (auto& f : pending) {
    try {
      out.push_back(f.get());
    } catch (...) {
      if (!first) first = std::current_exception();
    }
  }
  pending.clear();
  if (first) std::rethrow_exception(first);
  return out;
}

}  // namespace armstudy::scene
