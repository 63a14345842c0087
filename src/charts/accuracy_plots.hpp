#pragma once
// The plots of `bookspin accuracy` beyond error-vs-dt: the work–precision diagram and the
// long-time energy plot (docs/physics.md §10).
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "common/stop.hpp"
#include "overlay/plot.hpp"

namespace bookspin::charts {

/// "rigid-quaternion splitting4": the method as the table and the legends name it.
std::string method_label(const analysis::Method& m);

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

/// The settings of the long-time energy plot: every rigid method at dt = 1/60 over 100 flip
/// periods, in 400 windows.
inline constexpr double kLongTimeFlips = 100.0;
inline constexpr double kLongTimeDt = 1.0 / 60.0;
inline constexpr int kLongTimeWindows = 400;

/// Where write_accuracy_plots() writes (the accuracy product names them).
struct AccuracyPlotPaths {
  std::filesystem::path work_precision_png;  ///< error against cost, from the rows
  std::filesystem::path energy_vs_dt_png;    ///< energy error against dt, from the rows
  std::filesystem::path energy_png;          ///< the long-time energy plot
  std::filesystem::path energy_csv;          ///< its data: t, one column per method
};

/// Runs the long-time energy histories, then writes the work–precision plot and the energy
/// error against dt (from `rows`, one line per method of `methods`), the energy plot and its
/// CSV. The long-time histories are those of analysis::rigid_methods() when `methods` is every
/// method (analysis::accuracy_methods()), else of every method of `methods` but the particle
/// model's. Returns the paths written. `stop` is polled around each history ("accuracy
/// energy") and inside it ("accuracy energy steps"): a signal throws Interrupted before any
/// file is written. Throws OutputError when a file cannot be written.
std::vector<std::filesystem::path> write_accuracy_plots(
    const AccuracyPlotPaths& paths, const analysis::AccuracySettings& settings,
    const physics::ExactRotation& exact, const std::vector<analysis::AccuracyRow>& rows,
    const std::vector<analysis::Method>& methods, const StopPoll& stop = {});

}  // namespace bookspin::charts
