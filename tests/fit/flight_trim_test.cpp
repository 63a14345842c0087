// A flight's ends cut by the fitted motion (docs/phone-lab.md, "How the flights are found"):
// fit, trim each end while the exact motion's residual stays above the flight's own noise,
// refit; the rule fit_recording applies for the command line and the page alike.
#include "fit/flight_trim.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "fit/pool.hpp"
#include "fit/report.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

// Flights that run 0.1 s into their catch come back to within 20 ms of the true flight's end;
// left untrimmed, they keep it and are flagged for it.
TEST(FlightTrim, AFlightRunningIntoItsThrowAndCatchIsCutBackToTheFreeFlight) {
  const test::SyntheticRecording synthetic = test::make_recording(
      test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}}, 61);
  const GyroRecording recording = test::as_recording(synthetic);
  std::vector<std::pair<double, double>> long_ranges;
  for (const test::TrueToss& t : synthetic.tosses)
    long_ranges.emplace_back(t.t_start, t.t_end + 0.1);
  const FlightSearch given = hand_flights(recording, long_ranges);
  FitSettings untrimmed;
  untrimmed.trim_ends = false;
  const FitResult kept = fit_recording(recording, given, untrimmed);
  FitSettings trimming;
  trimming.trim_ends = true;
  const FitResult cut = fit_recording(recording, given, trimming);
  ASSERT_EQ(cut.tosses.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const test::TrueToss& truth = synthetic.tosses[k];
    EXPECT_NE(kept.tosses[k].flag.find("catch"), std::string::npos) << k << kept.tosses[k].flag;
    EXPECT_EQ(cut.tosses[k].flag, "") << k;
    std::cout << k << ": kept " << kept.tosses[k].flight.t_start << "–"
              << kept.tosses[k].flight.t_end << " residual " << kept.tosses[k].residual_rms
              << "; cut " << cut.tosses[k].flight.t_start << "–" << cut.tosses[k].flight.t_end
              << " residual " << cut.tosses[k].residual_rms << "\n";
    EXPECT_NEAR(cut.tosses[k].flight.t_start, truth.t_start, 0.02) << k;
    EXPECT_NEAR(cut.tosses[k].flight.t_end, truth.t_end, 0.02) << k;
    EXPECT_LT(cut.tosses[k].residual_rms, 0.5 * kept.tosses[k].residual_rms) << k;
  }
  // Flights that are free to their ends stay as they are.
  EXPECT_FALSE(trimmed_flights(recording, cut, given).has_value());
}

// Every flight of every development recording, each alone: none keeps its throw or its catch
// (a flag naming either) once trimmed; as found, 12-44-51's main throw keeps 70–90 ms of its
// throw (the samples there need a torque, toss_flags.hpp's step_torque). The bare phone's three
// main throws (its longest tosses) alone are clean, and pooled each of its tosses is: 12-13-01's
// and 12-13-51's throws, whole, fit at 5.1 % of |ω| overall but 2.8 and 1.2 % in their typical
// 50 ms, the rest in their last 0.1 s (the fit drifting off near the separatrix).
TEST(FlightTrim, NoRealFlightKeepsItsThrowOrCatch) {
  REQUIRE_REAL_RECORDINGS();
  const auto kept = [](const TossFit& toss) {
    return toss.flag.find("throw inside") != std::string::npos ||
           toss.flag.find("catch inside") != std::string::npos;
  };
  const auto longest = [](const std::vector<TossFit>& tosses) {
    return std::max_element(tosses.begin(), tosses.end(), [](const TossFit& a, const TossFit& b) {
      return a.flight.t_end - a.flight.t_start < b.flight.t_end - b.flight.t_start;
    });
  };
  int keeping = 0;
  for (const char* name :
       {"12-10-56", "12-13-01", "12-13-51", "12-22-44", "12-29-59", "12-38-00", "12-44-51"}) {
    const FitReport report = fit_report(pool_recordings({read_recording(real_dir() / name)}), {});
    for (const TossFit& toss : report.result.tosses) {
      keeping += kept(toss);
      std::cout << name << " " << toss.flight.t_start << "–" << toss.flight.t_end << ": "
                << (toss.flag.empty() ? "clean" : toss.flag) << "\n";
    }
    const bool bare_phone = std::string(name) <= "12-13-51";  // 12-10-56, 12-13-01, 12-13-51
    if (bare_phone) {
      EXPECT_EQ(longest(report.result.tosses)->flag, "") << name;
    }
  }
  EXPECT_EQ(keeping, 0);
  std::vector<GyroRecording> bare;
  for (const char* name : {"12-10-56", "12-13-01", "12-13-51"})
    bare.push_back(read_recording(real_dir() / name));
  const FitReport pooled = fit_report(pool_recordings(bare), {});
  ASSERT_EQ(pooled.result.tosses.size(), 6u);
  for (const TossFit& toss : pooled.result.tosses) {
    EXPECT_EQ(toss.flag, "");
    std::cout << "pooled " << toss.flight.t_start << "–" << toss.flight.t_end << ": "
              << (toss.flag.empty() ? "clean" : toss.flag) << "\n";
  }
}

}  // namespace
}  // namespace bookspin::fit
