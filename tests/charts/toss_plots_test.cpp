// The toss chart's pixels: the three components in the palette's first three colours, the
// fitted flips as grey lines where the fitted motion flips, on a synthetic toss
// (tests/fit/synthetic_recording.hpp).
#include "charts/toss_plots.hpp"

#include <gtest/gtest.h>

#include "fit/synthetic_recording.hpp"
#include "overlay/plot.hpp"

namespace bookspin::charts {
namespace {

/// Pixels of `image` within 10 of (r, g, b) in every channel, per column.
std::vector<int> columns_of(const RgbaImage& image, int r, int g, int b) {
  std::vector<int> count(image.width, 0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p =
          image.pixels.data() + 4 * (static_cast<std::size_t>(y) * image.width + x);
      if (std::abs(p[0] - r) <= 10 && std::abs(p[1] - g) <= 10 && std::abs(p[2] - b) <= 10)
        ++count[x];
    }
  return count;
}

TEST(TossPlots, ComponentsInThePaletteAndTheFlipsMarked) {
  const auto synthetic = fit::test::make_recording(
      fit::test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}}, 4);
  fit::GyroRecording recording;
  recording.name = recording.source = "synthetic";
  recording.t = synthetic.t;
  recording.omega = synthetic.omega;
  const fit::FitResult fit = fit::fit_recording(recording, fit::find_flights(recording));
  const RgbaImage image = toss_image(recording, fit, 0, 1000, 500);
  ASSERT_EQ(image.width, 1000);
  ASSERT_EQ(image.height, 500);
  for (int c = 0; c < 3; ++c) {
    double r, g, b;
    overlay::palette_colour(c, r, g, b);
    const std::vector<int> cols =
        columns_of(image, int(255 * r + 0.5), int(255 * g + 0.5), int(255 * b + 0.5));
    int total = 0;
    for (int n : cols) total += n;
    EXPECT_GT(total, 1500) << "component " << c;
  }
  // The flips: grey (0.5) columns 150 to 300 pixels tall, one per sign change of the true
  // ω about the intermediate axis (Euler's equations by RK4) within the flight found.
  const fit::test::SyntheticBody body = fit::test::phone_alone();
  const double t0 = synthetic.tosses[0].t_start;
  const fit::Flight& flight = fit.tosses[0].flight;
  int flips = 0;
  double previous = 0.0;
  for (double t = flight.t_start; t <= flight.t_end; t += 0.001) {
    const double w2 = fit::test::rk4(body.moments, Eigen::Vector3d(1.0, 18.0, 1.2), t - t0)[1];
    if (t > flight.t_start && (w2 > 0) != (previous > 0)) ++flips;
    previous = w2;
  }
  ASSERT_GE(flips, 2);
  const std::vector<int> grey = columns_of(image, 128, 128, 128);
  // A flip spans 1.05/1.1 of the plot area's height; the area's frame, also grey, all of it.
  const auto flip_column = [&](int x) { return grey[x] > 150 && grey[x] < 300; };
  int lines = 0;
  for (int x = 0; x < image.width; ++x)
    if (flip_column(x) && (x == 0 || !flip_column(x - 1))) ++lines;
  EXPECT_EQ(lines, flips);
}

}  // namespace
}  // namespace bookspin::charts
