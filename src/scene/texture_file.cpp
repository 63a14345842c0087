#include "scene/texture_file.hpp"

#include <libdeflate.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string_view>
#include <vector>

namespace bookspin::scene {

namespace {

constexpr std::array<unsigned char, 8> kSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t big_endian(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

/// What a file that is not a PNG is, by its first bytes, for the message.
std::string other_format(const std::vector<unsigned char>& bytes) {
  const auto starts = [&bytes](std::string_view magic) {
    return bytes.size() >= magic.size() &&
           std::equal(magic.begin(), magic.end(), bytes.begin(),
                      [](char a, unsigned char b) { return static_cast<unsigned char>(a) == b; });
  };
  if (starts("\xff\xd8\xff")) return "a JPEG file, not a PNG";
  if (starts("GIF8")) return "a GIF file, not a PNG";
  if (starts("RIFF") && bytes.size() >= 12 &&
      std::string_view("WEBP") ==
          std::string_view(reinterpret_cast<const char*>(bytes.data()) + 8, 4))
    return "a WebP file, not a PNG";
  if (starts("BM")) return "a BMP file, not a PNG";
  return "not a PNG file (no PNG signature)";
}

/// Bit depths allowed for each colour type (PNG specification §11.2.2, Table 11.1).
bool valid_depth(unsigned colour_type, unsigned depth) {
  switch (colour_type) {
    case 0:
      return depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16;
    case 3:
      return depth == 1 || depth == 2 || depth == 4 || depth == 8;
    case 2:
    case 4:
    case 6:
      return depth == 8 || depth == 16;
    default:
      return false;
  }
}

std::string check_header(const unsigned char* data, std::uint32_t length) {
  if (length != 13) return "its IHDR chunk is " + std::to_string(length) + " bytes, not 13";
  const std::uint32_t width = big_endian(data), height = big_endian(data + 4);
  if (width == 0 || height == 0 || width > kMaxTextureSide || height > kMaxTextureSide)
    return "its size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1 … " +
           std::to_string(kMaxTextureSide) + " a side";
  if (!valid_depth(data[9], data[8]))
    return "its IHDR has bit depth " + std::to_string(data[8]) + " with colour type " +
           std::to_string(data[9]) + ", which PNG does not allow";
  if (data[10] != 0 || data[11] != 0 || data[12] > 1)
    return "its IHDR names an unknown compression, filter or interlace method";
  return "";
}

}  // namespace

unsigned long png_crc32(const unsigned char* data, std::size_t size) {
  return libdeflate_crc32(0, data, size);  // PNG's CRC-32 is zlib's (PNG specification §5.5)
}

std::string png_problem(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot open the file";
  const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in),
                                         std::istreambuf_iterator<char>()};
  if (in.bad()) return "cannot read the file";
  if (bytes.empty()) return "the file is empty, not a PNG";
  if (bytes.size() < kSignature.size() ||
      !std::equal(kSignature.begin(), kSignature.end(), bytes.begin()))
    return other_format(bytes);
  std::size_t at = kSignature.size();
  bool header = false, data = false;
  while (true) {
    if (at == bytes.size()) return "truncated PNG: the file ends before its IEND chunk";
    if (bytes.size() - at < 12)
      return "truncated PNG: the file ends inside a chunk at byte " + std::to_string(at);
    const std::uint32_t length = big_endian(&bytes[at]);
    const std::string type(reinterpret_cast<const char*>(&bytes[at + 4]), 4);
    if (length > 0x7fffffffu || bytes.size() - at - 12 < length)
      return "truncated PNG: its " + type + " chunk at byte " + std::to_string(at) +
             " runs past the end of the file";
    const unsigned char* body = &bytes[at + 8];
    if (png_crc32(&bytes[at + 4], length + 4) != big_endian(body + length))
      return "corrupt PNG: its " + type + " chunk at byte " + std::to_string(at) +
             " fails its CRC-32 check";
    if (!header) {
      if (type != "IHDR") return "corrupt PNG: its first chunk is " + type + ", not IHDR";
      if (std::string problem = check_header(body, length); !problem.empty())
        return "corrupt PNG: " + problem;
      header = true;
    } else if (type == "IDAT") {
      // The zlib stream's first two bytes (RFC 1950 §2.2): method 8 (deflate), check bits.
      if (!data && length >= 2 && ((body[0] & 0x0f) != 8 || (body[0] * 256 + body[1]) % 31 != 0))
        return "corrupt PNG: its image data do not start with a zlib header";
      data = true;
    } else if (type == "IEND") {
      if (!data) return "corrupt PNG: it has no image data (IDAT)";
      return "";
    }
    at += 12 + std::size_t{length};
  }
}

}  // namespace bookspin::scene
