#pragma once
// PNG frames with libpng: 8-bit RGB or RGBA out, any PNG in.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/rgba_image.hpp"

namespace bookspin::output {

/// Writes `image` (8-bit RGBA, top row first) as a non-interlaced 8-bit PNG:
/// RGB when every pixel is opaque (alpha 255, as rendered frames are), RGBA
/// otherwise; read_png gives the same pixels back either way. The file is
/// written under a temporary name in the same directory and renamed onto
/// `path` only when complete (see AtomicFile), replacing any file there. `compression_level` is
/// zlib's 0 (none, fastest) … 9 (smallest). Throws std::invalid_argument for an empty image, a
/// pixel buffer whose size is not width·height·4, or a level outside 0…9; OutputError (naming
/// `path` and the OS or libpng reason) if the file cannot be created, written or renamed. On any
/// error no file is left under `path` or the temporary name.
void write_png(const std::filesystem::path& path, const RgbaImage& image,
               int compression_level = 1);

/// The same PNG bytes write_png would write, in memory (for images embedded in another file,
/// e.g. a glTF binary). Throws std::invalid_argument as write_png, std::bad_alloc.
std::vector<std::uint8_t> encode_png(const RgbaImage& image, int compression_level = 6);

/// Reads any PNG libpng understands (palette, grey, 16-bit, with or without
/// alpha, interlaced) and returns it as 8-bit RGBA, top row first; missing
/// alpha becomes 255, 16-bit samples are truncated to their high byte.
/// Throws std::runtime_error naming `path` if it cannot be opened or is not a
/// valid PNG.
RgbaImage read_png(const std::filesystem::path& path);

}  // namespace bookspin::output
