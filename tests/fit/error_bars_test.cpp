// The fit's error bars (docs/phone-lab.md, "Error bars") against values worked out here: the
// covariance's σ inflated by (1 + ρ)/(1 − ρ) for a residual correlated from sample to sample
// (an AR(1) noise of known ρ added to noiseless synthetic flights), and the grouped jackknife
// σ² = (G − 1)/G Σ (θ_g − θ̄)² computed here from the bodies fitted on each pair of three tosses.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

using test::as_recording;
using test::SyntheticToss;

std::vector<SyntheticToss> three_tosses() {
  return {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.3}, {{0.6, -13.0, -0.5}, 1.1}};
}

/// The flights' true ranges, for hand_flights.
std::vector<std::pair<double, double>> true_ranges(const test::SyntheticRecording& synthetic) {
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : synthetic.tosses) ranges.emplace_back(t.t_start, t.t_end);
  return ranges;
}

/// `synthetic` (made without noise) with a stationary AR(1) noise of standard deviation
/// `sigma` per component added to every sample: x_i = ρ x_{i−1} + √(1 − ρ²) σ ε_i, the ε the
/// same sequence for every ρ (seeded), so that only the correlation differs.
GyroRecording with_ar1_noise(const test::SyntheticRecording& synthetic, double sigma, double rho) {
  GyroRecording recording = as_recording(synthetic);
  std::mt19937 random(7);
  std::normal_distribution<double> gauss(0.0, 1.0);
  Eigen::Vector3d x(gauss(random), gauss(random), gauss(random));
  x *= sigma;
  for (Eigen::Vector3d& w : recording.omega) {
    const Eigen::Vector3d e(gauss(random), gauss(random), gauss(random));
    x = rho * x + std::sqrt(1.0 - rho * rho) * sigma * e;
    w += x;
  }
  return recording;
}

// The same flights with white noise and with an AR(1) noise of ρ = 0.6 of the same size: each
// toss's ω0 σ (the covariance's alone) grows by √((1 + ρ)/(1 − ρ)) = 2, the inflation's square
// root; without the inflation it would stay near 1.
TEST(ErrorBars, CorrelatedResidualInflatesTheCovarianceByOnePlusRhoOverOneMinusRho) {
  const test::SyntheticRecording clean =
      test::make_recording(test::phone_on_book(), three_tosses(), 3, 0.0);
  const double rho = 0.6, sigma = 0.01;
  FitSettings settings;
  settings.drag = physics::DragLaw::none;
  const GyroRecording white = with_ar1_noise(clean, sigma, 0.0);
  const GyroRecording red = with_ar1_noise(clean, sigma, rho);
  const FitResult a = fit_recording(white, hand_flights(white, true_ranges(clean)), settings);
  const FitResult b = fit_recording(red, hand_flights(red, true_ranges(clean)), settings);
  ASSERT_EQ(a.tosses.size(), 3u);
  ASSERT_EQ(b.tosses.size(), 3u);
  const double expected = std::sqrt((1.0 + rho) / (1.0 - rho));
  for (std::size_t k = 0; k < 3; ++k) {
    ASSERT_TRUE(a.tosses[k].omega0_sigma && b.tosses[k].omega0_sigma);
    for (int i = 0; i < 3; ++i) {
      const double ratio = (*b.tosses[k].omega0_sigma)[i] / (*a.tosses[k].omega0_sigma)[i];
      // ρ from ~1000 samples: ±0.03; the residual variance of the two noises: ±10 %.
      EXPECT_NEAR(ratio, expected, 0.25 * expected) << "toss " << k << " component " << i;
    }
  }
}

/// Appends `part` (its own times from 0) after `whole`'s last sample.
void append(test::SyntheticRecording& whole, const test::SyntheticRecording& part) {
  const double offset = whole.t.empty() ? 0.0 : whole.t.back() + 0.01;
  for (std::size_t i = 0; i < part.t.size(); ++i) {
    whole.t.push_back(part.t[i] + offset);
    whole.omega.push_back(part.omega[i]);
  }
  for (test::TrueToss toss : part.tosses) {
    toss.t_start += offset;
    toss.t_end += offset;
    whole.tosses.push_back(toss);
  }
}

// Three tosses of three slightly different bodies (I1/I3 and I2/I3 apart by a few %, far more
// than the noise moves them): the ratios' σ is the jackknife's, σ² = (G − 1)/G Σ (θ_g − θ̄)²
// with G = 3 folds, θ_g the body fitted without toss g (here: the fit of the other two alone).
TEST(ErrorBars, RatioSigmaIsTheGroupedJackknifeOverTheFolds) {
  const std::vector<SyntheticToss> tosses = three_tosses();
  const double stretch[3][2] = {{1.0, 1.0}, {1.04, 0.98}, {0.97, 1.03}};
  test::SyntheticRecording whole;
  for (int k = 0; k < 3; ++k) {
    test::SyntheticBody body = test::phone_on_book();
    body.moments[0] *= stretch[k][0];
    body.moments[1] *= stretch[k][1];
    append(whole, test::make_recording(body, {tosses[k]}, 20 + k, 0.005));
  }
  const GyroRecording recording = as_recording(whole);
  const std::vector<std::pair<double, double>> ranges = true_ranges(whole);
  FitSettings settings;
  settings.drag = physics::DragLaw::none;
  const FitResult all = fit_recording(recording, hand_flights(recording, ranges), settings);
  ASSERT_EQ(all.tosses.size(), 3u);
  ASSERT_TRUE(all.body.ratio_sigma.has_value());
  std::vector<Eigen::Vector3d> theta;
  for (int g = 0; g < 3; ++g) {
    std::vector<std::pair<double, double>> others;
    for (int j = 0; j < 3; ++j)
      if (j != g) others.push_back(ranges[j]);
    theta.push_back(
        fit_recording(recording, hand_flights(recording, others), settings).body.ratios);
  }
  const Eigen::Vector3d mean = (theta[0] + theta[1] + theta[2]) / 3.0;
  for (int i = 0; i < 2; ++i) {
    double sum2 = 0.0;
    for (const Eigen::Vector3d& t : theta) sum2 += (t[i] - mean[i]) * (t[i] - mean[i]);
    const double jackknife = std::sqrt(2.0 / 3.0 * sum2);
    ASSERT_GT(jackknife, 0.005 * mean[i]) << "ratio " << i << ": the bodies differ too little";
    EXPECT_NEAR((*all.body.ratio_sigma)[i], jackknife, 0.1 * jackknife) << "ratio " << i;
  }
  EXPECT_EQ((*all.body.ratio_sigma)[2], 0.0);
}

}  // namespace
}  // namespace bookspin::fit
