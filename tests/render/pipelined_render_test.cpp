// The renderer redraws only where the book was or is, and reads frames back
// through a ring of pixel buffers. Both must leave the pixels exactly as a full redraw
// with a synchronous read-back gives them.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "render/renderer.hpp"
#include "render_test_util.hpp"

namespace bookspin::render {
namespace {

RenderSettings small_settings(bool markers, int msaa) {
  RenderSettings s;
  s.width = 256;
  s.height = 144;
  s.camera = default_camera(default_bounding_radius, s.width, s.height);
  s.show_angular_momentum = markers;
  s.show_body_axes = markers;
  s.msaa_samples = msaa;
  return s;
}

/// A tumbling book with a jump, a blow-up, a non-finite frame and one too close to the
/// camera (clipped by the near plane), so the drawn region moves, grows, vanishes and
/// covers the whole frame.
std::vector<FrameInput> frames(const Camera& camera) {
  std::vector<FrameInput> out;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(0.4 * i, Eigen::Vector3d(1, 2, 0.5).normalized()).toRotationMatrix();
    FrameInput frame;
    frame.corners = testing::default_book(turn, Eigen::Vector3d(0.15 * std::sin(i), 0.0, 0.0));
    frame.angular_momentum_direction = Eigen::Vector3d(0.2, 1.0, 0.3);
    if (i == 2) frame.corners *= 2.5;
    if (i == 4) frame.corners.setConstant(NAN);
    if (i == 6) frame.corners = (frame.corners.colwise() + 0.97 * camera.eye).eval();
    out.push_back(frame);
  }
  return out;
}

// The ground truth of frame i: the first frame of a fresh renderer redraws everything.
std::vector<RgbaImage> fresh_renders(const RenderSettings& s, const std::vector<FrameInput>& in) {
  std::vector<RgbaImage> out;
  for (const FrameInput& frame : in) out.push_back(Renderer(s).render(frame));
  return out;
}

void expect_same(const RgbaImage& a, const RgbaImage& b, int index) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_TRUE(a.pixels == b.pixels) << "frame " << index << " differs";
}

class PipelinedRender : public ::testing::TestWithParam<int> {};

// One set of fresh renders (each renderer costs a few tenths of a second) checks both paths.
TEST_P(PipelinedRender, OnlyTheBooksRegionRedrawnAndPipelinedReadBackGiveFullRedrawPixels) {
  const RenderSettings s = small_settings(true, GetParam());
  const auto in = frames(s.camera);
  const auto truth = fresh_renders(s, in);
  Renderer synchronous(s);
  for (std::size_t i = 0; i < in.size(); ++i)
    expect_same(synchronous.render(in[i]), truth[i], int(i));
  Renderer pipelined(s);
  std::vector<RgbaImage> out;
  for (const FrameInput& frame : in) {
    pipelined.submit(frame);
    if (auto image = pipelined.collect()) {
      out.push_back(std::move(*image));
      pipelined.recycle(out.front());  // a spare buffer of the right size gets reused
    }
  }
  while (auto image = pipelined.flush()) out.push_back(std::move(*image));
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) expect_same(out[i], truth[i], int(i));
}

INSTANTIATE_TEST_SUITE_P(Msaa, PipelinedRender, ::testing::Values(4, 1));

TEST(PipelinedRenderApi, CollectWaitsUntilThePipelineIsFull) {
  Renderer renderer(small_settings(false, 4));
  ASSERT_GE(renderer.pipeline_depth(), 2);
  for (int i = 0; i < renderer.pipeline_depth() - 1; ++i) {
    renderer.submit(FrameInput{testing::default_book()});
    EXPECT_FALSE(renderer.collect().has_value());
  }
  renderer.submit(FrameInput{testing::default_book()});
  EXPECT_TRUE(renderer.collect().has_value());
}

TEST(PipelinedRenderApi, SubmittingIntoAFullPipelineThrows) {
  Renderer renderer(small_settings(false, 1));
  for (int i = 0; i < renderer.pipeline_depth(); ++i)
    renderer.submit(FrameInput{testing::default_book()});
  EXPECT_THROW(renderer.submit(FrameInput{testing::default_book()}), std::logic_error);
  EXPECT_TRUE(renderer.flush().has_value());
}

// render() between submit() and collect() neither disturbs nor is disturbed by the frames
// in flight.
TEST(PipelinedRenderApi, SynchronousRenderInBetweenKeepsFramesInFlightIntact) {
  const RenderSettings s = small_settings(true, 4);
  const auto in = frames(s.camera);
  Renderer renderer(s);
  renderer.submit(in[0]);
  const RgbaImage middle = renderer.render(in[1]);
  const auto first = renderer.flush();
  ASSERT_TRUE(first.has_value());
  expect_same(*first, Renderer(s).render(in[0]), 0);
  expect_same(middle, Renderer(s).render(in[1]), 1);
}

}  // namespace
}  // namespace bookspin::render
