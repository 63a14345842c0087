// The check of a scene's texture files (render.texture_*): a whole PNG, or one line saying
// why not. The bytes are built here by hand from the PNG specification, not by a PNG writer.
#include "scene/texture_file.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene_text.hpp"
#include "support/scratch.hpp"

namespace bookspin::scene {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

void put32(Bytes& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<unsigned char>(v >> shift));
}

/// One chunk: length, type, data, CRC over type and data.
void chunk(Bytes& out, const std::string& type, const Bytes& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  Bytes typed(type.begin(), type.end());
  typed.insert(typed.end(), data.begin(), data.end());
  out.insert(out.end(), typed.begin(), typed.end());
  put32(out, static_cast<std::uint32_t>(png_crc32(typed.data(), typed.size())));
}

/// A 1×1 grey PNG: signature, IHDR, one IDAT (zlib stream of the row "filter 0, value 0x80",
/// stored uncompressed: RFC 1950/1951), IEND.
Bytes one_pixel_png(std::uint32_t width = 1, std::uint32_t height = 1) {
  Bytes png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  Bytes ihdr;
  put32(ihdr, width);
  put32(ihdr, height);
  ihdr.insert(ihdr.end(), {8, 0, 0, 0, 0});  // 8-bit grey, deflate, filter 0, not interlaced
  chunk(png, "IHDR", ihdr);
  // zlib: 0x78 0x01, a stored block of 2 bytes (LEN 2, NLEN ~2), then the Adler-32 of
  // {0x00, 0x80}: a = 1 + 0 + 0x80 = 0x81, b = 1 + 0x81 = 0x82 → 0x00820081.
  chunk(png, "IDAT",
        {0x78, 0x01, 0x01, 0x02, 0x00, 0xfd, 0xff, 0x00, 0x80, 0x00, 0x82, 0x00, 0x81});
  chunk(png, "IEND", {});
  return png;
}

fs::path write(const std::string& name, const Bytes& bytes) {
  const fs::path dir = test::fresh_dir("texture_file_test/" + name);
  const fs::path path = dir / name;
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  return path;
}

TEST(TextureFile, Crc32MatchesThePublishedValues) {
  // The CRC of "IEND" ends every PNG file: AE 42 60 82. "123456789": the check value of
  // CRC-32/ISO-HDLC, 0xCBF43926.
  const std::string iend = "IEND", check = "123456789";
  EXPECT_EQ(png_crc32(reinterpret_cast<const unsigned char*>(iend.data()), 4), 0xae426082ul);
  EXPECT_EQ(png_crc32(reinterpret_cast<const unsigned char*>(check.data()), 9), 0xcbf43926ul);
}

TEST(TextureFile, AWholePngPasses) {
  EXPECT_EQ(png_problem(write("good.png", one_pixel_png())), "");
  // The repository's own textures and goldens (written by another PNG writer) pass too.
  const fs::path golden = fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "golden";
  int seen = 0;
  for (const auto& entry : fs::directory_iterator(golden)) {
    if (entry.path().extension() != ".png" || seen >= 5) continue;
    EXPECT_EQ(png_problem(entry.path()), "") << entry.path();
    ++seen;
  }
  EXPECT_GT(seen, 0);
}

TEST(TextureFile, OtherFormatsAreNamed) {
  EXPECT_EQ(png_problem(write("cover.jpg", {0xff, 0xd8, 0xff, 0xe0, 0, 16, 'J', 'F', 'I', 'F'})),
            "a JPEG file, not a PNG");
  EXPECT_EQ(png_problem(write("cover.gif", {'G', 'I', 'F', '8', '9', 'a'})),
            "a GIF file, not a PNG");
  EXPECT_EQ(png_problem(write("notes.png", {'h', 'e', 'l', 'l', 'o'})),
            "not a PNG file (no PNG signature)");
  EXPECT_EQ(png_problem(write("empty.png", {})), "the file is empty, not a PNG");
}

TEST(TextureFile, EveryTruncationIsCaught) {
  const Bytes png = one_pixel_png();
  // Cut anywhere after the signature: inside a chunk or between chunks, always refused.
  for (std::size_t size = 8; size < png.size(); ++size) {
    const Bytes cut(png.begin(), png.begin() + static_cast<long>(size));
    const std::string problem = png_problem(write("cut.png", cut));
    EXPECT_EQ(problem.rfind("truncated PNG: ", 0), 0u) << size << ": " << problem;
  }
  // IHDR is 8 + 12 + 13 = 33 bytes in; the IDAT chunk starts there.
  EXPECT_EQ(png_problem(write("cut.png", Bytes(png.begin(), png.begin() + 50))),
            "truncated PNG: its IDAT chunk at byte 33 runs past the end of the file");
  EXPECT_EQ(png_problem(write("cut.png", Bytes(png.begin(), png.end() - 12))),
            "truncated PNG: the file ends before its IEND chunk");
}

TEST(TextureFile, CorruptChunksAndHeadersAreCaught) {
  Bytes flipped = one_pixel_png();
  flipped[8 + 8 + 3] ^= 0x01;  // the IHDR's width: its CRC no longer matches
  EXPECT_EQ(png_problem(write("crc.png", flipped)),
            "corrupt PNG: its IHDR chunk at byte 8 fails its CRC-32 check");
  EXPECT_EQ(png_problem(write("wide.png", one_pixel_png(40000, 1))),
            "corrupt PNG: its size 40000x1 is outside 1 … 32767 a side");
  EXPECT_EQ(png_problem(write("zero.png", one_pixel_png(0, 1))),
            "corrupt PNG: its size 0x1 is outside 1 … 32767 a side");
}

TEST(TextureFile, TheSceneNamesTheKeyOfAnUnreadableTexture) {
  const fs::path jpeg = write("cover.jpg", {0xff, 0xd8, 0xff, 0xdb, 0, 0});
  const std::string error =
      testing::error_of("[render]\ntexture_back = \"" + jpeg.string() + "\"\n");
  EXPECT_EQ(error,
            "test.toml:2: render.texture_back: " + jpeg.string() + ": a JPEG file, not a PNG");
  const fs::path good = write("good.png", one_pixel_png());
  EXPECT_EQ(
      testing::parse("[render]\ntexture_pages = \"" + good.string() + "\"\n").render.texture_pages,
      good.string());
}

}  // namespace
}  // namespace bookspin::scene
