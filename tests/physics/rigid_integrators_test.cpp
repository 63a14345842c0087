// The rigid models' implicit midpoint step (docs/physics.md §10): it solves its equation or
// ends the run with a reason, never silently.
#include "physics/rigid_integrators.hpp"

#include <gtest/gtest.h>

#include "model_helpers.hpp"

namespace bookspin::physics {
namespace {

using namespace bookspin::physics::testing;  // model_helpers.hpp

using Eigen::Vector3d;
using physics::Integrator;
using physics::ModelKind;

// The rescaled Euler step (docs/physics.md §10.7): Π' along Π − dt ω × Π (ω = I⁻¹Π) with
// |Π'| = |Π|, and the body turned about the updated ω' = I⁻¹Π' by |ω'| dt, as Jolt turns it
// (not about the ω before the step, which differs by O(dt) in direction).
TEST(RescaledEuler, TurnsTheBodyWithTheUpdatedMomentum) {
  const Vector3d inverse = original_book().principal_moments().cwiseInverse();
  const Vector3d Pi(0.66, 0.05, -0.03);
  for (double dt : {1.0 / 60.0, 0.5}) {
    const physics::RescaledEulerStep step = physics::rescaled_euler_step(Pi, inverse, dt);
    const Vector3d explicit_euler = Pi - dt * inverse.cwiseProduct(Pi).cross(Pi);
    EXPECT_NEAR(step.Pi_body.norm(), Pi.norm(), 1e-14) << "dt " << dt;
    EXPECT_LT(step.Pi_body.normalized().cross(explicit_euler.normalized()).norm(), 1e-14);
    const Vector3d omega_after = inverse.cwiseProduct(step.Pi_body);
    const Eigen::AngleAxisd turn(step.increment);
    EXPECT_NEAR(turn.angle(), omega_after.norm() * dt, 1e-13) << "dt " << dt;
    EXPECT_LT((turn.axis() - omega_after.normalized()).norm(), 1e-12) << "dt " << dt;
  }
}

// A converged step solves Π_mid = Π_n + (dt/2) Π_mid × I⁻¹Π_mid: recover ω_mid from the
// Cayley quaternion (1, dt ω_mid/2)/|·| and check the residual.
TEST(ImplicitMidpoint, ConvergedIncrementSolvesTheMidpointEquation) {
  const Vector3d inverse = original_book().principal_moments().cwiseInverse();
  const Vector3d Pi(0.66, 0.05, -0.03);
  for (double dt : {1.0 / 60.0, 0.5, 2.0}) {
    const auto delta = physics::implicit_midpoint_increment(Pi, inverse, dt);
    ASSERT_TRUE(delta.has_value()) << "dt " << dt;
    const Vector3d omega_mid = 2.0 * delta->vec() / (delta->w() * dt);
    const Vector3d Pi_mid = omega_mid.cwiseQuotient(inverse);
    const Vector3d residual = Pi_mid - Pi - 0.5 * dt * Pi_mid.cross(omega_mid);
    EXPECT_LT(residual.norm(), 1e-14 * Pi.norm()) << "dt " << dt;
  }
}

// Far beyond the iteration's contraction range it returns no increment.
TEST(ImplicitMidpoint, IncrementIsEmptyWhenTheIterationCannotConverge) {
  const Vector3d inverse = original_book().principal_moments().cwiseInverse();
  EXPECT_FALSE(physics::implicit_midpoint_increment(Vector3d(20.0, 8.0, 5.0), inverse, 2.0));
}

// In the models a non-converged step ends the run: finite() turns false, the state is the
// last good one, and divergence_reason() says what happened. At the paper's dt it converges.
TEST(ImplicitMidpoint, ModelsReportNonConvergenceAsADivergedRun) {
  for (ModelKind kind : {ModelKind::rigid_matrix, ModelKind::rigid_quaternion}) {
    physics::ModelConfig c = config(kind, true);
    c.integrator = Integrator::implicit_midpoint;
    auto sim = physics::make_simulator(original_book(), c);
    sim->reset({Vector3d(0.114819, 0.0, 0.0), 1e-3, 3});
    EXPECT_TRUE(run(*sim, 1.0 / 60.0, 20000, 20000, [](const physics::Simulator&) {}));
    EXPECT_EQ(sim->divergence_reason(), "");

    sim->reset({Vector3d(3.0, 1.0, 0.5), 0.0, 3});
    sim->step(0.01);
    ASSERT_TRUE(sim->finite());
    const physics::Corners before = sim->corners();
    sim->step(5.0);
    EXPECT_FALSE(sim->finite()) << physics::to_string(kind);
    EXPECT_NE(sim->divergence_reason().find("did not converge"), std::string::npos)
        << sim->divergence_reason();
    EXPECT_EQ(sim->corners(), before);
    sim->step(0.01);  // the run stays ended
    EXPECT_FALSE(sim->finite());
  }
}

}  // namespace
}  // namespace bookspin::physics
