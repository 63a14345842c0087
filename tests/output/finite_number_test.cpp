// The closing check on numbers written out (output/finite_number.hpp) and the diagnostics
// CSV row that uses it (docs/outputs.md, "Numbers").
#include "output/finite_number.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "internal_error_of.hpp"
#include "output/diagnostics_csv.hpp"

namespace bookspin::output {
namespace {

TEST(FiniteNumber, PassesFiniteNumbersInShortestRoundTripForm) {
  EXPECT_EQ(finite(0.1, "x"), 0.1);
  EXPECT_EQ(finite_text(0.1, "x"), "0.1");
  EXPECT_EQ(finite_text(1e300, "x"), "1e+300");
  EXPECT_EQ(finite_text(std::numeric_limits<double>::denorm_min(), "x"), "5e-324");
  EXPECT_EQ(finite_text(std::optional<double>(), "x"), "");
  EXPECT_EQ(finite_text(std::optional<double>(-2.5), "x"), "-2.5");
}

TEST(FiniteNumber, NonFiniteIsAnInternalErrorNamingTheField) {
  EXPECT_EQ(internal_error_of([] { finite(kNan, "CSV column a"); }),
            "non-finite CSV column a in an output: nan");
  EXPECT_EQ(internal_error_of([] { finite_text(kInf, "JSON field b"); }),
            "non-finite JSON field b in an output: inf");
  EXPECT_EQ(internal_error_of([] { finite_text(std::optional<double>(-kInf), "c"); }),
            "non-finite c in an output: -inf");
}

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
