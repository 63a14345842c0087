// The hand-optimized Euler steps against the textbook formulas they replace.
#include <gtest/gtest.h>

#include "model_helpers.hpp"
#include "physics/particle_model.hpp"
#include "physics/rigid_quaternion_model.hpp"
#include "physics/shape.hpp"

namespace bookspin::physics {
namespace {

using namespace bookspin::physics::testing;  // model_helpers.hpp

using physics::Corners;

// Paper §3.3, spring by spring with unit vectors, as the model computed it before.
Corners reference_forces(const Corners& x, const Corners& v, const Corners& rest, double k,
                         double damping) {
  Corners f = Corners::Zero();
  for (const auto& [i, j] : physics::corner_pairs()) {
    const Eigen::Vector3d d = x.col(i) - x.col(j);
    const Eigen::Vector3d unit = d / d.norm();
    const double stretch = d.norm() - (rest.col(i) - rest.col(j)).norm();
    const double magnitude = damping * unit.dot(v.col(i) - v.col(j)) + k * stretch;
    f.col(i) -= magnitude * unit;
    f.col(j) += magnitude * unit;
  }
  return f;
}

TEST(FastSteps, ParticleEulerFollowsThePaperFormulaToRoundOff) {
  const physics::Book book = original_book();
  const physics::ModelConfig cfg = config(physics::ModelKind::particle, false, true, 10.0);
  const physics::InitialState initial{original_omega0(0), 0.05, 3};
  physics::ParticleModel model(book, cfg);
  model.reset(initial);
  Corners x = model.corners(), v = model.velocities();
  const double m = book.mass / 8.0, damping = 2.0 * std::sqrt(cfg.spring_constant * m),
               dt = 1.0 / 60;
  for (int step = 0; step < 2000; ++step) {
    const Corners f = reference_forces(x, v, book.body_corners(), cfg.spring_constant, damping);
    x += dt * v;
    v += (dt / m) * f;
    model.step(dt);
  }
  EXPECT_LT((model.corners() - x).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_LT((model.velocities() - v).cwiseAbs().maxCoeff(), 1e-11);
}

/// The Euler step of the paper in Eigen expressions, as the model wrote it before.
Eigen::Quaterniond reference_quaternion_step(const Eigen::Quaterniond& q, const Eigen::Vector3d& L,
                                             const Eigen::Vector3d& inverse_moments, double dt,
                                             bool normalize) {
  const Eigen::Matrix3d R = q.toRotationMatrix();
  const Eigen::Vector3d omega = R * (inverse_moments.asDiagonal() * (R.transpose() * L));
  const Eigen::Quaterniond omega_q(0.0, omega.x(), omega.y(), omega.z());
  Eigen::Quaterniond next = q;
  next.coeffs() += dt * (0.5 * (omega_q * q).coeffs());
  if (normalize) next.normalize();
  return next;
}

struct QuaternionCase {
  physics::Book book = original_book();
  physics::InitialState initial{original_omega0(0), 1e-3, 2012};
  Eigen::Vector3d L = physics::initial_angular_momentum(book, initial);
  Eigen::Vector3d inverse_moments = book.principal_moments().cwiseInverse();
  double dt = 1.0 / 60;
};

// Unnormalized, the scalar step repeats Eigen's operations in Eigen's order: equal bits.
TEST(FastSteps, UnnormalizedQuaternionEulerIsBitForBitTheEigenExpression) {
  const QuaternionCase c;
  physics::RigidQuaternionModel model(c.book, config(physics::ModelKind::rigid_quaternion, false));
  model.reset(c.initial);
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (int step = 0; step < 5000; ++step) {
    q = reference_quaternion_step(q, c.L, c.inverse_moments, c.dt, false);
    model.step(c.dt);
  }
  EXPECT_EQ(model.quaternion().coeffs(), q.coeffs());
}

// Normalized, it takes the body-frame form, the same step for a unit quaternion: every
// step agrees with the Eigen expression to round-off.
TEST(FastSteps, NormalizedQuaternionEulerIsTheEigenExpressionToRoundOff) {
  const QuaternionCase c;
  physics::RigidQuaternionModel model(c.book, config(physics::ModelKind::rigid_quaternion, true));
  model.reset(c.initial);
  double worst = 0.0;
  for (int step = 0; step < 20000; ++step) {
    const Eigen::Quaterniond expected =
        reference_quaternion_step(model.quaternion(), c.L, c.inverse_moments, c.dt, true);
    model.step(c.dt);
    worst =
        std::max(worst, (model.quaternion().coeffs() - expected.coeffs()).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-15);
}

}  // namespace
}  // namespace bookspin::physics
