#pragma once
// The plots of `bookspin accuracy` (docs/physics.md §10): error, energy error and turn-overs
// against dt, the work–precision diagram and the long-time energy plot, as plot specs; the jobs
// stage measures (jobs/accuracy_report.hpp), the accuracy product writes them.
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "common/rgba_image.hpp"
#include "overlay/plot.hpp"

namespace bookspin::charts {

/// One look per method in every accuracy plot: bookspin's own methods coloured by integrator,
/// dashed for the quaternion model, greys for the particle model, no mark; the engines marked
/// by engine (MuJoCo a square, Bullet a triangle, ODE a diamond), solid, coloured by the family
/// of the mode (explicit as bookspin's Euler, RK4 as bookspin's RK4, implicit green, no
/// gyroscopic term brown; a second mode of one family in one engine lighter).
void style_series(const analysis::Method& m, overlay::Series& s);

/// Work–precision diagram (log–log): orientation error after the run (rad) against the
/// measured cost per simulated time unit (µs of step() per time unit, ns_per_step/dt), one
/// line per method through its dt values. Lower left is better.
overlay::PlotSpec work_precision_plot(const std::vector<analysis::AccuracyRow>& rows, double flips);

/// Orientation error against the step (log–log): the angle of R_exactᵀ R after the run (rad)
/// against dt (time units), one line per method of `methods` through its rows' dt values (a
/// diverged row's error is NaN and breaks the line).
overlay::PlotSpec orientation_error_vs_dt_plot(const std::vector<analysis::AccuracyRow>& rows,
                                               const std::vector<analysis::Method>& methods,
                                               double flips, double spin_rate = 0.0);

/// Energy error against the step (log–log): the largest relative energy error |E/E0 − 1|
/// over the run (flips exact flip periods) against dt (time units), one line per method of
/// `methods` through its rows' dt values (a diverged row with its largest error before it
/// diverged); when an error exceeds 100 the y range is fixed to end there, and a line leaving
/// it is marked at the top edge.
///
/// These plots' titles say the run's spin when `spin_rate` (|ω0|, rad per time unit) is
/// positive: "; |ω0| = … rad/t, ω·dt = … … … rad" over the rows' dt (shorter titles then, to
/// fit one line).
overlay::PlotSpec energy_vs_dt_plot(const std::vector<analysis::AccuracyRow>& rows,
                                    const std::vector<analysis::Method>& methods, double flips,
                                    double spin_rate = 0.0);

/// Turn-overs against the step: the turn-overs a method counted (analysis::FlipDetector, a
/// wobble is none) divided by the exact motion's over the same run, against dt (log, time
/// units), on a linear range from 0 to the largest ratio rounded up to a whole number, at
/// least 2 and at most 10 (1 is right; a ratio over 10 is drawn at the top edge with a mark
/// where its line leaves the range), one line per method of `methods`; diverged rows and rows
/// whose exact motion
/// has no turn-over are left out; a method that counted none at every dt is labelled "(never
/// turns over)". Beside the energy, the chart that says whether the motion is right.
overlay::PlotSpec turnovers_vs_dt_plot(const std::vector<analysis::AccuracyRow>& rows,
                                       const std::vector<analysis::Method>& methods, double flips,
                                       double spin_rate);

/// Long-time energy plot: relative energy error |E/E0 − 1| (log scale, the largest in each
/// window) against t (time units), one line per history.
overlay::PlotSpec long_time_energy_plot(const std::vector<analysis::EnergyHistory>& histories,
                                        double flips);

/// The report's five plots, from what it measured.
struct AccuracyPlots {
  overlay::PlotSpec orientation_error_vs_dt;  ///< orientation_error_vs_dt_plot
  overlay::PlotSpec work_precision;           ///< work_precision_plot
  overlay::PlotSpec energy_vs_dt;             ///< energy_vs_dt_plot
  overlay::PlotSpec turnovers_vs_dt;          ///< turnovers_vs_dt_plot
  overlay::PlotSpec long_time_energy;         ///< long_time_energy_plot
};

/// The five plots of a report: `rows` (one line per method of `methods`, runs of `flips` exact
/// flip periods from a spin of |ω0| = `spin_rate` rad per time unit) and the long-time energy
/// `histories` (runs of `history_flips` periods). No I/O.
AccuracyPlots accuracy_plots(const std::vector<analysis::AccuracyRow>& rows,
                             const std::vector<analysis::Method>& methods, double flips,
                             double spin_rate,
                             const std::vector<analysis::EnergyHistory>& histories,
                             double history_flips);

/// The report's five plots drawn, 1280 × 640 pixels each (whole on a 1366×768 screen, under a
/// browser's bars).
struct AccuracyImages {
  RgbaImage orientation_error_vs_dt;
  RgbaImage work_precision;
  RgbaImage energy_vs_dt;
  RgbaImage turnovers_vs_dt;
  RgbaImage long_time_energy;
};

/// (rows, methods, histories) => the five plots of accuracy_plots(), drawn. No I/O.
AccuracyImages accuracy_images(const std::vector<analysis::AccuracyRow>& rows,
                               const std::vector<analysis::Method>& methods, double flips,
                               double spin_rate,
                               const std::vector<analysis::EnergyHistory>& histories,
                               double history_flips);

}  // namespace bookspin::charts
