// A recording that is one free flight: no rest before or after, uneven timestamps (an app that
// delivers the gyroscope in bursts), docs/phone-lab.md, "How the flights are found".
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

/// 0.65 s of a bare phone's flight at about 20 rad/s, sampled in bursts: two thirds of the steps
/// 2 ms, one third 12 ms (each ±20 %), about 190 Hz on average; a bias and 0.02 rad/s of noise;
/// the recording starts and ends in flight.
GyroRecording lone_flight(unsigned seed, Eigen::Vector3d* omega0_phone = nullptr) {
  const test::SyntheticBody body = test::phone_alone();
  const Eigen::Vector3d w0(1.0, 20.0, 1.2);
  const Eigen::Vector3d bias(0.02, -0.01, 0.015);
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  GyroRecording recording;
  recording.source = "lone-flight.csv";
  Eigen::Vector3d w = w0;
  double t = 0.0;
  while (t <= 0.65) {
    recording.t.push_back(t);
    recording.omega.push_back(body.axes * w + bias +
                              0.02 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random)));
    const double step = (random() % 3 == 2 ? 0.012 : 0.002) * (1.0 + 0.2 * uniform(random));
    w = test::rk4(body.moments, w, step, test::SyntheticDrag{});
    t += step;
  }
  if (omega0_phone) *omega0_phone = body.axes * w0;
  return pool_recordings({recording});
}

TEST(LoneFlight, IsFoundWithNoRestAndUnevenTimestampsAndFitsWithinFivePercent) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const GyroRecording recording = lone_flight(seed);
    const FlightSearch search = find_flights(recording);
    EXPECT_EQ(recording.parts.at(0).rest.samples, 0) << seed;
    ASSERT_EQ(search.flights.size(), 1u) << seed;
    // Nearly all of it: the finder trims at most a few samples at each end.
    EXPECT_GT(search.flights[0].t_end - search.flights[0].t_start, 0.55) << seed;
    const FitResult fit = fit_recording(recording, search);
    ASSERT_EQ(fit.tosses.size(), 1u);
    double mean_omega = 0.0;
    for (const Eigen::Vector3d& w : recording.omega) mean_omega += w.norm();
    mean_omega /= static_cast<double>(recording.omega.size());
    EXPECT_LT(fit.tosses[0].residual_rms, 0.05 * mean_omega) << seed;
    EXPECT_FALSE(fit.tosses[0].poor_fit) << seed << ": " << fit.tosses[0].flag;
  }
}

}  // namespace
}  // namespace bookspin::fit
