#pragma once
// PNG frames: written with libdeflate into a minimal PNG container of our own (8-bit RGB or
// RGBA), read with libpng (any PNG in).
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "common/rgba_image.hpp"

namespace bookspin::output {

/// Encodes `image` (8-bit RGBA, top row first) as a complete non-interlaced 8-bit PNG file in
/// memory: RGB (colour type 2) when every pixel is opaque (alpha 255, as rendered frames are),
/// RGBA (colour type 6) otherwise; read_png gives the same pixels back either way.
///
/// The container follows the PNG specification (W3C Recommendation "Portable Network Graphics
/// (PNG) Specification (Second Edition)", identical to ISO/IEC 15948:2003): the 8-byte
/// signature (§5.2), then chunks of length, type, data and the CRC-32 of type and data (§5.3,
/// §5.5; computed by libdeflate_crc32): IHDR (§11.2.2: width, height, bit
/// depth 8, colour type, compression 0, filter method 0, interlace 0), one or more IDAT
/// (§11.2.4) holding one zlib stream (§10, RFC 1950/1951, compressed by libdeflate) of the
/// filtered scanlines, each a filter-type byte and the row's bytes (§7.3, §9), and IEND.
///
/// `compression_level` is the project's zlib-like scale, 0 (none, fastest) … 9 (smallest),
/// mapped onto libdeflate's 0…12: 0…8 unchanged (libdeflate's scale follows zlib's there), 9 →
/// 12 (libdeflate's smallest). Levels 0…3 leave every row unfiltered (filter type 0; on the
/// clips' frames, a dithered gradient behind the book, adaptive filtering made zlib's fast
/// levels slower and the files larger); levels 4…9 choose each row's filter by the minimum sum of
/// absolute differences (§12.8 of the specification). Throws std::invalid_argument for an empty
/// image, a pixel buffer whose size is not width·height·4, or a level outside 0…9; std::bad_alloc
/// when memory runs out.
std::vector<std::uint8_t> encode_png(const RgbaImage& image, int compression_level = 1);

/// Writes encode_png(image, compression_level) to `path`. The file is written under a temporary
/// name in the same directory and renamed onto `path` only when complete (see AtomicFile),
/// replacing any file there. Throws what encode_png throws, and OutputError (naming `path` and
/// the OS reason: "No space left on device", "File too large", "Is a directory", …) if the file
/// cannot be created, written or renamed. On any error no file is left under `path` or the
/// temporary name.
void write_png(const std::filesystem::path& path, const RgbaImage& image,
               int compression_level = 1);

/// Writes encode_png(image, compression_level) to the open `file` (a device, a pipe, a file
/// the caller owns) and flushes it; `path` is the name used in error messages. Keeps its
/// working buffers (about 2.2× the image's RGB size) per thread for the next frame. Throws what
/// encode_png throws, and OutputError naming `path` and the OS reason if writing or flushing
/// fails (a full disk: "No space left on device"). Does not close `file`.
void write_png(std::FILE* file, const std::filesystem::path& path, const RgbaImage& image,
               int compression_level = 1);

/// Reads any PNG libpng understands (palette, grey, 16-bit, with or without
/// alpha, interlaced) and returns it as 8-bit RGBA, top row first; missing
/// alpha becomes 255, 16-bit samples are truncated to their high byte.
/// Throws std::runtime_error naming `path` if it cannot be opened or is not a
/// valid PNG.
RgbaImage read_png(const std::filesystem::path& path);

/// A PNG's size in pixels.
struct PngSize {
  int width = 0;
  int height = 0;
};

/// The size of the PNG at `path`, from its header alone (no pixels decoded). Throws
/// std::runtime_error naming `path` as read_png() does.
PngSize read_png_size(const std::filesystem::path& path);

}  // namespace bookspin::output
