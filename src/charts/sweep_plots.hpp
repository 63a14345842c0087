#pragma once
// A sweep's picture (`bookspin sweep`, docs/sweeps.md): for one varied key, or more than two,
// one line plot per measure against the first key; for two keys, one heat map per measure
// (heat_map.hpp). The table comes from the jobs stage (jobs/sweep_csv.hpp) as its cells.
#include <string>
#include <vector>

#include "analysis/measures.hpp"
#include "common/rgba_image.hpp"
#include "overlay/plot.hpp"

namespace bookspin::charts {

/// One varied key of a sweep, as its picture names it.
struct SweepAxis {
  std::string key;             ///< its CSV column, e.g. "initial.angular_velocity[1]"
  double start = 0.0;          ///< the range as given (--vary KEY=START:STOP:COUNT[:log])
  double stop = 0.0;           ///< ditto
  bool log = false;            ///< log spaced: a log axis
  std::vector<double> values;  ///< the grid's values on this key, in order (COUNT of them)
  /// The key in words with its unit, then its column (scene::key_caption), and its words alone
  /// (scene::key_words): the chart's text, made where the chart is (jobs::sweep_chart), so that
  /// its picture is drawn from the chart alone.
  std::string caption, words;
};

/// A sweep's table as its picture reads it: the varied keys in columns 0 … axes.size() − 1,
/// then the measures, then the exact columns (`<measure>_exact`).
struct SweepChart {
  std::string scene_name;
  std::string scene_title;  ///< scene.title, leading the header (empty: the name alone)
  std::vector<SweepAxis> axes;
  std::vector<const analysis::Measure*> measures;
  std::vector<std::string> header;             ///< every column's name, in order
  std::vector<std::vector<std::string>> rows;  ///< cells as written (%.17g, or empty)
};

/// One plot per measure against the first varied key (log axis where it was :log), one line
/// per combination of the other keys' values (in order of appearance), the exact curve dashed
/// beside the measured one where the table has the measure's exact column.
std::vector<overlay::PlotSpec> sweep_plots(const SweepChart& chart);

/// The sweep's picture, 1280 pixels wide and at most 640 tall (whole on a 1366×768 screen): a
/// header (the sweep and its runs, then one line per range), then for two keys the heat maps
/// (overlay::heat_map_sheet, two a row, a row at most 560 pixels tall), else sweep_plots (two a
/// row, one alone full width, a row at most 300 pixels tall); the rows share what is left
/// under the 120 pixels of the header. Throws std::invalid_argument for a two-key row whose
/// values are not on the grid.
RgbaImage sweep_sheet(const SweepChart& chart);

}  // namespace bookspin::charts
