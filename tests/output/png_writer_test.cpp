#include "output/png_writer.hpp"

#include <gtest/gtest.h>
#include <png.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <string>

#include "output/atomic_output.hpp"
#include "support/scratch.hpp"
#include "support/test_images.hpp"

namespace bookspin::output {
namespace {
namespace fs = std::filesystem;
using bookspin::test::ScratchDir;
using test::noise_frame;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Writes a PNG in another layout with libpng's simplified API (no setjmp).
void write_other_png(const fs::path& path, png_uint_32 format,
                     const std::vector<std::uint8_t>& data, int width, int height,
                     const std::vector<std::uint8_t>* colormap = nullptr) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  image.format = format;
  if (colormap) image.colormap_entries = static_cast<png_uint_32>(colormap->size() / 3);
  ASSERT_NE(png_image_write_to_file(&image, path.c_str(), 0, data.data(), 0,
                                    colormap ? colormap->data() : nullptr),
            0)
      << image.message;
}

TEST(PngWriter, RoundTripIsExactAtSeveralCompressionLevels) {
  ScratchDir dir;
  const RgbaImage image = noise_frame(67, 45, 7);  // odd sizes, alpha varies
  for (int level : {0, 1, 9}) {
    const fs::path path = dir / ("noise-" + std::to_string(level) + ".png");
    write_png(path, image, level);
    const RgbaImage back = read_png(path);
    EXPECT_EQ(back.width, image.width);
    EXPECT_EQ(back.height, image.height);
    EXPECT_TRUE(back.pixels == image.pixels) << "level " << level;
  }
  EXPECT_EQ(dir.entries().size(), 3u);  // no temporaries left behind
}

// The size from the header alone is the written image's, for RGB and RGBA alike; a file that is
// no PNG is refused naming it.
TEST(PngWriter, ReadPngSizeGivesTheWrittenSize) {
  ScratchDir dir;
  write_png(dir / "a.png", noise_frame(67, 45, 7));
  RgbaImage opaque(30, 11);
  write_png(dir / "b.png", opaque);
  EXPECT_EQ(read_png_size(dir / "a.png").width, 67);
  EXPECT_EQ(read_png_size(dir / "a.png").height, 45);
  EXPECT_EQ(read_png_size(dir / "b.png").width, 30);
  EXPECT_EQ(read_png_size(dir / "b.png").height, 11);
  std::ofstream(dir / "not.png") << "not a png";
  try {
    read_png_size(dir / "not.png");
    ADD_FAILURE() << "a file that is no PNG was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not.png"), std::string::npos) << e.what();
  }
}

unsigned char colour_type(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char header[26] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  EXPECT_EQ(std::string(reinterpret_cast<char*>(header + 12), 4), "IHDR");
  EXPECT_EQ(header[24], 8);  // bit depth
  return header[25];
}

// Rendered frames are opaque and go out as RGB (a quarter less to deflate); anything with
// transparency keeps its alpha. Both read back exactly.
TEST(PngWriter, OpaqueImagesAreWrittenAsRgbOthersAsRgba) {
  ScratchDir dir;
  const RgbaImage opaque = test::moving_square_frame(64, 48, 3);
  RgbaImage translucent = opaque;
  translucent.pixels[4 * 100 + 3] = 128;
  write_png(dir / "opaque.png", opaque, 1);
  write_png(dir / "translucent.png", translucent, 1);
  EXPECT_EQ(colour_type(dir / "opaque.png"), 2);       // RGB
  EXPECT_EQ(colour_type(dir / "translucent.png"), 6);  // RGBA
  EXPECT_EQ(read_png(dir / "opaque.png").pixels, opaque.pixels);
  EXPECT_EQ(read_png(dir / "translucent.png").pixels, translucent.pixels);
}

TEST(PngWriter, WritesEightBitAndHigherLevelsCompressSmoothImagesMore) {
  ScratchDir dir;
  const RgbaImage image = test::moving_square_frame(128, 96, 0);
  write_png(dir / "fast.png", image, 1);
  write_png(dir / "small.png", image, 9);
  write_png(dir / "none.png", image, 0);
  EXPECT_LE(fs::file_size(dir / "small.png"), fs::file_size(dir / "fast.png"));
  EXPECT_GT(fs::file_size(dir / "none.png"), fs::file_size(dir / "fast.png"));
  EXPECT_EQ(colour_type(dir / "fast.png"), 2);  // opaque: RGB
}

TEST(PngWriter, ReadPngExpandsGreyRgbAndPaletteToRgba) {
  ScratchDir dir;
  write_other_png(dir / "grey.png", PNG_FORMAT_GRAY, {0, 100, 200, 255}, 2, 2);
  const RgbaImage grey = read_png(dir / "grey.png");
  ASSERT_EQ(grey.pixels.size(), 16u);
  EXPECT_EQ(std::vector<std::uint8_t>(grey.pixels.begin() + 4, grey.pixels.begin() + 8),
            (std::vector<std::uint8_t>{100, 100, 100, 255}));

  write_other_png(dir / "rgb.png", PNG_FORMAT_RGB, {1, 2, 3, 4, 5, 6}, 2, 1);
  EXPECT_EQ(read_png(dir / "rgb.png").pixels,
            (std::vector<std::uint8_t>{1, 2, 3, 255, 4, 5, 6, 255}));

  const std::vector<std::uint8_t> palette = {255, 0, 0, 0, 0, 255};
  write_other_png(dir / "palette.png", PNG_FORMAT_RGB_COLORMAP, {1, 0, 1}, 3, 1, &palette);
  EXPECT_EQ(read_png(dir / "palette.png").pixels,
            (std::vector<std::uint8_t>{0, 0, 255, 255, 255, 0, 0, 255, 0, 0, 255, 255}));
}

TEST(PngWriter, MissingDirectoryThrowsOutputErrorNamingThePathAndLeavesNothing) {
  ScratchDir dir;
  const fs::path path = dir / "no" / "such" / "dir" / "frame.png";
  try {
    write_png(path, noise_frame(4, 4, 1));
    FAIL() << "write_png into a missing directory succeeded";
  } catch (const OutputError& e) {
    EXPECT_TRUE(contains(e.what(), path.string())) << e.what();
    EXPECT_TRUE(contains(e.what(), "No such file or directory")) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PngWriter, UnwritableDirectoryThrowsOutputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  ScratchDir dir;
  fs::create_directory(dir / "locked");
  fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(write_png(dir / "locked" / "f.png", noise_frame(4, 4, 1)), OutputError);
  fs::permissions(dir / "locked", fs::perms::owner_all);
  EXPECT_TRUE(fs::is_empty(dir / "locked"));
}

// A write error in mid-file (here EFBIG from a file-size limit, standing in for
// ENOSPC) must surface with the OS reason and leave neither file nor temporary.
TEST(PngWriter, WriteErrorMidFileThrowsWithOsReasonAndLeavesNothing) {
  ScratchDir dir;
  const RgbaImage big = noise_frame(256, 256, 3);  // ~256 KiB, incompressible
  auto* const old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  rlimit small = old_limit;
  small.rlim_cur = 16 * 1024;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    write_png(dir / "big.png", big, 0);
  } catch (const OutputError& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_TRUE(contains(message, "File too large")) << message;
  EXPECT_TRUE(contains(message, (dir / "big.png").string())) << message;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PngWriter, RejectsBadArguments) {
  ScratchDir dir;
  EXPECT_THROW(write_png(dir / "a.png", noise_frame(4, 4, 1), 10), std::invalid_argument);
  EXPECT_THROW(write_png(dir / "a.png", noise_frame(4, 4, 1), -1), std::invalid_argument);
  EXPECT_THROW(write_png(dir / "a.png", RgbaImage()), std::invalid_argument);
  RgbaImage short_buffer(4, 4);
  short_buffer.pixels.resize(10);
  EXPECT_THROW(write_png(dir / "a.png", short_buffer), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PngWriter, ReadingANonPngThrowsNamingThePath) {
  ScratchDir dir;
  std::ofstream(dir / "fake.png") << "not a png at all";
  try {
    read_png(dir / "fake.png");
    FAIL() << "read_png accepted text";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(contains(e.what(), (dir / "fake.png").string())) << e.what();
  }
  EXPECT_THROW(read_png(dir / "missing.png"), std::runtime_error);
}

}  // namespace
}  // namespace bookspin::output
