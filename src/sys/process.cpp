// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "sys/process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <sstream>

extern char** environ;

namespace armstudy::sys {
namespace fs = std::filesystem;

namespace {

std::vector<char*> c_strings(std::vector<std::string>& text) {
  std::vector<char*> out;
  for (auto& t : text) out.push_back(t.data());
  out.push_back(nullptr);
  return out;
}

pid_t spawn_posix(const SpawnOptions& o, char** argv, char** envp, int* error) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  for (const auto& [from, to] : o.fds) posix_spawn_file_actions_adddup2(&fa, from, to);
  for (const ChildFile& f : o.files) {
    if (f.child_fds.empty()) continue;
    posix_spawn_file_actions_addopen(&fa, f.child_fds[0], f.path.c_str(), f.flags, f.mode);
    for (size_t i = 1; i < f.child_fds.size(); ++i)
      posix_spawn_file_actions_adddup2(&fa, f.child_fds[0], f.child_fds[i]);
  }
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int s : o.default_signals) sigaddset(&defaults, s);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  short flags = POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF;
  if (o.own_group) {
    posix_spawnattr_setpgroup(&attr, 0);
    flags |= POSIX_SPAWN_SETPGROUP;
  }
  posix_spawnattr_setflags(&attr, flags);
  pid_t pid = -1;
  const int rc = ::posix_spawn(&pid, argv[0], &fa, &attr, argv, envp);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) {
    *error = rc;
    return -1;
  }
  return pid;
}

// the child's side of spawn_forked: only async-signal-safe calls until exec
[[noreturn]] void child_setup(const SpawnOptions& o, pid_t parent, int high_from, char** argv,
                              char** envp) {
  if (o.own_group) ::setpgid(0, 0);
  if (o.death_signal != 0) {
    ::prctl(PR_SET_PDEATHSIG, o.death_signal);
    if (::getppid() != parent) ::_exit(127);  // the parent ended before the line above
  }
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  for (int s : o.default_signals) ::sigaction(s, &dfl, nullptr);
  // every source descriptor first moved above all target numbers, so that a target never is
  // a source still needed (close-on-exec: the copies end with the exec)
  int high[16];
  const size_t n = std::min<size_t>(o.fds.size(), 16);
  for (size_t i = 0; i < n; ++i) {
    high[i] = ::fcntl(o.fds[i].first, F_DUPFD_CLOEXEC, high_from);
    if (high[i] < 0) ::_exit(127);
  }
  for (const ChildFile& f : o.files) {
    const int fd = ::open(f.path.c_str(), f.flags | O_CLOEXEC, f.mode);
    if (fd < 0) continue;
    for (int to : f.child_fds) {
      if (fd == to)
        ::fcntl(fd, F_SETFD, 0);  // kept open across the exec
      else
        ::dup2(fd, to);  // dup2 clears close-on-exec
    }
  }
  for (size_t i = 0; i < n; ++i)
    if (::dup2(high[i], o.fds[i].second) < 0) ::_exit(127);
  ::execve(argv[0], argv, envp);
  ::_exit(127);
}

pid_t spawn_forked(const SpawnOptions& o, char** argv, char** envp, int* error) {
  int high_from = 10;
  for (const auto& [from, to] : o.fds) high_from = std::max(high_from, to + 1);
  for (const ChildFile& f : o.files)
    for (int to : f.child_fds) high_from = std::max(high_from, to + 1);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    *error = errno;
    return -1;
  }
  if (pid == 0) child_setup(o, parent, high_from, argv, envp);
  if (o.own_group) ::setpgid(pid, pid);  // also here: no race with a kill of the group
  return pid;
}

}  // namespace

bool is_executable(const fs::path& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), X_OK) == 0;
}

std::string find_on_path(const std::vector<std::string>& names) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
  std::string dir;
  std::vector<std::string> entries;
  while (std::getline(dirs, dir, ':')) entries.push_back(dir.empty() ? "." : dir);
  for (const std::string& name : names)
    for (const auto& d : entries)
      if (is_executable(fs::path(d) / name)) return (fs::path(d) / name).string();
  return "";
}

std::vector<std::string> current_environment() {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) env.emplace_back(*e);
  return env;
}

double helper_timeout_seconds() {
  constexpr double kDefault = 120;
  const char* env = std::getenv("ARMSTUDY_HELPER_TIMEOUT_S");
  if (!env || !*env) return kDefault;
  char* end = nullptr;
  const double v = std::strtod(env, &end);
  return *end == '\0' && v >= 0.1 && v <= 86400 ? v : kDefault;
}

pid_t spawn(const SpawnOptions& o, int* error) {
  *error = 0;
  if (o.argv.empty()) {
    *error = EINVAL;
    return -1;
  }
  if (o.fds.size() > 16) {
    *error = EMFILE;
    return -1;
  }
  // built before a fork: the child allocates nothing
  std::vector<std::string> argv_text = o.argv, env_text = o.env;
  std::vector<char*> argv = c_strings(argv_text), envp = c_strings(env_text);
  if (o.death_signal != 0) return spawn_forked(o, argv.data(), envp.data(), error);
  return spawn_posix(o, argv.data(), envp.data(), error);
}

}  // namespace armstudy::sys
