// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// Runs the armstudy command as a user would (the ARMSTUDY_BINARY the test target defines),
// standard input closed, and returns its exit code and its standard output and error.

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace armstudy::testing {

/// The armstudy command under test (the ARMSTUDY_BINARY the test target defines).
inline const std::string kBin = ARMSTUDY_BINARY;

struct CliRun {
  int exit_code;
  std::string output;  ///< standard output and standard error, interleaved
};

/// `COMMAND 2>&1 </dev/null` through the shell; exit_code -1 when it did not exit normally.
inline CliRun run_shell(const std::string& command) {
  const std::string cmd = command + " 2>&1 </dev/null";
  CliRun r{-1, ""};
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (p && fgets(buf.data(), buf.size(), p)) r.output += buf.data();
  const int status = p ? pclose(p) : -1;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// `armstudy ARGS 2>&1 </dev/null`; exit_code -1 when it did not exit normally.
inline CliRun run_cli(const std::string& args) {
  // appended in place: GCC 12 misreads `std::string(...) + " " + args` inlined into some
  // callers as an out-of-bounds copy (-Warray-bounds)
  std::string command = ARMSTUDY_BINARY;
  command += ' ';
  command += args;
  return run_shell(command);
}

/// How run_bounded runs armstudy.
struct Bounds {
  double timeout_s = 60;    ///< then it is killed (SIGKILL) and counted as a hang
  bool stdin_open = false;  ///< standard input a pipe nobody writes to, kept open (else /dev/null)
  long open_files = 0;      ///< > 0: ulimit -n (soft and hard) for armstudy
  std::vector<std::pair<std::string, std::string>> env = {};  ///< set for armstudy only
};

struct BoundedRun {
  int exit_code = -1;  ///< -1 unless it exited normally
  int signal = 0;      ///< the signal that ended it, 0 if none
  bool hung = false;   ///< still running at the timeout (then killed)
  std::string output;  ///< standard output and standard error, interleaved
};

/// `armstudy ARGS` in a child process, never waited for longer than `b.timeout_s`.
inline BoundedRun run_bounded(const std::vector<std::string>& args, const Bounds& b = {}) {
  BoundedRun r;
  char log_name[] = "/tmp/armstudy_bounded_XXXXXX";
  const int log = ::mkstemp(log_name);
  int in[2] = {-1, -1};
  if (log < 0 || ::pipe(in) != 0) return r;
  std::vector<std::string> argv_text{ARMSTUDY_BINARY};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null_in = ::open("/dev/null", O_RDONLY);
    ::dup2(b.stdin_open ? in[0] : null_in, 0);
    ::dup2(log, 1);
    ::dup2(log, 2);
    ::close(in[1]);
    for (const auto& [k, v] : b.env) ::setenv(k.c_str(), v.c_str(), 1);
    if (b.open_files > 0) {
      const struct rlimit rl {
        static_cast<rlim_t>(b.open_files), static_cast<rlim_t>(b.open_files)
      };
      ::setrlimit(RLIMIT_NOFILE, &rl);
    }
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(in[0]);
  int status = 0;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(b.timeout_s);
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      r.hung = true;
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::close(in[1]);
  if (!r.hung && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (!r.hung && WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  ::lseek(log, 0, SEEK_SET);
  std::array<char, 4096> buf;
  for (ssize_t n; (n = ::read(log, buf.data(), buf.size())) > 0;) r.output.append(buf.data(), n);
  ::close(log);
  ::unlink(log_name);
  return r;
}

}  // namespace armstudy::testing
