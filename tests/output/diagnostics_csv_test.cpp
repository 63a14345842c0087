// The diagnostics CSV row (output/diagnostics_csv.hpp): every cell against numbers written out
// by hand, its empty cells, and the closing check naming the column (docs/outputs.md, "Numbers").
#include "output/diagnostics_csv.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/internal_error_of.hpp"

namespace bookspin::output {
namespace {

physics::Diagnostics spinning() {
  physics::Diagnostics d;
  d.t = 0.5;
  d.omega_body = {0.1, 0.0, 0.0};
  d.L = {0.2, 0.0, 0.0};
  d.energy_kinetic = d.energy_total = 0.01;
  d.cos_axis_L = {1.0, 0.0, 0.0};
  d.cos_principal_L = {0.0, 1.0, 0.0};
  d.orientation = Eigen::Matrix3d::Identity();
  return d;
}

TEST(DiagnosticsCsvRow, AtRestTheSixCosineCellsAreEmpty) {
  physics::Diagnostics d;  // L = 0, ω = 0
  d.cos_axis_L.setConstant(kNan);
  d.cos_principal_L.setConstant(kNan);
  d.orientation = Eigen::Matrix3d::Identity();
  EXPECT_EQ(diagnostics_csv_row(3, d), "3,0,0,0,0,0,0,0,0,0,0,,,,0,0,1,,,,1,0,0,0,0,0,0");
  // Finite cosines are left out as well: without L they mean nothing.
  d.cos_axis_L.setZero();
  d.cos_principal_L.setZero();
  EXPECT_EQ(diagnostics_csv_row(3, d), "3,0,0,0,0,0,0,0,0,0,0,,,,0,0,1,,,,1,0,0,0,0,0,0");
}

TEST(DiagnosticsCsvRow, SpinningEveryCellHoldsItsNumber) {
  EXPECT_EQ(diagnostics_csv_row(1, spinning()),
            "1,0.5,0.1,0,0,0.2,0,0,0.01,0,0.01,1,0,0,0,0,1,0,1,0,1,0,0,0,0,0,0");
}

TEST(DiagnosticsCsvRow, ANonFiniteNumberIsAnInternalErrorNamingItsColumn) {
  physics::Diagnostics d = spinning();
  d.energy_total = kInf;
  EXPECT_EQ(internal_error_of([&] { diagnostics_csv_row(1, d); }),
            "non-finite diagnostics CSV column energy_total in an output: inf");
  d = spinning();
  d.cos_principal_L[1] = kNan;  // L is not 0: a cosine must be a number
  EXPECT_EQ(internal_error_of([&] { diagnostics_csv_row(1, d); }),
            "non-finite diagnostics CSV column cos_intermediate_L in an output: nan");
  d = spinning();
  d.center_of_mass[2] = -kInf;
  EXPECT_EQ(internal_error_of([&] { diagnostics_csv_row(1, d); }),
            "non-finite diagnostics CSV column com_z in an output: -inf");
}

}  // namespace
}  // namespace bookspin::output
