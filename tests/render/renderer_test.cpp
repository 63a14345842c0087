// Frames rendered through EGL (llvmpipe is fine): placement, faces, robustness, errors.
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

#include "output/png_writer.hpp"
#include "render_test_util.hpp"
#include "support/scratch.hpp"

namespace bookspin::render {
namespace {

using testing::default_book;
using testing::difference_mask;
using testing::Mask;

constexpr int width = 256, height = 192;
constexpr double distance = 10.0;

RenderSettings axis_view(const Eigen::Vector3d& eye_direction) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.camera.eye = eye_direction.normalized() * distance;
  return settings;
}

FrameInput nan_frame() {
  FrameInput frame;
  frame.corners.setConstant(std::nan(""));
  return frame;
}

FrameInput book_frame(const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity(),
                      const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  FrameInput frame;
  frame.corners = default_book(rotation, offset);
  return frame;
}

// One renderer per camera, shared by the tests (context + textures take a while on llvmpipe).
class RendererTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    from_front = std::make_unique<Renderer>(axis_view({0, 0, 1}));
    background = from_front->render(nan_frame());
  }
  static void TearDownTestSuite() {
    from_front.reset();
    back_renderer.reset();
  }
  // Made on first use: CTest runs every test in its own process.
  static Renderer& from_back() {
    if (!back_renderer) back_renderer = std::make_unique<Renderer>(axis_view({0, 0, -1}));
    return *back_renderer;
  }
  static inline std::unique_ptr<Renderer> from_front, back_renderer;
  static inline RgbaImage background;
};

TEST_F(RendererTest, ImageHasTheRequestedSizeAndIsOpaque) {
  const RgbaImage image = from_front->render(book_frame());
  ASSERT_EQ(image.width, width);
  ASSERT_EQ(image.height, height);
  ASSERT_EQ(image.pixels.size(), std::size_t(width) * height * 4);
  for (std::size_t i = 3; i < image.pixels.size(); i += 4) ASSERT_EQ(image.pixels[i], 255);
}

TEST_F(RendererTest, FrameIsNotUniform) {
  const RgbaImage image = from_front->render(book_frame());
  const Mask mask = difference_mask(image, background);
  EXPECT_GT(mask.count, width * height / 10);
  EXPECT_LT(mask.count, width * height / 2);
}

TEST_F(RendererTest, BackgroundIsAGradientNotBlack) {
  const Eigen::Vector3d top = testing::pixel(background, width / 2, 2);
  const Eigen::Vector3d bottom = testing::pixel(background, width / 2, height - 3);
  EXPECT_GT(top.sum(), 3 * 60.0) << "top of the background is too dark";
  EXPECT_GT(bottom.sum(), 3 * 10.0) << "bottom is flat black";
  EXPECT_GT(top.sum(), bottom.sum() + 60.0) << "no vertical gradient (top lighter)";
  EXPECT_GT(top.z(), top.x()) << "background should be blue-grey";
}

// Seen from +z on the axis, the book's silhouette is its front cover: centred, a × b.
TEST_F(RendererTest, BookAtIdentityIsCentredWithTheRightShape) {
  const Mask mask = difference_mask(from_front->render(book_frame()), background);
  ASSERT_GT(mask.count, 0);
  EXPECT_NEAR(mask.centre_x(), (width - 1) / 2.0, 2.0);
  EXPECT_NEAR(mask.centre_y(), (height - 1) / 2.0, 2.0);
  EXPECT_NEAR(mask.width() / mask.height(), 1.878 / 2.9085, 0.03);
  // Projected height: b / (distance − c/2) / tan(15°) × height/2 pixels.
  const double expected_height =
      2.9085 / (distance - 0.25) / std::tan(15.0 * M_PI / 180) * height / 2;
  EXPECT_NEAR(mask.height(), expected_height, 3.0);
}

TEST_F(RendererTest, MovingTheCornersMovesTheBook) {
  const Mask centre = difference_mask(from_front->render(book_frame()), background);
  const Mask right = difference_mask(
      from_front->render(book_frame(Eigen::Matrix3d::Identity(), {1, 0, 0})), background);
  const Mask up = difference_mask(
      from_front->render(book_frame(Eigen::Matrix3d::Identity(), {0, 0.5, 0})), background);
  const double pixels_per_unit = height / 2 / std::tan(15.0 * M_PI / 180) / (distance - 0.25);
  EXPECT_NEAR(right.centroid_x() - centre.centroid_x(), pixels_per_unit, 3.0);
  EXPECT_LT(up.centre_y(), centre.centre_y() - 0.4 * pixels_per_unit);  // image y runs down
}

// Front cover dark blue, back cover burgundy: the right one faces the right camera.
TEST_F(RendererTest, FrontAndBackCoversDifferAndFaceTheRightWay) {
  const Mask front = difference_mask(from_front->render(book_frame()), background);
  const Mask back = difference_mask(from_back().render(book_frame()), background);
  EXPECT_GT(front.mean_color.z(), front.mean_color.x() + 10) << "front should be blue";
  EXPECT_GT(back.mean_color.x(), back.mean_color.z() + 10) << "back should be red";
  // Turning the book half around y shows the back to the +z camera.
  const Eigen::Matrix3d half_turn =
      Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Mask turned = difference_mask(from_front->render(book_frame(half_turn)), background);
  EXPECT_GT(turned.mean_color.x(), turned.mean_color.z() + 10);
}

// The back's barcode (near-white box) sits at the lower right seen from −z: not mirrored,
// not upside down.
TEST_F(RendererTest, BackCoverIsNotMirrored) {
  const RgbaImage image = from_back().render(book_frame());
  const Mask book = difference_mask(image, background);
  double sum_x = 0, sum_y = 0;
  int count = 0;
  for (int y = book.min_y; y <= book.max_y; ++y) {
    for (int x = book.min_x; x <= book.max_x; ++x) {
      if (testing::pixel(image, x, y).minCoeff() < 200) continue;
      sum_x += x;
      sum_y += y;
      ++count;
    }
  }
  ASSERT_GT(count, 20);
  EXPECT_GT(sum_x / count, book.centre_x() + 0.15 * book.width());
  EXPECT_GT(sum_y / count, book.centre_y() + 0.25 * book.height());
}

TEST_F(RendererTest, NonFiniteCornersDrawOnlyTheBackground) {
  FrameInput frame = book_frame();
  frame.corners(1, 3) = std::nan("");
  EXPECT_EQ(difference_mask(from_front->render(frame), background, 0).count, 0);
  frame.corners(1, 3) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(difference_mask(from_front->render(frame), background, 0).count, 0);
}

TEST_F(RendererTest, HugeCornersDoNotCrash) {
  FrameInput frame = book_frame();
  frame.corners *= 1e30;
  const RgbaImage image = from_front->render(frame);
  EXPECT_EQ(image.width, width);
  frame.corners = default_book() * 1e6;  // the camera is inside this book
  EXPECT_EQ(from_front->render(frame).height, height);
}

TEST_F(RendererTest, InfoNamesPlatformAndGl33) {
  const GlInfo& info = from_front->info();
  EXPECT_FALSE(info.egl_platform.empty());
  EXPECT_FALSE(info.gl_renderer.empty());
  int major = 0, minor = 0;
  ASSERT_EQ(std::sscanf(info.gl_version.c_str(), "%d.%d", &major, &minor), 2) << info.gl_version;
  EXPECT_GE(major * 10 + minor, 33);
  const auto lines = info.lines();
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0].rfind("EGL platform: ", 0), 0u);
}

// Two contexts on one thread: each render makes its own current; destroying a third one
// (sharing the EGL display) must not break them.
TEST_F(RendererTest, SeveralRenderersCoexist) {
  const RgbaImage before = from_front->render(book_frame());
  from_back().render(book_frame());
  { const GlInfo info = gl_info(); }
  const RgbaImage after = from_front->render(book_frame());
  EXPECT_EQ(before.pixels, after.pixels);
}

// ---- markers ---------------------------------------------------------------------------

int count_color(const RgbaImage& image, auto predicate) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) count += predicate(testing::pixel(image, x, y)) ? 1 : 0;
  return count;
}

TEST(RendererMarkers, ArrowAndAxesAppear) {
  RenderSettings settings = axis_view({0.2, 0.3, 1});
  settings.show_angular_momentum = true;
  settings.show_body_axes = true;
  Renderer renderer(settings);
  FrameInput frame = book_frame();
  frame.angular_momentum_direction = {-1, 0.4, 0};  // away from the red +x axis
  const RgbaImage image = renderer.render(frame);
  const auto yellow = [](const Eigen::Vector3d& c) {
    return c.x() > 150 && c.y() > 120 && c.z() < 80;
  };
  const auto red = [](const Eigen::Vector3d& c) { return c.x() > 140 && c.y() < 80 && c.z() < 80; };
  const auto green = [](const Eigen::Vector3d& c) {
    return c.y() > 120 && c.x() < 100 && c.z() < 100;
  };
  // Where it must be: yellow left of the centre (L points to −x), red right of it.
  int yellow_left = 0, red_right = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      yellow_left += x < image.width / 2 && yellow(testing::pixel(image, x, y));
      red_right += x > image.width / 2 && red(testing::pixel(image, x, y));
    }
  }
  EXPECT_GT(count_color(image, yellow), 30);
  EXPECT_GT(count_color(image, red), 10);
  EXPECT_GT(count_color(image, green), 10);
  EXPECT_EQ(yellow_left, count_color(image, yellow));
  EXPECT_EQ(red_right, count_color(image, red));
  // Background only, but L still drawn: no crash, arrow present.
  EXPECT_GT(count_color(renderer.render([] {
              FrameInput f = nan_frame();
              f.angular_momentum_direction = {0, 1, 0};
              return f;
            }()),
                        yellow),
            30);
}

// ---- settings errors ------------------------------------------------------------------

void expect_error(const RenderSettings& settings, const std::string& fragment) {
  try {
    Renderer renderer(settings);
    ADD_FAILURE() << "no RenderError; expected one mentioning '" << fragment << "'";
  } catch (const RenderError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "message must be one line";
  }
}

TEST(RendererErrors, BadSizesThrow) {
  RenderSettings settings;
  settings.width = 0;
  expect_error(settings, "positive");
  settings.width = 255;
  settings.height = 192;
  expect_error(settings, "even");
  settings.width = 256;
  settings.height = -2;
  expect_error(settings, "positive");
  settings.height = 192;
  settings.msaa_samples = 0;
  expect_error(settings, "msaa_samples");
  settings.msaa_samples = 4;
  settings.max_anisotropy = 17.0f;
  expect_error(settings, "max_anisotropy");
}

TEST(RendererAnisotropy, AutomaticIsTrilinearOnSoftwareRasterizersOnly) {
  EXPECT_EQ(effective_anisotropy(kAutoAnisotropy, "llvmpipe (LLVM 15.0.6, 256 bits)"), 1.0f);
  EXPECT_EQ(effective_anisotropy(kAutoAnisotropy, "softpipe"), 1.0f);
  EXPECT_EQ(effective_anisotropy(kAutoAnisotropy, "NVIDIA H100 80GB HBM3/PCIe/SSE2"), 4.0f);
  EXPECT_EQ(effective_anisotropy(8.0f, "llvmpipe (LLVM 15.0.6, 256 bits)"), 8.0f);
  EXPECT_EQ(effective_anisotropy(1.0f, "NVIDIA H100 80GB HBM3/PCIe/SSE2"), 1.0f);
}

// A cover seen nearly edge-on is where anisotropic filtering differs from trilinear: the
// setting must reach the texture sampler.
TEST(RendererAnisotropy, ForcedAnisotropyChangesAGrazingCover) {
  RenderSettings settings = axis_view({0.05, 0.0, 1.0});
  settings.camera.eye = Eigen::Vector3d(0.0, -9.0, 1.2);
  settings.max_anisotropy = 1.0f;
  const RgbaImage trilinear = Renderer(settings).render(book_frame());
  settings.max_anisotropy = 8.0f;
  const RgbaImage anisotropic = Renderer(settings).render(book_frame());
  EXPECT_GT(difference_mask(trilinear, anisotropic, 8).count, 50);
}

TEST(RendererErrors, SizeBeyondTheGlLimitThrows) {
  RenderSettings settings;
  settings.width = 1 << 20;
  settings.height = 2;
  expect_error(settings, "GL_MAX_RENDERBUFFER_SIZE");
}

TEST(RendererErrors, DegenerateCameraThrows) {
  RenderSettings settings;
  settings.camera.eye = settings.camera.target;
  expect_error(settings, "camera");
}

TEST(RendererErrors, MissingOrBrokenTextureFileThrowsNamingIt) {
  RenderSettings settings;
  settings.textures.front = "/nonexistent/cover.png";
  expect_error(settings, "front texture '/nonexistent/cover.png': file not found");
  const std::string junk = test::fresh_dir("renderer_errors") / "junk.png";
  std::FILE* file = std::fopen(junk.c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fputs("this is not a PNG", file);
  std::fclose(file);
  settings.textures.front.clear();
  settings.textures.pages = junk;
  expect_error(settings, "pages texture '" + junk + "'");
  std::filesystem::remove(junk);
}

TEST(RendererErrors, BadEglDeviceIndexThrows) {
  ::setenv("BOOKSPIN_EGL_DEVICE", "not-a-number", 1);
  EXPECT_THROW(gl_info(), RenderError);
  ::setenv("BOOKSPIN_EGL_DEVICE", "99", 1);
  try {
    gl_info();
    ADD_FAILURE() << "device 99 accepted";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("BOOKSPIN_EGL_DEVICE"), std::string::npos);
  }
  ::unsetenv("BOOKSPIN_EGL_DEVICE");
}

// ---- custom textures --------------------------------------------------------------------

TEST(RendererTextures, CustomFrontPngIsUsed) {
  RgbaImage green(64, 96);
  for (std::size_t i = 0; i < green.pixels.size(); i += 4) {
    green.pixels[i + 1] = 230;
    green.pixels[i + 3] = 255;
  }
  const std::string path = test::fresh_dir("renderer_textures") / "green.png";
  output::write_png(path, green, 1);
  RenderSettings settings = axis_view({0, 0, 1});
  settings.textures.front = path;
  settings.msaa_samples = 1;  // also covers the no-MSAA path
  Renderer renderer(settings);
  const RgbaImage background = renderer.render(nan_frame());
  const Mask mask = difference_mask(renderer.render(book_frame()), background);
  EXPECT_GT(mask.mean_color.y(), mask.mean_color.x() + 50);
  EXPECT_GT(mask.mean_color.y(), mask.mean_color.z() + 50);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace bookspin::render

// ---- EGL platform steps -------------------------------------------------------------

namespace bookspin::render {
namespace {

// Each step alone must give a working context where the implementation offers it
// (Mesa offers both the device and the surfaceless platform).
void expect_platform_works(const char* platform, const char* missing_marker, const char* label) {
  ::setenv("BOOKSPIN_EGL_PLATFORM", platform, 1);
  try {
    const GlInfo info = gl_info();
    ::unsetenv("BOOKSPIN_EGL_PLATFORM");
    EXPECT_NE(info.egl_platform.find(label), std::string::npos) << info.egl_platform;
  } catch (const RenderError& error) {
    ::unsetenv("BOOKSPIN_EGL_PLATFORM");
    if (std::string(error.what()).find(missing_marker) != std::string::npos)
      GTEST_SKIP() << error.what();
    FAIL() << error.what();
  }
}

TEST(EglPlatforms, DevicePlatformAlone) {
  expect_platform_works("device", "no EGL_EXT_device_enumeration", "device platform");
}

TEST(EglPlatforms, SurfacelessPlatformAlone) {
  expect_platform_works("surfaceless", "no EGL_MESA_platform_surfaceless", "surfaceless");
}

TEST(EglPlatforms, UnknownPlatformNameThrows) {
  ::setenv("BOOKSPIN_EGL_PLATFORM", "wayland", 1);
  EXPECT_THROW(gl_info(), RenderError);
  ::unsetenv("BOOKSPIN_EGL_PLATFORM");
}

TEST(EglPlatforms, ExplicitDeviceZeroWorks) {
  ::setenv("BOOKSPIN_EGL_DEVICE", "0", 1);
  try {
    const GlInfo info = gl_info();
    EXPECT_NE(info.egl_platform.find("device 0"), std::string::npos) << info.egl_platform;
  } catch (const RenderError& error) {
    ::unsetenv("BOOKSPIN_EGL_DEVICE");
    if (std::string(error.what()).find("no device platform") != std::string::npos)
      GTEST_SKIP() << error.what();
    ADD_FAILURE() << error.what();
  }
  ::unsetenv("BOOKSPIN_EGL_DEVICE");
}

}  // namespace
}  // namespace bookspin::render
