// The list of every column of the sweep, accuracy, energy and diagnostics CSVs and of every
// measure (docs/physics.md §9, §14, docs/accuracy.md), each with the test that checks its
// value against a number computed without the code that writes it. The list is compared with
// the real headers and the real measure table: a column or measure that exists and is not
// listed here fails, and so does a listed one that no longer exists or whose test is gone.
//
// Adding a column or a measure means adding its independent check first (a closed form, a
// rotation from axis and angle, a run replayed by hand: tests/jobs/csv_columns_test.cpp
// compares each CSV column by name and fails on a column it has no value for), then its line
// here naming that test.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/measures.hpp"
#include "common/csv_writer.hpp"
#include "common/text_file.hpp"
#include "jobs/accuracy_report.hpp"
#include "jobs/sweep.hpp"
#include "output/diagnostics_csv.hpp"
#include "scene/scene.hpp"

namespace bookspin {
namespace {

/// A column or measure and the test ("FILE: Suite.Name", FILE under tests/) that checks it.
struct Covered {
  std::string name;
  std::string test;
};

const std::string kSweepFlipping =
    "jobs/csv_columns_test.cpp: CsvColumns.SweepRowsOfAFlippingRunMatchTheReplayAndTheClosedForm";
const std::string kSweepTwist =
    "jobs/csv_columns_test.cpp: CsvColumns.SweepTwistColumnsOfASymmetricTopAreTheHandFormula";
const std::string kSweepSteady =
    "jobs/csv_columns_test.cpp: CsvColumns.SweepRowsOfASteadySpinHoldTheEulerLagAndNothingElse";
const std::string kSweepDiverging =
    "jobs/csv_columns_test.cpp: CsvColumns.SweepRowsOfADivergingRunDivergeAtTheClosedFormStep";
const std::string kSweepRefused =
    "jobs/csv_columns_test.cpp: "
    "CsvColumns.SweepRowsOfPointsTheEngineRefusesSayWhyAndMeasureNothing";
const std::string kOrientation =
    "analysis/orientation_error_test.cpp: "
    "OrientationErrorMeasure.EulerStepsOfASteadySpinLagByTheClosedFormAngle";
const std::string kAccuracy =
    "jobs/csv_columns_test.cpp: CsvColumns.AccuracyAndEnergyCsvRowsMatchTheReplayAndTheClosedForm";
const std::string kQuaternionRows =
    "jobs/csv_columns_test.cpp: CsvColumns.DiagnosticsCsvOfTheQuaternionModelIsItsEquationsByHand";
const std::string kParticleRows =
    "jobs/csv_columns_test.cpp: CsvColumns.DiagnosticsCsvOfTheParticleModelIsItsStateByHand";

/// Every measure of analysis::measure_table(), and every exact column beside one.
const std::vector<Covered> kMeasures{
    {"first_flip", kSweepFlipping},       {"flip_period", kSweepFlipping},
    {"energy_drift", kSweepFlipping},     {"orientation_error", kOrientation},
    {"diverged_at", kSweepDiverging},     {"twist", kSweepTwist},
    {"first_flip_exact", kSweepFlipping}, {"flip_period_exact", kSweepFlipping},
    {"twist_exact", kSweepTwist},
};

/// The sweep CSV's columns after the varied keys (each key's cells are the grid values,
/// checked in every sweep test): the measures, their exact columns, then refused.
const std::vector<Covered> kSweepColumns{
    {"first_flip", kSweepFlipping},       {"flip_period", kSweepFlipping},
    {"energy_drift", kSweepFlipping},     {"orientation_error", kSweepSteady},
    {"diverged_at", kSweepDiverging},     {"twist", kSweepTwist},
    {"first_flip_exact", kSweepFlipping}, {"flip_period_exact", kSweepFlipping},
    {"twist_exact", kSweepTwist},         {"refused", kSweepRefused},
};

/// The accuracy CSV. ns_per_step is a measured time: checked finite and positive only.
const std::vector<Covered> kAccuracyColumns{
    {"model", kAccuracy},        {"integrator", kAccuracy},
    {"dt", kAccuracy},           {"steps", kAccuracy},
    {"t_end", kAccuracy},        {"orientation_error_rad", kAccuracy},
    {"energy_drift", kAccuracy}, {"L_drift", kAccuracy},
    {"flip_period", kAccuracy},  {"flip_period_error", kAccuracy},
    {"ns_per_step", kAccuracy},  {"diverged", kAccuracy},
    {"first_flip", kAccuracy},   {"first_flip_error", kAccuracy},
    {"flips", kAccuracy},        {"flips_exact", kAccuracy},
};

/// The long-time energy CSV: t, then one column per rigid method.
const std::vector<Covered> kEnergyColumns{
    {"t", kAccuracy},
    {"rigid-matrix euler", kAccuracy},
    {"rigid-matrix rk4", kAccuracy},
    {"rigid-matrix implicit-midpoint", kAccuracy},
    {"rigid-matrix splitting", kAccuracy},
    {"rigid-matrix splitting4", kAccuracy},
    {"rigid-matrix rescaled-euler", kAccuracy},
    {"rigid-quaternion euler", kAccuracy},
    {"rigid-quaternion rk4", kAccuracy},
    {"rigid-quaternion implicit-midpoint", kAccuracy},
    {"rigid-quaternion splitting", kAccuracy},
    {"rigid-quaternion splitting4", kAccuracy},
    {"rigid-quaternion rescaled-euler", kAccuracy},
};

/// The diagnostics CSV (docs/physics.md §9). The centre of mass stays at the origin in every
/// model of the book, so com_x, com_y, com_z are checked as 0.
const std::vector<Covered> kDiagnosticsColumns{
    {"frame", kQuaternionRows},
    {"t", kQuaternionRows},
    {"omega_x", kParticleRows},
    {"omega_y", kParticleRows},
    {"omega_z", kParticleRows},
    {"L_x", kParticleRows},
    {"L_y", kParticleRows},
    {"L_z", kParticleRows},
    {"energy_kinetic", kParticleRows},
    {"energy_potential", kParticleRows},
    {"energy_total", kParticleRows},
    {"cos_x_L", kQuaternionRows},
    {"cos_y_L", kQuaternionRows},
    {"cos_z_L", kQuaternionRows},
    {"strain_max", kQuaternionRows},
    {"orthogonality_error", kQuaternionRows},
    {"quaternion_norm", kQuaternionRows},
    {"cos_smallest_L", kQuaternionRows},
    {"cos_intermediate_L", kQuaternionRows},
    {"cos_largest_L", kQuaternionRows},
    {"q_w", kQuaternionRows},
    {"q_x", kQuaternionRows},
    {"q_y", kQuaternionRows},
    {"q_z", kQuaternionRows},
    {"com_x", kParticleRows},
    {"com_y", kParticleRows},
    {"com_z", kParticleRows},
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

/// Fails for every name of `actual` that `listed` lacks, every listed name that `actual`
/// lacks, and every listed test that its file does not define.
void expect_listed(const std::vector<std::string>& actual, const std::vector<Covered>& listed,
                   const std::string& what) {
  ASSERT_FALSE(actual.empty()) << what;
  for (const std::string& name : actual) {
    const bool found =
        std::any_of(listed.begin(), listed.end(), [&](const Covered& c) { return c.name == name; });
    EXPECT_TRUE(found) << what << ": " << name
                       << " has no independent check listed here: add its check (a number "
                          "computed without the code that writes it) and its line here";
  }
  for (const Covered& c : listed) {
    EXPECT_NE(std::find(actual.begin(), actual.end(), c.name), actual.end())
        << what << ": " << c.name << " is listed but does not exist any more";
    const auto colon = c.test.find(": ");
    const auto dot = c.test.find('.', colon);
    ASSERT_NE(dot, std::string::npos) << c.test;
    const std::string file = std::string(BOOKSPIN_SOURCE_DIR) + "/tests/" + c.test.substr(0, colon);
    const std::string definition =
        "TEST(" + c.test.substr(colon + 2, dot - colon - 2) + ", " + c.test.substr(dot + 1) + ")";
    EXPECT_NE(read_text_file(file, "the test file").find(definition), std::string::npos)
        << what << ": " << c.name << " names " << c.test << ", which " << file
        << " does not define";
  }
}

TEST(CsvColumnList, EveryMeasureHasAnIndependentCheck) {
  std::vector<std::string> names;
  for (const analysis::Measure& m : analysis::measure_table()) {
    names.emplace_back(m.name);
    if (m.exact) names.emplace_back(m.exact_name);
  }
  expect_listed(names, kMeasures, "measure table");
}

TEST(CsvColumnList, EverySweepColumnHasAnIndependentCheck) {
  jobs::MeasureList all;
  for (const analysis::Measure& m : analysis::measure_table()) all.push_back(&m);
  expect_listed(jobs::sweep_csv_header({}, all), kSweepColumns, "sweep CSV");
}

TEST(CsvColumnList, EveryAccuracyColumnHasAnIndependentCheck) {
  expect_listed(jobs::accuracy_csv_columns(), kAccuracyColumns, "accuracy CSV");
}

TEST(CsvColumnList, EveryDiagnosticsColumnHasAnIndependentCheck) {
  expect_listed(split(output::diagnostics_csv_header()), kDiagnosticsColumns, "diagnostics CSV");
}

// The energy CSV's header as `bookspin accuracy` writes it: a short run of a fast spin.
TEST(CsvColumnList, EveryEnergyColumnHasAnIndependentCheck) {
  jobs::AccuracyRequest request;
  request.scene = scene::parse_scene_text(
      "[model]\nnormalize = true\n[initial]\njiggle = 0\nangular_velocity = [4.6, 1.2, 0]\n",
      "energy.toml");
  request.flips = 1.0;
  request.dts = {0.1};
  const std::string energy =
      csv_text(jobs::energy_csv(jobs::measure_accuracy(request)), "energy CSV");
  const std::string header = energy.substr(0, energy.find('\n'));
  expect_listed(split(header), kEnergyColumns, "energy CSV");
}

}  // namespace
}  // namespace bookspin
