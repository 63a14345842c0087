// examples/one_frame.cpp runs and writes the frame it promises: a PNG of the scene's size
// with the book drawn in it (not only the background).
#include <gtest/gtest.h>

#include "output/png_writer.hpp"
#include "support/cli_runner.hpp"

namespace bookspin::examples {
namespace {

using test::fresh_dir;
using test::run_program;
using test::scene_path;

TEST(OneFrame, WritesThePngOfTheSceneWithTheBookInIt) {
  const auto png = fresh_dir("one-frame") / "frame.png";
  const test::CliResult r = run_program(
      "", BOOKSPIN_ONE_FRAME_EXE, scene_path("fig05-particle-unstable-x") + " 120 " + png.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("t = 60"), std::string::npos) << r.output;
  const RgbaImage image = output::read_png(png);
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 720);
  // The centre pixel is the book, the corner the background: they differ.
  const auto pixel = [&](int x, int y) {
    const std::uint8_t* p = image.row(y) + 4 * x;
    return (p[0] << 16) | (p[1] << 8) | p[2];
  };
  EXPECT_NE(pixel(640, 360), pixel(2, 2));
}

TEST(OneFrame, BadSceneFailsWithTheSceneError) {
  const test::CliResult r = run_program("", BOOKSPIN_ONE_FRAME_EXE, "no-such.toml 0 /tmp/x.png");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("no-such.toml: scene file not found"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace bookspin::examples
