// The result first (docs/phone-lab.md, "Reading the result"): the summary opens with one table,
// a row a toss (its recording, its flight, T/2 measured, T/2 predicted ± 2σ, within or not), then
// the bias, one line a recording, then the details; on the real recordings pooled (skipped,
// saying why, where absent) and on a synthetic class.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "common/number_text.hpp"
#include "fit/pool.hpp"
#include "fit/report.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// `report`'s summary: its title, header and one row a toss, each row's cells the toss's own;
/// the bias in one line a recording, right after the table.
void expect_result_first(const FitReport& report) {
  const std::vector<std::string>& s = report.summary;
  const std::size_t n = report.result.tosses.size();
  ASSERT_GE(s.size(), n + 2);
  EXPECT_EQ(s[0].rfind("result", 0), 0u) << s[0];
  EXPECT_NE(s[1].find("T/2 predicted ± 2σ (s)"), std::string::npos) << s[1];
  for (std::size_t k = 0; k < n; ++k) {
    const TossFit& t = report.result.tosses[k];
    const std::vector<std::string> cells = words(s[2 + k]);
    SCOPED_TRACE(s[2 + k]);
    ASSERT_GE(cells.size(), 5u);
    EXPECT_EQ(cells[0], std::to_string(k + 1));
    EXPECT_EQ(cells[1], report.tosses[k].chart.recording);
    EXPECT_EQ(cells[3], t.half_period_measured ? fixed(*t.half_period_measured, 3) : "–");
    // Within 2σ, judged here from the toss's own values.
    std::string within = "–";
    if (t.half_period_measured && t.half_period_predicted && t.half_period_predicted_sigma)
      within = std::abs(*t.half_period_measured - *t.half_period_predicted) <=
                       2.0 * *t.half_period_predicted_sigma
                   ? "yes"
                   : "no";
    EXPECT_EQ(cells.back(), within);
    if (!t.half_period_predicted) {
      EXPECT_NE(s[2 + k].find("not predicted"), std::string::npos);
    }
    if (t.half_period_predicted && !t.half_period_predicted_sigma) {
      EXPECT_NE(s[2 + k].find("(uncalibrated)"), std::string::npos);
    }
  }
  // One σ convention a line: below the table every ± says what it is (1σ, or 2σ as the table
  // gives it, or the rest's scatter), and a kept toss's prediction is its row's, ± 2σ.
  for (std::size_t i = 2 + n; i < s.size(); ++i) {
    if (s[i].find(" ± ") == std::string::npos) continue;  // an uncertainty, not a range "±34.9"
    EXPECT_TRUE(s[i].find("1σ") != std::string::npos || s[i].find("2σ") != std::string::npos ||
                s[i].find("± their scatter") != std::string::npos)
        << s[i];
  }
  for (std::size_t k = 0; k < n; ++k) {
    const TossFit& t = report.result.tosses[k];
    if (!t.half_period_predicted || !t.half_period_predicted_sigma) continue;
    const std::string both =
        plus_minus(*t.half_period_predicted, 2.0 * *t.half_period_predicted_sigma);
    EXPECT_NE(s[2 + k].find(both), std::string::npos) << s[2 + k];
    const std::string kept = "kept toss " + std::to_string(k + 1) + ": ";
    bool found = false;
    for (const std::string& line : s)
      if (line.rfind(kept, 0) == 0) {
        found = true;
        EXPECT_NE(line.find("T/2 predicted " + both + " s (2σ)"), std::string::npos) << line;
      }
    EXPECT_TRUE(found) << kept;
  }
  // Then the bias: one line a recording, no other line about it.
  const std::size_t parts = report.result.parts.size();
  int bias = 0;
  for (const std::string& line : s)
    bias += line.rfind("bias", 0) == 0 || line.rfind("no still stretch", 0) == 0;
  EXPECT_EQ(bias, static_cast<int>(parts));
  for (std::size_t g = 0; g < parts; ++g) {
    const std::string& line = s.at(2 + n + g);
    EXPECT_TRUE(line.rfind("bias", 0) == 0 || line.rfind("no still stretch", 0) == 0) << line;
  }
}

TEST(ResultTable, TheSummaryOpensWithTheResultThenTheBiasOneLineARecording) {
  const std::vector<test::SyntheticToss> throws = {
      {{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, -16.0, -1.0}, 1.25}};
  std::vector<GyroRecording> recordings;
  for (int s = 0; s < 3; ++s)
    recordings.push_back(test::as_read(
        test::make_recording(test::phone_alone(), {throws[s], throws[(s + 1) % 3]}, 61 + s),
        "student" + std::to_string(s + 1)));
  expect_result_first(fit_report(pool_recordings(recordings), {}));
}

TEST(ResultTable, RealRecordingsPooledOpenWithTheResult) {
  REQUIRE_REAL_RECORDINGS();
  std::vector<GyroRecording> recordings;
  for (const char* name : {"12-10-56", "12-13-01", "12-13-51"})
    recordings.push_back(read_recording(real_dir() / name));
  const FitReport report = fit_report(pool_recordings(recordings), {});
  for (const std::string& line : report.summary) std::printf("%s\n", line.c_str());
  expect_result_first(report);
}

}  // namespace
}  // namespace bookspin::fit
