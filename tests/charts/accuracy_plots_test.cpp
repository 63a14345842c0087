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
// diverged row keeps its largest error before it diverged; the range is the data's.
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
  EXPECT_EQ(spec.series[0].x, (std::vector<double>{0.1, 0.01}));
  EXPECT_EQ(spec.series[0].y, (std::vector<double>{0.5, 0.05}));
  EXPECT_EQ(spec.series[1].label, "rigid-quaternion rk4");
  EXPECT_EQ(spec.series[1].x, (std::vector<double>{0.1, 0.01}));
  EXPECT_EQ(spec.series[1].y, (std::vector<double>{1e-3, 1e-7}));
  EXPECT_TRUE(spec.log_x && spec.log_y);
  EXPECT_FALSE(spec.y_range);
}

// An energy error beyond 100 (MuJoCo's Euler at dt = 1/30 reaches 1.2e8 before it blows up)
// fixes the range from the decade of the smallest error to 100: drawn at the edge, marked.
TEST(AccuracyPlots, EnergyBeyondAHundredIsDrawnAtTheTopEdge) {
  const Method euler{ModelKind::mujoco, Integrator::euler};
  const overlay::PlotSpec spec = energy_vs_dt_plot(
      {row(euler, 1.0 / 30, 1.2e8, true), row(euler, 1.0 / 60, 6.1), row(euler, 1e-3, 3e-4)},
      {euler}, 10.0);
  ASSERT_TRUE(spec.y_range);
  EXPECT_EQ(spec.y_range->first, 1e-4);
  EXPECT_EQ(spec.y_range->second, 100.0);
  EXPECT_EQ(spec.series[0].y.front(), 1.2e8);
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

// Turn-overs counted over exact ones, per row: diverged rows and rows without an exact
// turn-over left out, a method that never turns over labelled so, the range fixed at 0 … 2;
// the title says the spin and the angle per step at the smallest and largest dt.
TEST(AccuracyPlots, TurnoversAgainstDtIsTheCountOverTheExactCount) {
  const Method rk4{ModelKind::rigid_quaternion, Integrator::rk4};
  const Method none{ModelKind::bullet, Integrator::none};
  std::vector<AccuracyRow> rows{row(rk4, 0.1, 1e-3),   row(rk4, 0.05, 1e-5),
                                row(rk4, 0.01, 1e-7),  row(rk4, 0.5, 1.0, true),
                                row(none, 0.1, 1e-15), row(none, 0.01, 1e-15)};
  rows[0].flips = 12, rows[0].flips_exact = 10;
  rows[1].flips = 3, rows[1].flips_exact = 0;  // no exact turn-over: no ratio
  rows[2].flips = 10, rows[2].flips_exact = 10;
  rows[3].flips = 40, rows[3].flips_exact = 10;  // diverged
  rows[4].flips_exact = rows[5].flips_exact = 10;
  const overlay::PlotSpec spec = turnovers_vs_dt_plot(rows, {rk4, none}, 10.0, 6.0);
  ASSERT_EQ(spec.series.size(), 2u);
  EXPECT_EQ(spec.series[0].label, "rigid-quaternion rk4");
  EXPECT_EQ(spec.series[0].x, (std::vector<double>{0.1, 0.05, 0.01}));
  EXPECT_EQ(spec.series[0].y[0], 1.2);
  EXPECT_TRUE(std::isnan(spec.series[0].y[1]));
  EXPECT_EQ(spec.series[0].y[2], 1.0);
  EXPECT_EQ(spec.series[1].label, "bullet none (never turns over)");
  EXPECT_EQ(spec.series[1].y, (std::vector<double>{0.0, 0.0}));
  EXPECT_TRUE(spec.log_x);
  EXPECT_FALSE(spec.log_y);
  ASSERT_TRUE(spec.y_range);
  EXPECT_EQ(*spec.y_range, (std::pair{0.0, 2.0}));
  // |ω0| = 6, dt from 0.01 to 0.5 (the diverged row's dt counts: it was run): 0.06 … 3.
  EXPECT_NE(spec.title.find("; |ω0| = 6 rad/t, ω·dt = 0.06 … 3 rad"), std::string::npos)
      << spec.title;
  EXPECT_EQ(energy_vs_dt_plot(rows, {rk4}, 10.0).title.find("ω0"), std::string::npos);
}

// The turn-over axis covers every ratio it draws: a method that turns over 25 to 49 times
// where the exact motion turns 10 (2.5 … 4.9) lifts the top from 2 to 5, so its whole line is
// inside the plot; a ratio past 10 (a runaway count) keeps the top at 10, and that line leaves
// the range at the top edge, where the plot marks it
// (Plot.FixedYRangeCutsTheCurveAndMarksWhereItLeaves).
TEST(AccuracyPlots, TurnoverAxisCoversTheRatiosUpToTen) {
  const Method step{ModelKind::ode, Integrator::step};
  const Method quick{ModelKind::ode, Integrator::quickstep};
  std::vector<AccuracyRow> rows{row(step, 0.1, 1e-3), row(step, 0.01, 1e-5), row(quick, 0.1, 1e-3),
                                row(quick, 0.01, 1e-5)};
  for (AccuracyRow& r : rows) r.flips_exact = 10;
  rows[0].flips = 49, rows[1].flips = 25, rows[2].flips = 31, rows[3].flips = 10;
  const overlay::PlotSpec spec = turnovers_vs_dt_plot(rows, {step, quick}, 10.0, 6.0);
  ASSERT_TRUE(spec.y_range);
  EXPECT_EQ(*spec.y_range, (std::pair{0.0, 5.0}));
  for (const overlay::Series& s : spec.series)
    for (double y : s.y) EXPECT_LE(y, spec.y_range->second) << s.label;
  rows[0].flips = 1000;  // 100 times the exact count, the run not diverged
  EXPECT_EQ(*turnovers_vs_dt_plot(rows, {step, quick}, 10.0, 6.0).y_range, (std::pair{0.0, 10.0}));
}

// The engines are coloured by family of mode (docs/engines.md): an engine's explicit step as
// bookspin's Euler, its RK4 as bookspin's RK4, both "none" modes alike; two modes of one family
// in one engine (Bullet's implicit body and world) apart.
TEST(AccuracyPlots, EnginesAreColouredByFamilyAndMarkedByEngine) {
  const auto look = [](ModelKind kind, Integrator integrator) {
    overlay::Series s;
    style_series(Method{kind, integrator}, s);
    return s;
  };
  const auto same_colour = [](const overlay::Series& a, const overlay::Series& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
  };
  EXPECT_TRUE(same_colour(look(ModelKind::mujoco, Integrator::euler),
                          look(ModelKind::rigid_matrix, Integrator::euler)));
  EXPECT_TRUE(same_colour(look(ModelKind::bullet, Integrator::explicit_gyro),
                          look(ModelKind::mujoco, Integrator::euler)));
  EXPECT_TRUE(same_colour(look(ModelKind::mujoco, Integrator::rk4),
                          look(ModelKind::rigid_quaternion, Integrator::rk4)));
  EXPECT_TRUE(same_colour(look(ModelKind::bullet, Integrator::none),
                          look(ModelKind::ode, Integrator::none)));
  EXPECT_TRUE(same_colour(look(ModelKind::mujoco, Integrator::implicit),
                          look(ModelKind::ode, Integrator::step)));
  EXPECT_FALSE(same_colour(look(ModelKind::bullet, Integrator::implicit_body),
                           look(ModelKind::bullet, Integrator::implicit_world)));
  EXPECT_FALSE(same_colour(look(ModelKind::ode, Integrator::step),
                           look(ModelKind::ode, Integrator::quickstep)));
  EXPECT_FALSE(same_colour(look(ModelKind::bullet, Integrator::none),
                           look(ModelKind::bullet, Integrator::implicit_body)));
  EXPECT_EQ(look(ModelKind::ode, Integrator::none).marker, overlay::Marker::diamond);
  EXPECT_EQ(look(ModelKind::bullet, Integrator::none).marker, overlay::Marker::triangle);
  EXPECT_EQ(look(ModelKind::mujoco, Integrator::rk4).marker, overlay::Marker::square);
  EXPECT_EQ(look(ModelKind::rigid_quaternion, Integrator::rk4).marker, overlay::Marker::circle);
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
