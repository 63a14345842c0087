// What a fit that failed blames in its samples (fit/toss_flags.hpp, scale_cause): one axis in
// °/s beside two in rad/s, every axis in °/s, and samples that explain nothing.
#include "fit/toss_flags.hpp"

#include <gtest/gtest.h>

namespace bookspin::fit {
namespace {

TossData toss_of(const std::vector<Eigen::Vector3d>& omega) {
  TossData d;
  for (std::size_t i = 0; i < omega.size(); ++i) d.tau.push_back(0.01 * i);
  d.omega = omega;
  d.samples = static_cast<int>(omega.size());
  return d;
}

TEST(ScaleCause, NamesTheAxisBeyondAnyGyroscopesRangeAndTheOthers) {
  // A 15 rad/s spin about y written in °/s (859 °/s read as rad/s), x and z in rad/s.
  const TossData mixed = toss_of({{0.5, 859.4, -1.2}, {0.7, 800.0, 2.5}});
  EXPECT_EQ(scale_cause({mixed}),
            "ω_y reaches 859.4 rad/s, beyond any gyroscope's range (±69.8 rad/s), while ω_x and "
            "ω_z stay within 2.5: that axis in °/s, or scaled?");
  const TossData two = toss_of({{100.0, 859.4, -1.2}});
  EXPECT_EQ(scale_cause({two}),
            "ω_x and ω_y reach 859.4 rad/s, beyond any gyroscope's range (±69.8 rad/s), while "
            "ω_z stays within 1.2: those axes in °/s, or scaled?");
  const TossData all = toss_of({{100.0, 859.4, -120.0}});
  EXPECT_EQ(scale_cause({all}),
            "every axis of ω passes any gyroscope's range (±69.8 rad/s), up to 859.4 rad/s: a "
            "recording in °/s, or scaled?");
  // At the widest range itself (4000 °/s), nothing to blame.
  EXPECT_EQ(scale_cause({toss_of({{69.8, 10.0, -3.0}})}), "");
}

}  // namespace
}  // namespace bookspin::fit
