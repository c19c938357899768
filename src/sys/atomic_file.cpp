// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "sys/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>
#include <system_error>

namespace armstudy::sys {
namespace fs = std::filesystem;

std::string system_error_text(const std::string& what, const fs::path& path, int err) {
  return "cannot " + what + " " + path.string() + ": " +
         std::error_code(err, std::generic_category()).message();
}

void write_file_atomic(const fs::path& path, const std::string& text) {
  const fs::path part = part_path(path);
  const int fd = ::open(part.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error(system_error_text("write", path, errno));
  const char* p = text.data();
  size_t left = text.size();
  int err = 0;
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      err = n < 0 ? errno : EIO;
      break;
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  if (::close(fd) != 0 && !err) err = errno;
  if (!err && ::rename(part.c_str(), path.c_str()) != 0) err = errno;
  if (err) {
    ::unlink(part.c_str());
    throw std::runtime_error(system_error_text("write", path, err));
  }
}

}  // namespace armstudy::sys
