// A recording whose axes are in mixed units (one in °/s, two in rad/s): the fit that goes
// through names the likely cause, the axis and its units, once for the recording
// (fit/toss_flags.hpp, scale_cause), besides the flags of the tosses it spoils; and a recording
// all in rad/s gets no such note. Where the axis in °/s stays within a gyroscope's range and
// the file says nothing of units (no header units, no |ω| column), the fit whose every toss is
// flagged, or that fails, names the axis and the file ("mixed units?", docs/phone-lab.md,
// "Flags"): on a real recording with each axis in turn taken to °/s, and on a synthetic
// one with one axis and with two.
#include "fit/mixed_units.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <tuple>
#include <utility>

#include "common/errors.hpp"
#include "fit/flights.hpp"
#include "fit/report.hpp"
#include "fit/toss_fit.hpp"
#include "physics/exact_solution.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

/// The fit of a synthetic phone-on-book recording (three flipping tosses) with its y axis
/// multiplied by `y_scale`, its flights the true ones.
FitResult fit_with_y_scaled(double y_scale) {
  const test::SyntheticRecording s = test::make_recording(
      test::phone_on_book(),
      {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.3}, {{0.6, -13.0, -0.5}, 1.1}});
  GyroRecording read = test::as_read(s);
  for (Eigen::Vector3d& w : read.omega) w[1] *= y_scale;
  const GyroRecording recording = pool_recordings({read});
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : s.tosses) ranges.emplace_back(t.t_start, t.t_end);
  FitSettings settings;
  settings.drag = physics::DragLaw::none;
  return fit_recording(recording, hand_flights(recording, ranges), settings);
}

bool names_units(const std::string& note) {
  return note.find("in °/s, or scaled?") != std::string::npos;
}

TEST(MixedUnits, OneAxisInDegreesPerSecondIsNamedAsTheLikelyCause) {
  const FitResult fit = fit_with_y_scaled(180.0 / M_PI);
  const std::vector<std::string>& notes = fit.body.notes;
  const auto it = std::find_if(notes.begin(), notes.end(), [](const std::string& note) {
    return note.rfind("ω_y reaches", 0) == 0 && names_units(note);
  });
  ASSERT_NE(it, notes.end()) << "no note names ω_y's units; notes:\n"
                             << [&] {
                                  std::string all;
                                  for (const std::string& n : notes) all += n + "\n";
                                  return all;
                                }();
  EXPECT_NE(it->find("while ω_x and ω_z stay within"), std::string::npos) << *it;
  EXPECT_NE(it->find("that axis in °/s"), std::string::npos) << *it;
}

TEST(MixedUnits, ARecordingInRadiansPerSecondGetsNoUnitsNote) {
  const FitResult fit = fit_with_y_scaled(1.0);
  for (const std::string& note : fit.body.notes) EXPECT_FALSE(names_units(note)) << note;
}

const char* const kAxis[3] = {"ω_x", "ω_y", "ω_z"};

/// `recording`'s samples written as a bare "t,wx,wy,wz" CSV (no units, no |ω|) named `name`
/// in a fresh folder, the axes in `degrees` (bit c: axis c) multiplied by 180/π, and read back.
GyroRecording written_in_mixed_units(const GyroRecording& recording, int degrees,
                                     const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("bookspin-mixed-units-" + name);
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / (name + ".csv");
  {
    std::ofstream out(file);
    out << "t,wx,wy,wz\n";
    char line[160];
    for (std::size_t i = 0; i < recording.t.size(); ++i) {
      Eigen::Vector3d w = recording.omega[i];
      for (int c = 0; c < 3; ++c)
        if (degrees & (1 << c)) w[c] *= 180.0 / M_PI;
      std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g\n", recording.t[i], w[0], w[1], w[2]);
      out << line;
    }
  }
  GyroRecording read = read_recording(file);
  std::filesystem::remove_all(dir);
  return read;
}

/// What the fit of `recording` (its flights found) says of its units: the "mixed units?" note,
/// or the failure's message where it fails; empty where neither names them.
std::string units_named(const GyroRecording& recording) {
  try {
    const FitReport report = fit_report(pool_recordings({recording}), {});
    for (const std::string& note : report.result.body.notes)
      if (note.find("(mixed units?)") != std::string::npos) return note;
    return {};
  } catch (const InputError& e) {
    const std::string what = e.what();
    return what.find("(mixed units?)") != std::string::npos ? what : std::string();
  }
}

TEST(MixedUnits, ARealRecordingWithEachAxisInTurnInDegreesPerSecondIsNamed) {
  REQUIRE_REAL_RECORDINGS();
  const GyroRecording real = read_recording(real_dir() / "12-22-44");
  for (int c = 0; c < 3; ++c) {
    const std::string name = std::string("12-22-44-") + "xyz"[c] + "-in-degrees";
    const std::string said = units_named(written_in_mixed_units(real, 1 << c, name));
    std::printf("%s: %s\n", name.c_str(), said.c_str());
    EXPECT_NE(said.find(name + ".csv: " + kAxis[c] + " looks like it is in °/s"), std::string::npos)
        << said;
  }
  // As recorded, all in rad/s: no such note (nor in a bare CSV).
  EXPECT_EQ(units_named(real), "");
  EXPECT_EQ(units_named(written_in_mixed_units(real, 0, "12-22-44-as-recorded")), "");
}

TEST(MixedUnits, ASyntheticRecordingWithOneOrTwoAxesInDegreesPerSecondIsNamed) {
  const test::SyntheticRecording s = test::make_recording(
      test::phone_on_book(), {{{0.5, 3.0, 0.4}, 1.2}, {{-0.3, 2.5, 0.7}, 1.3}});
  const GyroRecording synthetic = test::as_read(s);
  const std::string one = units_named(written_in_mixed_units(synthetic, 1, "synthetic-x"));
  std::printf("x in °/s: %s\n", one.c_str());
  EXPECT_NE(one.find("synthetic-x.csv: ω_x looks like it is in °/s while ω_y and ω_z are in "
                     "rad/s (mixed units?)"),
            std::string::npos)
      << one;
  const std::string two = units_named(written_in_mixed_units(synthetic, 5, "synthetic-xz"));
  std::printf("x and z in °/s: %s\n", two.c_str());
  EXPECT_NE(two.find("synthetic-xz.csv: ω_x and ω_z look like they are in °/s while ω_y is in "
                     "rad/s (mixed units?)"),
            std::string::npos)
      << two;
  EXPECT_EQ(units_named(written_in_mixed_units(synthetic, 0, "synthetic")), "");
}

TEST(MixedUnits, ARefitInDegreesThatRunsPastTheHorizonIsNoCauseNotACrash) {
  // The units' probe fits the recording again with an axis taken as °/s; where that refit drives
  // the moments so far apart that the exact motion passes its time horizon (a real recording
  // re-timed at a browser's ~55 Hz did), the probe finds no cause, as where the refit fails:
  // the fit as read stands, with its own flags.
  REQUIRE_REAL_RECORDINGS();
  const GyroRecording recording = pool_recordings(
      {written_in_mixed_units(read_recording(real_dir() / "12-22-44"), 1, "12-22-44-probe")});
  const FlightSearch search = find_flights(recording);
  FitSettings settings;
  settings.trim_ends = true;
  int refits = 0;
  const auto past_horizon = [&](const GyroRecording&, const FlightSearch&,
                                const FitSettings&) -> FitResult {
    ++refits;
    throw physics::ExactHorizonError("t = 0.02 is beyond the exact motion's time horizon");
  };
  const auto refused = [&](const GyroRecording&, const FlightSearch&,
                           const FitSettings&) -> FitResult {
    ++refits;
    throw InputError("no flight");
  };
  EXPECT_EQ(units_cause(recording, search, settings, nullptr, past_horizon), "");
  EXPECT_EQ(units_cause(recording, search, settings, nullptr, refused), "");
  EXPECT_EQ(refits, 2) << "the probe did not refit: the case tests nothing";
}

const char* const kReal[] = {"12-10-56", "12-13-01", "12-13-51", "12-22-44",
                             "12-29-59", "12-38-00", "12-44-51"};

/// `recording` thinned to every `every`-th sample from sample `from`, its times shifted by
/// `shift` s.
GyroRecording thinned(const GyroRecording& recording, std::size_t every, std::size_t from,
                      double shift) {
  GyroRecording thin;
  thin.name = recording.name;
  thin.source = recording.source;
  for (std::size_t i = from; i < recording.t.size(); i += every)
    thin.t.push_back(recording.t[i] + shift), thin.omega.push_back(recording.omega[i]);
  for (double pause : recording.pauses) thin.pauses.push_back(pause + shift);
  thin.gyroscope_range = recording.gyroscope_range;
  return thin;
}

// The relation "a clean recording stays clean": thinning a real recording (all in rad/s) to every
// second sample, from the first or the second (a 100 Hz recording at 50 Hz), or shifting its
// times, never adds a "mixed units?" note or cause that the recording as read does not have. A
// units probe that names an axis on a thinned clean recording makes a false claim.
TEST(MixedUnits, ThinningOrShiftingACleanRecordingNeverAddsAUnitsNote) {
  REQUIRE_REAL_RECORDINGS();
  for (const char* name : kReal) {
    const GyroRecording real = read_recording(real_dir() / name);
    ASSERT_EQ(units_named(real), "") << name;
    for (const auto& [every, from, shift] :
         {std::tuple<std::size_t, std::size_t, double>{2, 0, 0.0}, {2, 1, 0.0}, {1, 0, 1000.0}}) {
      const std::string said = units_named(thinned(real, every, from, shift));
      EXPECT_EQ(said, "") << name << " every " << every << " from " << from << ", shifted " << shift
                          << " s";
    }
  }
}

// An axis in °/s in a bare CSV is named wherever its refit explains the flights: 12-29-59 with
// ω_x or ω_y and 12-44-51 with ω_y in °/s went through with no word at 4f909b3 (the probe ran only
// where every toss was flagged, and judged shares of |ω| on other flights); each is now named,
// the right axis (the seven recordings' 21 axes all are, docs/phone-lab.md, "Flags"). Planted
// back, the old rule alone misses 12-29-59's ω_y.
TEST(MixedUnits, AnAxisInDegreesIsNamedWhereItsTossesAreNotAllFlagged) {
  REQUIRE_REAL_RECORDINGS();
  for (const auto& [name, axis] :
       {std::pair<const char*, int>{"12-29-59", 0}, {"12-29-59", 1}, {"12-44-51", 1}}) {
    const std::string file = std::string(name) + "-" + "xyz"[axis] + "-bare";
    const std::string said =
        units_named(written_in_mixed_units(read_recording(real_dir() / name), 1 << axis, file));
    EXPECT_NE(said.find(file + ".csv: " + kAxis[axis] + " looks like it is in °/s"),
              std::string::npos)
        << file << ": " << said;
  }
}

}  // namespace
}  // namespace bookspin::fit
