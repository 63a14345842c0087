// The accuracy report (src/jobs/accuracy_report.hpp): which methods the long-time energy plot
// runs, decided by the list the report measures and not by its length.
#include "jobs/accuracy_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/csv_writer.hpp"

namespace bookspin::jobs {
namespace {

using analysis::Method;
using physics::Integrator;
using physics::ModelKind;

std::vector<std::string> names(const std::vector<Method>& methods) {
  std::vector<std::string> out;
  for (const Method& m : methods)
    out.push_back(std::string(physics::to_string(m.kind)) + ":" +
                  std::string(physics::to_string(m.integrator)));
  return out;
}

TEST(AccuracyReport, EveryMethodRunsTheRigidPairsOverTheLongTime) {
  // The rigid pairs: rigid-matrix and rigid-quaternion × the six rigid integrators
  // (docs/physics.md §10), written out here.
  std::vector<std::string> rigid;
  for (const char* kind : {"rigid-matrix", "rigid-quaternion"})
    for (const char* integrator :
         {"euler", "rk4", "implicit-midpoint", "splitting", "splitting4", "rescaled-euler"})
      rigid.push_back(std::string(kind) + ":" + integrator);
  EXPECT_EQ(names(long_time_methods(analysis::accuracy_methods())), rigid);
}

TEST(AccuracyReport, AChosenListRunsItsMethodsButTheParticleModels) {
  const std::vector<Method> chosen{Method(ModelKind::particle, Integrator::euler),
                                   Method(ModelKind::rigid_quaternion, Integrator::rk4),
                                   Method(ModelKind::mujoco, Integrator::rk4)};
  EXPECT_EQ(names(long_time_methods(chosen)),
            (std::vector<std::string>{"rigid-quaternion:rk4", "mujoco:rk4"}));
  EXPECT_TRUE(long_time_methods({Method(ModelKind::particle, Integrator::euler)}).empty());

  // As many methods as every method, but not every method: the list itself, no particles.
  std::vector<Method> as_many = analysis::accuracy_methods();
  as_many.front() = {ModelKind::bullet, Integrator::none};
  std::vector<std::string> expected;
  for (const Method& m : as_many)
    if (m.kind != ModelKind::particle) expected.push_back(names({m}).front());
  EXPECT_EQ(names(long_time_methods(as_many)), expected);
  EXPECT_NE(names(long_time_methods(as_many)), names(analysis::rigid_methods()));
}

// The tables of a report measured by hand: a diverged row with fewer than two flips leaves its
// orientation error and flip period cells empty; every other cell is the hand-written text of
// its number in the column's format (docs/accuracy.md). No histories: the energy CSV is its
// header alone.
TEST(AccuracyReport, TheTablesLeaveCellsEmptyWhereThereIsNoValue) {
  analysis::AccuracyRow row;
  row.method = {ModelKind::rigid_matrix, Integrator::euler};
  row.dt = 0.5;
  row.steps = 20;
  row.t_end = 10.0;
  row.orientation_error = std::nan("");
  row.energy_drift = 0.25;
  row.L_drift = 0.125;
  row.flip_period = row.flip_period_error = std::nan("");
  row.first_flip = 3.5;
  row.first_flip_error = 0.0625;
  row.flips = 1;
  row.flips_exact = 2;
  row.ns_per_step = 12.345;
  row.diverged = true;
  const AccuracyReport report{10.0, {row.method}, {row}, {}, {}, {}};
  EXPECT_EQ(csv_text(accuracy_csv(report), "accuracy CSV"),
            "model,integrator,dt,steps,t_end,orientation_error_rad,energy_drift,L_drift,"
            "flip_period,flip_period_error,ns_per_step,diverged,first_flip,first_flip_error,"
            "flips,flips_exact\n"
            "rigid-matrix,euler,0.5,20,10,,2.500000e-01,1.250000e-01,,,12.35,1,3.5,6.250000e-02,"
            "1,2\n");
  EXPECT_EQ(csv_text(energy_csv(report), "energy CSV"), "t\n");
}

// The long-time energy CSV when the first method diverges (Euler of the matrix model, fig10):
// the table keeps every window of the method that ran on, and the diverged method's missing
// windows stay empty (energy_csv, docs/accuracy.md). Written by hand: four windows of 0.5 time
// units, the first method gone after two, the second through all four.
TEST(AccuracyReport, TheEnergyCsvKeepsEveryWindowWhenTheFirstMethodDiverges) {
  analysis::EnergyHistory euler;
  euler.method = {ModelKind::rigid_matrix, Integrator::euler};
  euler.dt = 0.25;
  euler.t = {0.5, 1.0};
  euler.relative_error = {0.25, 0.5};
  euler.diverged = true;
  analysis::EnergyHistory rk4;
  rk4.method = {ModelKind::rigid_quaternion, Integrator::rk4};
  rk4.dt = 0.25;
  rk4.t = {0.5, 1.0, 1.5, 2.0};
  rk4.relative_error = {0.125, 0.0625, 0.03125, 0.015625};
  const std::string expected =
      "t,rigid-matrix euler,rigid-quaternion rk4\n"
      "0.5,2.500000e-01,1.250000e-01\n"
      "1,5.000000e-01,6.250000e-02\n"
      "1.5,,3.125000e-02\n"
      "2,,1.562500e-02\n";
  const AccuracyReport report{10.0, {euler.method, rk4.method}, {}, {euler, rk4}, {}, {}};
  EXPECT_EQ(csv_text(energy_csv(report), "energy CSV"), expected);
  // The other way round, the diverged method last: the same windows.
  const AccuracyReport swapped{10.0, {rk4.method, euler.method}, {}, {rk4, euler}, {}, {}};
  EXPECT_EQ(csv_text(energy_csv(swapped), "energy CSV"),
            "t,rigid-quaternion rk4,rigid-matrix euler\n"
            "0.5,1.250000e-01,2.500000e-01\n"
            "1,6.250000e-02,5.000000e-01\n"
            "1.5,3.125000e-02,\n"
            "2,1.562500e-02,\n");
}

}  // namespace
}  // namespace bookspin::jobs
