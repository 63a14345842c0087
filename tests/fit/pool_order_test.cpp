// A pooled set is a set (docs/phone-lab.md, "A class's recordings"): the recordings of one body
// given in any order (a command line's, a dropped folder's) give the same tosses, numbers, names
// and outputs to the last digit, on the real recordings in ../shared/recordings-real/ (skipped,
// saying why, where absent) and on synthetic ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

/// Every value a door presents, `b`'s against `a`'s, to the last bit: the name, the tables' and
/// summary's text, every toss's flight, numbers, chart and scene.
void expect_same_report(const FitReport& a, const FitReport& b) {
  EXPECT_EQ(a.recording, b.recording);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.toss_csv, b.toss_csv);
  EXPECT_EQ(a.body_csv, b.body_csv);
  EXPECT_EQ(a.summary, b.summary);
  EXPECT_EQ(a.dropped, b.dropped);
  EXPECT_EQ(a.result.body.ratios, b.result.body.ratios);
  EXPECT_EQ(a.result.body.axes, b.result.body.axes);
  EXPECT_EQ(a.result.body.ratio_sigma, b.result.body.ratio_sigma);
  ASSERT_EQ(a.tosses.size(), b.tosses.size());
  for (std::size_t k = 0; k < a.tosses.size(); ++k) {
    SCOPED_TRACE("toss " + std::to_string(k + 1));
    const TossFit &x = a.result.tosses[k], &y = b.result.tosses[k];
    EXPECT_EQ(x.flight.t_start, y.flight.t_start);
    EXPECT_EQ(x.flight.t_end, y.flight.t_end);
    EXPECT_EQ(x.omega0, y.omega0);
    EXPECT_EQ(x.drag_rate, y.drag_rate);
    EXPECT_EQ(x.half_period_measured, y.half_period_measured);
    EXPECT_EQ(x.half_period_predicted, y.half_period_predicted);
    EXPECT_EQ(x.half_period_predicted_sigma, y.half_period_predicted_sigma);
    EXPECT_EQ(x.not_predicted, y.not_predicted);
    EXPECT_EQ(a.tosses[k].chart.recording, b.tosses[k].chart.recording);
    EXPECT_EQ(a.tosses[k].chart.t, b.tosses[k].chart.t);
    EXPECT_EQ(a.tosses[k].chart.curve, b.tosses[k].chart.curve);
    EXPECT_EQ(a.tosses[k].scene_text, b.tosses[k].scene_text);
    EXPECT_EQ(a.tosses[k].measured_csv, b.tosses[k].measured_csv);
  }
}

/// `recordings` pooled and fitted in the order given, then in each order of `orders` (indices
/// into `recordings`): every report the same as the first.
void expect_any_order_same(const std::vector<GyroRecording>& recordings,
                           const std::vector<std::vector<int>>& orders) {
  const FitReport first = fit_report(pool_recordings(recordings), {});
  ASSERT_FALSE(first.tosses.empty());
  for (const std::vector<int>& order : orders) {
    std::vector<GyroRecording> given;
    std::string said;
    for (int i : order) given.push_back(recordings.at(i)), said += recordings.at(i).name + " ";
    SCOPED_TRACE("given as " + said);
    expect_same_report(first, fit_report(pool_recordings(given), {}));
  }
}

// The bare phone's three recordings and the plate's four, each set in three other orders.
TEST(PoolOrder, RealRecordingsInAnyOrderGiveTheSameAnswerToTheLastDigit) {
  REQUIRE_REAL_RECORDINGS();
  const std::vector<std::vector<std::string>> sets = {
      {"12-10-56", "12-13-01", "12-13-51"}, {"12-22-44", "12-29-59", "12-38-00", "12-44-51"}};
  for (const std::vector<std::string>& names : sets) {
    std::vector<GyroRecording> recordings;
    for (const std::string& name : names) recordings.push_back(read_recording(real_dir() / name));
    SCOPED_TRACE(names.front() + " and the others");
    if (names.size() == 3)
      expect_any_order_same(recordings, {{2, 1, 0}, {1, 2, 0}, {2, 0, 1}});
    else
      expect_any_order_same(recordings, {{3, 2, 1, 0}, {1, 3, 0, 2}, {2, 0, 3, 1}});
  }
}

// Three students' recordings of one phone, one throw each and biases of their own; one of them
// on a clock 100 s ahead. Every order of the three.
TEST(PoolOrder, SyntheticRecordingsInAnyOrderGiveTheSameAnswerToTheLastDigit) {
  const std::vector<test::SyntheticToss> throws = {
      {{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, -16.0, -1.0}, 1.25}};
  const Eigen::Vector3d biases[3] = {
      {0.021, -0.014, 0.008}, {-0.03, 0.02, 0.011}, {0.005, 0.04, -0.025}};
  std::vector<GyroRecording> recordings;
  for (int s = 0; s < 3; ++s) {
    test::SyntheticRecording rec =
        test::make_recording(test::phone_alone(), {throws[s]}, 301 + s, 0.01);
    for (Eigen::Vector3d& w : rec.omega) w += biases[s] - rec.bias;
    if (s == 1)
      for (double& t : rec.t) t += 100.0;
    recordings.push_back(test::as_read(rec, "student" + std::to_string(s + 1)));
  }
  expect_any_order_same(recordings, {{0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}});
}

// Two recordings given the same name (one export's folder name in two places): their order is
// still one, by their samples.
TEST(PoolOrder, RecordingsOfOneNameAreOrderedByTheirSamples) {
  const std::vector<test::SyntheticToss> throws = {{{1.0, 18.0, 1.2}, 1.3},
                                                   {{-1.2, 17.0, 1.5}, 1.2}};
  const GyroRecording a =
      test::as_read(test::make_recording(test::phone_alone(), {throws[0]}, 11), "export");
  GyroRecording b =
      test::as_read(test::make_recording(test::phone_alone(), {throws[1]}, 12), "export");
  b.source = "elsewhere/export.csv";
  const GyroRecording ab = pool_recordings({a, b}), ba = pool_recordings({b, a});
  EXPECT_EQ(ab.t, ba.t);
  EXPECT_EQ(ab.omega, ba.omega);
  EXPECT_EQ(ab.source, ba.source);
  ASSERT_EQ(ab.parts.size(), 2u);
  EXPECT_EQ(ab.parts[0].source, ba.parts[0].source);
}

}  // namespace
}  // namespace bookspin::fit
