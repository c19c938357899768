// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/version_text.hpp"

#include <fcntl.h>
#include <mujoco/mujoco.h>
#include <nlopt.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Core>
#include <cerrno>
#include <chrono>
#include <exception>
#include <string>

#include "report/case_report.hpp"
#include "scene/osmesa_context.hpp"
#include "sys/process.hpp"
#include "version.hpp"

namespace armstudy::cli {
namespace {

// the OpenGL context's "GL_VERSION (GL_RENDERER)", or why there is none
std::string mesa_text() {
  try {
    scene::OsmesaContext gl(1, 1);
    const std::string version = gl.version(), renderer = gl.renderer();
    scene::OsmesaContext::release_current();
    return version + " (" + renderer + ")";
  } catch (const std::exception& e) {
    return std::string("not found (") + e.what() + ")";
  }
}

// the browser --pdf would use, with its own version line
std::string browser_text(int timeout_ms) {
  const std::string browser = report::find_chromium();
  if (browser.empty()) return "not found";
  const std::string line = program_version_line(browser, timeout_ms);
  if (!line.empty()) return browser + ": " + line;
  return browser + ": version unknown (its --version gave no line within " +
         std::to_string(timeout_ms) + " ms)";
}

}  // namespace

std::string program_version_line(const std::string& program, int timeout_ms) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return "";
  // its own process group (killed whole on a timeout) and default signals (armstudy blocks
  // the termination signals in every thread)
  sys::SpawnOptions o;
  o.argv = {program, "--version"};
  o.env = sys::current_environment();
  o.fds = {{fds[1], 1}};
  o.files = {{"/dev/null", O_RDONLY, 0, {0}}, {"/dev/null", O_WRONLY, 0, {2}}};
  for (int s = 1; s < NSIG; ++s)
    if (s != SIGKILL && s != SIGSTOP) o.default_signals.push_back(s);
  o.own_group = true;
  int error = 0;
  const pid_t pid = sys::spawn(o, &error);
  ::close(fds[1]);
  if (pid < 0) {
    ::close(fds[0]);
    return "";
  }
  std::string out;
  bool timed_out = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                          deadline - std::chrono::steady_clock::now())
                          .count();
    if (left <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int n = ::poll(&p, 1, static_cast<int>(left));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      timed_out = n == 0;
      break;
    }
    char buf[512];
    const ssize_t got = ::read(fds[0], buf, sizeof buf);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;  // end of output (a grandchild holding the pipe would time out)
    if (out.size() < 4096) out.append(buf, static_cast<size_t>(got));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(-pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return "";
  const std::string line = out.substr(0, out.find('\n'));
  return line.find_first_not_of(" \t\r") == std::string::npos ? "" : line;
}

std::string version_text(int browser_timeout_ms) {
  std::string t = std::string("armstudy ") + kVersion;
  t += std::string(" (commit ") + (*git_commit() ? git_commit() : "unknown") + ")\n";
  t += std::string("MuJoCo ") + mj_versionString() + " (headers " +
       std::to_string(mjVERSION_HEADER) + ")\n";
  t += "OSMesa/Mesa " + mesa_text() + "\n";
  t += "Eigen " + std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
       "." + std::to_string(EIGEN_MINOR_VERSION) + " (headers, at build time)\n";
#ifdef ARMSTUDY_YAML_CPP_VERSION
  t += "yaml-cpp " ARMSTUDY_YAML_CPP_VERSION " (at build time)\n";
#else
  t += "yaml-cpp version unknown\n";
#endif
  int major = 0, minor = 0, bugfix = 0;
  nlopt_version(&major, &minor, &bugfix);
  t += "NLopt " + std::to_string(major) + "." + std::to_string(minor) + "." +
       std::to_string(bugfix) + "\n";
  t += "browser (--pdf) " + browser_text(browser_timeout_ms);
  return t;
}

}  // namespace armstudy::cli
