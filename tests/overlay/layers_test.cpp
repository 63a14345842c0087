// The layered overlays give exactly the pixels of drawing everything anew: the row blend
// against the per-pixel one, the sphere inset and the caption painter against draw_sphere
// and draw_caption over frames whose changing parts change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "common/argb32.hpp"
#include "overlay/caption.hpp"
#include "overlay/sphere.hpp"

namespace bookspin::overlay {
namespace {

TEST(BlendRow, EqualsThePerPixelBlendForEveryAlphaColourAndDestination) {
  // Every premultiplied (a, c ≤ a) over every destination byte, in each channel.
  std::vector<unsigned char> src;
  std::vector<std::uint8_t> dst;
  for (std::uint32_t a = 0; a < 256; ++a) {
    for (std::uint32_t c = 0; c <= a; ++c) {
      for (std::uint32_t d = 0; d < 256; d += 3) {
        const std::uint32_t word =
            a << 24 | c << 16 | ((c * 7) % (a + 1)) << 8 | ((c * 13) % (a + 1));
        const unsigned char* w = reinterpret_cast<const unsigned char*>(&word);
        src.insert(src.end(), w, w + 4);
        dst.insert(dst.end(), {static_cast<std::uint8_t>(d), static_cast<std::uint8_t>(255 - d),
                               static_cast<std::uint8_t>((d * 5) & 255), 255});
      }
    }
  }
  std::vector<std::uint8_t> expected = dst;
  const int n = static_cast<int>(src.size() / 4);
  for (int i = 0; i < n; ++i)
    argb32::blend_over_opaque(argb32::load(&src[4 * i]), &expected[4 * i]);
  argb32::blend_row_over_opaque(src.data(), dst.data(), n);
  ASSERT_EQ(dst.size(), expected.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < dst.size(); ++i) differing += dst[i] != expected[i];
  EXPECT_EQ(differing, 0u);
}

/// A frame that is not flat, so that blending over it shows.
RgbaImage backdrop(int width, int height) {
  RgbaImage image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.row(y) + 4 * x;
      p[0] = static_cast<std::uint8_t>(x * 3), p[1] = static_cast<std::uint8_t>(y * 5);
      p[2] = static_cast<std::uint8_t>((x + y) * 2), p[3] = 255;
    }
  }
  return image;
}

SphereSpec spec_with_curves() {
  SphereSpec spec;
  spec.title = "L/|L| in the body frame";
  spec.view = {1.0, 0.5, 0.6};
  for (int axis = 0; axis < 3; ++axis)
    spec.axes.push_back({Eigen::Vector3d::Unit(axis), "axis " + std::to_string(axis),
                         Rgb{0.2 * axis, 0.5, 0.8 - 0.2 * axis}});
  for (int k = 1; k <= 3; ++k) {
    SphereCurve curve;
    for (int i = 0; i <= 120; ++i) {
      const double phi = 2 * M_PI * i / 120, z = 0.25 * k;
      const double r = std::sqrt(1 - z * z);
      curve.points.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
    curve.colour = {0.5, 0.5, 0.6};
    spec.curves.push_back(curve);
  }
  return spec;
}

SphereTrail trail_until(int n) {
  SphereTrail trail;
  for (int i = 0; i < n; ++i) {
    const double phi = 0.05 * i;
    trail.points.push_back(Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.3).normalized());
  }
  trail.colour = {0.9, 0.3, 0.1};
  return trail;
}

TEST(SphereInset, DrawsExactlyWhatDrawSphereDrawsFrameAfterFrame) {
  const PixelRect rect{12, 40, 200, 200};
  SphereInset inset(320, 260, rect, spec_with_curves());
  for (int frame : {0, 1, 5, 40, 130}) {
    SphereSpec spec = spec_with_curves();
    spec.trails = {trail_until(frame)};
    RgbaImage expected = backdrop(320, 260), layered = backdrop(320, 260);
    draw_sphere(expected, rect, spec);
    inset.draw(layered, spec.trails);
    EXPECT_EQ(layered.pixels, expected.pixels) << "frame " << frame;
    EXPECT_NE(layered.pixels, backdrop(320, 260).pixels);
  }
}

TEST(SphereInset, RefusesAnImageOfAnotherSize) {
  SphereInset inset(320, 260, {12, 40, 200, 200}, spec_with_curves());
  RgbaImage other = backdrop(322, 260);
  EXPECT_THROW(inset.draw(other, {}), std::invalid_argument);
}

TEST(CaptionPainter, DrawsExactlyWhatDrawCaptionDrawsAsLinesChange) {
  CaptionPainter painter;
  CaptionLayout layout;
  layout.max_width = 500;
  const std::vector<std::vector<CaptionLine>> frames = {
      {{"Title", CaptionStyle::normal, true}, {"model"}, {"t = 0.0"}},
      {{"Title", CaptionStyle::normal, true}, {"model"}, {"t = 0.5"}},
      {{"Title", CaptionStyle::normal, true}, {"model"}, {"t = 1.0"}},
      {{"Title", CaptionStyle::normal, true},
       {"model"},
       {"t = 1.5"},
       {"diverged at t = 1.40", CaptionStyle::warning, true}},
      {{"Another title", CaptionStyle::normal, true}, {"model"}, {"t = 2.0"}},
      {{"Another title", CaptionStyle::normal, true},
       {"a much longer model line, wider"},
       {"t = 2.5"}},
      {{"Another title", CaptionStyle::normal, true},
       {"a much longer model line, wider"},
       {"t = 3.0"}}};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    RgbaImage expected = backdrop(640, 360), layered = backdrop(640, 360);
    draw_caption(expected, frames[i], layout);
    painter.draw(layered, frames[i], layout);
    EXPECT_EQ(layered.pixels, expected.pixels) << "frame " << i;
  }
}

}  // namespace
}  // namespace bookspin::overlay
