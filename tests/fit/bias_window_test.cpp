// The gyroscope's bias (docs/phone-lab.md, "How the flights are found"): the mean ω over the
// stretches at rest (|ω| under 0.5 rad/s) of 0.3 s or longer; a shorter slow moment within the
// motion is no rest. A recording made here, without noise, so that the mean is known exactly.
#include <gtest/gtest.h>

#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"

namespace bookspin::fit {
namespace {

// 0–0.99 s at rest on b (100 samples), 1.00–1.49 s turning at 5 rad/s, 1.50–1.59 s slow
// (0.3 rad/s: under the rest threshold, but 0.09 s long), 1.60–1.99 s turning, 2.00–2.99 s at
// rest on b (100 samples): the bias is b from the 200 rest samples, the slow moment left out.
TEST(BiasWindow, OnlyRestOfThreeTenthsOfASecondOrLongerMeasuresTheBias) {
  const Eigen::Vector3d b(0.0625, -0.03125, 0.015625);
  GyroRecording recording;
  recording.name = "bias";
  recording.source = "bias.csv";
  for (int i = 0; i < 300; ++i) {
    const double t = 0.01 * i;
    Eigen::Vector3d w = b;
    if (i >= 100 && i < 200) w = Eigen::Vector3d(5.0, 0.0, 0.0);
    if (i >= 150 && i < 160) w = Eigen::Vector3d(0.3, 0.0, 0.0);
    recording.t.push_back(t);
    recording.omega.push_back(w);
  }
  // Measured once, where the recording becomes a pool (of one): the finder and the flights by
  // hand both take it from there.
  const GyroRecording pooled = pool_recordings({recording});
  ASSERT_EQ(pooled.parts.size(), 1u);
  EXPECT_EQ(pooled.parts[0].rest.samples, 200);
  EXPECT_LE((pooled.parts[0].bias - b).norm(), 1e-15);
}

}  // namespace
}  // namespace bookspin::fit
