// Several recordings of one body pooled (docs/phone-lab.md, "A class's recordings"): three
// one-throw recordings of one phone, each with its own bias, fitted as one body.
#include "fit/pool.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/errors.hpp"
#include "fit/fit_tables.hpp"
#include "fit/flights.hpp"
#include "fit/report.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

struct Class {
  std::vector<test::SyntheticRecording> synthetic;
  std::vector<GyroRecording> recordings;
};

/// Three students each toss the same bare phone once; their phones' biases differ.
Class three_students() {
  Class c;
  const std::vector<test::SyntheticToss> throws = {
      {{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, -16.0, -1.0}, 1.25}};
  const Eigen::Vector3d biases[3] = {
      {0.021, -0.014, 0.008}, {-0.03, 0.02, 0.011}, {0.005, 0.04, -0.025}};
  for (int s = 0; s < 3; ++s) {
    test::SyntheticRecording rec =
        test::make_recording(test::phone_alone(), {throws[s]}, 201 + s, 0.01);
    for (Eigen::Vector3d& w : rec.omega) w += biases[s] - rec.bias;
    rec.bias = biases[s];
    GyroRecording r = test::as_recording(rec);
    r.name = "student" + std::to_string(s + 1);
    r.source = r.name + ".csv";
    c.synthetic.push_back(std::move(rec));
    c.recordings.push_back(std::move(r));
  }
  return c;
}

TEST(PoolRecordings, ThreeOneThrowRecordingsGiveOneBodyAndPredictEachThrow) {
  const Class c = three_students();
  const GyroRecording pooled = pool_recordings(c.recordings);
  ASSERT_EQ(pooled.parts.size(), 3u);
  EXPECT_EQ(pooled.name, "student1-and-2-more");
  // Each part's bias is its own recording's rest mean: within 0.01 rad/s of its generator's.
  for (int s = 0; s < 3; ++s)
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(pooled.parts[s].bias[i], c.synthetic[s].bias[i], 0.01) << s << " " << i;
  // Each recording's samples as measured, 1 s after the previous one's, a pause between.
  for (int s = 0; s < 3; ++s) {
    const RecordingPart& part = pooled.parts[s];
    const GyroRecording& own = c.recordings[s];
    ASSERT_EQ(part.last - part.first + 1, static_cast<int>(own.t.size()));
    for (std::size_t i = 0; i < own.t.size(); i += 97) {
      EXPECT_EQ(pooled.t[part.first + i], own.t[i] + part.t_offset);
      EXPECT_EQ(pooled.omega[part.first + i], own.omega[i]);
    }
    if (s > 0) {
      EXPECT_DOUBLE_EQ(pooled.t[part.first] - pooled.t[part.first - 1], 1.0);
      EXPECT_NE(std::find(pooled.pauses.begin(), pooled.pauses.end(), pooled.t[part.first] - 0.5),
                pooled.pauses.end());
    }
  }
  const FitReport report = fit_report(pooled, {});
  const FitResult& fit = report.result;
  ASSERT_EQ(fit.tosses.size(), 3u);
  const test::SyntheticBody body = test::phone_alone();
  const Eigen::Vector3d truth = body.moments / body.moments.maxCoeff();
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(fit.body.ratios[i], truth[i], 0.01 * truth[i]) << i;
  // Each throw predicted from the other two students' throws: within 8 %, the median within 3 %.
  std::vector<double> errors;
  for (int s = 0; s < 3; ++s) {
    const TossFit& toss = fit.tosses[s];
    ASSERT_TRUE(toss.half_period_predicted.has_value()) << s;
    EXPECT_EQ(toss.predicted_from_tosses, 2);
    const double want = c.synthetic[s].tosses[0].half_period;
    errors.push_back(std::abs(*toss.half_period_predicted - want) / want);
    EXPECT_LT(errors.back(), 0.08) << s;
  }
  std::sort(errors.begin(), errors.end());
  EXPECT_LT(errors[1], 0.03);
  // The tables name each toss's recording and give its own times.
  const CsvTable table = fit_toss_csv(fit);
  ASSERT_EQ(table.columns.at(1), "recording");
  for (int s = 0; s < 3; ++s) {
    EXPECT_EQ(std::get<std::string>(table.rows.at(s).at(1)), "student" + std::to_string(s + 1));
    const double t_start = std::get<CsvNumber>(table.rows.at(s).at(2)).value.value();
    EXPECT_NEAR(t_start, c.synthetic[s].tosses[0].t_start, 0.1) << s;
  }
  int bias_lines = 0;
  for (const std::string& line : report.summary)
    bias_lines += line.rfind("bias of student", 0) == 0;
  EXPECT_EQ(bias_lines, 3);
}

// A recording alone is a pool of one: its name, source, samples and pauses as they were, one
// part holding its bias.
TEST(PoolRecordings, ARecordingAloneIsAPoolOfOne) {
  const Class c = three_students();
  const GyroRecording& own = c.recordings[1];
  const GyroRecording alone = pool_recordings({own});
  EXPECT_EQ(alone.name, own.name);
  EXPECT_EQ(alone.source, own.source);
  EXPECT_EQ(alone.t, own.t);
  EXPECT_EQ(alone.omega, own.omega);
  EXPECT_EQ(alone.pauses, own.pauses);
  ASSERT_EQ(alone.parts.size(), 1u);
  EXPECT_EQ(alone.parts[0].first, 0);
  EXPECT_EQ(alone.parts[0].last, static_cast<int>(own.t.size()) - 1);
  EXPECT_EQ(alone.parts[0].t_offset, 0.0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(alone.parts[0].bias[i], c.synthetic[1].bias[i], 0.01);
}

TEST(PoolRecordings, NoneOrOneGivenTwiceIsRefused) {
  const Class c = three_students();
  EXPECT_THROW(pool_recordings({}), InputError);
  try {
    pool_recordings({c.recordings[0], c.recordings[1], c.recordings[0]});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "student1.csv: given twice");
  }
  // Tosses by hand take one recording's times.
  FitRequest request;
  request.tosses = {{1.0, 2.0}};
  EXPECT_THROW(fit_report(pool_recordings(c.recordings), request), InputError);
}

}  // namespace
}  // namespace bookspin::fit
