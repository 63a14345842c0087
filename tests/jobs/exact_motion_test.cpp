// A scenario's exact motion at every step (jobs::exact_motion, docs/flipcheck.md "export"):
// checked against what any torque-free motion must do, not against physics::ExactRotation
// itself: it starts at q = 1 with the jiggled ω0 = I⁻¹(I ω + δL) (physics::jiggle_delta_L);
// L in the world and E stay their start values; ω_world = R(q) ω_body; and q follows its own
// kinematics, q̇ = ½ q ⊗ (0, ω_body), to the central difference's O(dt²).
#include "jobs/exact_motion.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "analysis/conformance.hpp"
#include "common/errors.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {
namespace {

analysis::Scenario scenario(const std::string& name) {
  return analysis::scenario_of(
      scene::parse_scene(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/flipcheck/" + name + ".toml"));
}

Eigen::Quaterniond quaternion(const Eigen::Vector4d& wxyz) {
  return Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
}

TEST(ExactMotion, StartsWhereTheScenarioSaysAndKeepsLAndE) {
  for (const char* name : {"mujoco-test-box", "book-intermediate-0.2"}) {
    SCOPED_TRACE(name);
    const analysis::Scenario s = scenario(name);
    const ExactMotion m = exact_motion(s);
    ASSERT_EQ(m.rows.size(), static_cast<std::size_t>(s.steps) + 1);
    const Eigen::Vector3d& I = s.body.moments;
    const Eigen::Vector3d omega0 = (I.cwiseProduct(s.initial.omega0_body) +
                                    physics::jiggle_delta_L(s.initial.seed, s.initial.jiggle))
                                       .cwiseQuotient(I);
    EXPECT_TRUE(m.omega0_body.isApprox(omega0, 1e-15));
    EXPECT_EQ(m.omega0_world, m.omega0_body);
    EXPECT_EQ(m.mass, s.body.cage.mass);
    EXPECT_LT((m.rows[0].q - Eigen::Vector4d(1, 0, 0, 0)).norm(), 1e-15);  // R(0) = I
    EXPECT_TRUE(m.rows[0].omega_body.isApprox(omega0, 1e-14));
    const Eigen::Vector3d L0 = I.cwiseProduct(omega0);
    const double E0 = 0.5 * omega0.dot(L0);
    for (std::size_t n = 0; n < m.rows.size(); ++n) {
      const ExactMotionRow& r = m.rows[n];
      ASSERT_EQ(r.t, static_cast<double>(n) * s.dt);
      ASSERT_NEAR(r.q.norm(), 1.0, 1e-15);
      ASSERT_GE(r.q[0], 0.0);
      const Eigen::Matrix3d R = quaternion(r.q).toRotationMatrix();
      ASSERT_TRUE(r.L.isApprox(L0, 1e-12)) << n;
      ASSERT_TRUE((R * I.cwiseProduct(r.omega_body)).isApprox(L0, 1e-12)) << n;
      ASSERT_TRUE(r.omega_world.isApprox(R * r.omega_body, 1e-14)) << n;
      ASSERT_NEAR(r.E / E0, 1.0, 1e-13) << n;
    }
  }
}

TEST(ExactMotion, TheQuaternionFollowsTheAngularVelocity) {
  const analysis::Scenario s = scenario("mujoco-test-box");
  const ExactMotion m = exact_motion(s);
  double worst = 0.0;
  for (std::size_t n = 1; n + 1 < m.rows.size(); ++n) {
    Eigen::Quaterniond before = quaternion(m.rows[n - 1].q), now = quaternion(m.rows[n].q),
                       after = quaternion(m.rows[n + 1].q);
    if (before.dot(now) < 0) before.coeffs() *= -1;  // w ≥ 0 may change the sign between rows
    if (after.dot(now) < 0) after.coeffs() *= -1;
    const Eigen::Vector4d rate = (after.coeffs() - before.coeffs()) / (2 * s.dt);
    const Eigen::Vector3d& w = m.rows[n].omega_body;
    const Eigen::Vector4d expected =
        0.5 * (now * Eigen::Quaterniond(0, w.x(), w.y(), w.z())).coeffs();
    worst = std::max(worst, (rate - expected).norm() / expected.norm());
  }
  // (ω dt)²/6 for |ω| ≈ 3.8, dt = 0.01: 2.4e-4.
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT(worst, 1e-6);  // the difference's own error: the test sees the motion, not noise
}

// The exact motion at given times (the Python module's exact_motion) is the scenario's rows at
// those times, bit for bit, in any order; bad numbers are named by their argument and index.
TEST(ExactMotion, AtGivenTimesAreTheScenariosRowsAtThem) {
  const analysis::Scenario s = scenario("book-intermediate-0.2");
  const ExactMotion m = exact_motion(s);
  const std::vector<std::size_t> picked = {500, 0, 3, 749};
  std::vector<double> times;
  for (std::size_t n : picked) times.push_back(m.rows[n].t);
  const std::vector<ExactMotionRow> rows = exact_motion_at(s.body.moments, m.omega0_body, times);
  ASSERT_EQ(rows.size(), picked.size());
  for (std::size_t i = 0; i < picked.size(); ++i) {
    const ExactMotionRow& want = m.rows[picked[i]];
    EXPECT_EQ(rows[i].t, want.t);
    EXPECT_EQ(rows[i].q, want.q);
    EXPECT_EQ(rows[i].omega_body, want.omega_body);
    EXPECT_EQ(rows[i].omega_world, want.omega_world);
    EXPECT_EQ(rows[i].L, want.L);
    EXPECT_EQ(rows[i].E, want.E);
  }
  const auto error_of = [](const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0,
                           const std::vector<double>& t) {
    try {
      exact_motion_at(moments, omega0, t);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const Eigen::Vector3d I(1, 2, 3), w(0, 1, 0);
  EXPECT_EQ(error_of({1, 0, 3}, w, {0.0}),
            "moments[1]: 0 is not a finite positive moment of inertia");
  EXPECT_EQ(error_of(I, {0, INFINITY, 0}, {0.0}),
            "omega0[1]: inf is not a finite angular velocity");
  EXPECT_EQ(error_of(I, w, {0.0, NAN}), "t[1]: nan is not a finite time");
  EXPECT_TRUE(exact_motion_at(I, w, {}).empty());
}

}  // namespace
}  // namespace bookspin::jobs
