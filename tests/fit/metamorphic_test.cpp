// Relations the lab's answer must keep for any recording (docs/phone-lab.md, "Tests by
// relation"): the fit of a recording against the fit of a transformed copy of it, on every real
// recording in ../shared/recordings-real/ (skipped, saying why, where it is absent) and on
// synthetic ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
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

GyroRecording read_real(const std::string& name) { return read_recording(real_dir() / name); }

bool has_text(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

/// The pooled fit of `recordings` against each one's fit alone: each toss of the pool is one of
/// its own recording's tosses alone (the same count per recording; its start and end within
/// `slack` s), named by that recording and given on that recording's clock in the CSV, the
/// chart, the scene and the summary; the body within 3 σ (the two fits' σ combined).
void expect_pool_keeps_each_recordings_tosses(const std::vector<GyroRecording>& recordings,
                                              double slack) {
  const FitReport pooled = fit_report(pool_recordings(recordings), {});
  const FitResult& fit = pooled.result;
  const CsvTable table = fit_toss_csv(fit);
  ASSERT_EQ(table.columns.at(1), "recording");
  std::size_t next = 0;  // the pool's tosses, in order: each recording's in turn, in the
                         // pool's own order of its recordings (by name: pool_recordings)
  ASSERT_EQ(fit.parts.size(), recordings.size());
  for (const RecordingPart& part : fit.parts) {
    const auto found = std::find_if(recordings.begin(), recordings.end(),
                                    [&](const GyroRecording& r) { return r.name == part.name; });
    ASSERT_NE(found, recordings.end()) << part.name;
    const GyroRecording& own = *found;
    const FitReport alone = fit_report(pool_recordings({own}), {});
    SCOPED_TRACE(own.name);
    for (const TossReport& single : alone.tosses) {
      ASSERT_LT(next, pooled.tosses.size()) << "a toss of " << own.name << " is missing";
      const TossReport& toss = pooled.tosses[next];
      const TossFit& fitted = fit.tosses[next];
      const std::vector<CsvCell>& row = table.rows.at(next);
      ++next;
      // Its own recording and times, as the recording alone gives them.
      EXPECT_EQ(toss.chart.recording, own.name);
      EXPECT_EQ(std::get<std::string>(row.at(1)), own.name);
      const double start = std::get<CsvNumber>(row.at(2)).value.value();
      const double end = std::get<CsvNumber>(row.at(3)).value.value();
      const double alone_start = single.chart.t.front(), alone_end = single.chart.t.back();
      EXPECT_NEAR(start, alone_start, slack);
      EXPECT_NEAR(end, alone_end, slack);
      EXPECT_NEAR(toss.chart.t.front(), start, 1e-9);
      EXPECT_NEAR(toss.chart.t.back(), end, 1e-9);
      EXPECT_NEAR(toss.chart.curve_t.front(), start, 1e-9);
      for (double flip : toss.chart.flips) {
        EXPECT_GE(flip, start - 1e-9);
        EXPECT_LE(flip, end + 1e-9);
      }
      // Its scene and the summary say the same.
      const std::string times = fixed(start, 3) + "–" + fixed(end, 3) + " s";
      if (toss.scene) {
        EXPECT_NE(toss.scene->title.find(own.name + ", toss "), std::string::npos)
            << toss.scene->title;
        EXPECT_NE(toss.scene->description.find("recording " + own.name + " (" + times + ")"),
                  std::string::npos)
            << toss.scene->description;
      }
      EXPECT_TRUE(has_text(pooled.summary, ": " + own.name + " " + times)) << times;
      // The flight itself: the same samples, the same clock.
      EXPECT_NEAR(fitted.flight.t_start - toss.chart.t_offset, start, 1e-9);
    }
    if (alone.result.body.ratio_sigma && fit.body.ratio_sigma && alone.tosses.size() >= 2)
      for (int i = 0; i < 2; ++i) {
        const double sigma =
            std::hypot((*alone.result.body.ratio_sigma)[i], (*fit.body.ratio_sigma)[i]);
        EXPECT_LT(std::abs(alone.result.body.ratios[i] - fit.body.ratios[i]), 3.0 * sigma)
            << "I" << i + 1 << "/I3";
      }
  }
  EXPECT_EQ(next, pooled.tosses.size()) << "the pool has tosses no recording has alone";
}

// Two (or three) recordings of one body pooled against each alone, for every real recording:
// the bare phone's and the plate's recordings in pairs of the same body, and the class of three
// the lab's users pool.
TEST(Metamorphic, PooledRealRecordingsKeepEachTossesOwnRecordingAndTimes) {
  REQUIRE_REAL_RECORDINGS();
  const std::vector<std::vector<std::string>> pools = {
      {"12-10-56", "12-13-01", "12-13-51"},  // the bare phone: a class of three
      {"12-13-51", "12-10-56"},
      {"12-22-44", "12-38-00"},  // the plate
      {"12-44-51", "12-29-59"}};
  for (const std::vector<std::string>& names : pools) {
    std::vector<GyroRecording> recordings;
    for (const std::string& name : names) recordings.push_back(read_real(name));
    SCOPED_TRACE(names.front() + " pooled");
    // Each flight's ends are trimmed by the fitted motion's residual (flight_trim.hpp), and
    // the pooled body differs from each one's alone: an end may move by up to 0.1 s.
    expect_pool_keeps_each_recordings_tosses(recordings, 0.1);
  }
}

TEST(Metamorphic, PooledSyntheticRecordingsKeepEachTossesOwnRecordingAndTimes) {
  const std::vector<test::SyntheticToss> throws = {
      {{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, -16.0, -1.0}, 1.25}};
  std::vector<GyroRecording> recordings;
  for (int s = 0; s < 3; ++s) {
    // Each its own clock: the second starts at 100 s, as a phone's experiment time may.
    test::SyntheticRecording rec =
        test::make_recording(test::phone_alone(), {throws[s], throws[(s + 1) % 3]}, 401 + s, 0.01);
    if (s == 1)
      for (double& t : rec.t) t += 100.0;
    if (s == 1)
      for (double& t : rec.pauses) t += 100.0;
    recordings.push_back(test::as_read(rec, "student" + std::to_string(s + 1)));
  }
  expect_pool_keeps_each_recordings_tosses(recordings, 0.02);
}

/// Every development recording, as read (not pooled).
std::vector<GyroRecording> every_real() {
  std::vector<GyroRecording> all;
  for (const char* name :
       {"12-10-56", "12-13-01", "12-13-51", "12-22-44", "12-29-59", "12-38-00", "12-44-51"})
    all.push_back(read_real(name));
  return all;
}

/// Synthetic recordings of a bare phone and a phone on a book, as read.
std::vector<GyroRecording> every_synthetic() {
  std::vector<GyroRecording> all;
  const std::vector<test::SyntheticToss> tosses = {{{1.0, 18.0, 1.2}, 1.3},
                                                   {{-1.2, 17.0, 1.5}, 1.2}};
  all.push_back(test::as_read(test::make_recording(test::phone_alone(), tosses, 81), "phone"));
  all.push_back(test::as_read(test::make_recording(test::phone_on_book(), tosses, 82), "book"));
  return all;
}

/// `b`'s fit against `a`'s, `b` a transformed copy of `a` whose times are `a`'s plus `shift`:
/// the same flights (each end within `slack` s), and the moment ratios within 3 σ (the two
/// fits' σ combined) where either flips.
void expect_same_fit(const GyroRecording& a, const GyroRecording& b, double shift, double slack) {
  const FitResult fa = fit_report(pool_recordings({a}), {}).result;
  const FitResult fb = fit_report(pool_recordings({b}), {}).result;
  ASSERT_EQ(fa.tosses.size(), fb.tosses.size());
  for (std::size_t k = 0; k < fa.tosses.size(); ++k) {
    EXPECT_NEAR(fb.tosses[k].flight.t_start - shift, fa.tosses[k].flight.t_start, slack) << k;
    EXPECT_NEAR(fb.tosses[k].flight.t_end - shift, fa.tosses[k].flight.t_end, slack) << k;
  }
  if (!fa.body.moments_determined || !fa.body.ratio_sigma || !fb.body.ratio_sigma) return;
  for (int i = 0; i < 2; ++i)
    EXPECT_LT(std::abs(fa.body.ratios[i] - fb.body.ratios[i]),
              3.0 * std::hypot((*fa.body.ratio_sigma)[i], (*fb.body.ratio_sigma)[i]) + 1e-9)
        << "I" << i + 1 << "/I3";
}

/// The relations of one recording: shifted 1000 s later; its axes permuted (x, y, z read as y,
/// z, x); one axis's sign flipped with another's (a rotation of the phone by π about z).
void expect_relations(const GyroRecording& r) {
  GyroRecording later = r;
  for (double& t : later.t) t += 1000.0;
  for (double& t : later.pauses) t += 1000.0;
  {
    SCOPED_TRACE("shifted in time");
    expect_same_fit(r, later, 1000.0, 1e-6);
  }
  GyroRecording permuted = r, turned = r;
  for (Eigen::Vector3d& w : permuted.omega) w = Eigen::Vector3d(w[1], w[2], w[0]);
  for (Eigen::Vector3d& w : turned.omega) w = Eigen::Vector3d(-w[0], -w[1], w[2]);
  {
    SCOPED_TRACE("axes permuted");
    expect_same_fit(r, permuted, 0.0, 0.02);
  }
  {
    SCOPED_TRACE("turned by pi about z");
    expect_same_fit(r, turned, 0.0, 0.02);
  }
}

/// A constant bias added on each axis of `r`: the same flights, and where `r` has a still rest,
/// the bias removed in flight is its own plus the one added.
void expect_bias_added_is_found(const GyroRecording& r) {
  const Eigen::Vector3d added(0.04, -0.03, 0.05);
  GyroRecording biased = r;
  for (Eigen::Vector3d& w : biased.omega) w += added;
  expect_same_fit(r, biased, 0.0, 0.02);
  const FitResult fa = fit_report(pool_recordings({r}), {}).result;
  const FitResult fb = fit_report(pool_recordings({biased}), {}).result;
  if (fa.parts.at(0).rest.samples == 0) return;
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(fb.parts.at(0).bias_in_flight()[i], fa.parts.at(0).bias_in_flight()[i] + added[i],
                0.005)
        << "axis " << i;
}

TEST(Metamorphic, AConstantBiasAddedIsFoundPlusIt) {
  std::vector<GyroRecording> all = every_synthetic();
  if (fs::is_directory(real_dir()))
    for (GyroRecording& r : every_real()) all.push_back(std::move(r));
  for (const GyroRecording& r : all) {
    SCOPED_TRACE(r.name);
    expect_bias_added_is_found(r);
  }
}

TEST(Metamorphic, RealRecordingsShiftedPermutedOrTurnedGiveTheSameFit) {
  REQUIRE_REAL_RECORDINGS();
  for (const GyroRecording& r : every_real()) {
    SCOPED_TRACE(r.name);
    expect_relations(r);
  }
}

TEST(Metamorphic, SyntheticRecordingsShiftedPermutedOrTurnedGiveTheSameFit) {
  for (const GyroRecording& r : every_synthetic()) {
    SCOPED_TRACE(r.name);
    expect_relations(r);
  }
}

/// `r` with each sample dropped with probability 1/4 (seeded), its first and last kept.
GyroRecording thinned(const GyroRecording& r, unsigned seed) {
  std::mt19937 random(seed);
  GyroRecording out = r;
  out.t.clear(), out.omega.clear();
  for (std::size_t i = 0; i < r.t.size(); ++i)
    if (i == 0 || i + 1 == r.t.size() || random() % 4 != 0)
      out.t.push_back(r.t[i]), out.omega.push_back(r.omega[i]);
  return out;
}

// Samples dropped at random: the same flights, each end within 0.05 s.
TEST(Metamorphic, SamplesDroppedAtRandomKeepTheSameFlights) {
  std::vector<GyroRecording> all = every_synthetic();
  if (fs::is_directory(real_dir()))
    for (GyroRecording& r : every_real()) all.push_back(std::move(r));
  for (const GyroRecording& r : all) {
    SCOPED_TRACE(r.name);
    expect_same_fit(r, thinned(r, 5), 0.0, 0.05);
  }
}

}  // namespace
}  // namespace bookspin::fit
