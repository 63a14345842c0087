// The rigid models under drag (docs/physics.md §21): every integrator converges to the damped
// exact motion at the order the Strang splitting allows; the particle model refuses drag.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/damped_exact.hpp"
#include "physics/exact_model.hpp"
#include "physics/simulator.hpp"

namespace bookspin::physics {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

/// A body with moments (2, 1, 3) (the book's cage for its corners; the rigid and exact models
/// use only the moments).
Body box_body(double, const Vector3d& moments) {
  Body body = book_body(Book{});
  body.moments = moments;
  return body;
}

/// The orientation error of `config` against the damped exact motion after time `span` in
/// steps of `dt`, for a body (2, 1, 3) spun off its intermediate axis.
double error_after(ModelConfig config, double dt, double span) {
  const Body body = box_body(1.0, Vector3d(2.0, 1.0, 3.0));
  InitialState initial;
  initial.omega0_body = Vector3d(0.3, 1.0, 0.2);
  auto model = make_simulator(body, config);
  model->reset(initial);
  const long steps = std::lround(span / dt);
  for (long i = 0; i < steps; ++i) model->step(dt);
  const DampedExactRotation exact(body.moments, initial.omega0_body, config.drag);
  const double t = static_cast<double>(steps) * dt;
  // ω as a check too: L_world and R give it.
  const Vector3d L = model->diagnostics().L;
  EXPECT_NEAR(L.norm(), exact.angular_momentum_world(t).norm(),
              1e-2 * exact.angular_momentum_world(0).norm());
  return (model->orientation() - exact.orientation(t)).norm();
}

// Halving dt divides the error by 2^p: p ≈ 1 for Euler, ≈ 2 for every second- and higher-order
// integrator (the splitting limits them); both laws, both rigid models.
TEST(Drag, RigidModelsConvergeToTheDampedExactMotion) {
  struct Case {
    ModelKind kind;
    Integrator integrator;
    double order;
  };
  const Case cases[] = {
      {ModelKind::rigid_quaternion, Integrator::euler, 1.0},
      {ModelKind::rigid_matrix, Integrator::rk4, 2.0},
      {ModelKind::rigid_quaternion, Integrator::rk4, 2.0},
      {ModelKind::rigid_quaternion, Integrator::implicit_midpoint, 2.0},
      {ModelKind::rigid_quaternion, Integrator::splitting, 2.0},
      {ModelKind::rigid_matrix, Integrator::splitting4, 2.0},
      {ModelKind::rigid_quaternion, Integrator::rescaled_euler, 1.0},
  };
  for (DragLaw law : {DragLaw::linear, DragLaw::quadratic}) {
    for (const Case& c : cases) {
      ModelConfig config;
      config.kind = c.kind;
      config.integrator = c.integrator;
      config.normalize = true;
      config.drag = Drag{law, 0.3};
      const double dt = c.order == 1.0 ? 2e-3 : 2e-2;
      const double coarse = error_after(config, dt, 6.0), fine = error_after(config, dt / 2, 6.0);
      const double measured = std::log2(coarse / fine);
      EXPECT_NEAR(measured, c.order, 0.25)
          << to_string(c.kind) << " " << to_string(c.integrator) << " " << to_string(law)
          << ": errors " << coarse << ", " << fine;
      EXPECT_LT(fine, 0.05) << to_string(c.integrator);
    }
  }
}

// Without drag the rigid models are unchanged bit for bit (a zero rate takes the same path).
TEST(Drag, AZeroRateChangesNoBit) {
  ModelConfig plain;
  plain.kind = ModelKind::rigid_quaternion;
  plain.integrator = Integrator::splitting;
  ModelConfig zero = plain;
  zero.drag = Drag{DragLaw::linear, 0.0};
  const Body body = box_body(1.0, Vector3d(2.0, 1.0, 3.0));
  auto a = make_simulator(body, plain), b = make_simulator(body, zero);
  a->reset({});
  b->reset({});
  for (int i = 0; i < 100; ++i) a->step(0.01), b->step(0.01);
  const Matrix3d Ra = a->orientation(), Rb = b->orientation();
  for (int i = 0; i < 9; ++i) EXPECT_EQ(Ra.data()[i], Rb.data()[i]);
}

// The exact model under drag is the damped closed form; the particle model refuses drag.
TEST(Drag, ExactModelIsTheDampedClosedFormAndTheParticleModelRefusesDrag) {
  ModelConfig config;
  config.kind = ModelKind::exact;
  config.drag = Drag{DragLaw::quadratic, 0.5};
  const Body body = box_body(1.0, Vector3d(2.0, 1.0, 3.0));
  auto model = make_simulator(body, config);
  InitialState initial;
  initial.omega0_body = Vector3d(0.3, 1.0, 0.2);
  model->reset(initial);
  for (int i = 0; i < 300; ++i) model->step(0.01);
  const DampedExactRotation exact(body.moments, initial.omega0_body, config.drag);
  const Diagnostics d = model->diagnostics();
  EXPECT_LE((d.omega_body - exact.omega_body(3.0)).norm(), 1e-12);
  EXPECT_LE((model->orientation() - exact.orientation(3.0)).norm(), 1e-12);
  EXPECT_NEAR(d.energy_kinetic, exact.energy(3.0), 1e-12);
  EXPECT_NEAR(d.L.norm(), body.moments.cwiseProduct(initial.omega0_body).norm() / 2.5, 1e-12);
  config.kind = ModelKind::particle;
  EXPECT_THROW(make_simulator(book_body(Book{}), config), std::invalid_argument);
}

}  // namespace
}  // namespace bookspin::physics
