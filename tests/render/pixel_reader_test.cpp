// Read-back (src/render/pixel_reader.*): the direct read with GL_MESA_pack_invert that the
// software rasterizer uses and the pixel-buffer ring a GPU uses give the same image, top row
// first, whichever path the machine running the tests would pick.
#include "render/pixel_reader.hpp"

#include <gtest/gtest.h>

#include <array>

#include "render/egl_context.hpp"
#include "render/gl_util.hpp"
#include "render/offscreen_target.hpp"

namespace bookspin::render {
namespace {

constexpr int kWidth = 64, kHeight = 32;

/// Clears the frame to blue, then the GL's top `red_rows` rows (largest y) to red and the
/// left `green_columns` columns to green (drawn last, so they cover the corner), and resolves.
void draw_pattern(OffscreenTarget& target, int red_rows, int green_columns) {
  target.bind_for_drawing();
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, kHeight - red_rows, kWidth, red_rows);
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glScissor(0, 0, green_columns, kHeight);
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  target.resolve();
  check_gl("drawing the test pattern");
}

std::array<std::uint8_t, 3> rgb(const RgbaImage& image, int x, int y) {
  const std::uint8_t* p = image.row(y) + 4 * x;
  return {p[0], p[1], p[2]};
}

void expect_pattern(const RgbaImage& image, int red_rows, int green_columns) {
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  const std::array<std::uint8_t, 3> red{255, 0, 0}, green{0, 255, 0}, blue{0, 0, 255};
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const auto expected = x < green_columns ? green : (y < red_rows ? red : blue);
      ASSERT_EQ(rgb(image, x, y), expected) << "x " << x << " y " << y;
    }
  }
}

TEST(PixelReader, DirectAndPixelBufferReadsGiveTheSameTopFirstImage) {
  EglContext context;
  context.make_current();
  OffscreenTarget target(kWidth, kHeight, 4);
  const bool direct_possible = epoxy_has_gl_extension("GL_MESA_pack_invert");
  for (const bool direct : {false, true}) {
    if (direct && !direct_possible) continue;  // NVIDIA: no GL_MESA_pack_invert
    SCOPED_TRACE(direct ? "direct" : "pixel buffers");
    PixelReader reader(2, direct);
    RgbaImage image;
    draw_pattern(target, 3, 5);
    reader.read(target, image);
    expect_pattern(image, 3, 5);
    // Through the ring, two frames in flight; a buffer handed back is read into again.
    reader.start(target);
    draw_pattern(target, 7, 2);
    reader.start(target);
    RgbaImage first = reader.finish();
    expect_pattern(first, 3, 5);
    const std::uint8_t* buffer = first.pixels.data();
    RgbaImage second = reader.finish(std::move(first));
    expect_pattern(second, 7, 2);
    reader.start(target);
    RgbaImage third = reader.finish();
    expect_pattern(third, 7, 2);
    // Pixel buffers copy out into the buffer finish() is given; direct reads read into it.
    EXPECT_EQ((direct ? third : second).pixels.data(), buffer) << "the buffer was not reused";
  }
}

}  // namespace
}  // namespace bookspin::render
