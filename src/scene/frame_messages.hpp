// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The messages between armstudy and its frame helper (scene/frame_worker.hpp): each one typed
/// struct with one `fields` list, which the writer (pack) and the reader (unpack) both walk, so
/// that a field added to the list is written and read at the same place of its message.
///
/// On the wire a message is its kind byte and its fields in list order, in this machine's byte
/// order (both ends are one machine): an int as 4 bytes, a bool as 1, a double as 8, a string
/// as its length (u64) and bytes, a vector as its size (i32) and doubles, an image's pixels as
/// its raw RGB rows. The reader refuses a string, a vector or an image past its limit.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>

#include <Eigen/Dense>

#include "scene/frame_worker.hpp"
#include "scene/image.hpp"
#include "scene/renderer.hpp"

namespace armstudy::scene::frame_wire {

/// The kind byte that opens a message.
enum Kind : char {
  kScene = 'S',  ///< parent: a SceneMessage to load
  kWarm = 'W',   ///< parent: as kScene, and one frame drawn and dropped (its contexts warm)
  kReset = 'R',  ///< parent: mj_resetData (no fields, no answer)
  kFrame = 'F',  ///< parent: a WorkerPose to draw
  kReady = 'K',  ///< helper: the scene is loaded (no fields)
  kImage = 'I',  ///< helper: the frame drawn, an Image
  kError = 'E',  ///< helper: an ErrorMessage
};

/// The reader's limits.
inline constexpr std::size_t kMaxMjcfBytes = std::size_t{1} << 30;
inline constexpr std::size_t kMaxLabelBytes = std::size_t{1} << 20;
inline constexpr std::size_t kMaxTextBytes = std::size_t{1} << 16;  ///< a source name, an error
inline constexpr int kMaxCoordinates = 4096;                        ///< of qpos, qvel
inline constexpr int kMaxImageSide = 1 << 14;                       ///< px

/// kScene, kWarm: the scene a helper loads.
struct SceneMessage {
  std::string mjcf;
  std::string source;  ///< names the model in MuJoCo's messages
  RenderSettings settings;
  ViewBox view;
};

/// kError: what failed, in words.
struct ErrorMessage {
  std::string text;
};

template <class V>
void fields(V& v, SceneMessage& m) {
  v(m.mjcf, kMaxMjcfBytes);
  v(m.source, kMaxTextBytes);
  v(m.settings.frame.width);
  v(m.settings.frame.height);
  v(m.settings.shadows);
  v(m.settings.margin);
  v(m.view.x_min);
  v(m.view.x_max);
  v(m.view.y_min);
  v(m.view.y_max);
}

/// kFrame: the pose to draw (scene/frame_worker.hpp).
template <class V>
void fields(V& v, WorkerPose& p) {
  v(p.t);
  v(p.qpos);
  v(p.qvel);
  v(p.labels.top_left, kMaxLabelBytes);
  v(p.labels.top_right, kMaxLabelBytes);
  v(p.labels.bottom_left, kMaxLabelBytes);
}

/// kImage: the frame; its pixels last.
template <class V>
void fields(V& v, Image& img) {
  v(img.width);
  v(img.height);
  v.pixels(img);
}

template <class V>
void fields(V& v, ErrorMessage& m) {
  v(m.text, kMaxTextBytes);
}

/// A message as bytes: the kind and the fields, then the pixels of an image (sent from
/// where they are, not copied).
struct Packed {
  std::string bytes;
  std::span<const std::uint8_t> raw;  ///< an image's pixels, sent after `bytes`

  template <class T>
  void operator()(const T& x, std::size_t = 0) {
    if constexpr (std::is_same_v<T, std::string>) {
      put<std::uint64_t>(x.size());
      bytes += x;
    } else if constexpr (std::is_same_v<T, Eigen::VectorXd>) {
      put<std::int32_t>(static_cast<std::int32_t>(x.size()));
      bytes.append(reinterpret_cast<const char*>(x.data()), sizeof(double) * x.size());
    } else if constexpr (std::is_same_v<T, bool>) {
      put<std::uint8_t>(x ? 1 : 0);
    } else if constexpr (std::is_same_v<T, int>) {
      put<std::int32_t>(x);
    } else {
      static_assert(std::is_same_v<T, double>, "a field type the frame messages do not know");
      put(x);
    }
  }
  void pixels(const Image& img) { raw = img.rgb; }

 private:
  template <typename T>
  void put(const T& v) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
};

/// `m` as the message `kind` (a message without fields: Packed{} and the kind byte).
template <class M>
Packed pack(Kind kind, const M& m) {
  Packed out;
  out.bytes.push_back(kind);
  fields(out, const_cast<M&>(m));  // the writer only reads
  return out;
}

/// The message of `kind` without fields (kReset, kReady).
inline Packed pack(Kind kind) {
  Packed out;
  out.bytes.push_back(kind);
  return out;
}

/// Writes everything, waiting at most timeout_ms for the other end to take each part (-1:
/// no limit); false if the other end is gone or the time ran out (`timed_out` set).
bool send_all(int fd, const char* p, std::size_t n, int timeout_ms = -1, bool* timed_out = nullptr);
/// Sends a packed message (its bytes, then its pixels); false as send_all.
bool send(int fd, const Packed& m, int timeout_ms = -1, bool* timed_out = nullptr);
/// Reads exactly n bytes, waiting at most timeout_ms for each part (-1: no limit); false at
/// the end of the connection, on an error or when the time ran out (`timed_out` set).
bool read_all(int fd, char* p, std::size_t n, int timeout_ms, bool* timed_out = nullptr);

/// Reads messages' fields from a connection; `ok` false from the first short read, value
/// past its limit or time-out on (`timed_out` says which).
struct Reader {
  int fd;
  int timeout_ms;  ///< for each part; -1: no limit
  bool timed_out = false;
  bool ok = true;

  /// The next kind byte.
  char kind() { return get<char>(); }

  template <class T>
  void operator()(T& x, std::size_t at_most = 0) {
    if constexpr (std::is_same_v<T, std::string>) {
      const auto n = get<std::uint64_t>();
      if (!ok || n > at_most) return fail(x);
      x.assign(n, '\0');
      bytes(x.data(), n);
    } else if constexpr (std::is_same_v<T, Eigen::VectorXd>) {
      const auto n = get<std::int32_t>();
      if (!ok || n < 0 || n > kMaxCoordinates) return fail(x);
      x.resize(n);
      bytes(reinterpret_cast<char*>(x.data()), sizeof(double) * n);
    } else if constexpr (std::is_same_v<T, bool>) {
      x = get<std::uint8_t>() != 0;
    } else if constexpr (std::is_same_v<T, int>) {
      x = get<std::int32_t>();
    } else {
      static_assert(std::is_same_v<T, double>, "a field type the frame messages do not know");
      x = get<double>();
    }
  }
  /// the pixels of an image whose width and height were read: refused unless both are in
  /// (0, kMaxImageSide]
  void pixels(Image& img) {
    if (!ok || img.width <= 0 || img.height <= 0 || img.width > kMaxImageSide ||
        img.height > kMaxImageSide) {
      ok = false;
      return;
    }
    img.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
    bytes(reinterpret_cast<char*>(img.rgb.data()), img.rgb.size());
  }

 private:
  template <typename T>
  T get() {
    T v{};
    bytes(reinterpret_cast<char*>(&v), sizeof v);
    return v;
  }
  void bytes(char* p, std::size_t n) { ok = ok && read_all(fd, p, n, timeout_ms, &timed_out); }
  template <class T>
  void fail(T& x) {
    x = T();
    ok = false;
  }
};

/// The fields of a message whose kind byte was read; false (and `in.ok` false) when the
/// connection ended or a value was past its limit.
template <class M>
bool unpack(Reader& in, M& m) {
  fields(in, m);
  return in.ok;
}

}  // namespace armstudy::scene::frame_wire
