#pragma once
// The check of a texture file named by a scene (render.texture_*): that it is a whole PNG, so
// that a JPEG, a truncated download or a corrupt file is bad input at the scene check (exit 2,
// naming the key) rather than a failure of the renderer. Structure only: the image data are
// decoded by the stages that draw them (render, output).
#include <filesystem>
#include <string>

namespace bookspin::scene {

/// The largest PNG side a texture may have: cairo's image surfaces, in which the renderer
/// reads textures, hold at most 32767 pixels a side.
inline constexpr unsigned kMaxTextureSide = 32767;

/// Why the file at `path` is not a usable PNG, or "" when it is one: the 8-byte signature
/// (a JPEG, GIF or other file is named as such), every chunk whole (length, type, data and
/// CRC-32 inside the file: a truncated file is "truncated"), its CRC-32 right (ISO 3309, the
/// polynomial 0xEDB88320 of the PNG specification, §5.5), an IHDR first with a size of 1 …
/// kMaxTextureSide a side and a valid bit depth, colour type, compression, filter and interlace
/// (PNG specification §11.2.2), at least one IDAT whose zlib stream starts with a valid header
/// (RFC 1950 §2.2: deflate, header check), and an IEND. One line, no path.
std::string png_problem(const std::filesystem::path& path);

/// CRC-32 of `size` bytes at `data` (PNG specification §5.5, Annex D).
unsigned long png_crc32(const unsigned char* data, std::size_t size);

}  // namespace bookspin::scene
