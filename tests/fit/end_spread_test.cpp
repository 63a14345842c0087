// The flight ends' uncertainty (docs/phone-lab.md, "Error bars") by relation: each end's is how
// far the trim moved it in from where the finder put it, never less than kEndUncertainty nor more
// than kEndShare of its flight, and it grows with the trim: a trim that moves an end further in
// never gives that end a smaller uncertainty, and leaves the other end's as it was; and the
// spread it adds to the body's σ grows with it, where the flights' starts hold what the model
// does not (a hand's push dying away).
#include "fit/end_spread.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fit/toss_solve.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::fit {
namespace {

/// The finder's flight [1, 2] s, trimmed in by `in_start` at its start and `in_end` at its end.
EndShifts trimmed_by(double in_start, double in_end) {
  FlightSearch found;
  found.flights = {Flight{100, 200, 1.0, 2.0}};
  const std::vector<Flight> flights = {Flight{100, 200, 1.0 + in_start, 2.0 - in_end}};
  return end_shifts(flights, &found);
}

TEST(EndShifts, EachEndIsHowFarTheTrimMovedItBetweenItsFloorAndItsShare) {
  double last_start = 0.0, last_end = 0.0;
  for (int i = 0; i <= 40; ++i) {
    const double in = 0.005 * i;  // 0 to 0.2 s moved in
    SCOPED_TRACE(in);
    // The start moved, the end kept: the start's uncertainty follows the trim, the end's stays
    // at the floor; and the same with the ends exchanged.
    const EndShifts start_moved = trimmed_by(in, 0.0), end_moved = trimmed_by(0.0, in);
    ASSERT_EQ(start_moved.start.size(), 1u);
    ASSERT_EQ(end_moved.end.size(), 1u);
    const double most = kEndShare * (1.0 - in);
    EXPECT_NEAR(start_moved.start[0], std::min(std::max(in, kEndUncertainty), most), 1e-12);
    EXPECT_DOUBLE_EQ(start_moved.end[0], kEndUncertainty);
    EXPECT_NEAR(end_moved.end[0], std::min(std::max(in, kEndUncertainty), most), 1e-12);
    EXPECT_DOUBLE_EQ(end_moved.start[0], kEndUncertainty);
    // A longer trim, a larger uncertainty, until the share of the (shorter) flight caps it.
    if (in > most) continue;
    EXPECT_GE(start_moved.start[0], last_start);
    EXPECT_GE(end_moved.end[0], last_end);
    if (in > kEndUncertainty) {
      EXPECT_GT(start_moved.start[0], last_start);
      EXPECT_GT(end_moved.end[0], last_end);
    }
    last_start = start_moved.start[0], last_end = end_moved.end[0];
  }
}

TEST(EndShifts, FlightsByHandHaveNoneAndFlightsTheTrimDidNotMatchHaveTheFloor) {
  const std::vector<Flight> flights = {Flight{100, 200, 1.1, 1.9}, Flight{300, 400, 3.1, 3.9}};
  EXPECT_TRUE(end_shifts(flights, nullptr).start.empty());
  FlightSearch found;
  found.flights = {Flight{100, 200, 1.0, 2.0}};  // one found, two fitted: not the trim's copies
  const EndShifts shifts = end_shifts(flights, &found);
  ASSERT_EQ(shifts.start.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_DOUBLE_EQ(shifts.start[k], kEndUncertainty);
    EXPECT_DOUBLE_EQ(shifts.end[k], kEndUncertainty);
  }
}

/// Three tosses of one body (moments 0.45 : 0.72 : 1, axes turned from the phone's), 1.2 s at
/// 100 Hz each, the first 0.15 s of each pushed by a hand: ω off the free motion by 0.4 rad/s
/// along a fixed phone direction, dying away linearly. No drag.
std::vector<TossData> pushed_tosses(Eigen::Matrix3d& axes) {
  axes = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -2, 1).normalized()).toRotationMatrix();
  const Eigen::Vector3d moments(0.45, 0.72, 1.0);
  const std::vector<Eigen::Vector3d> principal = {
      {0.6, 12.0, 0.8}, {-0.9, 10.0, 0.5}, {0.4, -11.0, -1.0}};
  std::vector<TossData> data;
  for (const Eigen::Vector3d& w : principal) {
    const physics::ExactRotation motion(moments, w);
    TossData d;
    for (int i = 0; i <= 120; ++i) {
      const double tau = 0.01 * i;
      const double push = tau < 0.15 ? 0.4 * (1.0 - tau / 0.15) : 0.0;
      d.tau.push_back(tau);
      d.omega.push_back(axes * motion.omega_body(tau) + push * Eigen::Vector3d(0.6, 0.0, 0.8));
    }
    d.samples = static_cast<int>(d.tau.size());
    data.push_back(std::move(d));
  }
  return data;
}

TEST(EndSpread, ALongerTrimOfAPushedStartWidensTheBodysSigmaMore) {
  Eigen::Matrix3d axes;
  const std::vector<TossData> data = pushed_tosses(axes);
  FitSettings settings;
  settings.drag = physics::DragLaw::none;
  Parameters p;
  p.R0 = axes;
  p.log_ratios = {std::log(0.45), std::log(0.72)};
  for (const TossData& d : data)
    p.omega0.push_back({d.omega[0][0], d.omega[0][1], d.omega[0][2], 0});
  SolveOptions options;
  options.drag = settings.drag;
  ASSERT_TRUE(solve(data, p, options).usable);
  normalise(p);
  const BiasFreedom bias{{std::nullopt}, {false}, {false}, {false}};
  double last = -1.0;
  for (const double start : {0.02, 0.04, 0.08, 0.12}) {
    SCOPED_TRACE(start);
    BodyEstimate body;
    body.axes = p.axes();
    body.ratio_sigma = Eigen::Vector3d::Zero();
    body.axis_sigma_deg = Eigen::Vector3d::Zero();
    TossSigmas sigmas{std::vector<std::optional<Eigen::Vector3d>>(3),
                      std::vector<std::optional<double>>(3)};
    const EndShifts shifts{{start, start, start}, {0.02, 0.02, 0.02}};
    widen_by_ends(data, p, shifts, settings, std::vector<bool>(3, false), bias,
                  {Eigen::Vector3d::Zero()}, body, sigmas);
    ASSERT_TRUE(body.ratio_sigma.has_value());
    const double spread = body.ratio_sigma->head<2>().norm();
    EXPECT_GT(spread, last);
    last = spread;
  }
}

}  // namespace
}  // namespace bookspin::fit
