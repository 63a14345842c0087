#pragma once
// Heat maps drawn from their description (docs/sweeps.md): a sheet of one map per measure over a
// two-key grid, the first key on x, the second on y, a colour bar with the measure's unit,
// diverged cells marked. The description is made by the charts stage (charts/heat_map.hpp).
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "common/rgba_image.hpp"

namespace bookspin::overlay {

/// One measure over a two-key grid. Cell (i, j) is x[i], y[j]; the cells are equal in size,
/// as the grid is evenly spaced on each axis (in log(value) where log).
struct HeatMapSpec {
  std::string title;        ///< the measure in words, then its CSV name ("… · first_flip")
  std::string x_label;      ///< the first key
  std::string y_label;      ///< the second key
  std::string value_label;  ///< the colour bar's label, with the measure's unit
  bool log_x = false, log_y = false, log_value = false;
  std::vector<double> x, y;  ///< the grid's values, in the order of the ranges
  /// value[j·x.size() + i]: the measure at (x[i], y[j]); NaN where the cell is empty
  std::vector<double> value;
  /// same layout: the run diverged (the sweep's diverged_at is set)
  std::vector<char> diverged;
  /// What an empty cell means, for the legend: "no value", or for diverged_at itself "ran to
  /// the end".
  std::string empty_meaning = "no value";
};

/// A rectangle in pixels.
struct MapRect {
  double left, top, width, height;
};

/// Where map `index` of `count` draws its cells in a width×height sheet with `header_lines`
/// lines of header (two maps a row): cell (i, j) of an nx×ny map is the rectangle
/// [left + i·width/nx, left + (i+1)·width/nx] × [top + height − (j+1)·height/ny, …], y up.
MapRect heat_map_cells(int width, int height, std::size_t header_lines, std::size_t count,
                       std::size_t index);

/// The colour of `fraction` (0 … 1, clamped) on the maps' scale: dark blue through green to
/// yellow (a viridis-like ramp of six stops), 8-bit RGB.
std::array<unsigned char, 3> heat_colour(double fraction);

/// The colour bar's tick labels for values from `lo` to `hi` (the values themselves, not
/// their logarithms): {fraction of the bar from its bottom, text}. Three (bottom, middle, top)
/// where lo < hi, each with the fewest significant digits, at least three, that tell the
/// three apart (813.94, 814.01, 814.08, not "814" three times); one, at the middle, where
/// every value is the same.
std::vector<std::pair<double, std::string>> colour_bar_ticks(double lo, double hi, bool log);

/// The sheet: `header` lines (the first bold), then the maps, two a row, each with its
/// title, a legend line (cells diverged, marked ×, and cells empty, each counted), axes
/// with the grid values, and a colour bar labelled with the unit.
RgbaImage heat_map_sheet(const std::vector<std::string>& header,
                         const std::vector<HeatMapSpec>& maps, int width, int height);

}  // namespace bookspin::overlay
