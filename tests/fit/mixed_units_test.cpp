// A recording whose axes are in mixed units (one in °/s, two in rad/s): the fit that goes
// through names the likely cause, the axis and its units, once for the recording
// (fit/toss_flags.hpp, scale_cause), besides the flags of the tosses it spoils; and a recording
// all in rad/s gets no such note.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fit/flights.hpp"
#include "fit/toss_fit.hpp"
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

}  // namespace
}  // namespace bookspin::fit
