// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/frame_messages.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

namespace armstudy::scene::frame_wire {

bool send_all(int fd, const char* p, std::size_t n, int timeout_ms, bool* timed_out) {
  while (n > 0) {
    if (timeout_ms >= 0) {
      pollfd pf{fd, POLLOUT, 0};
      const int r = ::poll(&pf, 1, timeout_ms);
      if (r < 0 && errno == EINTR) continue;
      if (r == 0 && timed_out) *timed_out = true;
      if (r <= 0) return false;
    }
    const ssize_t w = ::send(fd, p, n, MSG_NOSIGNAL | (timeout_ms >= 0 ? MSG_DONTWAIT : 0));
    if (w < 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

bool send(int fd, const Packed& m, int timeout_ms, bool* timed_out) {
  return send_all(fd, m.bytes.data(), m.bytes.size(), timeout_ms, timed_out) &&
         send_all(fd, reinterpret_cast<const char*>(m.raw.data()), m.raw.size(), timeout_ms,
                  timed_out);
}

bool read_all(int fd, char* p, std::size_t n, int timeout_ms, bool* timed_out) {
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
    n -= static_cast<std::size_t>(got);
  }
  return true;
}

}  // namespace armstudy::scene::frame_wire
