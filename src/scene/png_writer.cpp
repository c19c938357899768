// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/png_writer.hpp"

#include <png.h>
#include <sys/stat.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <thread>
#include <vector>

#include "scene/phase_times.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::scene {
namespace {

// errors return through libpng's own setjmp/longjmp (never unwind C++ through C frames)
void on_png_warning(png_structp, png_const_charp) {}

void append(png_structp png, png_bytep data, png_size_t n) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), n);
}
void flush(png_structp) {}

}  // namespace

namespace {

void put32(std::string* out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out->push_back(static_cast<char>((v >> s) & 0xFF));
}

void chunk(std::string* out, const char* type, const std::string& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const size_t at = out->size();
  out->append(type, 4);
  out->append(data);
  const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(out->data() + at),
                          static_cast<uInt>(4 + data.size()));
  put32(out, static_cast<std::uint32_t>(crc));
}

// rows [y0, y1) of `image`, each after its filter byte 0 (none), as raw deflate at level 1;
// the last band ends the stream, the others end on a byte boundary (sync flush). The rows
// go to zlib as they are (no copy), the output grows in chunks as zlib fills them (its
// bound is about the input's size, a hundred times what a frame compresses to)
std::string deflate_band(const Image& image, int y0, int y1, bool last, uLong* adler) {
  const size_t row = static_cast<size_t>(image.width) * 3;
  z_stream z{};
  if (deflateInit2(&z, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw SceneError("zlib: cannot start a deflate stream");
  std::string out;
  size_t used = 0;  // bytes of out written
  constexpr size_t kChunk = 64 << 10;
  uLong a = adler32(0L, nullptr, 0);
  int rc = Z_OK;
  const auto run = [&](const Bytef* in, size_t n, int flush) {
    z.next_in = const_cast<Bytef*>(in);
    z.avail_in = static_cast<uInt>(n);
    do {
      if (out.size() - used < kChunk / 2) out.resize(out.size() + kChunk);
      z.next_out = reinterpret_cast<Bytef*>(out.data() + used);
      z.avail_out = static_cast<uInt>(out.size() - used);
      rc = deflate(&z, flush);
      used = out.size() - z.avail_out;
    } while (rc == Z_OK && (z.avail_in != 0 || z.avail_out == 0));
  };
  static const Bytef kFilterNone = 0;
  for (int y = y0; y < y1 && rc == Z_OK; ++y) {
    const Bytef* r = &image.rgb[static_cast<size_t>(y) * row];
    a = adler32(a, &kFilterNone, 1);
    a = adler32(a, r, static_cast<uInt>(row));
    run(&kFilterNone, 1, Z_NO_FLUSH);
    if (rc == Z_OK) run(r, row, Z_NO_FLUSH);
  }
  if (rc == Z_OK) run(nullptr, 0, last ? Z_FINISH : Z_SYNC_FLUSH);
  deflateEnd(&z);
  if (rc != (last ? Z_STREAM_END : Z_OK) || z.avail_in != 0)
    throw SceneError("zlib could not compress a band of a " + std::to_string(image.width) + " x " +
                     std::to_string(image.height) + " image");
  *adler = a;
  out.resize(used);
  return out;
}

// the PNG of `image` with its rows compressed in `bands` bands, on up to `threads` threads
// at once (thread j takes bands j, j + threads, ...): the bytes depend on the bands alone
std::string encode_png_bands(const Image& image, int bands_wanted, int threads) {
  const int bands = std::clamp(bands_wanted, 1, std::max(1, image.height));
  const int workers = std::clamp(threads, 1, bands);
  std::vector<std::string> parts(static_cast<size_t>(bands));
  std::vector<uLong> adlers(static_cast<size_t>(bands));
  std::vector<std::exception_ptr> errors(static_cast<size_t>(bands));
  const auto run = [&](int first) {
    for (int b = first; b < bands; b += workers) {
      try {
        const int y0 = static_cast<int>(static_cast<long>(image.height) * b / bands);
        const int y1 = static_cast<int>(static_cast<long>(image.height) * (b + 1) / bands);
        parts[b] = deflate_band(image, y0, y1, b == bands - 1, &adlers[b]);
      } catch (...) {
        errors[b] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < workers; ++j) pool.emplace_back(run, j);
  run(0);
  for (auto& t : pool) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  std::string z = "\x78\x01";  // zlib header: deflate, 32 KiB window, fastest
  uLong adler = adler32(0L, nullptr, 0);
  const size_t row_bytes = static_cast<size_t>(image.width) * 3 + 1;
  for (int b = 0; b < bands; ++b) {
    const int y0 = static_cast<int>(static_cast<long>(image.height) * b / bands);
    const int y1 = static_cast<int>(static_cast<long>(image.height) * (b + 1) / bands);
    z += parts[b];
    adler = adler32_combine(adler, adlers[b],
                            static_cast<z_off_t>(row_bytes * static_cast<size_t>(y1 - y0)));
  }
  put32(&z, static_cast<std::uint32_t>(adler));
  std::string out = "\x89PNG\r\n\x1a\n";
  std::string ihdr;
  put32(&ihdr, static_cast<std::uint32_t>(image.width));
  put32(&ihdr, static_cast<std::uint32_t>(image.height));
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, filters, no interlace
  chunk(&out, "IHDR", ihdr);
  chunk(&out, "IDAT", z);
  chunk(&out, "IEND", "");
  return out;
}

// an image this large is compressed in kBands bands, whatever the thread count, so that
// its bytes are the same on any number of threads (the tiled strips and the animation
// sprites; a single frame is not)
constexpr size_t kBandedBytes = 4u << 20;
constexpr int kBands = 4;

}  // namespace

std::string encode_png(const Image& image, int threads) {
  PhaseScope phase("png");
  if (image.rgb.size() >= kBandedBytes && image.width > 0)
    return encode_png_bands(image, kBands, threads);
  std::string out;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, &on_png_warning);
  if (!png) throw SceneError("libpng: cannot create a write struct");
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw SceneError("libpng could not encode a " + std::to_string(image.width) + " x " +
                     std::to_string(image.height) + " image");
  }
  {
    png_set_write_fn(png, &out, &append, &flush);
    png_set_compression_level(png, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y)
      png_write_row(png,
                    const_cast<png_bytep>(&image.rgb[static_cast<size_t>(y) * image.width * 3]));
    png_write_end(png, nullptr);
  }
  png_destroy_write_struct(&png, &info);
  return out;
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  FILE* f = std::fopen(path.c_str(), "wbe");
  int err = f ? 0 : errno;
  if (f) {
    struct stat st {};
    const bool regular = ::fstat(::fileno(f), &st) == 0 && S_ISREG(st.st_mode);
    errno = 0;
    if (std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size() || std::fflush(f) != 0)
      err = errno ? errno : EIO;
    if (std::fclose(f) != 0 && err == 0) err = errno ? errno : EIO;
    if (err != 0 && regular) std::remove(path.c_str());  // never a device's node
  }
  if (err != 0) throw SceneError("cannot write " + path.string() + ": " + std::strerror(err));
}

void write_png(const std::filesystem::path& path, const Image& image, int threads) {
  const std::string bytes = encode_png(image, threads);
  write_bytes(path, bytes);  // the error says why (No space left on device)
}

Image read_png(const std::filesystem::path& path) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path.c_str()))
    throw SceneError(path.string() + ": cannot read PNG: " + img.message);
  img.format = PNG_FORMAT_RGB;
  Image out(static_cast<int>(img.width), static_cast<int>(img.height));
  if (!png_image_finish_read(&img, nullptr, out.rgb.data(), 0, nullptr))
    throw SceneError(path.string() + ": cannot read PNG: " + img.message);
  return out;
}

}  // namespace armstudy::scene
