// The PNG writer's own container, checked against independent readers: libpng's simplified
// decoder (not read_png), zlib's CRC-32 and inflate, and the pngcheck program.
#include <gtest/gtest.h>
#include <png.h>
#include <sys/wait.h>
#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "output/atomic_output.hpp"
#include "output/png_writer.hpp"
#include "support/scratch.hpp"
#include "support/test_images.hpp"

namespace bookspin::output {
namespace {
namespace fs = std::filesystem;
using bookspin::test::ScratchDir;

std::vector<std::uint8_t> file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Decodes `path` with libpng's simplified API into 8-bit RGBA, independently of read_png.
RgbaImage decode_with_libpng(const fs::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    ADD_FAILURE() << path << ": " << image.message;
    return {};
  }
  image.format = PNG_FORMAT_RGBA;
  RgbaImage out(static_cast<int>(image.width), static_cast<int>(image.height));
  if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) {
    ADD_FAILURE() << path << ": " << image.message;
    png_image_free(&image);
    return {};
  }
  return out;
}

std::uint32_t be32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         p[3];
}

struct Chunk {
  std::string type;
  std::vector<std::uint8_t> data;
};

/// Splits a PNG datastream into chunks, checking the signature and every chunk's CRC-32
/// with zlib's crc32 (PNG specification §5.2, §5.3, §5.5).
std::vector<Chunk> parse_chunks(const std::vector<std::uint8_t>& png) {
  static const std::uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  std::vector<Chunk> chunks;
  if (png.size() < 8 || std::memcmp(png.data(), kSignature, 8) != 0) {
    ADD_FAILURE() << "no PNG signature";
    return chunks;
  }
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const std::uint32_t length = be32(&png[at]);
    if (at + 12 + length > png.size()) {
      ADD_FAILURE() << "chunk runs past the end";
      break;
    }
    Chunk chunk{std::string(reinterpret_cast<const char*>(&png[at + 4]), 4),
                {png.begin() + static_cast<long>(at + 8),
                 png.begin() + static_cast<long>(at + 8 + length)}};
    const auto crc = static_cast<std::uint32_t>(crc32(0, &png[at + 4], 4 + length));
    EXPECT_EQ(be32(&png[at + 8 + length]), crc) << "CRC of chunk " << chunk.type;
    chunks.push_back(std::move(chunk));
    at += 12 + length;
  }
  EXPECT_EQ(at, png.size()) << "bytes after the last chunk";
  return chunks;
}

/// The decompressed IDAT stream (zlib's inflate): the filtered scanlines.
std::vector<std::uint8_t> inflate_idat(const std::vector<Chunk>& chunks, std::size_t expected) {
  std::vector<std::uint8_t> zlib_stream;
  for (const Chunk& c : chunks)
    if (c.type == "IDAT") zlib_stream.insert(zlib_stream.end(), c.data.begin(), c.data.end());
  std::vector<std::uint8_t> out(expected + 1);
  uLongf size = static_cast<uLongf>(out.size());
  EXPECT_EQ(uncompress(out.data(), &size, zlib_stream.data(), zlib_stream.size()), Z_OK);
  out.resize(size);
  return out;
}

/// pngcheck's verdict on `path`: true when it exits 0. Skips (or, under CI=true, fails) the
/// test where pngcheck is not installed.
bool pngcheck_accepts(const fs::path& path, std::string* output) {
  const std::string command = "pngcheck -v '" + path.string() + "' 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return false;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) output->append(buffer, n);
  const int status = ::pclose(pipe);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

bool have_pngcheck() { return std::system("command -v pngcheck > /dev/null 2>&1") == 0; }

void require_pngcheck() {
  if (have_pngcheck()) return;
  const char* ci = std::getenv("CI");
  if (ci && std::string(ci) == "true") FAIL() << "pngcheck is missing (scripts/install-deps.sh)";
  GTEST_SKIP() << "pngcheck is not installed (Debian: pngcheck)";
}

/// A frame like the renders: an opaque smooth dithered gradient with a square; `translucent`
/// makes one pixel in 97 (the first included) translucent, so the file goes out as RGBA.
RgbaImage sample_frame(int width, int height, bool translucent) {
  RgbaImage image = test::moving_square_frame(width, height, 2);
  const RgbaImage noise = test::noise_frame(width, height, 11);
  for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
    image.pixels[i] = static_cast<std::uint8_t>(image.pixels[i] ^ (noise.pixels[i] & 3));  // dither
    if (translucent && (i / 4) % 97 == 0) image.pixels[i + 3] = noise.pixels[i + 3] & 0x7f;
  }
  return image;
}

struct Size {
  int width, height;
};
// The goldens' sizes (tests/golden) and odd ones: a single pixel, odd sides, a row longer
// than 4096 pixels (a row of more than 12 KiB, past any power-of-two buffer of that size).
const Size kSizes[] = {{256, 256}, {512, 288}, {640, 360}, {1, 1}, {3, 7}, {4097, 2}};

TEST(PngContainer, EveryGoldenAndOddSizeDecodesThroughLibpngToTheWrittenPixels) {
  ScratchDir dir;
  int files = 0;
  for (const Size& s : kSizes) {
    for (bool translucent : {false, true}) {
      const RgbaImage image = sample_frame(s.width, s.height, translucent);
      for (int level : {0, 1, 4, 6, 9}) {
        const fs::path path = dir / ("f.png");
        write_png(path, image, level);
        const RgbaImage back = decode_with_libpng(path);
        ASSERT_EQ(back.width, s.width);
        ASSERT_EQ(back.height, s.height);
        EXPECT_TRUE(back.pixels == image.pixels)
            << s.width << "x" << s.height << (translucent ? " RGBA" : " RGB") << " level " << level;
        ++files;
      }
    }
  }
  EXPECT_EQ(files, 60);
}

TEST(PngContainer, EveryGoldenReEncodedDecodesToItsPixels) {
  ScratchDir dir;
  int goldens = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(BOOKSPIN_SOURCE_DIR) / "tests/golden")) {
    if (entry.path().extension() != ".png") continue;
    const RgbaImage golden = decode_with_libpng(entry.path());
    write_png(dir / "golden.png", golden, 1);
    EXPECT_TRUE(decode_with_libpng(dir / "golden.png").pixels == golden.pixels) << entry.path();
    ++goldens;
  }
  EXPECT_GT(goldens, 40);
}

TEST(PngContainer, ChunksAreSignatureIhdrIdatIendWithTheirCrcs) {
  for (const Size& s : kSizes) {
    for (bool translucent : {false, true}) {
      const RgbaImage image = sample_frame(s.width, s.height, translucent);
      const std::vector<Chunk> chunks = parse_chunks(encode_png(image, 1));
      ASSERT_GE(chunks.size(), 3u);
      EXPECT_EQ(chunks.front().type, "IHDR");
      ASSERT_EQ(chunks.front().data.size(), 13u);
      const std::uint8_t* ihdr = chunks.front().data.data();
      EXPECT_EQ(be32(ihdr), static_cast<std::uint32_t>(s.width));
      EXPECT_EQ(be32(ihdr + 4), static_cast<std::uint32_t>(s.height));
      EXPECT_EQ(ihdr[8], 8);                         // bit depth
      EXPECT_EQ(ihdr[9], translucent ? 6 : 2);       // RGBA : RGB
      EXPECT_EQ(ihdr[10] + ihdr[11] + ihdr[12], 0);  // deflate, filter method 0, no interlace
      EXPECT_EQ(chunks.back().type, "IEND");
      EXPECT_TRUE(chunks.back().data.empty());
      for (std::size_t i = 1; i + 1 < chunks.size(); ++i) EXPECT_EQ(chunks[i].type, "IDAT");
    }
  }
}

// Filter bytes (§9): type 0 for every row at the fast levels, a per-row choice among 0…4
// at the others, and on a smooth gradient that choice is not always None.
TEST(PngContainer, FastLevelsLeaveRowsUnfilteredHigherLevelsChooseFilters) {
  const RgbaImage image = test::moving_square_frame(97, 64, 1);  // opaque, smooth
  const std::size_t row_bytes = 1 + 97 * 3;
  for (int level : {0, 1, 3, 4, 9}) {
    const std::vector<std::uint8_t> scanlines =
        inflate_idat(parse_chunks(encode_png(image, level)), row_bytes * 64);
    ASSERT_EQ(scanlines.size(), row_bytes * 64) << "level " << level;
    int filtered_rows = 0;
    for (std::size_t y = 0; y < 64; ++y) {
      const std::uint8_t type = scanlines[y * row_bytes];
      EXPECT_LE(type, 4) << "row " << y;
      if (type != 0) ++filtered_rows;
    }
    if (level <= 3) {
      EXPECT_EQ(filtered_rows, 0) << "level " << level;
    } else {
      EXPECT_GT(filtered_rows, 32) << "level " << level;
    }
  }
}

TEST(PngContainer, PngcheckAcceptsEveryLevelAndSize) {
  require_pngcheck();
  ScratchDir dir;
  for (const Size& s : kSizes) {
    for (bool translucent : {false, true}) {
      for (int level : {0, 1, 9}) {
        const fs::path path = dir / ("check.png");
        write_png(path, sample_frame(s.width, s.height, translucent), level);
        std::string output;
        EXPECT_TRUE(pngcheck_accepts(path, &output))
            << s.width << "x" << s.height << " level " << level << ":\n"
            << output;
      }
    }
  }
}

// A frame of more than one IDAT chunk (the writer splits at 1 MiB): a 1280x720 noise frame
// at level 0 is 2.7 MB of stored blocks.
TEST(PngContainer, LargeFramesSpanSeveralIdatChunksAndStillDecode) {
  ScratchDir dir;
  RgbaImage image = test::noise_frame(1280, 720, 5);
  for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
  write_png(dir / "big.png", image, 0);
  const std::vector<Chunk> chunks = parse_chunks(file_bytes(dir / "big.png"));
  int idat = 0;
  for (const Chunk& c : chunks) idat += c.type == "IDAT";
  EXPECT_GE(idat, 3);
  EXPECT_TRUE(decode_with_libpng(dir / "big.png").pixels == image.pixels);
  if (have_pngcheck()) {
    std::string output;
    EXPECT_TRUE(pngcheck_accepts(dir / "big.png", &output)) << output;
  }
}

TEST(PngContainer, AFullDiskThrowsOutputErrorNamingThePathAndTheReason) {
  std::FILE* full = std::fopen("/dev/full", "wb");
  if (!full) GTEST_SKIP() << "/dev/full cannot be opened here";
  std::string message;
  try {
    write_png(full, "/dev/full", test::noise_frame(64, 64, 2), 1);
  } catch (const OutputError& e) {
    message = e.what();
  }
  std::fclose(full);
  EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  EXPECT_NE(message.find("/dev/full"), std::string::npos) << message;
}

TEST(PngContainer, ADirectoryInTheWayThrowsOutputErrorAndLeavesItAlone) {
  ScratchDir dir;
  fs::create_directory(dir / "frame.png");
  std::string message;
  try {
    write_png(dir / "frame.png", test::noise_frame(8, 8, 3), 1);
  } catch (const OutputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find((dir / "frame.png").string()), std::string::npos) << message;
  EXPECT_NE(message.find("Is a directory"), std::string::npos) << message;
  EXPECT_TRUE(fs::is_directory(dir / "frame.png"));
  EXPECT_TRUE(fs::is_empty(dir / "frame.png"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"frame.png"});  // no temporary left
}

// What a user gets at each level: the project's 9 (libdeflate's 12) is the smallest, 0 the
// largest (stored blocks), on a frame like the renders.
TEST(PngContainer, HigherLevelsAreSmallerOnRenderLikeFrames) {
  const RgbaImage image = sample_frame(640, 360, false);
  const std::size_t none = encode_png(image, 0).size(), fast = encode_png(image, 1).size(),
                    small = encode_png(image, 9).size();
  EXPECT_GT(none, 640u * 360u * 3u);  // stored: every byte plus the filter bytes
  EXPECT_LT(fast, none);
  EXPECT_LT(small, fast);
}

}  // namespace
}  // namespace bookspin::output
