#include "output/png_writer.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "output/atomic_output.hpp"

// libpng reports errors by longjmp-ing to a setjmp point. Jumping over a C++
// frame that owns objects with destructors is undefined, so every libpng call
// that can fail sits in a small function (encode_rows, read_header, read_rows)
// whose frame holds only plain data and which calls setjmp itself. RAII owners
// live one frame up, where no longjmp ever reaches.

namespace bookspin::output {
namespace {

/// What libpng's callbacks hand back to C++; plain data on purpose.
struct PngIo {
  std::FILE* file = nullptr;
  int io_errno = 0;        ///< errno of a failed fwrite/fflush, 0 if none
  char message[256] = {};  ///< libpng's last error text
};

void on_png_error(png_structp png, png_const_charp text) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  std::snprintf(io->message, sizeof io->message, "%s", text);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}  // a library must not print

void write_to_file(png_structp png, png_bytep data, std::size_t length) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, length, io->file) != length) {
    io->io_errno = errno;  // keep ENOSPC/EFBIG; libpng's own text would say only "Write Error"
    png_error(png, "write failed");
  }
}

void flush_file(png_structp png) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (std::fflush(io->file) != 0) {
    io->io_errno = errno;
    png_error(png, "flush failed");
  }
}

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

struct PngWriteHandle {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngWriteHandle() { png_destroy_write_struct(&png, &info); }
};

struct PngReadHandle {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngReadHandle() { png_destroy_read_struct(&png, &info, nullptr); }
};

void validate_for_writing(const RgbaImage& image, int compression_level) {
  if (image.width <= 0 || image.height <= 0) {
    throw std::invalid_argument("write_png: image is empty (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ")");
  }
  if (image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw std::invalid_argument("write_png: pixel buffer size does not match width·height·4");
  }
  if (compression_level < 0 || compression_level > 9) {
    throw std::invalid_argument("write_png: compression level " +
                                std::to_string(compression_level) + " is outside 0…9");
  }
}

constexpr int kUnfilteredUpTo = 3;

bool is_opaque(const RgbaImage& image) {
  for (std::size_t i = 3; i < image.pixels.size(); i += 4) {
    if (image.pixels[i] != 255) return false;
  }
  return true;
}

// setjmp frame: see the comment at the top of the file.
bool encode_rows(png_structp png, png_infop info, const RgbaImage& image, int level) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_compression_level(png, level);
  // Filtering only helps the deflate that level 0 skips. The fast levels skip it too: on
  // the clips' frames (a dithered gradient behind the book) libpng's adaptive filters
  // took twice as long at level 1 and the files came out ~15% larger, not smaller.
  if (level <= kUnfilteredUpTo) png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  // Rendered frames are opaque: an RGB file carries a quarter less to deflate and store.
  const bool opaque = is_opaque(image);
  png_set_IHDR(png, info, image.width, image.height, 8,
               opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (opaque) png_set_filler(png, 0, PNG_FILLER_AFTER);  // drop each row's alpha byte
  for (int y = 0; y < image.height; ++y) png_write_row(png, image.row(y));
  png_write_end(png, nullptr);
  return true;
}

[[noreturn]] void throw_png_write_error(const std::filesystem::path& path, const PngIo& io) {
  if (io.io_errno != 0) throw_output_error("cannot write PNG", path, io.io_errno);
  throw_output_error("cannot write PNG", path, io.message);
}

}  // namespace

void write_png(const std::filesystem::path& path, const RgbaImage& image, int compression_level) {
  validate_for_writing(image, compression_level);
  AtomicFile output(path);  // declared first: removes the temporary last, after fclose
  PngIo io;
  FilePtr file(std::fopen(output.temp_path().c_str(), "wb"));
  if (!file) throw_output_error("cannot create PNG", path, errno);
  io.file = file.get();
  {
    PngWriteHandle handle;
    handle.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &io, on_png_error, on_png_warning);
    if (handle.png) handle.info = png_create_info_struct(handle.png);
    if (!handle.info) throw_output_error("cannot write PNG", path, "libpng out of memory");
    png_set_write_fn(handle.png, &io, write_to_file, flush_file);
    if (!encode_rows(handle.png, handle.info, image, compression_level)) {
      throw_png_write_error(path, io);
    }
  }
  // fclose is where a full disk often shows up first (buffered data).
  if (std::fclose(file.release()) != 0) throw_output_error("cannot write PNG", path, errno);
  output.commit();
}

std::vector<std::uint8_t> encode_png(const RgbaImage& image, int compression_level) {
  validate_for_writing(image, compression_level);
  char* data = nullptr;
  std::size_t size = 0;
  PngIo io;
  FilePtr file(open_memstream(&data, &size));
  if (!file) throw std::bad_alloc();
  io.file = file.get();
  bool ok = false;
  {
    PngWriteHandle handle;
    handle.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &io, on_png_error, on_png_warning);
    if (handle.png) handle.info = png_create_info_struct(handle.png);
    if (handle.info) {
      png_set_write_fn(handle.png, &io, write_to_file, flush_file);
      ok = encode_rows(handle.png, handle.info, image, compression_level);
    }
  }
  std::fclose(file.release());  // sets data and size
  std::vector<std::uint8_t> bytes(data, data + size);
  std::free(data);
  if (!ok) throw std::bad_alloc();  // memory is the only thing that can fail here
  return bytes;
}

// ---- Reading -------------------------------------------------------------------

namespace {

[[noreturn]] void throw_read_error(const std::filesystem::path& path, const std::string& why) {
  throw InputError("cannot read PNG \"" + path.string() + "\": " + why);
}

// setjmp frame. Asks libpng for 8-bit RGBA whatever the file holds.
bool read_header(png_structp png, png_infop info, png_uint_32* width, png_uint_32* height,
                 std::size_t* row_bytes) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  png_set_expand(png);       // palette → RGB, grey < 8 bit → 8 bit, tRNS → alpha
  png_set_strip_16(png);     // 16 → 8 bit
  png_set_gray_to_rgb(png);  // grey → RGB
  png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);  // only acts when there is no alpha yet
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  *width = png_get_image_width(png, info);
  *height = png_get_image_height(png, info);
  *row_bytes = png_get_rowbytes(png, info);
  return true;
}

// setjmp frame.
bool read_rows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);  // handles interlace passes
  png_read_end(png, nullptr);
  return true;
}

}  // namespace

RgbaImage read_png(const std::filesystem::path& path) {
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file) throw_read_error(path, std::strerror(errno));
  PngIo io;
  PngReadHandle handle;
  handle.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &io, on_png_error, on_png_warning);
  if (handle.png) handle.info = png_create_info_struct(handle.png);
  if (!handle.info) throw_read_error(path, "libpng out of memory");
  png_init_io(handle.png, file.get());

  png_uint_32 width = 0, height = 0;
  std::size_t row_bytes = 0;
  if (!read_header(handle.png, handle.info, &width, &height, &row_bytes)) {
    throw_read_error(path, io.message);
  }
  constexpr png_uint_32 kMaxSide = 1u << 15;  // 32768: far beyond any frame we make
  if (width == 0 || height == 0 || width > kMaxSide || height > kMaxSide) {
    throw_read_error(path,
                     "unsupported size " + std::to_string(width) + "x" + std::to_string(height));
  }
  if (row_bytes != static_cast<std::size_t>(width) * 4) {
    throw_read_error(path, "libpng did not produce 8-bit RGBA rows");
  }
  RgbaImage image(static_cast<int>(width), static_cast<int>(height));
  std::vector<png_bytep> rows(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = image.row(static_cast<int>(y));
  if (!read_rows(handle.png, rows.data())) throw_read_error(path, io.message);
  return image;
}

}  // namespace bookspin::output
