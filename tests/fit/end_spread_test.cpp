// The flight ends' uncertainty (docs/phone-lab.md, "Error bars") by relation: each end's is how
// far the trim moved it in from where the finder put it, never less than kEndUncertainty nor more
// than kEndShare of its flight, and it grows with the trim: a trim that moves an end further in
// never gives that end a smaller uncertainty, and leaves the other end's as it was.
#include "fit/end_spread.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

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

}  // namespace
}  // namespace bookspin::fit
