// The restart from rigid bodies keeps the lowest cost of its starts (fit/rigid_restart.hpp):
// by a relation over every order of the starts, not one case.
#include "fit/rigid_restart.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace bookspin::fit {
namespace {

JointFitted fitted_at(double cost, double mark) {
  JointFitted fit;
  fit.solved.cost = cost;
  fit.p.log_ratios = {mark, 0.0};  // which start it came from
  return fit;
}

// Whatever the order of the starts, the fit kept is the one of the lowest cost of the suspect
// fit and every start that converged; a start passed over (nullopt) is never kept. Keeping the
// last start that beats the suspect fit, or the first, gives another in some order.
TEST(RigidRestart, KeepsTheLowestCostOfItsStartsInEveryOrder) {
  // Costs of the starts; < 0: a start passed over (it did not converge).
  std::vector<double> costs{5.0, 3.0, 7.0, -1.0, 4.0};
  std::sort(costs.begin(), costs.end());
  int orders = 0;
  do {
    for (double suspect : {6.0, 3.5, 2.0}) {
      JointFitted fit = fitted_at(suspect, -1.0);
      keep_lowest(fit, costs.size(), [&](std::size_t i) -> std::optional<JointFitted> {
        if (costs[i] < 0) return std::nullopt;
        return fitted_at(costs[i], static_cast<double>(i));
      });
      const double lowest = std::min(suspect, 3.0);
      EXPECT_EQ(fit.solved.cost, lowest) << "suspect " << suspect << ", order " << orders;
      if (lowest < suspect) {
        const std::size_t from = static_cast<std::size_t>(fit.p.log_ratios[0]);
        ASSERT_LT(from, costs.size());
        EXPECT_EQ(costs[from], lowest);  // the unknowns are the lowest start's too
      } else {
        EXPECT_EQ(fit.p.log_ratios[0], -1.0);  // the suspect fit stands
      }
    }
    ++orders;
  } while (std::next_permutation(costs.begin(), costs.end()));
  EXPECT_EQ(orders, 120);
}

// A suspect body: moments no rigid body has (I1 + I2 < I3), a needle (I1/I3 < kNeedle), or at the
// edge I2 = I3 where a fit from a poor start ends (I2/I3 > kAxisymmetricEdge); a book's, a slab's,
// a box's are not.
TEST(RigidRestart, ASuspectBodyIsPastTheTriangleInequalityOrANeedle) {
  const auto body = [](double i1, double i2) {
    Parameters p;
    p.log_ratios = {std::log(i1), std::log(i2)};
    return p;
  };
  EXPECT_TRUE(suspect_body(body(0.3, 0.6)));     // 0.3 + 0.6 < 1
  EXPECT_TRUE(suspect_body(body(0.05, 0.98)));   // a needle
  EXPECT_TRUE(suspect_body(body(0.45, 0.999)));  // at the edge I2 = I3
  EXPECT_FALSE(suspect_body(body(0.45, 0.98)));
  for (const auto& [m1, m2] : kRigidStarts) EXPECT_FALSE(suspect_body(body(m1, m2)));
}

// "No rigid body" in one place (rigid_bounds.hpp): each stage's cut-off nested in the next, the
// one that withholds σ inside the one that flags a toss inside the one that restarts the fit,
// and the note's words made from its numbers.
TEST(RigidRestart, EachStagesNoRigidBodyLiesWithinTheOneBeforeIt) {
  EXPECT_EQ(far_from_rigid_words(), "I1/I3 under 0.01, or I1 + I2 under 0.95 I3");
  for (double i1 = 0.001; i1 < 1.0; i1 *= 1.05)
    for (double i2 = i1; i2 <= 1.0; i2 += 0.01) {
      const Eigen::Vector3d m(i1, i2, 1.0);
      if (far_from_rigid(m)) {
        EXPECT_TRUE(flagged_moments(m)) << m.transpose();
      }
      if (flagged_moments(m)) {
        EXPECT_TRUE(suspect_moments(m)) << m.transpose();
      }
      EXPECT_EQ(needle(m), i1 < kNeedle);
    }
  EXPECT_FALSE(flagged_moments(Eigen::Vector3d(0.22, 0.80, 1.0)));   // a bare phone, on the bound
  EXPECT_TRUE(far_from_rigid(Eigen::Vector3d(0.0067, 0.011, 1.0)));  // 12-29-59 thinned's needle
}

}  // namespace
}  // namespace bookspin::fit
