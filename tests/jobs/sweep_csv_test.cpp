// A sweep's table and its CSV (jobs/sweep_csv.hpp, docs/sweeps.md): the measures parsed, the
// columns they make, a row's cells and the CSV's bytes, against lines written out by hand.
#include "jobs/sweep_csv.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

#include "common/csv_writer.hpp"
#include "common/errors.hpp"

namespace bookspin::jobs {
namespace {

TEST(SweepMeasures, ParsesNamesAndRejectsUnknownOrRepeated) {
  EXPECT_EQ(
      parse_measures("flip_period,first_flip"),
      (MeasureList{analysis::find_measure("flip_period"), analysis::find_measure("first_flip")}));
  EXPECT_EQ(analysis::find_measure("flip_period")->name, "flip_period");
  EXPECT_THROW(parse_measures("flip_time"), InputError);
  EXPECT_THROW(parse_measures("first_flip,first_flip"), InputError);
  EXPECT_THROW(parse_measures(""), InputError);
}
TEST(SweepCsv, TheColumnsAreTheKeysTheMeasuresTheirExactColumnsThenRefused) {
  const std::vector<VaryRange> ranges{parse_vary("time.dt=0.01:0.02:2"),
                                      parse_vary("initial.angular_velocity[1]=1e-3:1e-2:2:log")};
  EXPECT_EQ(sweep_csv_header(ranges, parse_measures("energy_drift,flip_period,first_flip")),
            (std::vector<std::string>{"time.dt", "initial.angular_velocity[1]", "energy_drift",
                                      "flip_period", "first_flip", "flip_period_exact",
                                      "first_flip_exact", "refused"}));
}

TEST(SweepCsv, ARowIsTheFullPrecisionValuesWithEmptyCellsForWhatARunDidNotReach) {
  analysis::RunMeasures m;
  m.first_flip = 12.5;
  m.first_flip_exact = 0.1;  // 0.1 is not a binary fraction: 17 digits show it
  m.energy_drift = 2.0e-3;   // no flip_period: the run flipped once
  const MeasureList measures = parse_measures("first_flip,flip_period,energy_drift");
  EXPECT_EQ(
      sweep_row_cells({0.25, 3.0}, measures, m),
      (std::vector<std::string>{"0.25", "3", "12.5", "", "0.002", "0.10000000000000001", "", ""}));
}

TEST(SweepCsv, ARefusedPointHasItsValuesNoMeasureAndItsReasonLast) {
  const MeasureList measures = parse_measures("first_flip,flip_period,energy_drift");
  EXPECT_EQ(sweep_refused_cells({1e-320, 3.0}, measures, "time.dt: a reason, with a comma"),
            (std::vector<std::string>{"9.9998886718268301e-321", "3", "", "", "", "", "",
                                      "time.dt: a reason, with a comma"}));
}

TEST(SweepCsv, TheFileIsTheHeaderThenOneLinePerRowWithoutTheGridIndex) {
  SweepTable table;
  table.header = {"time.dt", "first_flip", "first_flip_exact"};
  table.rows = {{4, {"0.01", "", "7"}}, {9, {"0.02", "5.5", "6"}}};
  std::ostringstream out;
  write_sweep_csv(table, out);
  EXPECT_EQ(out.str(), "time.dt,first_flip,first_flip_exact\n0.01,,7\n0.02,5.5,6\n");
}

TEST(SweepCsv, ALineSplitsBackIntoItsCellsEmptyOnesIncluded) {
  const std::vector<std::string> cells{"", "1", "", "2.5", ""};
  EXPECT_EQ(csv_row(cells), ",1,,2.5,");
  EXPECT_EQ(csv_row(after("7", cells)), "7,,1,,2.5,");
  EXPECT_EQ(csv_cells(",1,,2.5,"), cells);
  EXPECT_EQ(csv_cells("x"), std::vector<std::string>{"x"});
}

TEST(SweepCsv, AQuotedCellReadsBackWithItsCommasAndQuotes) {
  // RFC 4180 by hand: a field with a comma or a quote is quoted, its quotes doubled.
  const std::vector<std::string> cells{
      "3", "", "time.dt: ODE (below 2.2e-308, got 1e-320)", "say \"no\"", ",", "\"\""};
  const std::string line =
      "3,,\"time.dt: ODE (below 2.2e-308, got 1e-320)\",\"say \"\"no\"\"\","
      "\",\",\"\"\"\"\"\"";
  EXPECT_EQ(csv_row(cells), line);
  EXPECT_EQ(csv_cells(line), cells);
  EXPECT_EQ(csv_cells("\"\""), std::vector<std::string>{""});
  EXPECT_EQ(csv_cells("a,\"b\""), (std::vector<std::string>{"a", "b"}));
  EXPECT_THROW(csv_cells("1,\"open"), std::invalid_argument);
  EXPECT_THROW(csv_cells("1,\"closed\"x,2"), std::invalid_argument);
  EXPECT_THROW(csv_cells("\"a\"\""), std::invalid_argument);  // a doubled quote, never closed
}

}  // namespace
}  // namespace bookspin::jobs
