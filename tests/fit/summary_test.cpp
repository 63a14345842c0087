// What the summary says and how much of it (docs/phone-lab.md, "Reading the result"): the
// result first, the stretches too slow for a flight as one counted line (every one of them in
// fit_dropped_lines, which --verbose prints), and the page's remedies in the page's terms.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "fit/fit_tables.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

namespace fs = std::filesystem;

int count_with(const std::vector<std::string>& lines, const std::string& part) {
  return static_cast<int>(std::count_if(lines.begin(), lines.end(), [&](const std::string& l) {
    return l.find(part) != std::string::npos;
  }));
}

/// The summary of `report` holds one line for all the stretches dropped as too slow, saying
/// how many (the finder's count of them), and the dropped lines list each one.
void expect_slow_stretches_counted_once(const FitReport& report) {
  int slow = 0;
  for (const DroppedStretch& d : report.result.search.dropped)
    slow += d.reason.rfind("turning slower than", 0) == 0;
  ASSERT_GE(slow, 3) << "the recording should drop several slow stretches";
  EXPECT_EQ(count_with(report.summary, "turning slower than"), 1);
  EXPECT_EQ(count_with(report.summary,
                       "dropped " + std::to_string(slow) + " stretches of motion: turning slower"),
            1);
  EXPECT_EQ(report.dropped.size(), report.result.search.dropped.size());
  EXPECT_EQ(count_with(report.dropped, "turning slower than"), slow);
  // The moments come within a few lines: the bias, the tosses, one line for the slow ones and
  // each other dropped stretch.
  const auto moments =
      std::find_if(report.summary.begin(), report.summary.end(),
                   [](const std::string& l) { return l.rfind("moments", 0) == 0; });
  ASSERT_NE(moments, report.summary.end());
  // One line per reason: the finder gives two (too slow, no torque-free stretch long enough).
  EXPECT_LE(count_with(report.summary, "dropped"), 2);
  // The result table first (a title, a header and a row a toss), then the bias, the tosses.
  const int tosses = static_cast<int>(report.tosses.size());
  EXPECT_EQ(report.summary.front().rfind("result", 0), 0u) << report.summary.front();
  EXPECT_LE(moments - report.summary.begin(), 2 + tosses + 3 + tosses + 2);
}

// Every real recording: the hand-held ones drop dozens of slow stretches before and after the
// throw.
TEST(FitSummary, RealRecordingsCountTheSlowStretchesInOneLine) {
  if (!fs::is_directory(real_dir())) GTEST_SKIP() << "no real recordings at " << real_dir();
  for (const char* name :
       {"12-10-56", "12-13-01", "12-13-51", "12-22-44", "12-29-59", "12-38-00", "12-44-51"}) {
    SCOPED_TRACE(name);
    expect_slow_stretches_counted_once(
        fit_report(pool_recordings({read_recording(real_dir() / name)}), {}));
  }
}

// The synthetic twin: a recording whose rests are held in a hand that moves now and then.
TEST(FitSummary, SyntheticHandHeldRecordingCountsTheSlowStretchesInOneLine) {
  test::SyntheticRecording rec = test::make_recording(
      test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}}, 31);
  // Six brief hand movements of about 1 rad/s in the rests.
  for (double at : {0.3, 0.7, 1.1, rec.tosses[0].t_end + 0.5, rec.tosses[0].t_end + 0.9,
                    rec.tosses[1].t_end + 0.6})
    for (std::size_t i = 0; i < rec.t.size(); ++i)
      if (rec.t[i] >= at && rec.t[i] < at + 0.06) rec.omega[i] += Eigen::Vector3d(0.8, -0.6, 0.3);
  expect_slow_stretches_counted_once(fit_report(test::as_recording(rec), {}));
}

// Every toss stable: the moments cannot be fitted, and the remedy is the command line's option
// there, the page's own terms in the page.
TEST(FitSummary, ThePageIsNeverToldToGiveAnOption) {
  const std::vector<test::SyntheticToss> tosses{{{0.5, 0.2, 12.0}, 1.2}, {{-0.3, 0.4, 11.0}, 1.3}};
  const GyroRecording recording =
      test::as_recording(test::make_recording(test::phone_alone(), tosses, 12));
  const FitReport command = fit_report(recording, {});
  ASSERT_FALSE(command.result.body.moments_determined);
  EXPECT_EQ(count_with(command.summary, kGiveMoments), 1);
  FitRequest page;
  page.reader = Reader::page;
  const FitReport shown = fit_report(recording, page);
  EXPECT_EQ(count_with(shown.summary, "--"), 0);
  EXPECT_EQ(count_with(shown.summary, kMomentsRemedyPage), 1);
  EXPECT_EQ(shown.summary.size(), command.summary.size());
}

// Moments that no rigid body has (1 : 1.5 : 5, I1 + I2 < I3, as a recording's data may fit): no
// toss has a scene, and the summary says why in its last line, which the command line prints
// and the page shows (it gave no Play button and no word). A body that is one has no such line.
TEST(FitSummary, NoSceneOfTheTossesSaysWhyForEveryReader) {
  test::SyntheticBody impossible = test::phone_on_book();
  impossible.moments = Eigen::Vector3d(1.0, 1.5, 5.0);
  const std::vector<test::SyntheticToss> tosses{{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.2}};
  const GyroRecording recording = test::as_recording(test::make_recording(impossible, tosses, 3));
  for (const Reader reader : {Reader::command_line, Reader::page}) {
    FitRequest request;
    request.reader = reader;
    const FitReport report = fit_report(recording, request);
    const Eigen::Vector3d& I = report.result.body.ratios;
    ASSERT_LT(I[0] + I[1], I[2]) << "the fit should find the impossible body: " << I.transpose();
    EXPECT_FALSE(report.has_scenes);
    for (const TossReport& toss : report.tosses) EXPECT_FALSE(toss.scene.has_value());
    ASSERT_FALSE(report.summary.empty());
    EXPECT_EQ(report.summary.back(), kNoSceneLine);
  }
  const FitReport possible =
      fit_report(test::as_recording(test::make_recording(test::phone_on_book(), tosses, 3)), {});
  EXPECT_TRUE(possible.has_scenes);
  EXPECT_EQ(count_with(possible.summary, "no scene of the tosses"), 0);
}

}  // namespace
}  // namespace bookspin::fit
