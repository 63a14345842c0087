// The lab's rules on real phones (docs/phone-lab.md, "The development recordings"): seven
// phyphox recordings of a tossed iPhone 13 Pro made by other people, kept beside the project in
// ../shared/recordings-real/ (its README says what each shows). Each rule of the finder, the
// bias, saturation, the flags and the drag is tried on a named recording here, beside its
// synthetic test. The expected values come from the recordings themselves (their README's
// still seconds and largest readings), not from the code under test. Skipped, saying why, where
// the folder is absent.
#include "real_recordings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "common/errors.hpp"
#include "fit/fit_tables.hpp"
#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "fit/saturation.hpp"
#include "fit/toss_fit.hpp"
#include "support/scratch.hpp"

namespace bookspin::fit {
namespace {

namespace fs = std::filesystem;

/// The development recording `name`, read and pooled (a pool of one), as the fit takes it.
GyroRecording real(const std::string& name) {
  return pool_recordings({read_recording(real_dir() / name)});
}

/// The mean ω over [a, b] s of `recording`: the reference the tests compare with, taken from
/// the README's still seconds.
Eigen::Vector3d mean_over(const GyroRecording& recording, double a, double b) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (std::size_t i = 0; i < recording.t.size(); ++i)
    if (recording.t[i] >= a && recording.t[i] <= b) sum += recording.omega[i], ++n;
  return sum / std::max(n, 1);
}

bool has_line(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

// The five recordings with a still rest (the README's "from" second): the bias removed in
// flight is within 0.05 rad/s of the mean over 0.3 s of that rest, and the still stretches the
// summary names start there, not in the hand before the throw.
TEST(RealRecordings, TheBiasIsWithinFiveHundredthsOfTheStillRestsMean) {
  REQUIRE_REAL_RECORDINGS();
  const std::pair<const char*, double> still_from[] = {{"12-10-56", 5.2},
                                                       {"12-13-01", 4.4},
                                                       {"12-22-44", 5.3},
                                                       {"12-38-00", 7.9},
                                                       {"12-44-51", 7.9}};
  for (const auto& [name, from] : still_from) {
    const GyroRecording recording = real(name);
    const FlightSearch search = find_flights(recording);
    const Rest& rest = recording.parts.at(0).rest;
    ASSERT_GT(rest.samples, 20) << name;
    EXPECT_GE(rest.stretches.front().first, from - 0.1) << name;
    const Eigen::Vector3d reference = mean_over(recording, from + 0.1, from + 0.4);
    const FitResult fit = fit_recording(recording, search);
    for (int c = 0; c < 3; ++c) {
      EXPECT_LT(std::abs(fit.parts.at(0).bias_in_flight()[c] - reference[c]), 0.05)
          << name << " axis " << c;
      EXPECT_LT(rest.sigma[c], 0.03) << name << " axis " << c;  // still, not held
    }
    EXPECT_TRUE(has_line(fit_summary(fit), "where the phone lay still")) << name;
  }
}

// The two recordings held in the hand only (scatter 0.05–0.18 rad/s): no still stretch, and the
// summary says so (the old |ω| < 0.5 rad/s rule took 93–99 hand-held samples as rest).
TEST(RealRecordings, AHandHeldRestIsNoStillStretch) {
  REQUIRE_REAL_RECORDINGS();
  for (const char* name : {"12-13-51", "12-29-59"}) {
    const GyroRecording recording = real(name);
    const FlightSearch search = find_flights(recording);
    EXPECT_EQ(recording.parts.at(0).rest.samples, 0) << name;
    const FitResult fit = fit_recording(recording, search);
    EXPECT_TRUE(has_line(fit_summary(fit), "no still stretch in the recording")) << name;
  }
}

// Every clipped recording is named (the iPhone writes no range: its clips are found at the
// standard ±2000 °/s), and none of the three that stay under 31 rad/s is. Each marked sample
// reads within a few percent of 34.9 rad/s on some axis (the README's largest readings).
TEST(RealRecordings, EveryClippedRecordingIsNamedAndNoOther) {
  REQUIRE_REAL_RECORDINGS();
  for (const char* name : {"12-10-56", "12-13-01", "12-13-51", "12-29-59"}) {
    const GyroRecording recording = real(name);
    const Saturation saturation = find_saturation(recording);
    ASSERT_TRUE(saturation.range.has_value()) << name;
    EXPECT_NEAR(*saturation.range, 2000.0 * M_PI / 180.0, 1e-9) << name;
    int marked = 0;
    for (std::size_t i = 0; i < recording.t.size(); ++i)
      if (saturation.at_range[i]) {
        ++marked;
        EXPECT_GT(recording.omega[i].cwiseAbs().maxCoeff(), 34.5)
            << name << " t " << recording.t[i];
      }
    EXPECT_GE(marked, 1) << name;
    const FitResult fit = fit_recording(recording, find_flights(recording));
    EXPECT_TRUE(has_line(fit_summary(fit), "the gyroscope saturated")) << name;
  }
  for (const char* name : {"12-22-44", "12-38-00", "12-44-51"}) {
    const Saturation saturation = find_saturation(real(name));
    EXPECT_FALSE(saturation.range.has_value()) << name;
  }
  // Pooled, one phone's seven: each recording's clip kept (none reads past ±2000 °/s's band),
  // and the note names the four that clipped, each with its own count, and no other.
  std::vector<GyroRecording> all;
  for (const char* name :
       {"12-10-56", "12-13-01", "12-13-51", "12-22-44", "12-29-59", "12-38-00", "12-44-51"})
    all.push_back(read_recording(real_dir() / name));
  const GyroRecording pooled = pool_recordings(all);
  const Saturation saturation = find_saturation(pooled);
  const std::string note =
      saturation_note(saturation, pooled.parts, std::vector<int>(pooled.parts.size(), 0));
  for (std::size_t g = 0; g < pooled.parts.size(); ++g) {
    const std::string& name = pooled.parts[g].name;
    const bool clipped = name != "12-22-44" && name != "12-38-00" && name != "12-44-51";
    EXPECT_EQ(saturation.parts[g].range.has_value(), clipped) << name;
    EXPECT_EQ(note.find(name + " (") != std::string::npos, clipped) << name << ": " << note;
  }
  EXPECT_EQ(note.find("the gyroscope saturated at ±34.9066 rad/s (2000 °/s, a standard full "
                      "scale) in 12-10-56 ("),
            0u)
      << note;
}

// No fitted drag rate is below zero, alone or pooled; those the fit wanted below (12-13-51's
// bounce, 12-44-51's tosses) are held at 0 and the summary says why.
TEST(RealRecordings, NoDragRateIsBelowZero) {
  REQUIRE_REAL_RECORDINGS();
  std::vector<GyroRecording> bare;
  for (const char* name : {"12-10-56", "12-13-01", "12-13-51"}) bare.push_back(real(name));
  int held = 0;
  for (const GyroRecording& recording : {bare[2], real("12-44-51"), pool_recordings(bare)}) {
    const FitResult fit = fit_recording(recording, find_flights(recording));
    int held_here = 0;
    for (const TossFit& toss : fit.tosses) {
      EXPECT_GE(toss.drag_rate, 0.0) << recording.name;
      held_here += toss.drag_rate == 0.0;
    }
    if (held_here > 0) {
      EXPECT_TRUE(has_line(fit_summary(fit), "air cannot speed a body up")) << recording.name;
    }
    held += held_here;
  }
  EXPECT_GE(held, 1);  // the rule was tried, not only passed by positive rates
}

// The finder on a clean real throw: 12-10-56's main flight (thrown about 2.0 s, landing about
// 3.0 s: its chart) is found whole and fitted under 5 % of |ω| unflagged; the flat body's
// 12-38-00 main throw (a residual over 10 % of |ω|) is flagged.
TEST(RealRecordings, TheMainThrowIsFoundAndACleanOneIsNotFlagged) {
  REQUIRE_REAL_RECORDINGS();
  const GyroRecording clean = real("12-10-56");
  const FitResult fit = fit_recording(clean, find_flights(clean));
  ASSERT_GE(fit.tosses.size(), 1u);
  const TossFit& main = fit.tosses.front();
  EXPECT_NEAR(main.flight.t_start, 2.0, 0.1);
  EXPECT_NEAR(main.flight.t_end, 3.0, 0.1);
  EXPECT_LT(main.residual_rms / main.omega0.norm(), 0.05);
  EXPECT_FALSE(main.poor_fit) << main.flag;
  const GyroRecording flexing = real("12-38-00");
  const FitResult flagged = fit_recording(flexing, find_flights(flexing));
  ASSERT_GE(flagged.tosses.size(), 1u);
  EXPECT_TRUE(flagged.tosses.front().poor_fit);
}

// A lone flight as real apps write it: 0.65 s cut from the middle of 12-22-44's throw (no rest,
// no throw or catch), then every third sample dropped at random (steps 10–40 ms): found as one
// flight over nearly all of it and fitted under 5 % of |ω|.
TEST(RealRecordings, ALoneFlightCutFromARealThrowIsFoundAndFitted) {
  REQUIRE_REAL_RECORDINGS();
  const GyroRecording whole = real("12-22-44");
  std::mt19937 random(7);
  for (bool uneven : {false, true}) {
    GyroRecording lone;
    lone.name = "lone";
    lone.source = "lone.csv";
    for (std::size_t i = 0; i < whole.t.size(); ++i) {
      if (whole.t[i] < 2.75 || whole.t[i] > 3.40) continue;
      if (uneven && random() % 3 == 0 && whole.t[i] > 2.76 && whole.t[i] < 3.39) continue;
      lone.t.push_back(whole.t[i]);
      lone.omega.push_back(whole.omega[i]);
    }
    lone = pool_recordings({lone});
    const FlightSearch search = find_flights(lone);
    ASSERT_EQ(search.flights.size(), 1u) << uneven;
    EXPECT_GT(search.flights[0].t_end - search.flights[0].t_start, 0.9 * 0.65) << uneven;
    const FitResult fit = fit_recording(lone, search);
    EXPECT_LT(fit.tosses[0].residual_rms / fit.tosses[0].omega0.norm(), 0.05) << uneven;
  }
}

// A folder holding one CSV (phyphox's single-CSV export, as 12-10-56 is kept) is that CSV,
// named after its folder; a folder of several CSVs and no "Raw Data.csv" is refused, listing
// them.
TEST(RealRecordings, AFolderOfOneCsvIsThatCsv) {
  REQUIRE_REAL_RECORDINGS();
  const GyroRecording folder = real("12-10-56");
  EXPECT_EQ(folder.name, "12-10-56");
  EXPECT_EQ(folder.t.size(), 849u);  // the README's samples
  const fs::path dir = test::fresh_dir("fit/two-csvs");
  for (const char* file : {"a.csv", "b.csv"})
    fs::copy_file(real_dir() / "12-10-56" / "Gyroscope rotation rate 2022-05-03 12-10-56.csv",
                  dir / file);
  try {
    read_recording(dir);
    ADD_FAILURE() << "a folder of two CSVs was read";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("holds 2 CSVs"), std::string::npos) << what;
    EXPECT_NE(what.find("\"a.csv\", \"b.csv\""), std::string::npos) << what;
  }
}

/// `recording` as a phone's browser records it (docs/phone-lab.md, "Recording in the page"): a
/// reading at each tick of a clock of `hz` (50 to 62 Hz, each tick ±10 % late or early), the
/// latest sample, its stamp off by up to 1 ms; seeded, so the same each run.
GyroRecording thinned_as_a_browser(const GyroRecording& recording, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double period = 1.0 / (50.0 + 12.0 * unit(random));
  GyroRecording thin = recording;
  thin.t.clear(), thin.omega.clear();
  double next = -1e300;
  for (std::size_t i = 0; i < recording.t.size(); ++i) {
    if (recording.t[i] < next) continue;
    next = recording.t[i] + period * (0.9 + 0.2 * unit(random));
    const double t = recording.t[i] + 0.002 * (unit(random) - 0.5);
    if (!thin.t.empty() && t <= thin.t.back()) continue;
    thin.t.push_back(t), thin.omega.push_back(recording.omega[i]);
  }
  return thin;
}

// Thinned as a browser thins it (~55 Hz of the 100 Hz), a recording gives the body its full
// rate gives, within twice the two σ together: 12-29-59 (two flagged flights, no still
// stretch) fell into moments past the triangle inequality (I1/I3 near 0, the residual four to
// ten times the physical body's) in about half of such thinnings before the fit was started
// again from rigid bodies where it ends past it ("The fit").
TEST(RealRecordings, ThinnedAsABrowserThinsItTheBodyIsTheFullRatesWithinTwoSigma) {
  REQUIRE_REAL_RECORDINGS();
  const std::pair<const char*, int> cases[] = {{"12-29-59", 8}, {"12-13-01", 2}, {"12-22-44", 2}};
  int no_rigid_body = 0;
  for (const auto& [name, seeds] : cases) {
    const GyroRecording as_read = read_recording(real_dir() / name);
    const BodyEstimate full = fit_report(pool_recordings({as_read}), {}).result.body;
    ASSERT_TRUE(full.ratio_sigma.has_value()) << name;
    for (int seed = 0; seed < seeds; ++seed) {
      SCOPED_TRACE(std::string(name) + ", seed " + std::to_string(seed));
      const GyroRecording thin = thinned_as_a_browser(as_read, 1000u + seed);
      ASSERT_LT(thin.t.size(), as_read.t.size() * 2 / 3);
      const BodyEstimate body = fit_report(pool_recordings({thin}), {}).result.body;
      // Or no rigid body from any start (I1/I3 under 0.01): then no σ, and the note says so
      // (rigid_restart.hpp, fitted_no_rigid_body); in few of the thinnings.
      if (!body.ratio_sigma && body.ratios[0] < 0.01 * body.ratios[2]) {
        ++no_rigid_body;
        EXPECT_NE(std::find_if(body.notes.begin(), body.notes.end(),
                               [](const std::string& note) {
                                 return note.find("no rigid body") != std::string::npos;
                               }),
                  body.notes.end());
        continue;
      }
      ASSERT_TRUE(body.ratio_sigma.has_value())
          << body.ratios.transpose() << " " << thin.t.size() << " samples";
      for (int i = 0; i < 2; ++i) {
        const double sigma = std::hypot((*full.ratio_sigma)[i], (*body.ratio_sigma)[i]);
        EXPECT_LT(std::abs(body.ratios[i] - full.ratios[i]), 2.0 * sigma)
            << "I" << i + 1 << "/I3 " << body.ratios[i] << " against " << full.ratios[i];
      }
    }
  }
  EXPECT_LE(no_rigid_body, 2) << "of 12 thinnings";
}

}  // namespace
}  // namespace bookspin::fit
