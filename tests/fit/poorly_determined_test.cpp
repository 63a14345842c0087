// What the body rests on (docs/phone-lab.md, "Reading the result"): no clean flipping toss, or
// under 0.6 s of them, and the body row says "poorly determined"; a clean throw's does not.
#include <gtest/gtest.h>

#include <cmath>

#include "fit/fit_tables.hpp"
#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

/// The body CSV's `moments` cell.
std::string moments_cell(const FitResult& fit) {
  const CsvTable body = fit_body_csv(fit);
  for (std::size_t c = 0; c < body.columns.size(); ++c)
    if (body.columns[c] == "moments") return std::get<std::string>(body.rows.at(0).at(c));
  return "";
}

TEST(PoorlyDetermined, ABodyFromAFlaggedTossOrTooShortAFlightSaysSo) {
  const test::SyntheticBody body = test::phone_alone();
  // One clean 1.2 s throw: fitted.
  test::SyntheticRecording clean = test::make_recording(body, {{{1.0, 18.0, 1.2}, 1.2}}, 91);
  const GyroRecording clean_recording = test::as_recording(clean);
  const FitResult fitted = fit_recording(clean_recording, find_flights(clean_recording));
  ASSERT_EQ(fitted.tosses.size(), 1u);
  ASSERT_FALSE(fitted.tosses[0].poor_fit) << fitted.tosses[0].flag;
  EXPECT_EQ(moments_cell(fitted), "fitted");
  // The same throw whose |ω| breathes by ±10 % (a body that flexes): flagged, and the body
  // resting on it alone is poorly determined.
  test::SyntheticRecording flexing = clean;
  const test::TrueToss& truth = flexing.tosses[0];
  for (std::size_t i = 0; i < flexing.t.size(); ++i) {
    const double s = flexing.t[i] - truth.t_start;
    if (s < 0.0 || flexing.t[i] > truth.t_end) continue;
    flexing.omega[i] = flexing.bias + (flexing.omega[i] - flexing.bias) *
                                          (1.0 + 0.1 * std::sin(2.0 * M_PI * s / 0.25));
  }
  const GyroRecording flexing_recording = test::as_recording(flexing);
  const FitResult flagged = fit_recording(
      flexing_recording, hand_flights(flexing_recording, {{truth.t_start, truth.t_end}}));
  ASSERT_TRUE(flagged.tosses.at(0).poor_fit);
  EXPECT_EQ(moments_cell(flagged), "poorly determined");
  // The clean throw cut to its first 0.5 s (under 0.6 s of flight): poorly determined.
  const FitResult short_fit = fit_recording(
      clean_recording, hand_flights(clean_recording, {{truth.t_start, truth.t_start + 0.5}}));
  ASSERT_FALSE(short_fit.tosses.at(0).poor_fit) << short_fit.tosses[0].flag;
  EXPECT_EQ(moments_cell(short_fit), "poorly determined");
  bool said = false;
  for (const std::string& note : short_fit.body.notes)
    said |= note.find("s of flight (under 0.6 s): the moment ratios are poorly determined") !=
            std::string::npos;
  EXPECT_TRUE(said);
}

}  // namespace
}  // namespace bookspin::fit
