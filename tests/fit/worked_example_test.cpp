// docs/phone-lab.md's worked example, reproduced: the synthetic phone alone (a 7 × 15 × 0.8 cm
// slab, three tosses about its intermediate axis, 100 Hz with jitter, noise 0.01 rad/s, bias,
// spikes, a pause), its flights, its moments and its half periods as the page prints them.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <string>

#include "fit/fit.hpp"
#include "fit/pool.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

std::string three(const std::optional<double>& value) {
  if (!value) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", *value);
  return text;
}

TEST(WorkedExample, ThePhoneAloneInAirAsDocsPhoneLabPrintsIt) {
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_alone(),
      {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}, {{0.9, -19.0, -1.4}, 1.4}}, 11, 0.01,
      0.15, 4.0, /*drag=*/0.15);
  GyroRecording recording;
  recording.name = "phone-alone";
  recording.source = "phone-alone";
  recording.t = synthetic.t;
  recording.omega = synthetic.omega;
  recording.pauses = synthetic.pauses;
  recording = pool_recordings({recording});
  const FitResult fit = fit_recording(recording, find_flights(recording));
  ASSERT_EQ(fit.tosses.size(), 3u);
  std::string table;
  for (const TossFit& t : fit.tosses)
    table += three(t.flight.t_start) + " " + three(t.flight.t_end) + " " +
             three(t.half_period_measured) + " " + three(t.half_period_fitted) + " " +
             three(t.half_period_predicted) + " " + three(t.drag_rate) + "\n";
  // The page's numbers (docs/phone-lab.md, "A worked example").
  EXPECT_EQ(table,
            "1.673 2.924 0.649 0.649 0.650 0.150\n"
            "4.449 5.601 0.622 0.622 0.624 0.150\n"
            "7.101 8.462 0.571 0.571 0.571 0.150\n");
  EXPECT_EQ(three(fit.body.ratios[0]) + " " + three(fit.body.ratios[1]), "0.181 0.823");
  // And the page's numbers are the truth's: the drag rate within 5 %, the predicted flips'
  // spacing within 1 % of the measured one (the generator's ω, integrated from the torque), the
  // slab's moments (49.64 : 225.64 : 274 cm²) within 1 %.
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(fit.tosses[k].drag_rate, 0.15, 0.05 * 0.15);
    EXPECT_NEAR(*fit.tosses[k].half_period_predicted, *fit.tosses[k].half_period_measured,
                0.01 * *fit.tosses[k].half_period_measured);
  }
  EXPECT_NEAR(fit.body.ratios[0], 49.64 / 274.0, 0.01 * 49.64 / 274.0);
  EXPECT_NEAR(fit.body.ratios[1], 225.64 / 274.0, 0.01 * 225.64 / 274.0);
}

}  // namespace
}  // namespace bookspin::fit
