// The tosses given by hand (--tosses; docs/phone-lab.md, "The flights by hand") on a recording
// made here: 100 samples 10 ms apart (t = 0, 0.01, ..., 0.99 s), a pause at 0.5 s. The limits
// are counted by hand: a toss needs 10 samples, never spans a pause, never shares an instant.
#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"
#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"

namespace bookspin::fit {
namespace {

GyroRecording hundred_samples() {
  GyroRecording recording;
  recording.name = "hand";
  recording.source = "hand.csv";
  for (int i = 0; i < 100; ++i) {
    recording.t.push_back(0.01 * i);
    recording.omega.push_back(Eigen::Vector3d(0.01, -0.02, 0.03));
  }
  recording.pauses = {0.505};
  return pool_recordings({recording});
}

std::string error_of(const GyroRecording& recording,
                     const std::vector<std::pair<double, double>>& ranges) {
  try {
    hand_flights(recording, ranges);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// 0.095–0.195 s holds the samples at 0.10, ..., 0.19 s: ten, the fewest a toss may have; one
// fewer (to 0.185 s) is refused with the count.
TEST(TossRanges, TenSamplesAreATossAndNineAreNot) {
  const GyroRecording recording = hundred_samples();
  const FlightSearch ten = hand_flights(recording, {{0.095, 0.195}});
  ASSERT_EQ(ten.flights.size(), 1u);
  EXPECT_EQ(ten.flights[0].first, 10);
  EXPECT_EQ(ten.flights[0].last, 19);
  EXPECT_EQ(error_of(recording, {{0.095, 0.185}}),
            "--tosses 0.095:0.185: 9 samples of hand.csv in it; a toss needs at least 10");
}

// A range across the pause (0.505 s) is refused, naming the first sample after it; ranges on
// either side of it are tosses.
TEST(TossRanges, ARangeAcrossAPauseIsRefused) {
  const GyroRecording recording = hundred_samples();
  EXPECT_EQ(error_of(recording, {{0.395, 0.605}}),
            "--tosses 0.395:0.605: spans a pause or a gap of hand.csv (at 0.510 s)");
  EXPECT_EQ(hand_flights(recording, {{0.295, 0.495}, {0.515, 0.715}}).flights.size(), 2u);
}

}  // namespace
}  // namespace bookspin::fit
