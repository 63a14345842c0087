// The fit's CSVs (docs/phone-lab.md, "What the fit writes") column by column, from a fit given
// by hand whose every value differs from every other, so that two cells swapped, an axis's
// components written by rows instead of columns, or a σ in another's column show.
#include "fit/fit_tables.hpp"

#include <gtest/gtest.h>

#include <string>

namespace bookspin::fit {
namespace {

/// The cell of `column` in row `row` of `table`: a number's value, or the text.
std::string text_of(const CsvTable& table, const std::string& column, std::size_t row = 0) {
  for (std::size_t i = 0; i < table.columns.size(); ++i) {
    if (table.columns[i] != column) continue;
    const CsvCell& cell = table.rows.at(row).at(i);
    if (const auto* text = std::get_if<std::string>(&cell)) return *text;
    const CsvNumber& number = std::get<CsvNumber>(cell);
    return number.value ? std::to_string(*number.value) : std::string("(empty)");
  }
  ADD_FAILURE() << "no column " << column;
  return {};
}
double number_of(const CsvTable& table, const std::string& column, std::size_t row = 0) {
  for (std::size_t i = 0; i < table.columns.size(); ++i)
    if (table.columns[i] == column) {
      const auto* number = std::get_if<CsvNumber>(&table.rows.at(row).at(i));
      if (number && number->value) return *number->value;
      ADD_FAILURE() << column << " is not a number";
      return 0.0;
    }
  ADD_FAILURE() << "no column " << column;
  return 0.0;
}

FitResult hand_fit() {
  FitResult fit;
  fit.drag = physics::DragLaw::linear;
  fit.parts.resize(1);  // one recording: a pool of one
  fit.parts[0].name = "hand";
  // Axes: the columns of a rotation with nine different entries (a turn of 0.7 rad about
  // (1, 2, 3)/√14); axis a's phone components are column a.
  fit.body.axes = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  fit.body.ratios = Eigen::Vector3d(0.3125, 0.6875, 1.0);
  fit.body.ratio_sigma = Eigen::Vector3d(0.0011, 0.0022, 0.0);
  fit.body.axis_sigma_deg = Eigen::Vector3d(0.125, 0.25, 0.375);
  for (int k = 0; k < 2; ++k) {
    TossFit toss;
    toss.flight = {10 + 100 * k, 90 + 100 * k, 1.5 + 3 * k, 2.75 + 3 * k};
    toss.omega0 = Eigen::Vector3d(0.5 + k, 13.0 + k, -0.75 - k);
    toss.half_period_measured = 0.4375 + k;
    toss.half_period_fitted = 0.4453125 + k;
    toss.half_period_predicted = 0.453125 + k;
    toss.predicted_from_tosses = 4 + k;
    toss.predicted_from_seconds = 5.5 + k;
    toss.residual_rms = 0.0123 + k;
    toss.L_decay = 0.0625 + k;
    toss.drag_rate = 0.1875 + k;
    toss.drag_rate_sigma = 0.03125 + k;
    toss.saturated = 7 + k;
    toss.stable = k == 1;
    toss.poor_fit = k == 0;
    toss.flag = k == 0 ? "a knock" : "";
    fit.tosses.push_back(toss);
  }
  return fit;
}

TEST(FitTables, EveryTossColumnHoldsItsOwnValue) {
  const FitResult fit = hand_fit();
  const CsvTable table = fit_toss_csv(fit);
  ASSERT_EQ(table.rows.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const double d = static_cast<double>(k);
    EXPECT_EQ(text_of(table, "toss", k), std::to_string(k + 1));
    EXPECT_EQ(number_of(table, "t_start", k), 1.5 + 3 * d);
    EXPECT_EQ(number_of(table, "t_end", k), 2.75 + 3 * d);
    EXPECT_EQ(number_of(table, "omega0_x", k), 0.5 + d);
    EXPECT_EQ(number_of(table, "omega0_y", k), 13.0 + d);
    EXPECT_EQ(number_of(table, "omega0_z", k), -0.75 - d);
    EXPECT_EQ(number_of(table, "half_period_measured", k), 0.4375 + d);
    EXPECT_EQ(number_of(table, "half_period_fitted", k), 0.4453125 + d);
    EXPECT_EQ(number_of(table, "half_period_predicted", k), 0.453125 + d);
    EXPECT_EQ(text_of(table, "predicted_from_tosses", k), std::to_string(4 + k));
    EXPECT_EQ(number_of(table, "predicted_from_seconds", k), 5.5 + d);
    EXPECT_EQ(number_of(table, "residual_rms", k), 0.0123 + d);
    EXPECT_EQ(number_of(table, "L_decay", k), 0.0625 + d);
    EXPECT_EQ(number_of(table, "drag_rate", k), 0.1875 + d);
    EXPECT_EQ(number_of(table, "drag_rate_sigma", k), 0.03125 + d);
    EXPECT_EQ(text_of(table, "saturated", k), std::to_string(7 + k));
    EXPECT_EQ(text_of(table, "stable", k), k == 1 ? "yes" : "no");
    EXPECT_EQ(text_of(table, "poor_fit", k), k == 0 ? "yes" : "no");
    EXPECT_EQ(text_of(table, "flag", k), k == 0 ? "a knock" : "");
  }
}

TEST(FitTables, TheBodyRowWritesEachAxisAsItsPhoneComponents) {
  const FitResult fit = hand_fit();
  const CsvTable table = fit_body_csv(fit);
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(number_of(table, "I1_over_I3"), 0.3125);
  EXPECT_EQ(number_of(table, "I2_over_I3"), 0.6875);
  EXPECT_EQ(number_of(table, "I3_over_I3"), 1.0);
  EXPECT_EQ(number_of(table, "I1_sigma"), 0.0011);
  EXPECT_EQ(number_of(table, "I2_sigma"), 0.0022);
  // Column a of the axes matrix is axis a+1: axis1_y is axes(1, 0), not axes(0, 1).
  const char* xyz[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(number_of(table, "axis" + std::to_string(a + 1) + "_" + xyz[c]),
                fit.body.axes(c, a))
          << "axis " << a + 1 << " component " << xyz[c];
  EXPECT_EQ(number_of(table, "axis1_sigma_deg"), 0.125);
  EXPECT_EQ(number_of(table, "axis2_sigma_deg"), 0.25);
  EXPECT_EQ(number_of(table, "axis3_sigma_deg"), 0.375);
  EXPECT_EQ(text_of(table, "moments"), "fitted");
  EXPECT_EQ(text_of(table, "tosses"), "2");
  EXPECT_EQ(text_of(table, "drag"), "linear");
}

// The moments column says where the ratios came from: given, fitted, or poorly determined.
TEST(FitTables, TheMomentsColumnSaysGivenFittedOrPoorlyDetermined) {
  FitResult fit = hand_fit();
  fit.body.moments_fixed = true;
  EXPECT_EQ(text_of(fit_body_csv(fit), "moments"), "given");
  fit.body.moments_fixed = false;
  fit.body.moments_determined = false;
  EXPECT_EQ(text_of(fit_body_csv(fit), "moments"), "poorly determined");
}

}  // namespace
}  // namespace bookspin::fit
