#include "output/png_writer.hpp"

#include <libdeflate.h>
#include <png.h>

#include <algorithm>
#include <cerrno>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "output/atomic_output.hpp"

// Writing goes through libdeflate and a container of our own (below); libpng only reads.
// libpng reports errors by longjmp-ing to a setjmp point. Jumping over a C++
// frame that owns objects with destructors is undefined, so every libpng call
// that can fail sits in a small function (read_header, read_rows)
// whose frame holds only plain data and which calls setjmp itself. RAII owners
// live one frame up, where no longjmp ever reaches.

namespace bookspin::output {
namespace {

/// What libpng's callbacks hand back to C++; plain data on purpose.
struct PngIo {
  char message[256] = {};  ///< libpng's last error text
};

void on_png_error(png_structp png, png_const_charp text) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  std::snprintf(io->message, sizeof io->message, "%s", text);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}  // a library must not print

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

struct PngReadHandle {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngReadHandle() { png_destroy_read_struct(&png, &info, nullptr); }
};

}  // namespace

// ---- Writing: libdeflate and a minimal PNG container ------------------------------
//
// Everything here follows the PNG specification (W3C PNG Second Edition = ISO/IEC 15948:2003);
// the section numbers below are that document's.

namespace {

constexpr int kUnfilteredUpTo = 3;  ///< levels 0…3 write every row with filter type 0 (None)
constexpr std::size_t kMaxIdatBytes = std::size_t{1} << 20;  ///< data bytes per IDAT chunk

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

/// The project's level 0…9 on libdeflate's 0…12 (see encode_png).
int libdeflate_level(int compression_level) {
  return compression_level == 9 ? 12 : compression_level;
}

/// One compressor per thread and level, kept: allocating one costs more than compressing a
/// small frame. libdeflate compressors must not be shared between threads.
libdeflate_compressor* compressor_for(int level) {
  struct Cache {
    libdeflate_compressor* compressors[13] = {};
    ~Cache() {
      for (auto* c : compressors) libdeflate_free_compressor(c);
    }
  };
  thread_local Cache cache;
  auto*& compressor = cache.compressors[level];
  if (!compressor) compressor = libdeflate_alloc_compressor(level);
  if (!compressor) throw std::bad_alloc();
  return compressor;
}

/// Writes `value` big-endian (§7.1) at `out` and moves past it.
void put_u32(std::uint8_t*& out, std::uint32_t value) {
  out[0] = static_cast<std::uint8_t>(value >> 24);
  out[1] = static_cast<std::uint8_t>(value >> 16);
  out[2] = static_cast<std::uint8_t>(value >> 8);
  out[3] = static_cast<std::uint8_t>(value);
  out += 4;
}

/// Writes one chunk (§5.3) at `out` and moves past it: length, type, data, CRC-32 over type
/// and data (§5.5).
void put_chunk(std::uint8_t*& out, const char (&type)[5], const std::uint8_t* data,
               std::size_t length) {
  put_u32(out, static_cast<std::uint32_t>(length));
  std::uint8_t* const type_at = out;
  std::memcpy(out, type, 4);
  if (length > 0) std::memcpy(out + 4, data, length);
  out += 4 + length;
  put_u32(out, libdeflate_crc32(0, type_at, 4 + length));
}

/// The Paeth predictor (§9, PaethPredictor).
inline std::uint8_t paeth(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return static_cast<std::uint8_t>(a);
  return static_cast<std::uint8_t>(pb <= pc ? b : c);
}

/// Filters `row` (the unfiltered bytes of this scanline) with filter `type` (§9.2: 0 None, 1
/// Sub, 2 Up, 3 Average, 4 Paeth) into `out`, given the unfiltered previous scanline `prior`
/// (all zero for the first row) and `bpp` bytes per pixel.
void filter_row(int type, const std::uint8_t* row, const std::uint8_t* prior, std::size_t bytes,
                std::size_t bpp, std::uint8_t* out) {
  for (std::size_t i = 0; i < bytes; ++i) {
    const int a = i >= bpp ? row[i - bpp] : 0, b = prior[i], c = i >= bpp ? prior[i - bpp] : 0;
    int predicted = 0;
    switch (type) {
      case 1:
        predicted = a;
        break;
      case 2:
        predicted = b;
        break;
      case 3:
        predicted = (a + b) / 2;
        break;
      case 4:
        predicted = paeth(a, b, c);
        break;
      default:
        break;
    }
    out[i] = static_cast<std::uint8_t>(row[i] - predicted);
  }
}

/// §12.8's heuristic: the sum of the filtered bytes taken as signed values, absolute.
std::uint64_t sum_of_absolute_differences(const std::uint8_t* bytes, std::size_t n) {
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < n; ++i)
    sum += static_cast<std::uint64_t>(std::abs(static_cast<std::int8_t>(bytes[i])));
  return sum;
}

/// Copies row `source` (RGBA) into `out` as `channels` bytes per pixel (3: alpha dropped).
/// Returns the AND of the row's alpha bytes (255 when every pixel of it is opaque).
std::uint8_t pack_row(const std::uint8_t* source, std::size_t width, int channels,
                      std::uint8_t* out) {
  if (channels == 4) {
    std::memcpy(out, source, 4 * width);
    return 0;  // not asked
  }
  // Four bytes at a time, each store's fourth byte overwritten by the next pixel's.
  std::uint8_t alpha = 255;
  for (std::size_t x = 0; x + 1 < width; ++x) {
    std::memcpy(out + 3 * x, source + 4 * x, 4);
    alpha &= source[4 * x + 3];
  }
  std::memcpy(out + 3 * (width - 1), source + 4 * (width - 1), 3);
  return alpha & source[4 * width - 1];
}

/// The image data before compression (§7.3) into `data`: per scanline, the filter-type byte
/// and the filtered row of `channels` bytes per pixel. With channels 3 (the caller's guess that
/// the image is opaque) returns false, and stops, at the first row holding a pixel that is not.
bool filtered_scanlines(const RgbaImage& image, int channels, bool adaptive,
                        std::vector<std::uint8_t>& data) {
  const std::size_t width = static_cast<std::size_t>(image.width);
  const std::size_t bytes = width * static_cast<std::size_t>(channels);
  data.resize((bytes + 1) * static_cast<std::size_t>(image.height));
  if (!adaptive) {
    for (int y = 0; y < image.height; ++y) {
      std::uint8_t* line = data.data() + (bytes + 1) * static_cast<std::size_t>(y);
      line[0] = 0;  // filter type None
      if (pack_row(image.row(y), width, channels, line + 1) != 255 && channels == 3) return false;
    }
    return true;
  }
  std::vector<std::uint8_t> row(bytes), prior(bytes, 0), trial(bytes), best(bytes);
  for (int y = 0; y < image.height; ++y) {
    std::uint8_t* line = data.data() + (bytes + 1) * static_cast<std::size_t>(y);
    if (pack_row(image.row(y), width, channels, row.data()) != 255 && channels == 3) return false;
    int chosen = 0;
    std::uint64_t best_sum = UINT64_MAX;
    for (int type = 0; type <= 4; ++type) {
      filter_row(type, row.data(), prior.data(), bytes, static_cast<std::size_t>(channels),
                 trial.data());
      const std::uint64_t sum = sum_of_absolute_differences(trial.data(), bytes);
      if (sum < best_sum) {
        best_sum = sum;
        chosen = type;
        best.swap(trial);
      }
    }
    line[0] = static_cast<std::uint8_t>(chosen);
    std::memcpy(line + 1, best.data(), bytes);
    prior.swap(row);
  }
  return true;
}

/// What encoding a frame allocates, kept between frames of one thread: fresh multi-megabyte
/// buffers would cost a page fault per 4 KiB every frame.
struct EncodeBuffers {
  std::vector<std::uint8_t> scanlines, zlib, png;
};

[[noreturn]] void throw_write_error(const std::filesystem::path& path, int error) {
  throw_output_error("cannot write PNG", path, error);
}

}  // namespace

namespace {

/// encode_png into buffers.png (see encode_png), reusing `buffers`.
void encode_png_into(const RgbaImage& image, int compression_level, EncodeBuffers& buffers) {
  validate_for_writing(image, compression_level);
  // Rendered frames are opaque: RGB carries a quarter less. Packed as RGB while checking
  // that, and again as RGBA at the first pixel that is not.
  const bool adaptive = compression_level > kUnfilteredUpTo;
  const bool opaque = filtered_scanlines(image, 3, adaptive, buffers.scanlines);
  if (!opaque) filtered_scanlines(image, 4, adaptive, buffers.scanlines);
  const std::vector<std::uint8_t>& scanlines = buffers.scanlines;

  libdeflate_compressor* compressor = compressor_for(libdeflate_level(compression_level));
  std::vector<std::uint8_t>& zlib = buffers.zlib;
  zlib.resize(libdeflate_zlib_compress_bound(compressor, scanlines.size()));
  const std::size_t zlib_size = libdeflate_zlib_compress(
      compressor, scanlines.data(), scanlines.size(), zlib.data(), zlib.size());
  if (zlib_size == 0) throw std::logic_error("encode_png: libdeflate exceeded its own bound");

  const std::size_t idat_chunks = (zlib_size + kMaxIdatBytes - 1) / kMaxIdatBytes;
  std::vector<std::uint8_t>& png = buffers.png;
  png.resize(8 + (12 + 13) + 12 * idat_chunks + zlib_size + 12);
  std::uint8_t* out = png.data();
  static constexpr std::uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};  // §5.2
  std::memcpy(out, kSignature, 8);
  out += 8;
  std::uint8_t header[13];  // IHDR (§11.2.2)
  std::uint8_t* h = header;
  put_u32(h, static_cast<std::uint32_t>(image.width));
  put_u32(h, static_cast<std::uint32_t>(image.height));
  h[0] = 8;                // bit depth
  h[1] = opaque ? 2 : 6;   // colour type: truecolour, or truecolour with alpha
  h[2] = h[3] = h[4] = 0;  // deflate, filter method 0, no interlace
  put_chunk(out, "IHDR", header, sizeof header);
  for (std::size_t at = 0; at < zlib_size; at += kMaxIdatBytes) {  // §11.2.4: IDATs concatenate
    put_chunk(out, "IDAT", zlib.data() + at, std::min(kMaxIdatBytes, zlib_size - at));
  }
  put_chunk(out, "IEND", nullptr, 0);
  if (out != png.data() + png.size()) throw std::logic_error("encode_png: size miscounted");
}

}  // namespace

std::vector<std::uint8_t> encode_png(const RgbaImage& image, int compression_level) {
  EncodeBuffers buffers;
  encode_png_into(image, compression_level, buffers);
  return std::move(buffers.png);
}

void write_png(std::FILE* file, const std::filesystem::path& path, const RgbaImage& image,
               int compression_level) {
  thread_local EncodeBuffers buffers;
  encode_png_into(image, compression_level, buffers);
  const std::vector<std::uint8_t>& png = buffers.png;
  if (std::fwrite(png.data(), 1, png.size(), file) != png.size()) throw_write_error(path, errno);
  if (std::fflush(file) != 0) throw_write_error(path, errno);
}

void write_png(const std::filesystem::path& path, const RgbaImage& image, int compression_level) {
  validate_for_writing(image, compression_level);  // before a temporary is made
  AtomicFile output(path);  // declared first: removes the temporary last, after fclose
  FilePtr file(std::fopen(output.temp_path().c_str(), "wb"));
  if (!file) throw_output_error("cannot create PNG", path, errno);
  write_png(file.get(), path, image, compression_level);
  // fclose is where a full disk often shows up first (buffered data).
  if (std::fclose(file.release()) != 0) throw_write_error(path, errno);
  output.commit();
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

/// A PNG being read: its file, libpng's state and error text (`io` before `handle`, so that
/// libpng's state goes first), and its header once read.
struct PngReading {
  FilePtr file;
  PngIo io;
  PngReadHandle handle;
  png_uint_32 width = 0, height = 0;
  std::size_t row_bytes = 0;
};

/// `path` opened into `png` and its header read (read_header); throws as read_png().
void start_reading(const std::filesystem::path& path, PngReading& png) {
  png.file.reset(std::fopen(path.c_str(), "rb"));
  if (!png.file) throw_read_error(path, std::strerror(errno));
  PngReadHandle& handle = png.handle;
  handle.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &png.io, on_png_error, on_png_warning);
  if (handle.png) handle.info = png_create_info_struct(handle.png);
  if (!handle.info) throw_read_error(path, "libpng out of memory");
  png_init_io(handle.png, png.file.get());
  if (!read_header(handle.png, handle.info, &png.width, &png.height, &png.row_bytes))
    throw_read_error(path, png.io.message);
}

}  // namespace

PngSize read_png_size(const std::filesystem::path& path) {
  PngReading png;
  start_reading(path, png);
  return {static_cast<int>(png.width), static_cast<int>(png.height)};
}

RgbaImage read_png(const std::filesystem::path& path) {
  PngReading png;
  start_reading(path, png);
  const png_uint_32 width = png.width, height = png.height;
  constexpr png_uint_32 kMaxSide = 1u << 15;  // 32768: far beyond any frame we make
  if (width == 0 || height == 0 || width > kMaxSide || height > kMaxSide) {
    throw_read_error(path,
                     "unsupported size " + std::to_string(width) + "x" + std::to_string(height));
  }
  if (png.row_bytes != static_cast<std::size_t>(width) * 4) {
    throw_read_error(path, "libpng did not produce 8-bit RGBA rows");
  }
  RgbaImage image(static_cast<int>(width), static_cast<int>(height));
  std::vector<png_bytep> rows(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = image.row(static_cast<int>(y));
  if (!read_rows(png.handle.png, rows.data())) throw_read_error(path, png.io.message);
  return image;
}

}  // namespace bookspin::output
