// The sphere inset draws where it should: the trail's end dot at its projected position, the
// far side fainter than the near side, the outline on the disc's rim, nothing outside the
// inset (docs/physics.md §15 for what the curves mean; here only the drawing).
#include "overlay/sphere.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace bookspin::overlay {
namespace {

constexpr int kSize = 300;
const PixelRect kRect{20, 30, 240, 240};

RgbaImage white() {
  RgbaImage image(kSize, kSize);
  std::fill(image.pixels.begin(), image.pixels.end(), 255);
  return image;
}

const std::uint8_t* px(const RgbaImage& image, double x, double y) {
  return image.row(static_cast<int>(std::lround(y))) + 4 * static_cast<int>(std::lround(x));
}

SphereSpec bare_spec() {
  SphereSpec spec;
  spec.view = {1.0, 0.5, 0.6};
  spec.up = {0, 0, 1};
  return spec;
}

/// A small circle of angular radius 0.3 rad around unit vector `centre`.
std::vector<Eigen::Vector3d> ring_around(const Eigen::Vector3d& centre) {
  const Eigen::Vector3d a = centre.unitOrthogonal(), b = centre.cross(a);
  std::vector<Eigen::Vector3d> ring;
  for (int i = 0; i <= 200; ++i) {
    const double phi = 2 * M_PI * i / 200;
    ring.push_back(
        (std::cos(0.3) * centre + std::sin(0.3) * (std::cos(phi) * a + std::sin(phi) * b))
            .normalized());
  }
  return ring;
}

TEST(Sphere, ProjectionPutsTheViewerAtTheCentreAndUpAtTheTop) {
  const SphereSpec spec = bare_spec();
  double depth = 0;
  const Eigen::Vector2d centre =
      project_to_inset(spec, spec.view.normalized(), 100, 100, 50, &depth);
  EXPECT_NEAR(centre.x(), 100, 1e-9);
  EXPECT_NEAR(centre.y(), 100, 1e-9);
  EXPECT_NEAR(depth, 1.0, 1e-12);
  project_to_inset(spec, -spec.view.normalized(), 100, 100, 50, &depth);
  EXPECT_NEAR(depth, -1.0, 1e-12);
  // z (up) lands above the centre (image rows grow downwards).
  EXPECT_LT(project_to_inset(spec, Eigen::Vector3d::UnitZ(), 100, 100, 50).y(), 100);
}

TEST(Sphere, TrailEndsInADotOfItsColour) {
  RgbaImage image = white();
  SphereSpec spec = bare_spec();
  const Eigen::Vector3d front = spec.view.normalized();
  spec.trails.push_back({{Eigen::Vector3d::UnitZ(), front}, {0.0, 0.45, 0.70}});
  draw_sphere(image, kRect, spec);
  const SphereDisc disc = sphere_disc(kRect);
  const std::uint8_t* p = px(image, disc.cx, disc.cy);  // the dot: the near pole of the view
  EXPECT_LT(p[0], 40);
  EXPECT_NEAR(p[1], 0.45 * 255, 25);
  EXPECT_NEAR(p[2], 0.70 * 255, 25);
}

TEST(Sphere, OutlineOnTheRimAndNothingOutsideTheInset) {
  RgbaImage image = white();
  draw_sphere(image, kRect, bare_spec());
  const SphereDisc disc = sphere_disc(kRect);
  // The grey outline, at the rim's right, left and bottom (its top may carry the up axis's
  // label on its patch of paper, 12 px text at this inset's size).
  EXPECT_LT(px(image, disc.cx + disc.r, disc.cy)[0], 150);
  EXPECT_LT(px(image, disc.cx - disc.r, disc.cy)[0], 150);
  EXPECT_LT(px(image, disc.cx, disc.cy + disc.r)[0], 150);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const bool inside =
          x >= kRect.x - 1 && x <= kRect.right() + 1 && y >= kRect.y - 1 && y <= kRect.bottom() + 1;
      if (inside) continue;
      const std::uint8_t* p = image.row(y) + 4 * x;
      ASSERT_EQ(p[0] + p[1] + p[2], 3 * 255) << x << "," << y;
    }
  }
}

// The same ring drawn around the near pole and around the far pole projects onto the same
// screen circle; the far one must come out fainter.
TEST(Sphere, FarSideIsFainterThanNearSide) {
  const Eigen::Vector3d front = bare_spec().view.normalized();
  const auto darkness_of = [](const SphereSpec& spec) {
    RgbaImage image = white();
    draw_sphere(image, kRect, spec);
    double sum = 0;  // green missing from the disc's middle band: the red ring's ink
    const SphereDisc disc = sphere_disc(kRect);
    for (int y = static_cast<int>(disc.cy - disc.r); y < disc.cy + disc.r; ++y)
      for (int x = static_cast<int>(disc.cx - 0.5 * disc.r); x < disc.cx + 0.5 * disc.r; ++x)
        sum += 255 - image.row(y)[4 * x + 1];
    return sum;
  };
  const auto darkness = [&](const Eigen::Vector3d& pole) {
    SphereSpec spec = bare_spec();
    spec.curves.push_back({ring_around(pole), {0.9, 0.0, 0.0}, 2.0});
    return darkness_of(spec);
  };
  const double none = darkness_of(bare_spec());
  const double near_side = darkness(front) - none, far_side = darkness(-front) - none;
  EXPECT_GT(far_side, 0.0);  // drawn, but
  EXPECT_GT(near_side, far_side * 1.3);
}

TEST(Sphere, TooSmallAnInsetDrawsNothing) {
  RgbaImage image = white();
  draw_sphere(image, {10, 10, 40, 40}, bare_spec());
  EXPECT_TRUE(
      std::all_of(image.pixels.begin(), image.pixels.end(), [](auto v) { return v == 255; }));
}

}  // namespace
}  // namespace bookspin::overlay
