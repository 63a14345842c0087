// The fit product: its layout, its two CSVs' exact bytes for a fit given by hand, and make_fit
// on a synthetic export: every file made, up to date the second time, made again with --force.
#include "products/fit.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "common/text_file.hpp"
#include "fit/synthetic_recording.hpp"
#include "output/manifest.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

TEST(FitProduct, LayoutNamesEveryFile) {
  const FitLayout layout = fit_layout("out", "rec", 2);
  EXPECT_EQ(layout.csv, fs::path("out/rec-fit.csv"));
  EXPECT_EQ(layout.body_csv, fs::path("out/rec-fit-body.csv"));
  EXPECT_EQ(layout.pngs, (std::vector<fs::path>{"out/rec-toss1.png", "out/rec-toss2.png"}));
  EXPECT_EQ(layout.scenes, (std::vector<fs::path>{"out/rec-toss1.toml", "out/rec-toss2.toml"}));
  EXPECT_EQ(layout.measured,
            (std::vector<fs::path>{"out/rec-toss1-measured.csv", "out/rec-toss2-measured.csv"}));
  EXPECT_EQ(layout.manifest, fs::path("out/rec/fit-manifest.json"));
  EXPECT_EQ(layout.outputs().size(), 8u);
  EXPECT_EQ(fit_layout("out", "rec", 2, false).outputs().size(), 4u);
}

TEST(FitProduct, CsvsOfAFitGivenByHand) {
  fit::FitResult result;
  fit::TossFit toss;
  toss.flight = {10, 120, 1.5, 2.75};
  toss.omega0 = Eigen::Vector3d(0.25, 14, -0.5);
  toss.half_period_fitted = 0.625;
  toss.half_period_predicted = 0.5;
  toss.predicted_from_tosses = 2;
  toss.predicted_from_seconds = 2.25;
  toss.residual_rms = 0.01;
  toss.L_decay = 0.125;
  toss.drag_rate = 0.1875;
  toss.drag_rate_sigma = 0.0625;
  toss.poor_fit = true;
  toss.flag = "a catch inside the flight? the residual jumps, near t = 1.00 s";
  toss.saturated = 3;
  result.tosses.push_back(toss);
  result.drag = physics::DragLaw::quadratic;
  result.body.ratios = Eigen::Vector3d(0.25, 0.75, 1.0);
  result.body.axes = Eigen::Matrix3d::Identity();
  result.body.ratio_sigma = Eigen::Vector3d(0.001, 0.002, 0.0);
  result.parts.resize(1);  // one recording: a pool of one
  fit::RecordingPart& part = result.parts[0];
  part.rest.samples = 100;
  part.rest.stretches = {{0.25, 1.25}};
  part.bias = part.rest.mean = Eigen::Vector3d(0.5, -0.25, 0.125);
  part.rest.sigma = Eigen::Vector3d(0.03125, 0.0625, 0.015625);
  EXPECT_EQ(
      csv_text(fit::fit_toss_csv(result), "fit CSV"),
      "toss,t_start,t_end,omega0_x,omega0_y,omega0_z,half_period_measured,"
      "half_period_fitted,half_period_predicted,half_period_predicted_sigma,"
      "half_period_propagated_sigma,prediction_interval,predicted_from_"
      "tosses,predicted_from_seconds,predicted_window,not_predicted,"
      "residual_rms,L_decay,drag_rate,"
      "drag_rate_sigma,saturated,stable,poor_fit,flag\n"
      "1,1.5,2.75,0.25,14,-0.5,,0.625,0.5,,,,2,2.25,,,0.01,0.125,0.1875,0.0625,3,no,yes,\"a catch "
      "inside "
      "the flight? the residual jumps, near t = 1.00 s\"\n");
  EXPECT_EQ(csv_text(fit::fit_body_csv(result), "fit body CSV"),
            "I1_over_I3,I2_over_I3,I3_over_I3,I1_sigma,I2_sigma,axis1_x,axis1_y,axis1_z,axis2_x,"
            "axis2_y,axis2_z,axis3_x,axis3_y,axis3_z,axis1_sigma_deg,axis2_sigma_deg,"
            "axis3_sigma_deg,moments,tosses,drag,bias_x,bias_y,bias_z,bias_sigma_x,bias_sigma_y,"
            "bias_sigma_z\n"
            "0.25,0.75,1,0.001,0.002,1,0,0,0,1,0,0,0,1,,,,fitted,1,quadratic,0.5,-0.25,0.125,"
            "0.03125,0.0625,0.015625\n");
  // The bias's line follows the result table (its title, header and the one toss's row).
  EXPECT_EQ(fit::fit_summary(result).at(3),
            "bias (rad/s, the mean of 100 samples where the phone lay still, 0.25–1.25 s, ± their "
            "scatter): 0.500 ± 0.031, -0.250 ± 0.062, 0.125 ± 0.016");
  // No still stretch: the bias fitted from the flights (all of it the correction), its σ the
  // fit's standard error.
  part.rest = {};
  part.bias_correction = part.bias;
  part.bias = Eigen::Vector3d::Zero();
  part.bias_fitted_sigma = Eigen::Vector3d(0.25, 0.5, 0.75);
  EXPECT_NE(csv_text(fit::fit_body_csv(result), "fit body CSV")
                .find(",quadratic,0.5,-0.25,0.125,0.25,0.5,0.75\n"),
            std::string::npos);
  EXPECT_EQ(fit::fit_summary(result).at(3),
            "no still stretch in the recording: the bias (rad/s) is fitted from the flights: "
            "0.50 ± 0.25, -0.25 ± 0.50, 0.12 ± 0.75 (1σ)");
  // Fitted but consistent with zero: held at zero, said so, its σ kept.
  part.bias_not_applied = part.bias_correction;
  part.bias_correction = Eigen::Vector3d::Zero();
  EXPECT_EQ(fit::fit_summary(result).at(3),
            "no still stretch in the recording: the bias (rad/s) the flights give, 0.50 ± 0.25, "
            "-0.25 ± 0.50, 0.12 ± 0.75 (1σ), is consistent with zero (χ² 4.3 over 3 axes, under "
            "11.3): not removed, held at zero within those σ");
  EXPECT_NE(
      csv_text(fit::fit_body_csv(result), "fit body CSV").find(",quadratic,0,0,0,0.25,0.5,0.75\n"),
      std::string::npos);
  part.bias_not_applied.reset();
  // Neither: no bias removed, no σ.
  part.bias = part.bias_correction = Eigen::Vector3d::Zero();
  part.bias_fitted_sigma.reset();
  EXPECT_NE(csv_text(fit::fit_body_csv(result), "fit body CSV").find(",quadratic,0,0,0,,,\n"),
            std::string::npos);
  EXPECT_EQ(fit::fit_summary(result).at(3),
            "no still stretch in the recording: the gyroscope's bias is not removed");
}

TEST(FitProduct, MakesEveryFileThenIsUpToDate) {
  const fs::path dir = bookspin::test::fresh_dir("products/fit");
  const auto synthetic = fit::test::make_recording(
      fit::test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}}, 6);
  fit::test::write_export(dir / "toss", synthetic, fit::test::Dialect::comma);
  FitJob job;
  job.recording = fit::pool_recordings({fit::read_recording(dir / "toss")});
  job.out_dir = dir / "out";
  job.width = 640;
  job.height = 360;
  std::vector<std::string> summary;
  EXPECT_EQ(make_fit(job, &summary), cache::Outcome::made);
  const FitLayout layout = fit_layout(job.out_dir, "toss", 2);
  for (const fs::path& path : layout.outputs()) EXPECT_TRUE(fs::exists(path)) << path;
  EXPECT_TRUE(fs::exists(layout.manifest));
  // The result table first (its title, header and a row for each of the two tosses), the bias.
  ASSERT_GE(summary.size(), 5u);
  EXPECT_EQ(summary[0].rfind("result", 0), 0u) << summary[0];
  EXPECT_EQ(summary[4].rfind("bias (rad/s, the mean of ", 0), 0u) << summary[4];
  EXPECT_EQ(make_fit(job), cache::Outcome::up_to_date);
  // The manifest's head names the bookspin that fitted (as every scene product's does), so a
  // rebuilt bookspin fits again.
  EXPECT_NE(read_text_file(layout.manifest, "the manifest")
                .find("\"build_id\": \"sha256:" + output::program_build_id() + "\""),
            std::string::npos);
  job.freshness.force = true;
  EXPECT_EQ(make_fit(job), cache::Outcome::made);
  // Another --moments is another fit.
  job.freshness.force = false;
  job.request.settings.moments = Eigen::Vector3d(49.64, 225.64, 274.0);
  EXPECT_EQ(make_fit(job), cache::Outcome::made);
}

}  // namespace
}  // namespace bookspin::products
