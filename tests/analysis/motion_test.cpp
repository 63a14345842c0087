// The flip detector (docs/physics.md §14): a flip is a turn-over, the intermediate-axis cosine
// going from one side of 0 past the margin on the other, not every sign change. Checked on
// signals whose crossings are known by hand, on the exact wobble about the book's two stable
// axes (no turn-over, many sign changes) and on the exact motion near its unstable axis, whose
// count and first flip come from the closed form (tests/support/closed_form_flips.hpp: the
// standard library's elliptic integrals, not physics::ExactRotation).
#include "analysis/motion.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/book.hpp"
#include "physics/exact_solution.hpp"
#include "physics/shape.hpp"
#include "support/closed_form_flips.hpp"

namespace bookspin::analysis {
namespace {

// A dip to −0.3 and back is no turn-over; going on to −0.8 is one, placed at the last zero
// crossing, between 0.3 (t = 4) and −0.3 (t = 5) at t = 4.5, not where the margin was passed.
TEST(FlipDetector, CountsATurnOverAtItsZeroCrossingNotADip) {
  FlipDetector flips;
  const double samples[][2] = {{0.0, 1.0}, {1.0, 0.3},  {2.0, -0.3}, {3.0, 0.2},
                               {4.0, 0.3}, {5.0, -0.3}, {6.0, -0.8}, {7.0, -1.0}};
  for (const auto& s : samples) flips.observe(s[0], s[1]);
  EXPECT_EQ(flips.count(), 1);
  ASSERT_TRUE(flips.first_flip());
  EXPECT_DOUBLE_EQ(*flips.first_flip(), 4.5);
  EXPECT_FALSE(flips.flip_period());
}

// Back and forth past the margin: each passage one flip, spaced as the crossings are; a zero
// sample keeps the sign before it (the crossing is placed between 0 and the next sample).
TEST(FlipDetector, CountsEveryPassageAndSpacesThemByTheCrossings) {
  FlipDetector flips;
  const double samples[][2] = {{0.0, -0.9}, {1.0, -0.1}, {2.0, 0.7}, {3.0, 0.0},
                               {4.0, -0.6}, {5.0, 0.2},  {6.0, 0.9}};
  for (const auto& s : samples) flips.observe(s[0], s[1]);
  EXPECT_EQ(flips.count(), 3);
  EXPECT_DOUBLE_EQ(*flips.first_flip(), 1.0 + 0.1 / 0.8);
  // Crossings at 1.125, 3 (the zero sample: 0 → −0.6 places it at 3) and 4 + 0.6/0.8.
  EXPECT_DOUBLE_EQ(*flips.flip_period(), (4.75 - 1.125) / 2.0);
}

// A start inside the band takes the sign of its first sample as its side.
TEST(FlipDetector, StartsOnTheSideOfItsFirstNonZeroSample) {
  FlipDetector flips;
  flips.observe(0.0, 0.0);
  flips.observe(1.0, 0.2);
  flips.observe(2.0, -0.2);
  EXPECT_EQ(flips.count(), 0);
  flips.observe(3.0, -0.8);
  EXPECT_EQ(flips.count(), 1);
  EXPECT_DOUBLE_EQ(*flips.first_flip(), 1.5);
}

TEST(FlipDetector, RefusesAMarginOutsideZeroToOne) {
  EXPECT_THROW(FlipDetector(-0.1), std::invalid_argument);
  EXPECT_THROW(FlipDetector(1.0), std::invalid_argument);
  EXPECT_NO_THROW(FlipDetector(0.0));
}

/// The book spun at `rate` (rad per time unit) about body `axis`, its L jiggled by 0.1 % of
/// |L| (docs/physics.md §5): the body-frame ω0 every model starts from.
Eigen::Vector3d jiggled_spin(int axis, double rate, std::uint64_t seed) {
  const Eigen::Vector3d moments = physics::Book{}.principal_moments();
  physics::InitialState initial;
  initial.omega0_body = Eigen::Vector3d::Zero();
  initial.omega0_body[axis] = rate;
  initial.jiggle = 1e-3 * moments[axis] * std::abs(rate);
  initial.seed = seed;
  return physics::initial_angular_momentum(moments, initial).cwiseQuotient(moments);
}

struct SampledRun {
  int flips = 0, sign_changes = 0;
  double max_abs = 0.0;  ///< largest |cos(intermediate axis, L)| seen
  FlipDetector detector;
};

/// The exact motion's flip signal, cos(x, L) = I_x ω_x / |L| (x the book's intermediate axis,
/// docs/physics.md §9), sampled every `dt` for `steps` steps into `run.detector`.
void sample_exact(const Eigen::Vector3d& omega0, double dt, long steps, SampledRun& run) {
  const Eigen::Vector3d moments = physics::Book{}.principal_moments();
  const physics::ExactRotation exact(moments, omega0);
  double previous = 0.0;
  for (long n = 0; n <= steps; ++n) {
    const double t = static_cast<double>(n) * dt;
    const double c = exact.angular_momentum_body(t)[0] / exact.angular_momentum_norm();
    run.detector.observe(t, c);
    if (n > 0 && (c > 0.0) != (previous > 0.0)) ++run.sign_changes;
    run.max_abs = std::max(run.max_abs, std::abs(c));
    previous = c;
  }
  run.flips = run.detector.count();
}

// The book at 5 rad per time unit about its largest (z) and its smallest (y) axis, 0.1 %
// jiggle, dt = 1/60, 10⁵ steps: a wobble. |cos(x, L)| stays below 3e-3 (the tilt of L,
// ~1e-3, times at most √(1 + 5.8) for the polhode's ellipse, docs/physics.md §14), and its
// hundreds of sign changes are no turn-over. With margin 0 (every sign change) the count is
// the sign changes: the detector this test guards against.
TEST(FlipDetector, AWobbleAboutEitherStableAxisCountsNoFlip) {
  for (int axis : {2, 1}) {
    for (std::uint64_t seed : {1u, 7u}) {
      SCOPED_TRACE("axis " + std::to_string(axis) + " seed " + std::to_string(seed));
      SampledRun run;
      sample_exact(jiggled_spin(axis, 5.0, seed), 1.0 / 60.0, 100000, run);
      EXPECT_LT(run.max_abs, 3e-3);
      EXPECT_GT(run.sign_changes, 100);
      EXPECT_EQ(run.flips, 0);
      EXPECT_FALSE(run.detector.first_flip());
    }
  }
  SampledRun every_sign;
  every_sign.detector = FlipDetector(0.0);
  sample_exact(jiggled_spin(2, 5.0, 1), 1.0 / 60.0, 100000, every_sign);
  EXPECT_EQ(every_sign.flips, every_sign.sign_changes);
}

// The book near its intermediate axis x (ε of the spin about y), sampled every step: the count
// over the run equals the closed form's, 1 + ⌊(t_end − first)/(T/2)⌋, and the first flip and
// the spacing agree with it to the chord's O(dt³) error (sn is odd about its zeros).
TEST(FlipDetector, CountsTheExactMotionsTurnOversAsTheClosedForm) {
  const Eigen::Vector3d moments = physics::Book{}.principal_moments();
  for (double epsilon : {1e-3, 2e-2}) {
    for (double dt : {1.0 / 60.0, 0.2}) {
      SCOPED_TRACE("epsilon " + std::to_string(epsilon) + " dt " + std::to_string(dt));
      const Eigen::Vector3d omega0(1.0, epsilon, 0.0);
      const test::ClosedFormFlips closed = test::closed_form_flips(moments, omega0);
      const double t_end = closed.first_flip + 9.5 * closed.half_period;
      const long steps = std::lround(t_end / dt);
      SampledRun run;
      sample_exact(omega0, dt, steps, run);
      const double t_last = static_cast<double>(steps) * dt;
      const int expected =
          1 + static_cast<int>(std::floor((t_last - closed.first_flip) / closed.half_period));
      EXPECT_EQ(expected, 10);
      EXPECT_EQ(run.flips, expected);
      ASSERT_TRUE(run.detector.first_flip());
      EXPECT_NEAR(*run.detector.first_flip(), closed.first_flip, dt * dt * dt);
      EXPECT_NEAR(*run.detector.flip_period(), closed.half_period, dt * dt * dt);
    }
  }
}

}  // namespace
}  // namespace bookspin::analysis

namespace bookspin::analysis {
namespace {

// The explorer's step loop reads the flip signal from the simulator (flip_signal of a
// Simulator), sweeps from the diagnostics: the same numbers, so both count the same flips, for
// the book (intermediate axis x) and a body whose intermediate axis is y.
TEST(FlipSignal, OfTheSimulatorIsThatOfItsDiagnosticsOnEveryIntermediateAxis) {
  for (const Eigen::Vector3d& size :
       {Eigen::Vector3d(1.878, 2.9085, 0.5), Eigen::Vector3d(2.9, 1.9, 0.5)}) {
    physics::ModelConfig config;
    config.kind = physics::ModelKind::rigid_quaternion;
    const physics::Book book{size, 8.0};
    auto sim = physics::make_simulator(book, config);
    const Eigen::Vector3d moments = book.principal_moments();
    physics::InitialState initial;
    initial.omega0_body = Eigen::Vector3d::Zero();
    initial.omega0_body[intermediate_axis(moments)] = 0.5;
    initial.jiggle = 0.01;
    sim->reset(initial);
    for (int step = 0; step < 300; ++step) {
      EXPECT_EQ(flip_signal(*sim, moments), flip_signal(sim->diagnostics(), moments));
      sim->step(0.05);
    }
  }
}

}  // namespace
}  // namespace bookspin::analysis
