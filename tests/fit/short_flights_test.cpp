// The flight finder's limits (docs/phone-lab.md, "How the flights are found"), on recordings
// made here of a steady spin (ω = (0, 0, 5) rad/s throughout: torque-free for any body, ω̇ = 0,
// so every sample is flight): a flight needs 0.3 s and 10 samples, and none spans a gap of
// more than five sample intervals. The samples are counted by hand.
#include <gtest/gtest.h>

#include <vector>

#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"

namespace bookspin::fit {
namespace {

/// A steady spin at the sample times `t`.
GyroRecording steady_spin(const std::vector<double>& t) {
  GyroRecording recording;
  recording.name = "steady";
  recording.source = "steady.csv";
  recording.t = t;
  recording.omega.assign(t.size(), Eigen::Vector3d(0.0, 0.0, 5.0));
  return pool_recordings({recording});
}

std::vector<double> evenly(int n, double h, double from = 0.0) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(from + h * i);
  return t;
}

// At 25 Hz, 10 samples span 0.36 s: a flight. 9 samples span 0.32 s, over the 0.3 s minimum,
// but are too few to fit: dropped, and said why.
TEST(ShortFlights, TenSamplesAreAFlightAndNineAreNotHoweverLong) {
  const FlightSearch ten = find_flights(steady_spin(evenly(10, 0.04)));
  ASSERT_EQ(ten.flights.size(), 1u);
  EXPECT_EQ(ten.flights[0].first, 0);
  EXPECT_EQ(ten.flights[0].last, 9);
  const FlightSearch nine = find_flights(steady_spin(evenly(9, 0.04)));
  EXPECT_TRUE(nine.flights.empty());
  ASSERT_EQ(nine.dropped.size(), 1u);
}

// 128 Hz (h = 2⁻⁷ s), two runs of 50 samples: 6 h apart they are two flights (a gap of more
// than 5 intervals), 4 h apart one.
TEST(ShortFlights, AGapOfMoreThanFiveIntervalsSplitsAFlight) {
  const double h = 1.0 / 128.0;
  for (const auto& [gap, flights] : {std::pair{6, 2u}, std::pair{4, 1u}}) {
    std::vector<double> t = evenly(50, h);
    const std::vector<double> after = evenly(50, h, t.back() + gap * h);
    t.insert(t.end(), after.begin(), after.end());
    const FlightSearch search = find_flights(steady_spin(t));
    EXPECT_EQ(search.flights.size(), flights) << "a gap of " << gap << " intervals";
  }
}

}  // namespace
}  // namespace bookspin::fit
