// The accuracy report's plots (src/charts/accuracy_plots.cpp): which rows make which line, and
// how the methods are told apart.
#include "charts/accuracy_plots.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bookspin::charts {
namespace {

using analysis::AccuracyRow;
using analysis::Method;
using physics::Integrator;
using physics::ModelKind;

AccuracyRow row(Method m, double dt, double energy_drift, bool diverged = false) {
  AccuracyRow r;
  r.method = m;
  r.dt = dt;
  r.energy_drift = energy_drift;
  r.diverged = diverged;
  return r;
}

// One line per asked method, through its own rows' (dt, energy drift) in row order; a
// diverged row has no energy to compare and is left out.
TEST(AccuracyPlots, EnergyAgainstDtHasOneLinePerMethodThroughItsRows) {
  const Method rk4{ModelKind::rigid_quaternion, Integrator::rk4};
  const Method bullet{ModelKind::bullet, Integrator::implicit_body};
  const Method ode_none{ModelKind::ode, Integrator::none};
  const std::vector<AccuracyRow> rows{row(rk4, 0.1, 1e-3),         row(rk4, 0.01, 1e-7),
                                      row(bullet, 0.1, 0.5, true), row(bullet, 0.01, 0.05),
                                      row(ode_none, 0.1, 2e-15),   row(ode_none, 0.01, 1e-15)};
  const overlay::PlotSpec spec = energy_vs_dt_plot(rows, {bullet, rk4}, 10.0);
  ASSERT_EQ(spec.series.size(), 2u);
  EXPECT_EQ(spec.series[0].label, "bullet implicit-body");
  EXPECT_EQ(spec.series[0].x, (std::vector<double>{0.01}));
  EXPECT_EQ(spec.series[0].y, (std::vector<double>{0.05}));
  EXPECT_EQ(spec.series[1].label, "rigid-quaternion rk4");
  EXPECT_EQ(spec.series[1].x, (std::vector<double>{0.1, 0.01}));
  EXPECT_EQ(spec.series[1].y, (std::vector<double>{1e-3, 1e-7}));
  EXPECT_TRUE(spec.log_x && spec.log_y);
}

// The orientation error keeps a diverged row (its NaN error breaks the line where it diverged)
// and leaves out a method without rows.
TEST(AccuracyPlots, OrientationErrorAgainstDtKeepsDivergedRows) {
  const Method euler{ModelKind::rigid_matrix, Integrator::euler};
  const Method rk4{ModelKind::rigid_matrix, Integrator::rk4};
  AccuracyRow coarse = row(euler, 0.1, 0.5, true);
  coarse.orientation_error = std::nan("");
  AccuracyRow fine = row(euler, 0.01, 1e-3);
  fine.orientation_error = 0.25;
  const overlay::PlotSpec spec = orientation_error_vs_dt_plot({coarse, fine}, {rk4, euler}, 10.0);
  ASSERT_EQ(spec.series.size(), 1u);
  EXPECT_EQ(spec.series[0].label, "rigid-matrix euler");
  EXPECT_EQ(spec.series[0].x, (std::vector<double>{0.1, 0.01}));
  EXPECT_TRUE(std::isnan(spec.series[0].y[0]));
  EXPECT_EQ(spec.series[0].y[1], 0.25);
}

// The work–precision cost is the CPU time per simulated time unit: ns_per_step / dt ns, shown
// in µs. Worked by hand: 50 ns a step at dt = 0.01 is 100 steps per time unit, 5000 ns = 5 µs;
// 30 ns at dt = 0.1 is 0.3 µs; 400 ns at dt = 1/60 is 24 µs. The error is each row's own.
TEST(AccuracyPlots, WorkPrecisionCostIsNsPerStepOverDtInMicroseconds) {
  const Method rk4{ModelKind::rigid_quaternion, Integrator::rk4};
  const Method mujoco{ModelKind::mujoco, Integrator::euler};
  AccuracyRow coarse = row(rk4, 0.1, 0.0), fine = row(rk4, 0.01, 0.0),
              engine = row(mujoco, 1.0 / 60.0, 0.0);
  coarse.ns_per_step = 30.0;
  coarse.orientation_error = 1e-3;
  fine.ns_per_step = 50.0;
  fine.orientation_error = 1e-7;
  engine.ns_per_step = 400.0;
  engine.orientation_error = 0.5;
  const overlay::PlotSpec spec = work_precision_plot({coarse, engine, fine}, 10.0);
  ASSERT_EQ(spec.series.size(), 2u);  // accuracy_methods() order: bookspin's, then engines'
  EXPECT_EQ(spec.series[0].label, "rigid-quaternion rk4");
  ASSERT_EQ(spec.series[0].x.size(), 2u);
  EXPECT_NEAR(spec.series[0].x[0], 0.3, 1e-12);
  EXPECT_NEAR(spec.series[0].x[1], 5.0, 1e-12);
  EXPECT_EQ(spec.series[0].y, (std::vector<double>{1e-3, 1e-7}));
  EXPECT_EQ(spec.series[1].label, "mujoco euler");
  ASSERT_EQ(spec.series[1].x.size(), 1u);
  EXPECT_NEAR(spec.series[1].x[0], 24.0, 1e-12);
  EXPECT_EQ(spec.series[1].y, (std::vector<double>{0.5}));
  EXPECT_TRUE(spec.log_x && spec.log_y);
}

// Every accuracy method looks different from every other: colour, dash and mark together.
TEST(AccuracyPlots, NoTwoMethodsShareALook) {
  const auto methods = analysis::accuracy_methods();
  for (std::size_t i = 0; i < methods.size(); ++i) {
    overlay::Series a;
    style_series(methods[i], a);
    for (std::size_t j = 0; j < i; ++j) {
      overlay::Series b;
      style_series(methods[j], b);
      EXPECT_FALSE(a.r == b.r && a.g == b.g && a.b == b.b && a.dashed == b.dashed &&
                   a.marker == b.marker)
          << methods[i].label << " looks like " << methods[j].label;
    }
  }
}

}  // namespace
}  // namespace bookspin::charts
