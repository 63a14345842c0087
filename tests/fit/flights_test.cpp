// The flight finder on synthetic recordings (synthetic_recording.hpp): every flight found to
// 0.05 s, the bias measured at rest, no flight across a pause, the stretches dropped said.
#include "fit/flights.hpp"

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

GyroRecording as_recording(const test::SyntheticRecording& synthetic) {
  GyroRecording recording;
  recording.name = "synthetic";
  recording.source = "synthetic.csv";
  recording.t = synthetic.t;
  recording.omega = synthetic.omega;
  recording.pauses = synthetic.pauses;
  return recording;
}

void expect_flights_found(const test::SyntheticBody& body,
                          const std::vector<test::SyntheticToss>& tosses) {
  const test::SyntheticRecording synthetic = test::make_recording(body, tosses, 5);
  const FlightSearch search = find_flights(as_recording(synthetic));
  ASSERT_EQ(search.flights.size(), synthetic.tosses.size());
  for (std::size_t k = 0; k < search.flights.size(); ++k) {
    EXPECT_NEAR(search.flights[k].t_start, synthetic.tosses[k].t_start, 0.05) << "toss " << k;
    EXPECT_NEAR(search.flights[k].t_end, synthetic.tosses[k].t_end, 0.05) << "toss " << k;
  }
  EXPECT_GT(search.rest_samples, 300);
  EXPECT_LT((search.bias - synthetic.bias).norm(), 0.03);  // the hand wobbles 0.03 rad/s at rest
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
