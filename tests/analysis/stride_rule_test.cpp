// The judge's rule for rows too far apart (docs/flipcheck.md, "What it reads"), held against its
// own documented relation rather than against a case: the exact motion sampled at a stride is
// judged iff, at those rows, it counts every one of its turn-overs and puts the first within 1 %
// of the half period T/2 of its time; the stride a refusal names is at most 1 % of T/2 apart,
// and every stride up to it is judged and passes. The turn-overs here are found independently of
// the judge's code: the cosine of the intermediate axis with L (docs/physics.md §14) sampled at
// the rows, a turn-over counted where it passes the margin 0.5 on the other side and placed at
// the zero crossing before it by linear interpolation; the exact first turn-over bisected on ω.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "analysis/judgement.hpp"
#include "common/errors.hpp"
#include "physics/body.hpp"
#include "physics/exact_solution.hpp"
#include "support/scenario_rows.hpp"

namespace bookspin::analysis {
namespace {

using scenario_rows::exact_rows;
using scenario_rows::scenario;

/// The documented tolerance of the rule: 1 % of T/2 (docs/flipcheck.md).
constexpr double kSamplingShare = 0.01;

/// Turn-overs of the exact motion seen at rows every `stride` steps up to `last_step`.
struct Seen {
  int count = 0;
  std::optional<double> first;
  std::vector<long long> counted_at;  ///< the step of the row each was counted at
};

Seen seen_at(const physics::ExactRotation& exact, int mid, double dt, long long stride,
             long long last_step) {
  Seen seen;
  int side = 0, last_sign = 0;
  double previous_t = 0.0, previous_v = 0.0, crossing = 0.0;
  for (long long n = 0; n <= last_step; n += stride) {
    const double t = static_cast<double>(n) * dt;
    const double v = exact.angular_momentum_body(t)[mid] / exact.angular_momentum_norm();
    const int sign = v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
    if (sign != 0) {
      if (side == 0) side = sign;
      if (last_sign != 0 && sign != last_sign)
        crossing = previous_t + (t - previous_t) * previous_v / (previous_v - v);
      if (sign == -side && std::abs(v) > 0.5) {
        ++seen.count;
        seen.counted_at.push_back(n);
        if (!seen.first) seen.first = crossing;
        side = sign;
      }
      last_sign = sign;
    }
    previous_t = t;
    previous_v = v;
  }
  return seen;
}

/// The exact motion's first zero of ω about the intermediate axis after t = 0, bisected.
double first_zero(const physics::ExactRotation& exact, int mid) {
  const double half = exact.flip_period();
  const auto sign_at = [&](double t) { return exact.omega_body(t)[mid] > 0.0; };
  const bool s0 = sign_at(0.0);
  double a = 0.0, b = 0.0;
  for (int k = 1; k <= 1024; ++k) {
    b = half * k / 1024.0;
    if (sign_at(b) != s0) break;
    a = b;
  }
  for (int k = 0; k < 200; ++k) {
    const double m = 0.5 * (a + b);
    if (m == a || m == b) break;
    (sign_at(m) == s0 ? a : b) = m;
  }
  return a;
}

/// Whether the judge judges the exact motion of `s` at `stride` (no refusal), and the refusal.
bool judged(const Scenario& s, long long stride, std::string* refusal = nullptr) {
  try {
    judge_motion(s, exact_rows(s, stride));
    return true;
  } catch (const InputError& e) {
    if (refusal) *refusal = e.what();
    return false;
  }
}

/// The documented rule at `stride`: the exact motion at those rows counts every one of its
/// turn-overs (as rows at every step up to the same last row count them) and, where the first
/// falls within the rows, places it within `tolerance` of the exact first zero `first`.
/// `every`: the turn-overs at every step of the whole span (a turn-over is counted at a row from
/// the rows before it alone, so those up to a last row are those counted at or before it).
bool shows_turn_overs(const Scenario& s, const physics::ExactRotation& exact, int mid,
                      long long stride, double first, double tolerance, const Seen& every) {
  const long long last = s.steps / stride * stride;
  const auto every_count = std::count_if(every.counted_at.begin(), every.counted_at.end(),
                                         [last](long long n) { return n <= last; });
  const Seen rows = seen_at(exact, mid, s.dt, stride, last);
  return rows.count == every_count && (first > static_cast<double>(last) * s.dt || !rows.first ||
                                       std::abs(*rows.first - first) <= tolerance);
}

TEST(StrideRule, AStrideIsJudgedExactlyWhenItsRowsShowTheTurnOversWithinOnePercentOfTheHalfPeriod) {
  for (const char* name :
       {"book-intermediate-0.05", "book-intermediate-0.2", "book-intermediate-0.002"}) {
    const Scenario s = scenario(name);
    const physics::ExactRotation exact(s.body.moments, start_omega(s));
    const int mid = physics::principal_order(s.body.moments)[1];
    const double tolerance = kSamplingShare * exact.flip_period();
    const double first = first_zero(exact, mid);
    const Seen every = seen_at(exact, mid, s.dt, 1, s.steps);
    // Strides from every step to a third of the span, 6 % apart: where linear interpolation
    // still places the first turn-over well within 1 % of T/2, where it no longer does, and where
    // rows miss turn-overs.
    std::vector<long long> strides;
    for (double stride = 1.0; stride <= static_cast<double>(s.steps) / 3; stride *= 1.06)
      strides.push_back(std::llround(stride));
    std::sort(strides.begin(), strides.end());
    strides.erase(std::unique(strides.begin(), strides.end()), strides.end());
    int shown = 0, not_shown = 0;
    for (long long stride : strides) {
      const bool shows = shows_turn_overs(s, exact, mid, stride, first, tolerance, every);
      (shows ? shown : not_shown)++;
      std::string refusal;
      EXPECT_EQ(judged(s, stride, &refusal), shows)
          << name << ", rows every " << stride << " steps (1 % of T/2: " << tolerance
          << " time units) " << refusal;
    }
    // The relation is asked on both sides of its edge.
    EXPECT_GT(shown, 3) << name;
    EXPECT_GT(not_shown, 3) << name;
  }
}

TEST(StrideRule,
     TheStrideARefusalNamesIsWithinOnePercentOfTheHalfPeriodAndEveryStrideUpToItPasses) {
  for (const char* name : {"book-intermediate-0.05", "book-intermediate-0.002"}) {
    const Scenario s = scenario(name);
    const physics::ExactRotation exact(s.body.moments, start_omega(s));
    const double tolerance = kSamplingShare * exact.flip_period();
    std::string refusal;
    ASSERT_FALSE(judged(s, s.steps / 3, &refusal)) << name;
    const std::size_t at = refusal.find("write a row at least every ");
    ASSERT_NE(at, std::string::npos) << refusal;
    const long long named = std::stoll(refusal.substr(at + 27));
    ASSERT_GE(named, 1) << refusal;
    EXPECT_LE(static_cast<double>(named) * s.dt, tolerance * (1 + 1e-12)) << refusal;
    // It shows the turn-overs by the rule, and it is the coarsest such stride within the 1 % where
    // that one shows them (none finer than needed).
    const int mid = physics::principal_order(s.body.moments)[1];
    const double first = first_zero(exact, mid);
    const Seen every = seen_at(exact, mid, s.dt, 1, s.steps);
    EXPECT_TRUE(shows_turn_overs(s, exact, mid, named, first, tolerance, every)) << refusal;
    const long long coarsest = static_cast<long long>(std::floor(tolerance / s.dt));
    if (shows_turn_overs(s, exact, mid, coarsest, first, tolerance, every)) {
      EXPECT_EQ(named, coarsest) << refusal;
    }
    for (long long stride = named; stride >= 1; stride -= std::max<long long>(1, named / 12)) {
      EXPECT_TRUE(judged(s, stride)) << name << ", rows every " << stride << " steps";
      if (s.steps % stride == 0) {
        const Conformance c = judge_motion(s, exact_rows(s, stride));
        EXPECT_TRUE(c.pass()) << name << ", rows every " << stride << ": " << verdict_line(c);
      }
    }
  }
}

}  // namespace
}  // namespace bookspin::analysis
