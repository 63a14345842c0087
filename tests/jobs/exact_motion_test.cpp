// A scenario's exact motion at every step (jobs::exact_motion, docs/flipcheck.md "export"):
// checked against what any torque-free motion must do, not against physics::ExactRotation
// itself: it starts at q = 1 with the jiggled ω0 = I⁻¹(I ω + δL) (physics::jiggle_delta_L);
// L in the world and E stay their start values; ω_world = R(q) ω_body; and q follows its own
// kinematics, q̇ = ½ q ⊗ (0, ω_body), to the central difference's O(dt²).
#include "jobs/exact_motion.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "analysis/conformance.hpp"
#include "common/errors.hpp"
#include "scene/scene.hpp"
#include "support/exact_motion_property.hpp"

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

namespace bookspin::jobs {
namespace {

// The door's property over the whole input space (docs/physics.md §8, "How far in time"):
// exact_motion_at gives finite rows for every seeded draw of tests/support/
// exact_motion_property.hpp, or an InputError naming the true cause, judged here apart from the
// code: a bad argument names it, an energy or |L| beyond a double (summed here in long double)
// says "overflows", and a t past the horizon names that t and the horizon, never the energy.
TEST(ExactMotionDoor, AnyMomentsOmegaAndTimesGiveFiniteRowsOrTheTrueRefusal) {
  std::mt19937_64 rng(1082);
  std::uniform_int_distribution<int> spoil(0, 19);
  int refused = 0, given = 0;
  for (int n = 0; n < 6000; ++n) {
    test_support::ExactInput in = test_support::draw_exact_input(rng);
    const int bad = spoil(rng);  // a few bad arguments among the good
    if (bad == 0) in.moments[n % 3] = n % 2 ? -1.0 : std::nan("");
    if (bad == 1) in.omega0[n % 3] = n % 2 ? 2e6 : -3e7;
    if (bad == 2) in.t.push_back(n % 2 ? INFINITY : std::nan(""));
    const test_support::LongInvariants inv = test_support::long_invariants(in.moments, in.omega0);
    const bool overflow = inv.E > 1.7976931348623157e308L || inv.L > 1.7976931348623157e308L;
    try {
      const std::vector<ExactMotionRow> rows = exact_motion_at(in.moments, in.omega0, in.t);
      ASSERT_GT(bad, 2) << "a bad argument accepted: " << test_support::describe(in);
      ASSERT_FALSE(overflow) << test_support::describe(in);
      for (const ExactMotionRow& r : rows)
        ASSERT_TRUE(r.q.allFinite() && r.omega_body.allFinite() && r.L.allFinite() &&
                    std::isfinite(r.E))
            << test_support::describe(in);
      ++given;
    } catch (const InputError& e) {
      const std::string what = e.what();
      SCOPED_TRACE(what + " for " + test_support::describe(in));
      ++refused;
      if (bad == 0) {
        EXPECT_EQ(what.rfind("moments[", 0), 0u);
      } else if (bad == 1) {
        EXPECT_TRUE(what.rfind("omega0[", 0) == 0 || what.rfind("moments[", 0) == 0);
      } else if (what.find("not a finite time") != std::string::npos) {
        // A t spoilt here, or drawn about the horizon of a motion slower than 1e-300.
        ASSERT_EQ(what.rfind("t[", 0), 0u);
        const std::size_t index = std::stoul(what.substr(2));
        ASSERT_LT(index, in.t.size());
        EXPECT_FALSE(std::isfinite(in.t[index]));
      } else if (what.find("overflows a double") != std::string::npos) {
        EXPECT_TRUE(overflow || inv.E > 1.79e308L || inv.L > 1.79e308L ||
                    test_support::peak_rate_bounds(in.moments, in.omega0, inv).upper > 1.79e308L);
      } else {
        // Past the horizon: the t named is one given, its angle bound |t| |L|/I_min past 2^40.
        ASSERT_EQ(what.rfind("t[", 0), 0u);
        EXPECT_NE(what.find("beyond the exact motion's time horizon"), std::string::npos);
        EXPECT_EQ(what.find("energy"), std::string::npos);
        const std::size_t index = std::stoul(what.substr(2));
        ASSERT_LT(index, in.t.size());
        EXPECT_GE(std::abs(in.t[index]) * inv.L / in.moments.minCoeff(),
                  physics::kExactMaxAngle * (1 - 1e-9L));
      }
    }
  }
  EXPECT_GT(refused, 1000);
  EXPECT_GT(given, 2000);
}

// The inputs of the crash (a SIGSEGV in Python) and of the false "energy overflows": the
// horizon's reason, naming t[1].
TEST(ExactMotionDoor, ATimeOf1e300IsRefusedForTheHorizonNotTheEnergy) {
  for (const Eigen::Vector3d& moments : {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(3, 1, 2)}) {
    try {
      (void)exact_motion_at(moments, Eigen::Vector3d(0.1, 1, 0.05), {0.0, 1e300});
      ADD_FAILURE() << "t = 1e300 evaluated";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("t[1]: t = 1e+300 is beyond the exact motion's time horizon, |t| ≤ ", 0),
                0u)
          << what;
      EXPECT_EQ(what.find("energy"), std::string::npos) << what;
    }
  }
}

// A body whose moments lie 1e320 apart, E 5e301 and |L| 1e302: ω about the smallest axis would
// reach √(I2(I3 − I2)ω2²/(I1 I3)) ~ 4.5e312 (docs/physics.md §8's amplitude), beyond a double.
// Refused before any row, naming the moments, not evaluated into infinite rows.
TEST(ExactMotionDoor, AnAngularVelocityThatWouldPassADoubleIsRefused) {
  try {
    (void)exact_motion_at(Eigen::Vector3d(5e-324, 1e290, 1e296), Eigen::Vector3d(0, 1e6, 1),
                          {0.0, 1e-310});
    ADD_FAILURE() << "evaluated";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "moments (5e-324, 1e+290, 1e+296) and omega0 (0, 1e+06, 1): the motion's energy "
                 "½ ω·Iω, |L| or largest |ω| overflows a double (beyond 1.8e308)");
  }
}

// A scenario whose dt takes its last step past the horizon (the npm package's exactMotion with
// dt = 1e100 returned 3001 rows of NaN): refused, naming the scenario and dt × steps.
TEST(ExactMotionDoor, AScenarioPastTheHorizonIsRefusedNamingDtAndSteps) {
  analysis::Scenario s = scenario("mujoco-test-box");
  s.dt = 1e100;
  try {
    (void)exact_motion(s);
    ADD_FAILURE() << "evaluated";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(s.name + ": dt × steps: t = ", 0), 0u) << what;
    EXPECT_NE(what.find("time horizon"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace bookspin::jobs
