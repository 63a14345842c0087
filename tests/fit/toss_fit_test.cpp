// The fit against synthetic recordings made independently (synthetic_recording.hpp): the
// moment ratios within 1 %, the principal axes within 1°, half_period_predicted within 2 % of
// the closed form.
#include "fit/toss_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "fit/fit_tables.hpp"
#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "support/scratch.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

using test::SyntheticBody;
using test::SyntheticToss;

using test::as_recording;

/// Angle (degrees) between two axes, sign ignored.
double axis_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180.0 / M_PI;
}

/// The recording written as a phyphox export in `dialect` and read back, as `bookspin fit` reads
/// it.
GyroRecording through_file(const test::SyntheticRecording& synthetic, test::Dialect dialect,
                           const std::string& name) {
  const auto dir = bookspin::test::fresh_dir("fit/toss-fit/" + name);
  test::write_export(dir, synthetic, dialect);
  return pool_recordings({read_recording(dir)});
}

void expect_body_recovered(const SyntheticBody& body, const std::vector<SyntheticToss>& tosses,
                           unsigned seed, test::Dialect dialect, const std::string& name) {
  const test::SyntheticRecording synthetic = test::make_recording(body, tosses, seed);
  const GyroRecording recording = through_file(synthetic, dialect, name);
  ASSERT_EQ(recording.pauses.size(), 1u);
  const FitResult fit = fit_recording(recording, find_flights(recording));
  ASSERT_EQ(fit.tosses.size(), tosses.size());
  const Eigen::Vector3d ratios = body.moments / body.moments[2];
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(fit.body.ratios[i], ratios[i], 0.01 * ratios[i]) << "ratio " << i;
    EXPECT_LT(axis_angle(fit.body.axes.col(i), body.axes.col(i)), 1.0) << "axis " << i;
  }
  ASSERT_TRUE(fit.body.ratio_sigma.has_value());
  for (std::size_t k = 0; k < tosses.size(); ++k) {
    const TossFit& toss = fit.tosses[k];
    const double truth = synthetic.tosses[k].half_period;
    EXPECT_FALSE(toss.stable);
    ASSERT_TRUE(toss.half_period_predicted.has_value()) << "toss " << k;
    EXPECT_NEAR(*toss.half_period_predicted, truth, 0.02 * truth) << "toss " << k;
    ASSERT_TRUE(toss.half_period_fitted.has_value());
    EXPECT_NEAR(*toss.half_period_fitted, truth, 0.01 * truth) << "toss " << k;
    EXPECT_LT(toss.residual_rms, 0.05);       // the noise is 0.01 rad/s a component
    EXPECT_LT(std::abs(toss.L_decay), 0.02);  // no drag in the synthetic flights
  }
}

TEST(TossFit, RecoversAPhoneAlone) {
  expect_body_recovered(
      test::phone_alone(),
      {{{0.3, 14.0, 0.5}, 1.2}, {{-0.4, 13.0, 0.6}, 1.1}, {{0.5, -15.0, -0.3}, 1.3}}, 11,
      test::Dialect::comma, "phone");
}

TEST(TossFit, RecoversAPhoneOnABook) {
  expect_body_recovered(
      test::phone_on_book(),
      {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.2}, {{0.6, -13.0, -0.5}, 1.1}}, 12,
      test::Dialect::tab, "book");
}

TEST(TossFit, RecoversARacquetWithTwoNearlyEqualMoments) {
  expect_body_recovered(
      test::racquet(),
      {{{0.4, 14.0, 0.8}, 1.2}, {{-0.6, 12.0, 0.9}, 1.3}, {{0.5, -13.0, -0.7}, 1.2}}, 13,
      test::Dialect::semicolon, "racquet");
}

TEST(TossFit, StableTossesSaySoAndTheOthersDetermineTheBody) {
  // Two flips about the intermediate axis and one spin about the largest, wobbling 5°.
  const SyntheticBody body = test::phone_on_book();
  const test::SyntheticRecording synthetic = test::make_recording(
      body, {{{0.5, 12.0, 0.4}, 1.2}, {{0.6, 0.5, 12.0}, 1.0}, {{-0.3, 11.0, 0.7}, 1.2}}, 21);
  const FitResult fit =
      fit_recording(as_recording(synthetic), find_flights(as_recording(synthetic)));
  ASSERT_EQ(fit.tosses.size(), 3u);
  EXPECT_FALSE(fit.tosses[0].stable);
  EXPECT_TRUE(fit.tosses[1].stable);
  EXPECT_FALSE(fit.tosses[2].stable);
  EXPECT_TRUE(fit.body.moments_determined);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(fit.body.ratios[i], body.moments[i] / body.moments[2],
                0.01 * body.moments[i] / body.moments[2]);
  ASSERT_EQ(fit.body.notes.size(), 1u);
  EXPECT_NE(fit.body.notes[0].find("1 stable toss"), std::string::npos);
}

TEST(TossFit, OnlyStableTossesLeaveTheMomentsPoorlyDetermined) {
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_on_book(), {{{0.6, 0.5, 12.0}, 1.0}, {{-0.5, 0.6, 11.0}, 1.0}}, 22);
  const FitResult fit =
      fit_recording(as_recording(synthetic), find_flights(as_recording(synthetic)));
  ASSERT_EQ(fit.tosses.size(), 2u);
  EXPECT_TRUE(fit.tosses[0].stable && fit.tosses[1].stable);
  EXPECT_FALSE(fit.body.moments_determined);
  bool said = false;
  for (const std::string& note : fit.body.notes)
    said |= note.find("--moments") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(TossFit, GivenMomentsAreKeptAndOneTossIsPredicted) {
  // One toss: with --moments its half period is still predicted (from its first 0.2 s).
  const SyntheticBody body = test::phone_alone();
  const test::SyntheticRecording synthetic =
      test::make_recording(body, {{{1.0, 18.0, 1.2}, 1.3}}, 23);
  FitSettings settings;
  settings.moments = Eigen::Vector3d(274.0, 49.64, 225.64);  // any order, any scale
  const FitResult fit =
      fit_recording(as_recording(synthetic), find_flights(as_recording(synthetic)), settings);
  EXPECT_TRUE(fit.body.moments_fixed);
  EXPECT_DOUBLE_EQ(fit.body.ratios[0], 49.64 / 274.0);
  EXPECT_DOUBLE_EQ(fit.body.ratios[1], 225.64 / 274.0);
  EXPECT_LT(axis_angle(fit.body.axes.col(1), body.axes.col(1)), 1.0);
  ASSERT_TRUE(fit.tosses[0].half_period_predicted.has_value());
  const double truth = synthetic.tosses[0].half_period;
  EXPECT_NEAR(*fit.tosses[0].half_period_predicted, truth, 0.02 * truth);
  // Without them, one toss has no prediction, and says so.
  const FitResult alone =
      fit_recording(as_recording(synthetic), find_flights(as_recording(synthetic)));
  EXPECT_FALSE(alone.tosses[0].half_period_predicted.has_value());
}

// Given moments however far apart, short of breaking the triangle inequality (a rod: 10^-e, 1, 1,
// at any scale): the fit gives finite ratios, or refuses in one line naming the ratio as the
// cause, where the exact motion about the smallest axis turns past its time horizon within a
// flight (docs/physics.md §8, "How far in time"); never the horizon's bare message.
TEST(TossFit, GivenMomentsTooFarApartAreNamedAsTheCause) {
  const test::SyntheticRecording synthetic =
      test::make_recording(test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}}, 23);
  const GyroRecording recording = as_recording(synthetic);
  const FlightSearch search = find_flights(recording);
  int refused = 0;
  for (double e : {3.0, 20.0, 60.0, 120.0, 150.0, 300.0})
    for (double scale : {1.0, 1e-150, 1e150}) {
      if (scale * std::pow(10.0, -e) == 0.0) continue;  // beyond a double
      FitSettings settings;
      settings.moments = Eigen::Vector3d(std::pow(10.0, -e) * scale, scale, scale);
      try {
        const FitResult fit = fit_recording(recording, search, settings);
        EXPECT_TRUE(fit.body.ratios.allFinite()) << e;
      } catch (const InputError& error) {
        ++refused;
        const std::string what = error.what();
        char ratio[40];
        std::snprintf(ratio, sizeof ratio, "(the smallest %.3g of the largest)",
                      std::pow(10.0, -e));
        EXPECT_EQ(
            what.find(recording.source + ": the moments given are too far apart to fit " + ratio),
            0u)
            << what;
      }
    }
  EXPECT_GT(refused, 0);
}

// Given moments with two equal (1, 1, 1; or 2, 5, 2 in any order) say that there is no
// intermediate axis; three distinct ones (the test above's) say nothing of it.
TEST(TossFit, GivenMomentsWithTwoEqualSayThereIsNoIntermediateAxis) {
  const test::SyntheticRecording synthetic =
      test::make_recording(test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}}, 23);
  const auto says = [&](const Eigen::Vector3d& moments) {
    FitSettings settings;
    settings.moments = moments;
    const FitResult fit =
        fit_recording(as_recording(synthetic), find_flights(as_recording(synthetic)), settings);
    return std::any_of(fit.body.notes.begin(), fit.body.notes.end(), [](const std::string& n) {
      return n.find("no intermediate axis") != std::string::npos;
    });
  };
  EXPECT_TRUE(says(Eigen::Vector3d(1, 1, 1)));
  EXPECT_TRUE(says(Eigen::Vector3d(2, 5, 2)));
  EXPECT_FALSE(says(Eigen::Vector3d(274.0, 49.64, 225.64)));
}

// Each prediction says what it rests on: the other folds' tosses (three tosses: the two others)
// and their flight time, summed here from the flights found; with --moments and one toss, 0 and
// 0. A prediction resting on too little flight (a 0.4 s bounce) is said to be poorly founded.
TEST(TossFit, EachPredictionSaysWhatItRestsOn) {
  const test::SyntheticRecording three = test::make_recording(
      test::phone_alone(),
      {{{0.3, 14.0, 0.5}, 1.2}, {{-0.4, 13.0, 0.6}, 1.1}, {{0.5, -15.0, -0.3}, 1.3}}, 11);
  const GyroRecording recording = as_recording(three);
  const FlightSearch search = find_flights(recording);
  const FitResult fit = fit_recording(recording, search);
  ASSERT_EQ(fit.tosses.size(), 3u);
  double total = 0.0;
  for (const Flight& f : search.flights) total += f.t_end - f.t_start;
  for (std::size_t k = 0; k < 3; ++k) {
    const TossFit& toss = fit.tosses[k];
    ASSERT_TRUE(toss.predicted_from_tosses.has_value());
    EXPECT_EQ(*toss.predicted_from_tosses, 2);
    const double own = search.flights[k].t_end - search.flights[k].t_start;
    EXPECT_NEAR(*toss.predicted_from_seconds, total - own, 1e-12);
  }
  const auto warns = [](const FitResult& f) {
    return std::any_of(f.body.notes.begin(), f.body.notes.end(), [](const std::string& n) {
      return n.find("too little flight to pin it well") != std::string::npos;
    });
  };
  EXPECT_FALSE(warns(fit));
  // A throw and its 0.4 s bounce: the throw's prediction rests on the bounce alone.
  const test::SyntheticRecording bounce = test::make_recording(
      test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.2}, {{-0.4, 13.0, 0.6}, 0.4}}, 12);
  const GyroRecording with_bounce = as_recording(bounce);
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : bounce.tosses) ranges.emplace_back(t.t_start, t.t_end);
  const FitResult short_fit = fit_recording(with_bounce, hand_flights(with_bounce, ranges));
  ASSERT_EQ(short_fit.tosses.size(), 2u);
  EXPECT_EQ(short_fit.tosses[0].predicted_from_tosses, 1);
  EXPECT_LT(*short_fit.tosses[0].predicted_from_seconds, 0.6);
  EXPECT_TRUE(warns(short_fit));
  // One toss with --moments: the given moments, no other toss.
  FitSettings given;
  given.moments = Eigen::Vector3d(274.0, 49.64, 225.64);
  const test::SyntheticRecording one =
      test::make_recording(test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}}, 23);
  const FitResult alone = fit_recording(as_recording(one), find_flights(as_recording(one)), given);
  ASSERT_TRUE(alone.tosses[0].half_period_predicted.has_value());
  EXPECT_EQ(alone.tosses[0].predicted_from_tosses, 0);
  EXPECT_EQ(alone.tosses[0].predicted_from_seconds, 0.0);
}

TEST(TossFit, AStretchHoldingTheThrowIsAPoorFitAndSaysSo) {
  // By hand, a stretch that starts 0.1 s before the release: the throw's ramp and spikes are in
  // it, and no exact motion fits them.
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}}, 25);
  const GyroRecording recording = as_recording(synthetic);
  const auto& truth = synthetic.tosses;
  const FitResult fit = fit_recording(
      recording, hand_flights(recording, {{truth[0].t_start + 0.02, truth[0].t_end - 0.02},
                                          {truth[1].t_start - 0.1, truth[1].t_end - 0.02}}));
  ASSERT_EQ(fit.tosses.size(), 2u);
  EXPECT_TRUE(fit.tosses[1].poor_fit);
  bool said = false;
  for (const std::string& note : fit.body.notes) said |= note.rfind("toss 2 flagged: ", 0) == 0;
  EXPECT_TRUE(said);
  // The clean stretches of the other tests are not.
  const FitResult clean = fit_recording(recording, find_flights(recording));
  for (const TossFit& toss : clean.tosses) EXPECT_FALSE(toss.poor_fit);
}

TEST(TossFit, UncertaintiesAreTheScatterOverTheNoise) {
  // The same two tosses of a phone on a book, twelve times with fresh noise (0.05 rad/s): the
  // spread of the fitted ratios and axes about the truth is what the reported σ says, within a
  // factor of two (the spread of twelve is itself uncertain by about a fifth).
  const SyntheticBody body = test::phone_on_book();
  constexpr int kSeeds = 12;
  Eigen::Vector2d ratio_sum2 = Eigen::Vector2d::Zero(), ratio_sigma = Eigen::Vector2d::Zero();
  Eigen::Vector3d axis_sum2 = Eigen::Vector3d::Zero(), axis_sigma = Eigen::Vector3d::Zero();
  for (int seed = 0; seed < kSeeds; ++seed) {
    const test::SyntheticRecording synthetic = test::make_recording(
        body, {{{0.5, 12.0, 0.4}, 1.0}, {{-0.3, 11.0, 0.7}, 1.0}}, 100 + seed, 0.05);
    const FitResult fit =
        fit_recording(as_recording(synthetic), find_flights(as_recording(synthetic)));
    ASSERT_EQ(fit.tosses.size(), 2u);
    ASSERT_TRUE(fit.body.ratio_sigma && fit.body.axis_sigma_deg);
    for (int i = 0; i < 2; ++i) {
      ratio_sum2[i] += std::pow(fit.body.ratios[i] - body.moments[i] / body.moments[2], 2);
      ratio_sigma[i] += (*fit.body.ratio_sigma)[i] / kSeeds;
    }
    for (int i = 0; i < 3; ++i) {
      axis_sum2[i] += std::pow(axis_angle(fit.body.axes.col(i), body.axes.col(i)), 2);
      axis_sigma[i] += (*fit.body.axis_sigma_deg)[i] / kSeeds;
    }
  }
  for (int i = 0; i < 2; ++i) {
    const double spread = std::sqrt(ratio_sum2[i] / kSeeds);
    EXPECT_GT(spread / ratio_sigma[i], 0.5) << "ratio " << i;
    EXPECT_LT(spread / ratio_sigma[i], 2.0) << "ratio " << i;
  }
  for (int i = 0; i < 3; ++i) {
    const double spread = std::sqrt(axis_sum2[i] / kSeeds);  // the angle has two components
    EXPECT_GT(spread / axis_sigma[i], 0.5) << "axis " << i;
    EXPECT_LT(spread / axis_sigma[i], 2.0) << "axis " << i;
  }
}

TEST(TossFit, DragShowsAsLDecay) {
  // |ω| shrinking as e^(−0.05 τ): |L| loses 5 % a second; the straight line through
  // e^(−0.05 τ) over 1.2 s has slope/intercept −0.0515 (least squares), within 5 % of 0.05.
  const test::SyntheticRecording synthetic =
      test::make_recording(test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.2}, {{-1.2, 17.0, 1.5}, 1.2}},
                           24, 0.01, 0.15, 4.0, 0.05);
  const FitResult fit =
      fit_recording(as_recording(synthetic), find_flights(as_recording(synthetic)));
  ASSERT_EQ(fit.tosses.size(), 2u);
  for (const TossFit& toss : fit.tosses) EXPECT_NEAR(toss.L_decay, 0.05, 0.005);
}

// Strong drag (|L| decaying at 1.5 /s) fitted without a drag law: the flights alone would read the
// lost spin as a bias of rad/s. The correction stays within 3σ of the rest on each axis, σ the
// rest's own scatter (here measured independently on the first rest, the 1.5 s before the first
// throw: its wobble of 0.03 rad/s and the 0.01 rad/s noise).
TEST(TossFit, TheBiasCorrectionStaysWithinWhatTheRestAllows) {
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_alone(),
      {{{1.0, 18.0, 1.2}, 1.2}, {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, 16.0, -1.0}, 1.2}}, 31, 0.01, 0.15,
      4.0, 1.5);
  const GyroRecording recording = as_recording(synthetic);
  FitSettings settings;
  settings.drag = physics::DragLaw::none;
  const FitResult fit = fit_recording(recording, find_flights(recording), settings);
  ASSERT_GT(fit.parts.at(0).rest.samples, 0);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), squares = Eigen::Vector3d::Zero();
  int n = 0;
  for (std::size_t i = 0; synthetic.t[i] < 1.4; ++i, ++n) mean += synthetic.omega[i];
  mean /= n;
  for (int i = 0; i < n; ++i) squares += (synthetic.omega[i] - mean).cwiseAbs2();
  const Eigen::Vector3d scatter = (squares / (n - 1)).cwiseSqrt();
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(fit.parts.at(0).rest.sigma[c], scatter[c], 0.3 * scatter[c]) << c;
    EXPECT_LE(std::abs(fit.parts.at(0).bias_correction[c]), fit.parts.at(0).rest.bound()[c] + 1e-12)
        << c;
    // The bias removed in flight is the generator's within the bound.
    EXPECT_NEAR(fit.parts.at(0).bias_in_flight()[c], synthetic.bias[c],
                3.0 * fit.parts.at(0).rest.sigma[c] + 0.01)
        << c;
  }
  // The body CSV says both: the bias removed and the rest's σ.
  const CsvTable body = fit_body_csv(fit);
  const auto column = [&](const std::string& name) {
    const auto at = std::find(body.columns.begin(), body.columns.end(), name);
    EXPECT_NE(at, body.columns.end()) << name;
    return std::get<CsvNumber>(body.rows.at(0).at(at - body.columns.begin())).value.value();
  };
  EXPECT_EQ(column("bias_x"), fit.parts.at(0).bias_in_flight()[0]);
  EXPECT_EQ(column("bias_sigma_z"), fit.parts.at(0).rest.sigma[2]);
}

// A recording of the flights alone (the rests cut out): the bias is fitted from the flights, with
// its standard error, and the summary and the body CSV say so; the generator's bias lies within
// 3σ of it on each axis.
TEST(TossFit, WithNoRestTheBiasIsFittedFromTheFlightsWithItsSigma) {
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_on_book(),
      {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.3}, {{0.6, -13.0, -0.5}, 1.1}}, 33, 0.01);
  GyroRecording recording;
  recording.source = "flights-only.csv";
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& toss : synthetic.tosses) ranges.emplace_back(toss.t_start, toss.t_end);
  for (std::size_t i = 0; i < synthetic.t.size(); ++i)
    for (const auto& [t0, t1] : ranges)
      if (synthetic.t[i] >= t0 && synthetic.t[i] <= t1) {
        recording.t.push_back(synthetic.t[i]);
        recording.omega.push_back(synthetic.omega[i]);
      }
  recording = pool_recordings({recording});
  const FitResult fit = fit_recording(recording, hand_flights(recording, ranges));
  ASSERT_EQ(fit.parts.at(0).rest.samples, 0);
  ASSERT_TRUE(fit.parts.at(0).bias_fitted_sigma.has_value());
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT((*fit.parts.at(0).bias_fitted_sigma)[c], 0.0) << c;
    EXPECT_NEAR(fit.parts.at(0).bias_in_flight()[c], synthetic.bias[c],
                3.0 * (*fit.parts.at(0).bias_fitted_sigma)[c])
        << c;
  }
  // The bias's line follows the result table (its title, header and a row a toss).
  const std::size_t bias_line = 2 + fit.tosses.size();
  EXPECT_EQ(
      fit_summary(fit).at(bias_line).rfind(
          "no still stretch in the recording: the bias (rad/s) is fitted from the flights: ", 0),
      0u)
      << fit_summary(fit).at(bias_line);
  const CsvTable body = fit_body_csv(fit);
  const auto at = std::find(body.columns.begin(), body.columns.end(), "bias_sigma_y");
  ASSERT_NE(at, body.columns.end());
  EXPECT_EQ(std::get<CsvNumber>(body.rows.at(0).at(at - body.columns.begin())).value.value(),
            (*fit.parts.at(0).bias_fitted_sigma)[1]);
}

// A light, broad body whose |L| decays at 3 /s over four 1.3 s flights (linear drag): each
// toss's fitted rate is within 2σ of the generator's 3 /s, or the toss is flagged with a reason;
// the bias removed is within 3σ of the rest's mean.
TEST(TossFit, StrongDragIsFittedAsDragNotBias) {
  const test::SyntheticRecording synthetic = test::make_recording(test::phone_on_book(),
                                                                  {{{0.5, 14.0, 0.4}, 1.3},
                                                                   {{-0.3, 13.0, 0.7}, 1.3},
                                                                   {{0.6, -14.0, -0.5}, 1.3},
                                                                   {{-0.4, -13.0, 0.6}, 1.3}},
                                                                  41, 0.01, 0.15, 4.0, 3.0);
  const GyroRecording recording = as_recording(synthetic);
  const FitResult fit = fit_recording(recording, find_flights(recording));
  ASSERT_GT(fit.parts.at(0).rest.samples, 0);
  for (int c = 0; c < 3; ++c)
    EXPECT_LE(std::abs(fit.parts.at(0).bias_correction[c]), fit.parts.at(0).rest.bound()[c] + 1e-12)
        << c;
  ASSERT_EQ(fit.tosses.size(), 4u);
  for (const TossFit& toss : fit.tosses) {
    if (toss.poor_fit) {
      EXPECT_FALSE(toss.flag.empty());
      continue;
    }
    ASSERT_TRUE(toss.drag_rate_sigma.has_value());
    EXPECT_NEAR(toss.drag_rate, 3.0, 2.0 * *toss.drag_rate_sigma);
  }
}

/// The tosses of the drag tests: three flipping tosses of a phone on a book, 1.1–1.3 s each.
std::vector<SyntheticToss> drag_tosses() {
  return {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.3}, {{0.6, -13.0, -0.5}, 1.1}};
}

// Drag of 0.05–0.3 /s under both laws, each phyphox dialect, noise, bias and jitter: the fitted
// rate within 5 % of the generator's (its RK4 written from the torque, synthetic_recording.hpp),
// the ratios within 1 %, the axes within 1°.
TEST(TossFit, RecoversTheDragRateUnderEitherLaw) {
  const test::Dialect dialects[] = {test::Dialect::comma, test::Dialect::tab,
                                    test::Dialect::semicolon};
  int n = 0;
  for (bool quadratic : {false, true}) {
    for (double rate : {0.05, 0.15, 0.3}) {
      const SyntheticBody body = test::phone_on_book();
      test::SyntheticDrag air;
      air.rate = rate;
      air.quadratic = quadratic;
      const test::SyntheticRecording synthetic =
          test::make_recording(body, drag_tosses(), 40 + n, 0.01, 0.15, 4.0, 0.0, 100.0, air);
      const GyroRecording recording =
          through_file(synthetic, dialects[n % 3], "drag-" + std::to_string(n));
      ++n;
      FitSettings settings;
      settings.drag = quadratic ? physics::DragLaw::quadratic : physics::DragLaw::linear;
      const FitResult fit = fit_recording(recording, find_flights(recording), settings);
      const std::string what =
          std::string(quadratic ? "quadratic" : "linear") + " " + std::to_string(rate);
      ASSERT_EQ(fit.tosses.size(), 3u) << what;
      const Eigen::Vector3d ratios = body.moments / body.moments[2];
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(fit.body.ratios[i], ratios[i], 0.01 * ratios[i]) << what << " ratio " << i;
        EXPECT_LT(axis_angle(fit.body.axes.col(i), body.axes.col(i)), 1.0) << what << " axis " << i;
      }
      for (const TossFit& toss : fit.tosses) {
        EXPECT_NEAR(toss.drag_rate, rate, 0.05 * rate) << what;
        ASSERT_TRUE(toss.drag_rate_sigma.has_value());
        EXPECT_FALSE(toss.poor_fit) << what << ": " << toss.flag;
      }
    }
  }
}

// Without drag the fitted rate is noise: within 2σ of zero (σ its own), for most tosses of
// several recordings (at 2σ, about 1 in 20 may stray: at most 2 of 12).
TEST(TossFit, WithoutDragTheFittedRateIsWithinTwoSigmaOfZero) {
  int strays = 0, count = 0;
  for (unsigned seed : {51u, 52u, 53u, 54u}) {
    const test::SyntheticRecording synthetic =
        test::make_recording(test::phone_on_book(), drag_tosses(), seed);
    const FitResult fit =
        fit_recording(as_recording(synthetic), find_flights(as_recording(synthetic)));
    for (const TossFit& toss : fit.tosses) {
      ASSERT_TRUE(toss.drag_rate_sigma.has_value());
      EXPECT_LT(*toss.drag_rate_sigma, 0.02);  // the rate is well measured, not just uncertain
      if (std::abs(toss.drag_rate) > 2.0 * *toss.drag_rate_sigma) ++strays;
      ++count;
    }
  }
  EXPECT_EQ(count, 12);
  EXPECT_LE(strays, 2);
}

// A catch inside a flight (the hand grabs the phone 0.3 s before the flight's end) is flagged
// and says so; the clean tosses of the same recording are not.
TEST(TossFit, ACatchInsideTheFlightIsFlaggedAndCleanTossesAreNot) {
  const test::SyntheticRecording synthetic =
      test::make_recording(test::phone_on_book(), drag_tosses(), 61, 0.01, 0.15, 4.0, 0.1);
  // The flights by hand (the truth), the second running 0.25 s into its catch: ω there falls
  // to rest with spikes.
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : synthetic.tosses) ranges.emplace_back(t.t_start, t.t_end);
  const GyroRecording recording = as_recording(synthetic);
  const FitResult clean = fit_recording(recording, hand_flights(recording, ranges));
  for (const TossFit& toss : clean.tosses) EXPECT_FALSE(toss.poor_fit) << toss.flag;
  ranges[1].second += 0.1;
  const FitResult caught = fit_recording(recording, hand_flights(recording, ranges));
  EXPECT_FALSE(caught.tosses[0].poor_fit) << caught.tosses[0].flag;
  EXPECT_TRUE(caught.tosses[1].poor_fit);
  EXPECT_NE(caught.tosses[1].flag.find("catch"), std::string::npos) << caught.tosses[1].flag;
  EXPECT_FALSE(caught.tosses[2].poor_fit) << caught.tosses[2].flag;
}

// A recording whose ω no gyroscope can measure (ω scaled by 1e5: up to about 1.4e6 rad/s, far
// beyond the ±4000 °/s = 69.8 rad/s of the widest consumer gyroscope) is flagged for that,
// whatever its residual; the same recording as measured is not.
TEST(TossFit, OmegaBeyondAnyGyroscopesRangeIsFlaggedForIt) {
  const test::SyntheticRecording synthetic =
      test::make_recording(test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.0}, {{0.4, 13.0, 0.6}, 1.1}});
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : synthetic.tosses) ranges.emplace_back(t.t_start, t.t_end);
  GyroRecording recording = as_recording(synthetic);
  const FitResult measured = fit_recording(recording, hand_flights(recording, ranges));
  for (const TossFit& toss : measured.tosses) EXPECT_EQ(toss.flag.find("range"), std::string::npos);
  for (Eigen::Vector3d& w : recording.omega) w *= 1e5;
  const FitResult scaled = fit_recording(recording, hand_flights(recording, ranges));
  for (const TossFit& toss : scaled.tosses) {
    EXPECT_TRUE(toss.poor_fit);
    EXPECT_NE(toss.flag.find("beyond any gyroscope's range"), std::string::npos) << toss.flag;
    EXPECT_NE(toss.flag.find("69.8 rad/s"), std::string::npos) << toss.flag;
  }
}

// half_period_predicted sees nothing of its own toss after the first predict_window s: toss 2's
// later samples scaled by 5 % change its fitted half period but not its prediction (only the
// solver's tolerance apart); the fold that predicts toss 2 is the one without it.
TEST(TossFit, ThePredictionIgnoresItsOwnTossAfterTheWindow) {
  const test::SyntheticRecording synthetic =
      test::make_recording(test::phone_on_book(), drag_tosses(), 71, 0.01, 0.15, 4.0, 0.1);
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : synthetic.tosses) ranges.emplace_back(t.t_start, t.t_end);
  GyroRecording recording = as_recording(synthetic);
  const FitResult before = fit_recording(recording, hand_flights(recording, ranges));
  for (std::size_t i = 0; i < recording.t.size(); ++i)
    if (recording.t[i] > ranges[1].first + 0.25 && recording.t[i] <= ranges[1].second)
      recording.omega[i] = 1.05 * (recording.omega[i] - synthetic.bias) + synthetic.bias;
  const FitResult after = fit_recording(recording, hand_flights(recording, ranges));
  ASSERT_TRUE(before.tosses[1].half_period_predicted && after.tosses[1].half_period_predicted);
  EXPECT_NEAR(*after.tosses[1].half_period_predicted, *before.tosses[1].half_period_predicted,
              1e-6 * *before.tosses[1].half_period_predicted);
  EXPECT_GT(std::abs(*after.tosses[1].half_period_fitted - *before.tosses[1].half_period_fitted),
            1e-3 * *before.tosses[1].half_period_fitted);
}

// fitted_omega runs from each toss's own start: at t_start it is the fitted ω0, and through
// the flight it follows the measurement.
TEST(TossFit, FittedOmegaStartsAtItsTossesStart) {
  const test::SyntheticRecording synthetic =
      test::make_recording(test::phone_on_book(), drag_tosses(), 81, 0.01, 0.15, 4.0, 0.1);
  const GyroRecording recording = as_recording(synthetic);
  const FitResult fit = fit_recording(recording, find_flights(recording));
  ASSERT_EQ(fit.tosses.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const TossFit& toss = fit.tosses[k];
    EXPECT_LT((fitted_omega(fit, k, toss.flight.t_start) - toss.omega0).norm(), 1e-9);
    std::vector<double> t;
    std::vector<Eigen::Vector3d> w;
    measured_omega(recording, fit, k, t, w);
    for (std::size_t i = 0; i < t.size(); i += 10)
      EXPECT_LT((fitted_omega(fit, k, t[i]) - w[i]).norm(), 0.1) << "toss " << k << " t " << t[i];
  }
}

// Two recordings of one body in air whose drag the model cannot quite fit (anisotropic: the
// torque is not along L), with different tosses and noise: their moment ratios agree within two
// combined standard deviations, and each ratio's σ is not the white-noise covariance's alone
// (docs/phone-lab.md, "Error bars").
TEST(TossFit, TwoRecordingsOfOneBodyAgreeWithinTheirErrorBars) {
  test::SyntheticDrag air;
  air.rate = 0.18;
  air.anisotropy = Eigen::Vector3d(1.4, 0.8, 1.0);
  const SyntheticBody body = test::phone_on_book();
  const test::SyntheticRecording a =
      test::make_recording(body, drag_tosses(), 91, 0.02, 0.15, 4.0, 0.0, 100.0, air);
  const test::SyntheticRecording b = test::make_recording(body,
                                                          {{{-0.4, 12.5, 0.6}, 1.2},
                                                           {{0.5, -11.5, 0.3}, 1.2},
                                                           {{0.3, 12.0, -0.6}, 1.3},
                                                           {{-0.6, -12.0, -0.4}, 1.1}},
                                                          92, 0.02, 0.15, 4.0, 0.0, 100.0, air);
  const FitResult fa = fit_recording(as_recording(a), find_flights(as_recording(a)));
  const FitResult fb = fit_recording(as_recording(b), find_flights(as_recording(b)));
  ASSERT_TRUE(fa.body.ratio_sigma && fb.body.ratio_sigma);
  for (int i = 0; i < 2; ++i) {
    const double combined = std::hypot((*fa.body.ratio_sigma)[i], (*fb.body.ratio_sigma)[i]);
    EXPECT_LT(std::abs(fa.body.ratios[i] - fb.body.ratios[i]), 2.0 * combined)
        << "ratio " << i << ": " << fa.body.ratios[i] << " ± " << (*fa.body.ratio_sigma)[i]
        << " against " << fb.body.ratios[i] << " ± " << (*fb.body.ratio_sigma)[i];
  }
}

}  // namespace
}  // namespace bookspin::fit
