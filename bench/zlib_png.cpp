#include "bench/zlib_png.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "output/atomic_output.hpp"

namespace bookspin::bench {

namespace {

void on_error(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void on_warning(png_structp, png_const_charp) {}

bool is_opaque(const RgbaImage& image) {
  for (std::size_t i = 3; i < image.pixels.size(); i += 4)
    if (image.pixels[i] != 255) return false;
  return true;
}

// The setjmp frame holds plain data only (libpng longjmps here on an error).
bool encode(png_structp png, png_infop info, std::FILE* file, const RgbaImage& image, int level) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_compression_level(png, level);
  if (level <= 3) png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  const bool opaque = is_opaque(image);
  png_set_IHDR(png, info, image.width, image.height, 8,
               opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (opaque) png_set_filler(png, 0, PNG_FILLER_AFTER);
  for (int y = 0; y < image.height; ++y) png_write_row(png, image.row(y));
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

void write_png_with_zlib(const std::filesystem::path& path, const RgbaImage& image,
                         int compression_level) {
  output::AtomicFile output(path);  // as the former writer: a temporary, renamed when complete
  std::FILE* file = std::fopen(output.temp_path().c_str(), "wb");
  if (!file) throw std::runtime_error("bench: cannot create " + path.string());
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool ok = info && encode(png, info, file, image, compression_level);
  png_destroy_write_struct(&png, &info);
  if (std::fclose(file) != 0 || !ok)
    throw std::runtime_error("bench: cannot write " + path.string());
  output.commit();
}

}  // namespace bookspin::bench
