// Each pooled recording keeps its own bias (docs/phone-lab.md, "A class's recordings" and "The
// bias"): two recordings of one phone with no rest, their gyroscopes' biases far apart, pooled.
// The bias of each is fitted from its own flights: the generator's bias is the truth.
#include <gtest/gtest.h>

#include <algorithm>

#include "common/csv_writer.hpp"
#include "fit/fit_tables.hpp"
#include "fit/pool.hpp"
#include "fit/report.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

/// `rec`'s samples around its flights only (from 0.2 s before each to 0.15 s after: the throw
/// and the catch), its rests cut out, so that no bias can be measured at rest.
GyroRecording without_rest(const test::SyntheticRecording& rec, const std::string& name) {
  GyroRecording r = test::as_recording(rec, name);
  r.t.clear();
  r.omega.clear();
  r.pauses.clear();
  for (std::size_t i = 0; i < rec.t.size(); ++i)
    for (const test::TrueToss& toss : rec.tosses)
      if (rec.t[i] >= toss.t_start - 0.2 && rec.t[i] <= toss.t_end + 0.15) {
        r.t.push_back(rec.t[i]);
        r.omega.push_back(rec.omega[i]);
        break;
      }
  return r;
}

TEST(PooledBias, EachRecordingsBiasIsFittedFromItsOwnFlights) {
  const std::vector<test::SyntheticToss> tosses_a{{{0.3, 14.0, 0.5}, 1.2},
                                                  {{-0.4, 13.0, 0.6}, 1.1}};
  const std::vector<test::SyntheticToss> tosses_b{{{0.5, -15.0, -0.3}, 1.3},
                                                  {{0.2, 14.5, -0.4}, 1.2}};
  const Eigen::Vector3d bias_a(0.30, -0.20, 0.10), bias_b(-0.25, 0.15, 0.20);
  test::SyntheticRecording a = test::make_recording(test::phone_alone(), tosses_a, 31);
  test::SyntheticRecording b = test::make_recording(test::phone_alone(), tosses_b, 32);
  for (Eigen::Vector3d& w : a.omega) w += bias_a - a.bias;
  for (Eigen::Vector3d& w : b.omega) w += bias_b - b.bias;
  const GyroRecording pooled =
      pool_recordings({without_rest(a, "phone-a"), without_rest(b, "phone-b")});
  ASSERT_EQ(pooled.parts[0].rest.samples, 0);
  ASSERT_EQ(pooled.parts[1].rest.samples, 0);
  const FitReport report = fit_report(pooled, {});
  const FitResult& fit = report.result;
  ASSERT_EQ(fit.tosses.size(), 4u);
  // One correction for both would sit between them, 0.2–0.3 rad/s from each.
  const Eigen::Vector3d truth[2] = {bias_a, bias_b};
  for (int p = 0; p < 2; ++p) {
    const RecordingPart& part = fit.parts[p];
    ASSERT_TRUE(part.bias_fitted_sigma.has_value()) << p;
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(part.bias_correction[i], truth[p][i], 0.02) << p << " " << i;
      EXPECT_GT((*part.bias_fitted_sigma)[i], 0.0);
      EXPECT_LT((*part.bias_fitted_sigma)[i], 0.02);
    }
  }
  // The body CSV: a row per recording, named, with its own bias and σ.
  const CsvTable body = fit_body_csv(fit);
  ASSERT_EQ(body.rows.size(), 2u);
  ASSERT_EQ(body.columns.front(), "recording");
  const auto column = [&](const std::string& name) {
    return std::find(body.columns.begin(), body.columns.end(), name) - body.columns.begin();
  };
  for (int p = 0; p < 2; ++p) {
    EXPECT_EQ(std::get<std::string>(body.rows[p][0]), p == 0 ? "phone-a" : "phone-b");
    const auto number = [&](const std::string& name) {
      return std::get<CsvNumber>(body.rows[p][column(name)]).value;
    };
    ASSERT_TRUE(number("bias_y").has_value());
    EXPECT_NEAR(*number("bias_y"), truth[p][1], 0.02);
    EXPECT_TRUE(number("bias_sigma_z").has_value());
  }
  // The summary says where each bias came from.
  const std::vector<std::string> lines = fit_summary(fit);
  for (const char* name : {"phone-a", "phone-b"}) {
    const std::string expected = std::string("no still stretch in ") + name +
                                 ": its bias (rad/s) is fitted from its flights: ";
    EXPECT_NE(std::find_if(lines.begin(), lines.end(),
                           [&](const std::string& l) { return l.rfind(expected, 0) == 0; }),
              lines.end())
        << name;
  }
  // The measured ω the charts show has each recording's own bias removed: at each toss's
  // start within the noise (and the fit's residual) of the truth without bias.
  for (int k = 0; k < 4; ++k) {
    std::vector<double> t;
    std::vector<Eigen::Vector3d> omega;
    measured_omega(pooled, fit, k, t, omega);
    const Eigen::Vector3d fitted = fitted_omega(fit, k, t.front());
    EXPECT_LT((omega.front() - fitted).norm(), 0.1) << k;
  }
}

}  // namespace
}  // namespace bookspin::fit
