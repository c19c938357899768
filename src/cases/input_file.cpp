// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/input_file.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace armstudy::cases {
namespace {

std::string size_text(double bytes) {
  char buf[32];
  if (bytes >= 1 << 20)
    std::snprintf(buf, sizeof buf, "%.1f MiB", bytes / (1 << 20));
  else
    std::snprintf(buf, sizeof buf, "%.0f bytes", bytes);
  return buf;
}

bool is_runtime(int err) {
  return err == EMFILE || err == ENFILE || err == ENOMEM || err == EIO || err == EINTR ||
         err == EAGAIN;
}

struct FdCloser {
  int fd;
  ~FdCloser() { ::close(fd); }
};

}  // namespace

std::string errno_text(int err) {
  std::string text = std::strerror(err);
  if (err == EMFILE) {
    struct rlimit rl {};
    if (::getrlimit(RLIMIT_NOFILE, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
      text += " (the limit of open files, ulimit -n, is " + std::to_string(rl.rlim_cur) + ")";
  } else if (err == ENFILE) {
    text += " (the system's limit of open files)";
  }
  return text;
}

// (over 60 lines, kept whole: one open file descriptor from open to the last read, each
// refusal with its own message)
bool read_input_file(const std::string& path, const InputFileRules& rules, std::string* bytes,
                     std::string* why, bool* runtime) {
  *runtime = false;
  const auto fail = [&](std::string text, bool rt = false) {
    *why = std::move(text);
    *runtime = rt;
    return false;
  };
  // O_NONBLOCK: opening a FIFO without a writer must not wait for one; O_NOFOLLOW: a link
  // where armstudy wrote a file is refused, not followed
  const int flags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | (rules.follow_symlink ? 0 : O_NOFOLLOW);
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) {
    const int err = errno;
    if (err == ELOOP && !rules.follow_symlink)
      return fail("is a symbolic link; expected a regular " + rules.kind + ", not a link");
    if (err == ELOOP)
      return fail(
          "cannot open the file: too many levels of symbolic links (a link loop?); "
          "expected a readable " +
          rules.kind);
    return fail("cannot open the file: " + errno_text(err) + "; expected a readable " + rules.kind,
                is_runtime(err));
  }
  FdCloser closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) return fail("cannot read the file: " + errno_text(errno), true);
  if (S_ISDIR(st.st_mode)) return fail("is a folder; expected a " + rules.kind);
  if (!S_ISREG(st.st_mode)) {
    const char* what = S_ISFIFO(st.st_mode)                         ? "a FIFO (named pipe)"
                       : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                       : S_ISSOCK(st.st_mode)                       ? "a socket"
                                                                    : "not a regular file";
    return fail(std::string("is ") + what + "; expected a regular " + rules.kind);
  }
  const std::size_t cap = rules.max_bytes;
  if (static_cast<unsigned long long>(st.st_size) > cap)
    return fail("is " + size_text(double(st.st_size)) + "; expected a " + rules.kind +
                " of at most " + size_text(double(cap)));
  // back to blocking reads of a regular file; never more than the cap, even if it grows
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::string out;
  out.resize(static_cast<std::size_t>(st.st_size) + 1);
  std::size_t got = 0;
  for (;;) {
    if (got == out.size()) {
      if (out.size() > cap) break;
      out.resize(std::min(out.size() * 2, cap + 1));
    }
    const ssize_t r = ::read(fd, out.data() + got, out.size() - got);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) return fail("cannot read the file: " + errno_text(errno), true);
    if (r == 0) break;
    got += static_cast<std::size_t>(r);
  }
  if (got > cap)
    return fail("grew past " + size_text(double(cap)) + " while being read; expected a " +
                rules.kind + " of at most that size");
  out.resize(got);
  *bytes = std::move(out);
  return true;
}

std::string read_input_file(const std::string& path, const InputFileRules& rules) {
  std::string bytes, why;
  bool runtime = false;
  if (!read_input_file(path, rules, &bytes, &why, &runtime))
    throw InputFileError(path + ": " + why, runtime);
  return bytes;
}

}  // namespace armstudy::cases
