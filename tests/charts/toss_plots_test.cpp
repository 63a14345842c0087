// The toss chart's pixels: the three components in the palette's first three colours, the
// fitted flips as grey lines where the fitted motion flips, on a synthetic toss
// (tests/fit/synthetic_recording.hpp).
#include "charts/toss_plots.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "charts/sphere_view.hpp"
#include "common/colour.hpp"
#include "fit/synthetic_recording.hpp"
#include "overlay/plot.hpp"
#include "physics/polhode.hpp"

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

/// The synthetic recording read as a recording named "synthetic" and pooled, as the fit takes it.
fit::GyroRecording pooled(const fit::test::SyntheticRecording& synthetic) {
  fit::GyroRecording read;
  read.name = read.source = "synthetic";
  read.t = synthetic.t;
  read.omega = synthetic.omega;
  return fit::pool_recordings({read});
}

// ω_x, ω_y, ω_z in red, green and blue (common/colour.hpp, kComponentColours: the clips', the
// page's and the notebook's colours), each drawn; the flips marked.
TEST(TossPlots, ComponentsInTheirColoursAndTheFlipsMarked) {
  const auto synthetic = fit::test::make_recording(
      fit::test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}}, 4);
  const fit::GyroRecording recording = pooled(synthetic);
  const fit::FitResult fit = fit::fit_recording(recording, fit::find_flights(recording));
  const RgbaImage image = toss_image(fit::toss_chart(recording, fit, 0), 1000, 500);
  ASSERT_EQ(image.width, 1000);
  ASSERT_EQ(image.height, 500);
  for (int c = 0; c < 3; ++c) {
    const Rgb colour = kComponentColours[static_cast<std::size_t>(c)];
    const std::vector<int> cols = columns_of(image, int(255 * colour.r + 0.5),
                                             int(255 * colour.g + 0.5), int(255 * colour.b + 0.5));
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

TEST(TossPlots, AStableTossHasNoFlipsMarked) {
  // Two flips about the intermediate axis, then a spin about the largest wobbling 5°: its ω
  // about axis 2 changes sign every half wobble, but it never flips.
  const auto synthetic = fit::test::make_recording(
      fit::test::phone_on_book(),
      {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.2}, {{0.6, 0.5, 12.0}, 1.0}}, 21);
  const fit::GyroRecording recording = pooled(synthetic);
  const fit::FitResult fit = fit::fit_recording(recording, fit::find_flights(recording));
  ASSERT_EQ(fit.tosses.size(), 3u);
  ASSERT_TRUE(fit.tosses[2].stable);
  const Eigen::Vector3d axis2 = fit.body.axes.col(1);
  int sign_changes = 0;
  for (double t = fit.tosses[2].flight.t_start; t + 0.001 <= fit.tosses[2].flight.t_end; t += 0.001)
    if ((axis2.dot(fit::fitted_omega(fit, 2, t)) > 0) !=
        (axis2.dot(fit::fitted_omega(fit, 2, t + 0.001)) > 0))
      ++sign_changes;
  ASSERT_GE(sign_changes, 2);  // what the chart would have marked
  const RgbaImage image = toss_image(fit::toss_chart(recording, fit, 2), 1000, 500);
  const std::vector<int> grey = columns_of(image, 128, 128, 128);
  int flip_columns = 0;
  for (int x = 0; x < image.width; ++x) flip_columns += grey[x] > 150 && grey[x] < 300;
  EXPECT_EQ(flip_columns, 0);
}

TEST(TossPlots, TheSphereShowsTheMeasuredLOnTheFittedOrbit) {
  // A phone on a book: principal axes turned 20° from the phone's (a symmetric axes matrix
  // would hide a transposed one).
  const fit::test::SyntheticBody body = fit::test::phone_on_book();
  const Eigen::Vector3d omega0(0.5, 12.0, 0.4);  // principal frame
  const auto synthetic =
      fit::test::make_recording(body, {{omega0, 1.3}, {{-0.3, 11.0, 0.7}, 1.2}}, 4);
  const fit::GyroRecording recording = pooled(synthetic);
  const fit::FitResult fit = fit::fit_recording(recording, fit::find_flights(recording));
  const overlay::SphereSpec spec = toss_sphere_spec(fit::toss_chart(recording, fit, 0));
  // The truth: L/|L| of Euler's equations by RK4 (the generator's), principal frame (the
  // book's axes have their largest phone component positive: the fit's sign convention).
  const fit::Flight& flight = fit.tosses[0].flight;
  const double t0 = synthetic.tosses[0].t_start;
  std::vector<Eigen::Vector3d> truth;
  for (int i = flight.first; i <= flight.last; ++i)
    truth.push_back(
        body.moments.cwiseProduct(fit::test::rk4(body.moments, omega0, recording.t[i] - t0))
            .normalized());
  // The measured trail: one point a sample, each within 0.02 (about 1°) of the true L/|L|.
  ASSERT_EQ(spec.trails.size(), 1u);
  const overlay::SphereTrail& trail = spec.trails[0];
  EXPECT_EQ(trail.colour.r, kMeasuredLColour.r);
  ASSERT_EQ(trail.points.size(), truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i)
    EXPECT_LT((trail.points[i] - truth[i]).norm(), 0.02) << "sample " << i;
  // The fitted orbit: the curve in its colour, closed (one period), passing within 0.02 of
  // every true L/|L| of the flight.
  const overlay::SphereCurve* orbit = nullptr;
  for (const overlay::SphereCurve& c : spec.curves)
    if (c.colour.r == kFittedOrbitColour.r && c.colour.b == kFittedOrbitColour.b) orbit = &c;
  ASSERT_NE(orbit, nullptr);
  EXPECT_LT((orbit->points.front() - orbit->points.back()).norm(), 1e-6);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    double nearest = 2.0;
    for (const Eigen::Vector3d& p : orbit->points)
      nearest = std::min(nearest, (p - truth[i]).norm());
    EXPECT_LT(nearest, 0.02) << "sample " << i;
  }
  // Drawn: both colours in the sphere's square, right of the plot (1000 − 400 px).
  const RgbaImage image = toss_image(fit::toss_chart(recording, fit, 0), 1000, 500);
  const auto count_right = [&](const Rgb& c) {
    const std::vector<int> cols =
        columns_of(image, int(255 * c.r + 0.5), int(255 * c.g + 0.5), int(255 * c.b + 0.5));
    int n = 0;
    for (int x = 600; x < image.width; ++x) n += cols[x];
    return n;
  };
  EXPECT_GT(count_right(kMeasuredLColour), 100);
  EXPECT_GT(count_right(kFittedOrbitColour), 100);
}

// The sphere behind a toss is drawn from the chart alone (fit::TossChart::polhodes), and is
// the sphere of the fitted moments: every background curve a polhode of them (Σ u²/I constant
// along it, the separatrices' at 1/I₂, docs/physics.md §15), and the whole spec, axes and view
// included, what charts::sphere_spec draws for those moments, the principal order being the
// chart's ascending one.
TEST(TossPlots, TheSphereBehindATossIsThePolhodeFamilyOfItsFittedMoments) {
  const fit::test::SyntheticBody body = fit::test::phone_on_book();
  const auto synthetic =
      fit::test::make_recording(body, {{{0.5, 12.0, 0.4}, 1.3}, {{-0.3, 11.0, 0.7}, 1.2}}, 4);
  const fit::GyroRecording recording = pooled(synthetic);
  const fit::FitResult fit = fit::fit_recording(recording, fit::find_flights(recording));
  const auto same_spec = [](const overlay::SphereSpec& a, const overlay::SphereSpec& b,
                            std::size_t curves) {
    ASSERT_EQ(a.axes.size(), b.axes.size());
    for (std::size_t i = 0; i < a.axes.size(); ++i) {
      EXPECT_EQ(a.axes[i].direction, b.axes[i].direction) << "axis " << i;
      EXPECT_EQ(a.axes[i].colour.r, b.axes[i].colour.r) << "axis " << i;
    }
    EXPECT_EQ(a.view, b.view);
    EXPECT_EQ(a.up, b.up);
    ASSERT_GE(a.curves.size(), curves);
    ASSERT_GE(b.curves.size(), curves);
    for (std::size_t i = 0; i < curves; ++i) {
      EXPECT_EQ(a.curves[i].points, b.curves[i].points) << "curve " << i;
      EXPECT_EQ(a.curves[i].colour.r, b.curves[i].colour.r) << "curve " << i;
      EXPECT_EQ(a.curves[i].width, b.curves[i].width) << "curve " << i;
    }
  };
  for (int toss = 0; toss < 2; ++toss) {
    const fit::TossChart chart = fit::toss_chart(recording, fit, toss);
    const overlay::SphereSpec spec = toss_sphere_spec(chart);
    const Eigen::Vector3d I = chart.moments;
    ASSERT_FALSE(chart.polhodes.empty());
    int separatrices = 0;
    for (std::size_t i = 0; i < chart.polhodes.size(); ++i) {
      const overlay::SphereCurve& curve = spec.curves[i];
      ASSERT_GT(curve.points.size(), 2u);
      const auto level = [&](const Eigen::Vector3d& u) {
        return u.cwiseProduct(u).cwiseQuotient(I).sum();
      };
      const double first = level(curve.points.front());
      for (const Eigen::Vector3d& u : curve.points) {
        EXPECT_NEAR(u.norm(), 1.0, 1e-9);
        EXPECT_NEAR(level(u), first, 1e-9 * first) << "toss " << toss << ", curve " << i;
      }
      if (curve.colour.r == kSeparatrixColour.r && curve.colour.b == kSeparatrixColour.b) {
        ++separatrices;
        EXPECT_NEAR(first, 1.0 / I[1], 1e-9 / I[1]) << "toss " << toss;
      }
    }
    EXPECT_EQ(separatrices, 2) << "toss " << toss;
    same_spec(spec, sphere_spec(chart.moments, {}), chart.polhodes.size());
  }
  // Ascending moments of any spread: the chart's order is principal_order's.
  std::mt19937 random(88);
  std::uniform_real_distribution<double> log_ratio(-3.0, 0.0);
  for (int draw = 0; draw < 20; ++draw) {
    Eigen::Vector3d I(std::pow(10.0, log_ratio(random)), std::pow(10.0, log_ratio(random)), 1.0);
    if (I[0] > I[1]) std::swap(I[0], I[1]);
    fit::TossChart chart;
    chart.moments = I;
    chart.polhodes = physics::polhode_family(I);
    same_spec(toss_sphere_spec(chart), sphere_spec(I, {}), chart.polhodes.size());
  }
}

}  // namespace
}  // namespace bookspin::charts
