// One step of the games' gyroscopic step (docs/physics.md §10.7) against the step worked by
// hand: Π' = Π − dt ω × Π with ω = I⁻¹Π, Π'' = Π'·|Π|/|Π'|, the body turned by exp(dt I⁻¹Π'').
#include <gtest/gtest.h>

#include <cmath>

#include "physics/rigid_integrators.hpp"

namespace bookspin::physics {
namespace {

// I = (1, 2, 4), Π = (1, 2, 3), dt = 0.1: ω = (1, 1, 0.75), ω × Π = (1.5, −2.25, 1),
// Π' = (0.85, 2.225, 2.9), |Π|² = 14, |Π'|² = 14.083125 (= 14 + dt²|ω × Π|² = 14 + 0.083125).
TEST(RescaledEulerStep, IsTheExplicitEulerMomentumRescaledThenTheTurnAboutItsNewOmega) {
  const Eigen::Vector3d Pi(1.0, 2.0, 3.0), inverse_moments(1.0, 0.5, 0.25);
  const double dt = 0.1;
  const RescaledEulerStep step = rescaled_euler_step(Pi, inverse_moments, dt);
  const double scale = std::sqrt(14.0 / 14.083125);
  const Eigen::Vector3d Pi2 = scale * Eigen::Vector3d(0.85, 2.225, 2.9);
  EXPECT_LE((step.Pi_body - Pi2).norm(), 1e-15 * 4.0);
  EXPECT_NEAR(step.Pi_body.norm(), std::sqrt(14.0), 1e-14);
  // The turn: dt ω'' = dt (0.85, 1.1125, 0.725)·scale, as an angle and an axis.
  const Eigen::Vector3d turn = dt * scale * Eigen::Vector3d(0.85, 1.1125, 0.725);
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(turn.norm(), turn.normalized()));
  EXPECT_LE(step.increment.angularDistance(expected), 1e-14);
}

}  // namespace
}  // namespace bookspin::physics
