// The three models describe the same book (docs/physics.md §2–4).
#include <gtest/gtest.h>

#include "model_helpers.hpp"

namespace bookspin::physics {
namespace {

using namespace bookspin::physics::testing;  // model_helpers.hpp

using physics::ModelKind;

// Time of the first flip: when cos(x, L) first drops below −0.9.
double first_flip_time(physics::Simulator& sim, double dt) {
  double t = 0.0;
  while (sim.diagnostics().cos_axis_L[0] > -0.9 && t < 2000.0) {
    sim.step(dt);
    t += dt;
  }
  return t;
}

// A stiff mass-spring book (k large, dt small) is nearly rigid: its corners follow the
// rigid body's over the whole first flip, within 1% of the book's size.
TEST(ModelAgreement, StiffParticleFollowsRigidBodyOverFirstFlip) {
  const physics::InitialState initial{original_omega0(0), 1e-2, 11};
  const double dt = 1e-3;
  auto rigid = physics::make_simulator(original_book(), config(ModelKind::rigid_quaternion, true));
  rigid->reset(initial);
  const double flip = first_flip_time(*rigid, dt);
  ASSERT_LT(flip, 2000.0);
  rigid->reset(initial);
  auto particle =
      physics::make_simulator(original_book(), config(ModelKind::particle, true, true, 1e4));
  particle->reset(initial);
  const double size = original_book().size.norm();
  double worst = 0.0;
  const long steps = static_cast<long>(1.2 * flip / dt);
  for (long s = 1; s <= steps; ++s) {
    rigid->step(dt);
    particle->step(dt);
    if (s % 100 == 0) {
      const double gap = (rigid->corners() - particle->corners()).colwise().norm().maxCoeff();
      worst = std::max(worst, gap / size);
    }
  }
  EXPECT_LT(worst, 0.01) << "first flip at t = " << flip;
}

// Matrix and quaternion Euler steps both turn R about the same ω; their angles differ only
// at O(dt³), so with normalization and a small dt they agree closely.
TEST(ModelAgreement, NormalizedMatrixAndQuaternionAgree) {
  const physics::InitialState initial{original_omega0(0), 1e-2, 5};
  auto matrix = physics::make_simulator(original_book(), config(ModelKind::rigid_matrix, true));
  auto quaternion =
      physics::make_simulator(original_book(), config(ModelKind::rigid_quaternion, true));
  matrix->reset(initial);
  quaternion->reset(initial);
  const double dt = 1e-4;
  double worst = 0.0;
  for (long s = 1; s <= 500000; ++s) {  // 50 time units, most of a revolution
    matrix->step(dt);
    quaternion->step(dt);
    if (s % 1000 == 0)
      worst = std::max(worst, (matrix->corners() - quaternion->corners()).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace bookspin::physics
