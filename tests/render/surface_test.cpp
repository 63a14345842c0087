// Surfaces drawn instead of the book: same silhouette as the book on the same box, the
// book's lighting on face colours, nothing for non-finite positions, framing at any scale,
// a 20k-triangle surface streamed frame after frame, and the normals the lighting uses.
#include "render/surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "output/png_writer.hpp"
#include "render/renderer.hpp"
#include "render_test_util.hpp"
#include "support/scratch.hpp"
#include "surface_meshes.hpp"

namespace bookspin::render {
namespace {

using testing::box_corners;
using testing::box_triangles;
using testing::difference_mask;
using testing::Mask;
using testing::topology_of;

constexpr int width = 256, height = 192;

RenderSettings view_from(const Eigen::Vector3d& eye) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.camera.eye = eye;
  return settings;
}

FrameInput nothing() {
  FrameInput frame;
  frame.corners.setConstant(std::nan(""));
  return frame;
}

FrameInput surface_frame(std::shared_ptr<const SurfaceTopology> topology,
                         const Eigen::Matrix3Xd& positions,
                         const Eigen::Matrix<double, 3, 8>& corners) {
  FrameInput frame;
  frame.corners = corners;
  frame.surface.topology = std::move(topology);
  frame.surface.positions = positions;
  return frame;
}

Eigen::Vector3f grey(int) { return Eigen::Vector3f::Constant(0.5f); }

Eigen::Matrix3d some_rotation() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, 1.0, 0.4).normalized()).toRotationMatrix();
}

// What shaders/surface.frag (= book.frag's lights) gives a face of linear colour `albedo`
// with unit world normal `n`, seen at world point `p` from `eye`, with the camera looking
// along −z (view space = world shifted): sRGB, 0…255.
Eigen::Vector3d lit(const Eigen::Vector3d& albedo, const Eigen::Vector3d& n,
                    const Eigen::Vector3d& p, const Eigen::Vector3d& eye) {
  const Eigen::Vector3d v = (eye - p).normalized();
  auto light = [&](const Eigen::Vector3d& direction, const Eigen::Vector3d& colour,
                   double specular) {
    const Eigen::Vector3d l = direction.normalized();
    const double diffuse = std::max(n.dot(l), 0.0);
    const double highlight =
        diffuse > 0.0 ? std::pow(std::max(n.dot((l + v).normalized()), 0.0), 28.0) : 0.0;
    return Eigen::Vector3d(colour.cwiseProduct(albedo * diffuse) + colour * (specular * highlight));
  };
  Eigen::Vector3d c = Eigen::Vector3d(0.16, 0.17, 0.20).cwiseProduct(albedo);
  c += light({-0.45, 0.65, 0.75}, Eigen::Vector3d(1.00, 0.96, 0.90) * 0.95, 0.22);
  c += light({0.80, -0.15, 0.55}, Eigen::Vector3d(0.70, 0.80, 1.00) * 0.38, 0.3 * 0.22);
  c += light({0.20, 0.60, -0.80}, Eigen::Vector3d(0.80, 0.85, 1.00) * 0.35, 0.0);
  for (int i = 0; i < 3; ++i) c(i) = 255.0 * std::pow(std::clamp(c(i), 0.0, 1.0), 1.0 / 2.2);
  return c;
}

/// The pixel (column, row from the top) where world point p lands.
Eigen::Vector2i project(const RenderSettings& settings, const Eigen::Vector3d& p) {
  const Eigen::Matrix4d m =
      projection_matrix(settings.camera, double(settings.width) / settings.height) *
      view_matrix(settings.camera);
  const Eigen::Vector4d clip = m * p.homogeneous();
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  return {int((ndc.x() + 1) / 2 * settings.width), int((1 - ndc.y()) / 2 * settings.height)};
}

TEST(SurfaceRender, ACubeSurfaceOnTheBooksCornersLooksLikeTheBook) {
  // The book with one plain texture on every face and a surface of that colour on the same
  // 8 corners: the same silhouette, and the same colour on a cover (the surface has the
  // covers' sheen).
  const std::uint8_t srgb = 200;
  RgbaImage plain(32, 32);
  for (std::size_t i = 0; i < plain.pixels.size(); ++i) plain.pixels[i] = i % 4 == 3 ? 255 : srgb;
  const std::string texture = test::fresh_dir("surface_textures") / "plain.png";
  output::write_png(texture, plain, 1);
  RenderSettings settings = view_from(Eigen::Vector3d(0.9, 0.6, 3.2).normalized() * 10.0);
  settings.textures = {texture, texture, texture, texture};
  Renderer renderer(settings);
  std::filesystem::remove(texture);
  const RgbaImage background = renderer.render(nothing());
  const Eigen::Matrix3d rotation = some_rotation();
  const Eigen::Matrix<double, 3, 8> corners = box_corners({2.0, 2.0, 2.0}, rotation);
  FrameInput book;
  book.corners = corners;
  const RgbaImage book_image = renderer.render(book);
  const float linear = static_cast<float>(std::pow(srgb / 255.0, 2.2));
  const RgbaImage surface_image = renderer.render(surface_frame(
      topology_of(box_triangles(), [&](int) { return Eigen::Vector3f::Constant(linear); }), corners,
      corners));
  const Mask book_mask = difference_mask(book_image, background);
  const Mask surface_mask = difference_mask(surface_image, background);
  ASSERT_GT(book_mask.count, width * height / 20);
  int differing = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      auto covered = [&](const RgbaImage& image) {
        return (testing::pixel(image, x, y) - testing::pixel(background, x, y)).cwiseAbs().sum() >
               24;
      };
      differing += covered(book_image) != covered(surface_image);
    }
  }
  // Only antialiased edge pixels may fall on different sides of the threshold.
  EXPECT_LT(differing, book_mask.count / 50)
      << "book " << book_mask.count << ", surface " << surface_mask.count;
  EXPECT_NEAR(surface_mask.centre_x(), book_mask.centre_x(), 0.5);
  EXPECT_NEAR(surface_mask.centre_y(), book_mask.centre_y(), 0.5);
  // The cover turned towards the camera, a little off its centre (the centre is the book's
  // fan vertex): same colour.
  const Eigen::Vector3d cover = rotation * Eigen::Vector3d::UnitZ();
  const double side = cover.dot(settings.camera.eye) > 0 ? 1.0 : -1.0;
  const Eigen::Vector2i at = project(settings, rotation * Eigen::Vector3d(0.3, 0.2, side));
  const Eigen::Vector3d book_colour = testing::pixel(book_image, at.x(), at.y());
  const Eigen::Vector3d surface_colour = testing::pixel(surface_image, at.x(), at.y());
  EXPECT_LT((book_colour - surface_colour).cwiseAbs().maxCoeff(), 2.5)
      << book_colour.transpose() << " vs " << surface_colour.transpose();
}

TEST(SurfaceRender, AFlatFaceShowsItsOwnColourLitAsTheBookIs) {
  const Eigen::Vector3d eye(0, 0, 10);
  const RenderSettings settings = view_from(eye);
  Renderer renderer(settings);
  const Eigen::Matrix<double, 3, 8> corners = box_corners({2.0, 2.0, 2.0});
  // Every triangle its own colour: the +z face's two triangles are 10 and 11.
  auto colour = [](int t) {
    return Eigen::Vector3f(0.05f + 0.07f * t, 0.9f - 0.06f * t, 0.3f + 0.02f * (t % 5));
  };
  const auto topology = topology_of(box_triangles(), colour);
  const RgbaImage image = renderer.render(surface_frame(topology, corners, corners));
  // Triangle 10 is corners 4, 5, 7 (below the diagonal y = x), 11 is 4, 7, 6 (above it).
  const Eigen::Vector3d points[2] = {{0.5, -0.5, 1.0}, {-0.5, 0.5, 1.0}};
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2i pixel = project(settings, points[k]);
    const Eigen::Vector3d expected =
        lit(colour(10 + k).cast<double>(), Eigen::Vector3d::UnitZ(), points[k], eye);
    const Eigen::Vector3d got = testing::pixel(image, pixel.x(), pixel.y());
    EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 2.5)
        << "triangle " << 10 + k << ": got " << got.transpose() << ", expected "
        << expected.transpose();
  }
  // Another topology on the same renderer: its colours, not the first one's.
  auto blue = [](int) { return Eigen::Vector3f(0.1f, 0.2f, 0.9f); };
  const RgbaImage other =
      renderer.render(surface_frame(topology_of(box_triangles(), blue), corners, corners));
  const Eigen::Vector2i pixel = project(settings, points[0]);
  const Eigen::Vector3d expected =
      lit(blue(0).cast<double>(), Eigen::Vector3d::UnitZ(), points[0], eye);
  EXPECT_LT((testing::pixel(other, pixel.x(), pixel.y()) - expected).cwiseAbs().maxCoeff(), 2.5);
}

TEST(SurfaceRender, ANonFinitePositionDrawsOnlyTheBackground) {
  RenderSettings settings = view_from({0, 0, 10});
  Renderer renderer(settings);
  const RgbaImage background = renderer.render(nothing());
  const Eigen::Matrix<double, 3, 8> corners = box_corners({2.0, 2.0, 2.0});
  const auto topology = topology_of(box_triangles(), grey);
  for (double bad : {std::nan(""), HUGE_VAL, 1e39 /* finite, but not as a float */}) {
    Eigen::Matrix3Xd positions = corners;
    positions(1, 5) = bad;
    const RgbaImage image = renderer.render(surface_frame(topology, positions, corners));
    EXPECT_EQ(image.pixels, background.pixels) << bad;
    // And the next good frame draws again.
    EXPECT_GT(
        difference_mask(renderer.render(surface_frame(topology, corners, corners)), background)
            .count,
        1000);
  }
}

TEST(SurfaceRender, AFaceSeenFromBehindIsLitAsSeen) {
  // Reversed winding (an inside-out or exploded surface) shows the same picture.
  Renderer renderer(view_from(Eigen::Vector3d(0.9, 0.6, 3.2).normalized() * 10.0));
  const Eigen::Matrix<double, 3, 8> corners = box_corners({2.0, 1.0, 1.5}, some_rotation());
  const auto outward = topology_of(box_triangles(), grey);
  Eigen::Matrix3Xi reversed = box_triangles();
  reversed.row(1).swap(reversed.row(2));
  const RgbaImage a = renderer.render(surface_frame(outward, corners, corners));
  const RgbaImage b = renderer.render(surface_frame(topology_of(reversed, grey), corners, corners));
  int worst = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
  EXPECT_LE(worst, 2);
}

TEST(SurfaceRender, BodyAxesFollowTheCornersWithASurface) {
  // A small cube inside a larger box (the body's cage): the axes are placed and sized by the
  // cage's corners, so they reach well beyond the drawn surface.
  RenderSettings settings = view_from(Eigen::Vector3d(0.9, 0.6, 3.2).normalized() * 10.0);
  Renderer plain(settings);
  settings.show_body_axes = true;
  Renderer with_axes(settings);
  const RgbaImage background = plain.render(nothing());
  const Eigen::Matrix<double, 3, 8> cage = box_corners({3.0, 3.0, 3.0}, some_rotation());
  const Eigen::Matrix3Xd cube = box_corners({1.0, 1.0, 1.0}, some_rotation());
  const FrameInput frame = surface_frame(topology_of(box_triangles(), grey), cube, cage);
  const Mask body = difference_mask(plain.render(frame), background);
  const Mask axes = difference_mask(with_axes.render(frame), plain.render(frame));
  ASSERT_GT(body.count, 500);
  EXPECT_GT(axes.count, 150);
  EXPECT_GT(axes.width(), 1.5 * body.width());
  EXPECT_GT(axes.height(), 1.5 * body.height());
}

TEST(SurfaceRender, ABodyOfAnyExtentIsFramedTheSame) {
  // The camera is placed from the body's box (bounding_radius of its corners): a body a
  // thousand times smaller or larger fills the same part of the picture.
  Mask masks[3];
  const double scales[3] = {1e-3, 1.0, 1e3};
  const auto topology = topology_of(box_triangles(), grey);
  for (int k = 0; k < 3; ++k) {
    const Eigen::Matrix<double, 3, 8> corners =
        box_corners(Eigen::Vector3d(1.0, 3.0, 0.5) * scales[k], some_rotation());
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.camera = default_camera(bounding_radius(corners), width, height);
    Renderer renderer(settings);
    const RgbaImage background = renderer.render(nothing());
    masks[k] =
        difference_mask(renderer.render(surface_frame(topology, corners, corners)), background);
    ASSERT_GT(masks[k].count, width * height / 20) << scales[k];
    EXPECT_GT(masks[k].min_x, 0);
    EXPECT_GT(masks[k].min_y, 0);
    EXPECT_LT(masks[k].max_x, width - 1);
    EXPECT_LT(masks[k].max_y, height - 1);
  }
  for (int k : {0, 2}) {
    EXPECT_NEAR(masks[k].count, masks[1].count, 0.01 * masks[1].count) << scales[k];
    EXPECT_NEAR(masks[k].centre_x(), masks[1].centre_x(), 1.0) << scales[k];
  }
}

TEST(SurfaceRender, ATwentyThousandTriangleSurfaceStreamsFrameAfterFrame) {
  const testing::TestMesh torus = testing::torus(1.2, 0.45, 100, 100);
  ASSERT_EQ(torus.triangles.cols(), 20000);
  const auto topology = topology_of(
      torus.triangles,
      [](int t) {
        return ((t / 2) / 10 + (t / 2) % 10) % 2 ? Eigen::Vector3f(0.8f, 0.3f, 0.1f)
                                                 : Eigen::Vector3f(0.9f, 0.85f, 0.7f);
      },
      true);
  Renderer renderer(view_from(Eigen::Vector3d(0.9, 0.6, 3.2).normalized() * 10.0));
  const RgbaImage background = renderer.render(nothing());
  const Eigen::Matrix<double, 3, 8> cage = box_corners({3.3, 3.3, 0.9});
  int collected = 0;
  int first_count = 0;
  auto check = [&](const RgbaImage& image) {
    const int count = difference_mask(image, background).count;
    if (collected++ == 0) first_count = count;
    // A torus turning about its axis of symmetry covers the same pixels.
    EXPECT_NEAR(count, first_count, 0.01 * first_count) << "frame " << collected;
  };
  for (int f = 0; f < 30; ++f) {
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(0.05 * f, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    renderer.submit(surface_frame(topology, turn * torus.positions, turn * cage));
    if (auto image = renderer.collect()) check(*image);
  }
  while (auto image = renderer.flush()) check(*image);
  EXPECT_EQ(collected, 30);
  EXPECT_GT(first_count, width * height / 10);
}

TEST(SurfaceRender, SmoothShadingHidesTheFacetsThatFlatShadingShows) {
  // One colour on a coarse torus: flat shading jumps in brightness at every facet edge,
  // smooth shading (interpolated vertex normals) hardly anywhere.
  const testing::TestMesh torus = testing::torus(1.2, 0.45, 24, 12);
  Renderer renderer(view_from(Eigen::Vector3d(0.9, 0.6, 3.2).normalized() * 8.0));
  const RgbaImage background = renderer.render(nothing());
  const Eigen::Matrix<double, 3, 8> cage = box_corners({3.3, 3.3, 0.9});
  auto jumps = [&](bool smooth) {
    const RgbaImage image = renderer.render(
        surface_frame(topology_of(torus.triangles, grey, smooth), torus.positions, cage));
    int count = 0;
    for (int y = 0; y < height; ++y) {
      for (int x = 1; x + 1 < width; ++x) {
        auto inside = [&](int px) {
          return (testing::pixel(image, px, y) - testing::pixel(background, px, y))
                     .cwiseAbs()
                     .sum() > 24;
        };
        if (!inside(x - 1) || !inside(x) || !inside(x + 1)) continue;
        // A jump: the middle pixel differs from both neighbours' mean by more than 6 levels.
        const Eigen::Vector3d mean =
            0.5 * (testing::pixel(image, x - 1, y) + testing::pixel(image, x + 1, y));
        count += (testing::pixel(image, x, y) - mean).cwiseAbs().maxCoeff() > 6;
      }
    }
    return count;
  };
  const int flat = jumps(false), smooth = jumps(true);
  EXPECT_GT(flat, 100);
  EXPECT_LT(smooth, flat / 2) << "flat " << flat;  // 1200 and 400 on llvmpipe
}

TEST(SurfaceRender, MalformedSurfacesAreRejected) {
  Renderer renderer(view_from({0, 0, 10}));
  const Eigen::Matrix<double, 3, 8> corners = box_corners({2.0, 2.0, 2.0});
  Eigen::Matrix3Xi negative = box_triangles();
  negative(0, 3) = -1;
  EXPECT_THROW(renderer.render(surface_frame(topology_of(negative, grey), corners, corners)),
               std::invalid_argument);
  Eigen::Matrix3Xi beyond = box_triangles();
  beyond(2, 7) = 8;  // positions has 8 columns
  EXPECT_THROW(renderer.render(surface_frame(topology_of(beyond, grey), corners, corners)),
               std::invalid_argument);
  auto too_bright = [](int) { return Eigen::Vector3f(1.5f, 0.0f, 0.0f); };
  EXPECT_THROW(
      renderer.render(surface_frame(topology_of(box_triangles(), too_bright), corners, corners)),
      std::invalid_argument);
  auto few_colours = std::make_shared<SurfaceTopology>(*topology_of(box_triangles(), grey));
  few_colours->face_colours.conservativeResize(3, 11);
  EXPECT_THROW(renderer.render(surface_frame(few_colours, corners, corners)),
               std::invalid_argument);
  // The renderer still works afterwards.
  EXPECT_NO_THROW(
      renderer.render(surface_frame(topology_of(box_triangles(), grey), corners, corners)));
}

TEST(SurfaceNormals, FaceNormalsFollowTheWindingAndDegenerateOnesAreZero) {
  Eigen::Matrix3Xd positions(3, 4);
  positions << 0, 2, 0, 4,  //
      0, 0, 3, 0,           //
      1, 1, 1, 1;
  Eigen::Matrix3Xi triangles(3, 3);
  triangles << 0, 0, 0,  //
      1, 2, 1,           //
      2, 1, 3;
  const Eigen::Matrix3Xf n = face_normals(positions, triangles);
  EXPECT_TRUE(n.col(0).isApprox(Eigen::Vector3f(0, 0, 1)));
  EXPECT_TRUE(n.col(1).isApprox(Eigen::Vector3f(0, 0, -1)));
  EXPECT_TRUE(n.col(2).isZero());  // three points on a line
}

TEST(SurfaceNormals, SmoothNormalsOfAFineTorusAreItsTrueNormals) {
  const testing::TestMesh torus = testing::torus(1.2, 0.45, 120, 60);
  const Eigen::Matrix3Xf normals = vertex_normals(torus.positions, torus.triangles);
  double worst = 0;
  for (Eigen::Index v = 0; v < torus.positions.cols(); ++v) {
    const Eigen::Vector3d p = torus.positions.col(v);
    const Eigen::Vector3d ring = Eigen::Vector3d(p.x(), p.y(), 0).normalized() * 1.2;
    const Eigen::Vector3d truth = (p - ring).normalized();
    worst = std::max(worst, std::acos(std::min(1.0, truth.dot(normals.col(v).cast<double>()))));
  }
  EXPECT_LT(worst, 0.5 * 3.14159265358979 / 180);  // half a degree
}

TEST(SurfaceNormals, AreaWeightingFavoursTheLargerTriangle) {
  // Two triangles meeting at vertex 0 at right angles: the normal leans to the larger one.
  Eigen::Matrix3Xd positions(3, 5);
  positions.col(0) << 0, 0, 0;
  positions.col(1) << 3, 0, 0;
  positions.col(2) << 0, 3, 0;  // triangle 0: in z = 0, area 4.5, normal +z
  positions.col(3) << 0, 0, -1;
  positions.col(4) << 0, 1, 0;  // triangle 1: in x = 0, area 0.5, normal +x
  Eigen::Matrix3Xi triangles(3, 2);
  triangles << 0, 0,  //
      1, 3,           //
      2, 4;
  const Eigen::Vector3f n = vertex_normals(positions, triangles).col(0);
  EXPECT_TRUE(n.isApprox(Eigen::Vector3f(1, 0, 9).normalized())) << n.transpose();
}

TEST(SurfaceFraming, BoundingRadiusIsTheFarthestPointFromTheOrigin) {
  Eigen::Matrix3Xd points(3, 3);
  points << 1, 0, -2,  //
      0, 3, 0,         //
      0, 4, 0;
  EXPECT_DOUBLE_EQ(bounding_radius(points), 5.0);
  EXPECT_THROW(bounding_radius(Eigen::Matrix3Xd(3, 0)), RenderError);
  EXPECT_THROW(bounding_radius(Eigen::Matrix3Xd::Zero(3, 2)), RenderError);
  points(0, 0) = std::nan("");
  EXPECT_THROW(bounding_radius(points), RenderError);
}

}  // namespace
}  // namespace bookspin::render
