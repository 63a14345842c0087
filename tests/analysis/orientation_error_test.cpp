// The orientation error (docs/physics.md §14): analysis::rotation_angle_between and the
// orientation_error measure against angles known independently: rotations built from an axis
// and an angle (Eigen::AngleAxisd), and runs whose orientation lags the exact motion by an
// angle that the integrator's step gives in closed form.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

#include "analysis/accuracy.hpp"
#include "analysis/measures.hpp"
#include "analysis/motion.hpp"
#include "common/errors.hpp"
#include "scene/scene.hpp"

namespace bookspin::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

/// A unit axis far from the coordinate axes, and one orthogonal-ish to it.
const Eigen::Vector3d kAxisA = Eigen::Vector3d(0.36, -0.48, 0.8).normalized();
const Eigen::Vector3d kAxisB = Eigen::Vector3d(-0.6, 0.1, 0.3).normalized();

Eigen::Matrix3d turn(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}

/// The tolerance of an angle θ near 0 (relative: the chord keeps every digit there) and near
/// π, where sin(θ/2) ≈ 1 − (π − θ)²/8 leaves asin only √ε of the difference: 1e-7 rad.
double tolerance(double angle) { return angle > 3.0 ? 1e-7 : 1e-12 * std::max(angle, 1e-3); }

// The angle of aᵀb for a = any rotation and b = a turned by θ about any axis, on either side,
// is θ (for θ in [0, π]); a factor two (the quaternion's half-angle, or twice the angle) is
// far outside every tolerance here.
TEST(RotationAngleBetween, IsTheAngleOfAKnownTurnOnEitherSide) {
  const Eigen::Matrix3d base = turn(2.2, kAxisB) * turn(-0.7, kAxisA);
  for (double angle : {0.0, 1e-12, 1e-8, 1e-5, 1e-3, 0.1, 0.5, 1.0, 1.5, kPi / 2, 2.0, 2.5, 3.0,
                       kPi - 1e-4, kPi - 1e-7, kPi}) {
    for (const Eigen::Vector3d& axis : {kAxisA, kAxisB, Eigen::Vector3d::UnitZ().eval()}) {
      SCOPED_TRACE("angle " + std::to_string(angle));
      EXPECT_NEAR(rotation_angle_between(base, base * turn(angle, axis)), angle, tolerance(angle));
      EXPECT_NEAR(rotation_angle_between(base, turn(angle, axis) * base), angle, tolerance(angle));
      EXPECT_NEAR(rotation_angle_between(turn(angle, axis) * base, base), angle, tolerance(angle));
      // A turn by −θ is a turn by θ about −axis: the angle is never negative.
      EXPECT_NEAR(rotation_angle_between(base, base * turn(-angle, axis)), angle, tolerance(angle));
    }
  }
}

// Two turns about one axis differ by the difference of their angles, taken the short way round
// (a relative turn by 2π − θ is a turn by θ the other way).
TEST(RotationAngleBetween, TurnsAboutOneAxisDifferByTheDifferenceOfTheirAngles) {
  for (const auto& [alpha, beta] : {std::pair{0.3, 1.1},
                                    {-1.2, 0.9},
                                    {2.9, -2.9},
                                    {0.5, 0.5 + 1e-9},
                                    {3.1, -1.0},
                                    {6.0, 0.2}}) {
    double expected = std::fmod(std::abs(alpha - beta), 2 * kPi);
    if (expected > kPi) expected = 2 * kPi - expected;
    EXPECT_NEAR(rotation_angle_between(turn(alpha, kAxisA), turn(beta, kAxisA)), expected,
                tolerance(expected))
        << alpha << ", " << beta;
  }
  // Composed turns about two axes: a = Ra(α), b = Ra(α)·Rb(β)·Ra(γ)·Ra(−γ) is a turn by |β|
  // relative to a, whatever α and γ.
  const Eigen::Matrix3d a = turn(0.8, kAxisA);
  const Eigen::Matrix3d b = a * turn(0.4, kAxisB) * turn(1.7, kAxisA) * turn(-1.7, kAxisA);
  EXPECT_NEAR(rotation_angle_between(a, b), 0.4, 1e-12);
  // Two quarter turns about perpendicular axes x then y make a turn by 2π/3 (about (1,1,1)
  // up to sign): cos θ = (tr(RyRx) − 1)/2 = (0 − 1)/2.
  const Eigen::Matrix3d xy =
      turn(kPi / 2, Eigen::Vector3d::UnitY()) * turn(kPi / 2, Eigen::Vector3d::UnitX());
  EXPECT_NEAR(rotation_angle_between(Eigen::Matrix3d::Identity(), xy), 2 * kPi / 3, 1e-12);
}

/// The book spun about z (its largest axis, a steady spin: ω stays (0, 0, ω), L along z), no
/// jiggle, `steps` steps of dt with one step per frame, by `kind` with Euler and normalization.
scene::Scene steady_z_spin(const std::string& kind, double omega, double dt, int steps) {
  return scene::parse_scene_text(
      "[model]\nkind = \"" + kind +
          "\"\nintegrator = \"euler\"\nnormalize = true\n[initial]\nangular_velocity = [0, 0, " +
          std::to_string(omega) + "]\njiggle = 0\n[time]\ndt = " + std::to_string(dt) +
          "\nsteps_per_frame = 1\nframes = " + std::to_string(steps + 1) + "\n",
      "steady.toml");
}

// With ω = ω e_z constant, one Euler step of the matrix, R ← (I + h[e_z]×) R with h = ω dt,
// followed by the polar factor, turns the book by atan(h) about z (I + h[e_z]× is √(1 + h²)
// times a turn by atan h in the xy plane); one Euler step of the quaternion,
// q ← q ⊗ (1, ½h e_z), normalized, turns it by 2·atan(h/2) (docs/physics.md §3–4). The exact
// motion turns by h per step, so after N steps the model lags the exact motion by a turn about
// z of N(h − atan h), or N(h − 2 atan(h/2)).
TEST(OrientationErrorMeasure, EulerStepsOfASteadySpinLagByTheClosedFormAngle) {
  struct Case {
    const char* kind;
    double omega, dt;
    int steps;
    double lag_per_step;
  };
  const Case cases[] = {
      {"rigid-matrix", 1.0, 0.1, 1000, 0.1 - std::atan(0.1)},           // 0.332 rad
      {"rigid-matrix", 0.5, 0.25, 1200, 0.125 - std::atan(0.125)},      // 0.77 rad
      {"rigid-quaternion", 1.0, 0.1, 3000, 0.1 - 2 * std::atan(0.05)},  // 0.25 rad
      {"rigid-quaternion", 2.0, 0.1, 1000, 0.2 - 2 * std::atan(0.1)},   // 0.66 rad
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.kind) + " h = " + std::to_string(c.omega * c.dt));
    const double lag = c.steps * c.lag_per_step;
    ASSERT_GT(lag, 0.2);
    ASSERT_LT(lag, 3.0);
    const RunMeasures m = measure_run(steady_z_spin(c.kind, c.omega, c.dt, c.steps));
    ASSERT_TRUE(m.orientation_error);
    EXPECT_NEAR(*m.orientation_error, lag, 1e-9 * c.steps);
    EXPECT_FALSE(m.diverged_at);
    // The accuracy table's orientation error at the same time is the same angle.
    const scene::Scene s = steady_z_spin(c.kind, c.omega, c.dt, c.steps);
    const AccuracySettings settings{s.body, s.initial, s.model, 1.0};
    const Method method{s.model.kind, s.model.integrator};
    EXPECT_NEAR(
        orientation_error_at(settings, exact_reference(settings), method, c.dt, c.steps * c.dt),
        lag, 1e-9 * c.steps);
  }
}

// The exact model has no lag at all: the measure is round-off, not some offset.
TEST(OrientationErrorMeasure, TheExactModelAgainstItselfIsZero) {
  const RunMeasures m = measure_run(steady_z_spin("exact", 1.0, 0.1, 1000));
  ASSERT_TRUE(m.orientation_error);
  EXPECT_LT(*m.orientation_error, 1e-12);
}

}  // namespace
}  // namespace bookspin::analysis
