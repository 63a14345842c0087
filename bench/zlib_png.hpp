#pragma once
// The PNG writer bookspin had before libdeflate (libpng, hence zlib's deflate), kept in the
// bench as the yardstick of the PNG rows: same frame, same level, same filter choice, in the
// same run as the current writer.
#include <filesystem>

#include "common/rgba_image.hpp"

namespace bookspin::bench {

/// Writes `image` (8-bit RGBA, top row first) to `path` through libpng at zlib level
/// `compression_level` (0…9): RGB when every pixel is opaque, RGBA otherwise; every row
/// unfiltered at levels 0…3, libpng's adaptive filters above; under a temporary name renamed
/// onto `path` when complete (all as the former writer did).
/// Throws std::runtime_error naming `path` if it cannot be written.
void write_png_with_zlib(const std::filesystem::path& path, const RgbaImage& image,
                         int compression_level);

}  // namespace bookspin::bench
