// The exact motion over its whole input space (docs/physics.md §8, "How far in time"): finite
// states or a refusal for the true cause (tests/support/exact_motion_property.hpp), on seeded
// inputs; tests/fuzz/exact_fuzzer.cpp runs the same property under libFuzzer in CI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "physics/book.hpp"
#include "physics/exact_model.hpp"
#include "physics/exact_solution.hpp"
#include "support/exact_motion_property.hpp"

namespace bookspin::physics {
namespace {

using test_support::check_exact_property;
using test_support::ExactInput;

TEST(ExactHorizon, SeededInputsAcrossTheWholeRangeGiveFiniteStatesOrTheTrueRefusal) {
  std::mt19937_64 rng(82);
  int refused_by_horizon = 0, evaluated = 0;
  for (int n = 0; n < 20000; ++n) {
    const ExactInput in = test_support::draw_exact_input(rng);
    const std::string broken = check_exact_property(in);
    ASSERT_TRUE(broken.empty()) << "input " << n << ": " << broken;
    const ExactRotation exact(in.moments, in.omega0);
    for (double t : in.t) (std::abs(t) > exact.time_horizon() ? refused_by_horizon : evaluated)++;
  }
  // Both branches taken often (the draw reaches the horizon and stays within it).
  EXPECT_GT(refused_by_horizon, 2000);
  EXPECT_GT(evaluated, 10000);
}

// The input that crashed the Python process (a SIGSEGV from the table of base points, where the
// phase at t = 1e300 indexed it out of range) and, with the other moments, was refused as an
// energy overflow: the horizon's reason, and finite states up to the horizon.
TEST(ExactHorizon, TimesPastTheHorizonAreRefusedForThePhaseNotTheEnergy) {
  for (const Eigen::Vector3d& moments : {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(2, 1, 3)}) {
    const ExactRotation exact(moments, Eigen::Vector3d(0.1, 1, 0.05));
    ASSERT_TRUE(std::isfinite(exact.energy()));
    const double horizon = exact.time_horizon();
    EXPECT_GT(horizon, 1e11);
    EXPECT_LT(horizon, 1e13);
    for (double t : {1e300, -1e300, 1e100, 3e103, std::nextafter(horizon, 2 * horizon)}) {
      try {
        (void)exact.state(t);
        ADD_FAILURE() << "evaluated t = " << t;
      } catch (const ExactHorizonError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("beyond the exact motion's time horizon"), std::string::npos) << what;
        EXPECT_EQ(what.find("energy"), std::string::npos) << what;
      }
      EXPECT_THROW((void)exact.omega_body(t), ExactHorizonError);
      EXPECT_THROW((void)exact.orientation(t), ExactHorizonError);
    }
    for (double t : {horizon, -horizon, 0.5 * horizon}) {
      const ExactState s = exact.state(t);
      EXPECT_TRUE(s.q.allFinite() && s.omega_body.allFinite()) << t;
      EXPECT_NEAR(s.E, exact.energy(), 1e-12 * exact.energy());
    }
  }
}

// Found by tests/fuzz/exact_fuzzer.cpp: E = 9e307 is a double, but ω·L summed in doubles
// overflowed before it was halved, and the doors refused the motion as one whose energy
// overflows. Its energy and |L| against their sums in long double.
TEST(ExactHorizon, AnEnergyNearTheTopOfTheRangeIsNoOverflow) {
  const Eigen::Vector3d moments(1.949208239922177e-95, 7.1980310123944318e-172,
                                2.7292613582081936e+299);
  const Eigen::Vector3d omega0(-50076.180592312754, -4529.8243883423429, -26073.767141273125);
  const ExactRotation exact(moments, omega0);
  const test_support::LongInvariants inv = test_support::long_invariants(moments, omega0);
  EXPECT_NEAR(exact.energy() / static_cast<double>(inv.E), 1.0, 1e-15);
  EXPECT_NEAR(exact.angular_momentum_norm() / static_cast<double>(inv.L), 1.0, 1e-15);
  EXPECT_TRUE(check_exact_property({moments, omega0, {0.0, 1e-3, -2.0}}).empty());
}

// The largest |ω| in closed form: moments (1, 2, 3), ω0 = (0, 1, 1) circles the largest axis, and
// |ω|² = Σ L_i²/I_i² is linear along the segment {Σ L_i² = 13, Σ L_i²/I_i = 2E = 5} that the
// polhode sweeps, so its largest value is at an end: L² = (0, 4, 9) gives 2 (the start), and
// L_2 = 0 gives L² = (1, 0, 12), |ω|² = 1 + 12/9 = 7/3. Sampled over a period, |ω| reaches it.
TEST(ExactHorizon, TheLargestAngularVelocityIsAtAnEndOfThePolhodesSegment) {
  const ExactRotation exact(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 1, 1));
  EXPECT_NEAR(exact.peak_rate(), std::sqrt(7.0 / 3.0), 1e-12);
  double sampled = 0.0;
  for (int n = 0; n <= 4000; ++n)
    sampled = std::max(sampled, exact.omega_body(exact.period() * n / 4000.0).norm());
  EXPECT_NEAR(sampled, std::sqrt(7.0 / 3.0), 1e-6);
  EXPECT_LE(sampled, exact.peak_rate() * (1 + 1e-12));
  // A steady spin's is its |ω0|.
  EXPECT_EQ(ExactRotation(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 0, 2)).peak_rate(), 2.0);
}

// Found by tests/fuzz/exact_fuzzer.cpp: moments 1e318 apart keep E (3e302) and |L| (3e151) in a
// double, but ω about the smallest axis reaches up to |L|/I_min ~ 4e468, and the rows were NaN
// and infinite. The motion now says its largest |ω| is beyond a double, as the doors refuse it.
TEST(ExactHorizon, AnAngularVelocityPastADoubleWithAFiniteEnergyIsReported) {
  const Eigen::Vector3d moments(1, 2, 5.8295003179067016e-318);
  const Eigen::Vector3d omega0(2.5522833063287883e+151, 0.0054715960500556242,
                               -8.98846567431158e+306);
  const ExactRotation exact(moments, omega0);
  EXPECT_TRUE(std::isfinite(exact.energy()));
  EXPECT_TRUE(std::isfinite(exact.angular_momentum_norm()));
  EXPECT_TRUE(std::isinf(exact.peak_rate()));
  EXPECT_TRUE(check_exact_property(
                  {moments, omega0, {0.0, 3.4766779039174528e-310, 2.2250738667962474e-308}})
                  .empty());
}

// Found by tests/fuzz/exact_fuzzer.cpp: two moments 1e-13 apart and L within 1.5e-7 rad of the
// axis ω circles, where the momentum frame's axis L × e_r is set by components of L only ~1e4
// above ω's rounding (sn at 2K near k = 1). Its anchor, formed from ω0 as given rather than as
// state() evaluates ω(0), turned R(0) 9e-6 rad off the identity.
TEST(ExactHorizon, AStartWithLNearlyAlongTheReferenceAxisIsTheIdentity) {
  const Eigen::Vector3d moments(1.279243583355983e-150, 1.2792435833558541e-150,
                                3.5039672497896691e-150);
  const Eigen::Vector3d omega0(0, 3.3721104401498031e-132, 4.9040891223003885e-139);
  const ExactRotation exact(moments, omega0);
  const ExactState s = exact.state(0.0);
  EXPECT_NEAR(s.q[0], 1.0, 1e-15);
  EXPECT_LT(s.q.tail<3>().norm(), 1e-15);
  EXPECT_TRUE(check_exact_property({moments, omega0, {0.0, 0.2994382766334292}}).empty());
}

// A subnormal ω0 (the exact fuzzer's input): rounding there is absolute, a subnormal's last
// place, and ε |ω0| underflows to 0; the property allows the last place (two stableNorm()s of one
// vector differed by it), and the start is still ω0 at the identity component by component.
TEST(ExactHorizon, ASubnormalAngularVelocityStartsAtItselfToItsLastPlace) {
  const Eigen::Vector3d moments(0.25, 2.0, 3.7826255594622424e-307);
  const Eigen::Vector3d omega0(3.4734100304076369e-310, 3.4766779039175022e-310,
                               3.8395133023547756e-315);
  const ExactState s = ExactRotation(moments, omega0).state(0.0);
  EXPECT_EQ(s.omega_body, omega0);
  EXPECT_EQ(s.q[0], 1.0);
  EXPECT_TRUE(check_exact_property({moments, omega0, {0.0}}).empty());
}

// Near the horizon the angles are still carried to about 1e-6 rad: ψ is reduced by 2π in long
// double before it is rounded to a double (a double holds 2^40 only to 2^-12). The steady spin's
// angle |ω0| t is known exactly: ω0 = (0, 0, 1), t = 2^39 + 1, angle 2^39 + 1 rad, whose
// remainder by 2π is −0.361921305460894081… (mpmath at 50 digits).
TEST(ExactHorizon, ASteadySpinsAngleNearTheHorizonIsRightToAMicroradian) {
  const ExactRotation exact(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 0, 1));
  const Eigen::Matrix3d R = exact.orientation(0x1p39 + 1.0);
  EXPECT_NEAR(std::atan2(R(1, 0), R(0, 0)), -0.36192130546089408, 1e-6);
}

// The exact model of a scene: past the horizon its run ends there, finite() false and the
// reason said (the CLI's "diverged at t = …; the exact model: t = … is beyond …"), the last
// state kept, rather than rows of NaN or noise.
TEST(ExactHorizon, TheExactModelEndsItsRunAtTheHorizonSayingWhy) {
  ExactModel model(Book{});
  InitialState start;
  start.omega0_body = Eigen::Vector3d(0.1, 1.0, 0.05);
  model.reset(start);
  const double horizon = model.rotation().time_horizon();
  model.advance(horizon / 4, 3);
  ASSERT_TRUE(model.finite());
  const Eigen::Matrix3d kept = model.orientation();
  model.advance(horizon / 4, 2);
  EXPECT_FALSE(model.finite());
  EXPECT_NE(model.divergence_reason().find("the exact model: t = "), std::string::npos)
      << model.divergence_reason();
  EXPECT_NE(model.divergence_reason().find("time horizon"), std::string::npos);
  EXPECT_EQ(model.orientation(), kept);
  EXPECT_TRUE(model.diagnostics().omega_body.allFinite());
  model.reset(start);
  EXPECT_TRUE(model.finite());
}

}  // namespace
}  // namespace bookspin::physics
