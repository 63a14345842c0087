#pragma once
// The plots of `bookspin accuracy` (docs/physics.md §10): error and energy error against dt, the
// work–precision diagram and the long-time energy plot, as plot specs; the jobs stage measures
// and writes them (jobs/accuracy_report.hpp).
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "common/rgba_image.hpp"
#include "overlay/plot.hpp"

namespace bookspin::charts {

/// One look per method in every accuracy plot: colour by integrator, dashed for the
/// quaternion model, greys for the particle model.
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
                                               double flips);

/// Energy error against the step (log–log): the largest relative energy error |E/E0 − 1|
/// over the run (flips exact flip periods) against dt (time units), one line per method of
/// `methods` through its rows' dt values; diverged rows are left out.
overlay::PlotSpec energy_vs_dt_plot(const std::vector<analysis::AccuracyRow>& rows,
                                    const std::vector<analysis::Method>& methods, double flips);

/// Long-time energy plot: relative energy error |E/E0 − 1| (log scale, the largest in each
/// window) against t (time units), one line per history.
overlay::PlotSpec long_time_energy_plot(const std::vector<analysis::EnergyHistory>& histories,
                                        double flips);

/// The report's four plots, from what it measured.
struct AccuracyPlots {
  overlay::PlotSpec orientation_error_vs_dt;  ///< orientation_error_vs_dt_plot
  overlay::PlotSpec work_precision;           ///< work_precision_plot
  overlay::PlotSpec energy_vs_dt;             ///< energy_vs_dt_plot
  overlay::PlotSpec long_time_energy;         ///< long_time_energy_plot
};

/// The four plots of a report: `rows` (one line per method of `methods`, runs of `flips` exact
/// flip periods) and the long-time energy `histories` (runs of `history_flips` periods). No I/O.
AccuracyPlots accuracy_plots(const std::vector<analysis::AccuracyRow>& rows,
                             const std::vector<analysis::Method>& methods, double flips,
                             const std::vector<analysis::EnergyHistory>& histories,
                             double history_flips);

/// The report's four plots drawn, 1400 × 900 pixels each.
struct AccuracyImages {
  RgbaImage orientation_error_vs_dt;
  RgbaImage work_precision;
  RgbaImage energy_vs_dt;
  RgbaImage long_time_energy;
};

/// (rows, methods, histories) => the four plots of accuracy_plots(), drawn. No I/O.
AccuracyImages accuracy_images(const std::vector<analysis::AccuracyRow>& rows,
                               const std::vector<analysis::Method>& methods, double flips,
                               const std::vector<analysis::EnergyHistory>& histories,
                               double history_flips);

}  // namespace bookspin::charts
