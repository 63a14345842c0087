// The flight finder on synthetic recordings (synthetic_recording.hpp): every flight found to
// 0.05 s, the bias measured at rest, no flight across a pause, the stretches dropped said.
#include "fit/flights.hpp"

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

using test::as_recording;

void expect_flights_found(const test::SyntheticBody& body,
                          const std::vector<test::SyntheticToss>& tosses) {
  const test::SyntheticRecording synthetic = test::make_recording(body, tosses, 5);
  const GyroRecording recording = as_recording(synthetic);
  const FlightSearch search = find_flights(recording);
  ASSERT_EQ(search.flights.size(), synthetic.tosses.size());
  for (std::size_t k = 0; k < search.flights.size(); ++k) {
    EXPECT_NEAR(search.flights[k].t_start, synthetic.tosses[k].t_start, 0.05) << "toss " << k;
    EXPECT_NEAR(search.flights[k].t_end, synthetic.tosses[k].t_end, 0.05) << "toss " << k;
  }
  const RecordingPart& part = recording.parts.at(0);
  EXPECT_GT(part.rest.samples, 300);
  EXPECT_LT((part.bias - synthetic.bias).norm(), 0.03);  // the hand wobbles 0.03 rad/s at rest
}

TEST(Flights, FindsEveryFlightOfAPhoneAlone) {
  expect_flights_found(
      test::phone_alone(),
      {{{0.3, 14.0, 0.5}, 1.2}, {{-0.4, 13.0, 0.6}, 0.8}, {{0.5, -15.0, -0.3}, 1.3}});
}

TEST(Flights, FindsEveryFlightOfAPhoneOnABook) {
  expect_flights_found(test::phone_on_book(), {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 0.6}});
}

TEST(Flights, FindsEveryFlightOfARacquet) {
  expect_flights_found(test::racquet(), {{{0.4, 14.0, 0.8}, 1.2}, {{-0.6, 12.0, 0.9}, 1.0}});
}

TEST(Flights, ASmoothWindUpIsNotFlight) {
  // A 0.4 s throw without spikes: its ramp's |ω̇| (35 rad/s²) is within what Euler's equations
  // allow once |ω| > 7.4 rad/s, so only the torque the ramp needs tells it from flight.
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.2}, {{-0.4, 13.0, 0.6}, 1.0}}, 7, 0.01, 0.4, 0.0);
  const FlightSearch search = find_flights(as_recording(synthetic));
  ASSERT_EQ(search.flights.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(search.flights[k].t_start, synthetic.tosses[k].t_start, 0.05) << "toss " << k;
    EXPECT_NEAR(search.flights[k].t_end, synthetic.tosses[k].t_end, 0.05) << "toss " << k;
  }
}

TEST(Flights, ATooShortFlightIsDroppedAndSaysWhy) {
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.2}, {{0.3, 14.0, 0.5}, 0.15}});
  const FlightSearch search = find_flights(as_recording(synthetic));
  ASSERT_EQ(search.flights.size(), 1u);
  ASSERT_EQ(search.dropped.size(), 1u);
  EXPECT_NEAR(search.dropped[0].t_start, synthetic.tosses[1].t_start, 0.2);
  EXPECT_NE(search.dropped[0].reason.find("too short"), std::string::npos);
}

TEST(Flights, NoFlightInARecordingAtRest) {
  test::SyntheticRecording synthetic = test::make_recording(test::phone_alone(), {});
  const FlightSearch search = find_flights(as_recording(synthetic));
  EXPECT_TRUE(search.flights.empty());
}

TEST(Flights, NoFlightSpansAPause) {
  // A pause in the middle of the first flight: it is cut there, into two shorter flights or
  // fewer, never one across it.
  test::SyntheticRecording synthetic =
      test::make_recording(test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.2}});
  synthetic.pauses = {synthetic.tosses[0].t_start + 0.6};
  const FlightSearch search = find_flights(as_recording(synthetic));
  for (const Flight& f : search.flights)
    EXPECT_FALSE(f.t_start < synthetic.pauses[0] && f.t_end >= synthetic.pauses[0]);
}

TEST(Flights, HandFlightsAreCheckedAgainstTheRecording) {
  const test::SyntheticRecording synthetic =
      test::make_recording(test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.2}});
  const GyroRecording recording = as_recording(synthetic);
  const FlightSearch search = hand_flights(recording, {{1.7, 2.8}});
  ASSERT_EQ(search.flights.size(), 1u);
  EXPECT_NEAR(search.flights[0].t_start, 1.7, 0.011);
  EXPECT_THROW(hand_flights(recording, {{2.8, 1.7}}), InputError);
  EXPECT_THROW(hand_flights(recording, {{1.7, 1.72}}), InputError);
}

std::string hand_error(const GyroRecording& recording,
                       const std::vector<std::pair<double, double>>& ranges) {
  try {
    hand_flights(recording, ranges);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Flights, HandFlightsAreSortedAndNeverOverlap) {
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.0}, {{-0.4, 13.0, 0.6}, 1.0}});
  const GyroRecording recording = as_recording(synthetic);
  // Given in reverse: numbered in time order.
  const FlightSearch search = hand_flights(recording, {{4.2, 5.0}, {1.7, 2.5}});
  ASSERT_EQ(search.flights.size(), 2u);
  EXPECT_NEAR(search.flights[0].t_start, 1.7, 0.011);
  EXPECT_NEAR(search.flights[1].t_start, 4.2, 0.011);
  EXPECT_EQ(hand_error(recording, {{1.7, 2.5}, {2.0, 2.7}}),
            "--tosses 2.000:2.700: overlaps 1.700:2.500 (a sample belongs to one toss at most)");
  EXPECT_EQ(hand_error(recording, {{2.0, 2.7}, {1.7, 2.5}}),
            "--tosses 2.000:2.700: overlaps 1.700:2.500 (a sample belongs to one toss at most)");
  EXPECT_EQ(hand_error(recording, {{1.7, 2.5}, {2.5, 2.7}}),
            "--tosses 2.500:2.700: overlaps 1.700:2.500 (a sample belongs to one toss at most)");
  EXPECT_EQ(hand_error(recording, {{1.7, 2.5}, {1.7, 2.5}}), "--tosses 1.700:2.500: given twice");
}

TEST(Flights, TwoTossesAt10kHzAreTwoFlights) {
  // At 10 kHz a derivative over ±2 samples (0.2 ms) is the noise's, not the motion's: the
  // finder's window spans ±0.02 s whatever the rate, so the flights are found as at 100 Hz.
  const test::SyntheticRecording synthetic =
      test::make_recording(test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.0}, {{-0.4, 13.0, 0.6}, 0.8}},
                           3, 0.01, 0.15, 4.0, 0.0, 10000.0);
  const FlightSearch search = find_flights(as_recording(synthetic));
  ASSERT_EQ(search.flights.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(search.flights[k].t_start, synthetic.tosses[k].t_start, 0.05) << "toss " << k;
    EXPECT_NEAR(search.flights[k].t_end, synthetic.tosses[k].t_end, 0.05) << "toss " << k;
  }
}

TEST(Flights, TheBiasIsTheMeanOfTheStillSamplesOnly) {
  // 1 s slow (100 Hz): 0.4 s held in the hand (a 0.1 rad/s swing on x, 0.2 on y: under
  // rest_omega), then
  // 0.6 s lying still on b with the gyroscope's noise (±0.004 rad/s alternating), then 1 s
  // turning at 5 rad/s. The bias is b, from the still samples alone: the hand's swing is motion
  // (fit/rest.hpp), not the gyroscope's bias.
  const Eigen::Vector3d b(0.02, -0.01, 0.005);
  GyroRecording recording;
  recording.name = "rest";
  recording.source = "rest.csv";
  for (int i = 0; i < 200; ++i) {
    const double t = 0.01 * i;
    recording.t.push_back(t);
    Eigen::Vector3d w = b + Eigen::Vector3d::Constant(i % 2 ? 0.004 : -0.004);
    if (i < 40) w = Eigen::Vector3d(0.1 * std::sin(2.0 * M_PI * 2.5 * t), 0.2, 0.0);
    if (i >= 100) w = Eigen::Vector3d(5.0, 0.0, 0.0);
    recording.omega.push_back(w);
  }
  const RecordingPart part = pool_recordings({recording}).parts.at(0);
  EXPECT_EQ(part.rest.samples, 60);
  ASSERT_EQ(part.rest.stretches.size(), 1u);
  EXPECT_DOUBLE_EQ(part.rest.stretches[0].first, 0.40);
  EXPECT_DOUBLE_EQ(part.rest.stretches[0].second, 0.99);
  EXPECT_LE((part.bias - b).norm(), 1e-15);
  // The standard error: 0.004/√60 on each axis (alternating samples: ρ < 0, taken as 0).
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(part.rest.standard_error[c], 0.004 / std::sqrt(59.0), 1e-12) << c;
}

TEST(Flights, AFlightShorterThanTheMinimumIsDroppedHoweverManySamples) {
  // A smooth 0.4 s wind-up (a candidate, with the flight after it) before a 0.2 s flight: the
  // torque cut leaves 0.2 s (20 samples, enough to fit): shorter than min_flight, dropped.
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.2}, {{-0.4, 13.0, 0.6}, 0.2}}, 7, 0.01, 0.4, 0.0);
  const FlightSearch search = find_flights(as_recording(synthetic));
  ASSERT_EQ(search.flights.size(), 1u);
  EXPECT_LT(search.flights[0].t_end, synthetic.tosses[1].t_start);
  for (const Flight& f : search.flights)
    EXPECT_GE(f.t_end - f.t_start, FinderSettings{}.min_flight);
}

TEST(Flights, EulerInertiaOfExactEulerMotion) {
  // ω and ω̇ that satisfy Euler's equations for I = diag(1, 2, 3) (docs/physics.md §8): the
  // inertia comes back, scaled to a largest moment of 1.
  const Eigen::Vector3d I(1, 2, 3);
  std::vector<Eigen::Vector3d> omega, rate;
  std::vector<int> indices;
  Eigen::Vector3d w(0.2, 3.0, 0.4);
  for (int i = 0; i < 200; ++i) {
    omega.push_back(w);
    rate.push_back(test::euler_rate(I, w));
    indices.push_back(i);
    w = test::rk4(I, w, 0.01);
  }
  const Eigen::Matrix3d fitted = euler_inertia(omega, rate, indices);
  EXPECT_LT((fitted - Eigen::Matrix3d(Eigen::Vector3d(1, 2, 3).asDiagonal()) / 3.0).norm(), 1e-9);
}

}  // namespace
}  // namespace bookspin::fit
