#include "scene/png_writer.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <fstream>
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

std::string encode_png(const Image& image) {
  PhaseScope phase("png");
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
      png_write_row(png, const_cast<png_bytep>(&image.rgb[static_cast<size_t>(y) * image.width * 3]));
    png_write_end(png, nullptr);
  }
  png_destroy_write_struct(&png, &info);
  return out;
}

void write_png(const std::filesystem::path& path, const Image& image) {
  const std::string bytes = encode_png(image);
  std::ofstream f(path, std::ios::binary);
  f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  f.close();
  if (!f) throw SceneError("cannot write " + path.string());
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
