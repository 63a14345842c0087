#include "charts/heat_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <stdexcept>

#include "scene/key_label.hpp"

namespace bookspin::charts {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The grid index of `value` among `grid` (the cell's text parsed back), or -1.
int grid_index(const std::vector<double>& grid, double value) {
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (std::abs(grid[i] - value) <= 1e-12 * std::max(std::abs(grid[i]), 1e-300))
      return static_cast<int>(i);
  return -1;
}

double parse(const std::string& text) {
  return text.empty() ? kNaN : std::strtod(text.c_str(), nullptr);
}

}  // namespace

std::vector<HeatMapSpec> sweep_heat_maps(const std::vector<std::string>& header,
                                         const std::vector<std::vector<std::string>>& rows,
                                         const std::vector<double>& x, bool log_x,
                                         const std::vector<double>& y, bool log_y,
                                         const std::vector<const analysis::Measure*>& measures) {
  return captioned_heat_maps(scene::key_caption(header.at(0)), scene::key_caption(header.at(1)),
                             rows, x, log_x, y, log_y, measures);
}

std::vector<HeatMapSpec> captioned_heat_maps(
    const std::string& x_caption, const std::string& y_caption,
    const std::vector<std::vector<std::string>>& rows, const std::vector<double>& x, bool log_x,
    const std::vector<double>& y, bool log_y,
    const std::vector<const analysis::Measure*>& measures) {
  std::optional<std::size_t> diverged_column;
  for (std::size_t m = 0; m < measures.size(); ++m)
    if (measures[m]->name == "diverged_at") diverged_column = 2 + m;
  std::vector<HeatMapSpec> maps;
  for (std::size_t m = 0; m < measures.size(); ++m) {
    HeatMapSpec map;
    // The measure in words (its axis label, unit and all), its CSV column second.
    map.title = std::string(measures[m]->axis_label) + " \u00b7 " + std::string(measures[m]->name);
    map.x_label = x_caption;
    map.y_label = y_caption;
    map.value_label = std::string(measures[m]->axis_label);
    map.log_x = log_x;
    map.log_y = log_y;
    map.log_value = measures[m]->log_scale;
    map.x = x;
    map.y = y;
    map.value.assign(x.size() * y.size(), kNaN);
    map.diverged.assign(x.size() * y.size(), 0);
    if (measures[m]->name == "diverged_at") map.empty_meaning = "ran to the end";
    for (const auto& cells : rows) {
      const int i = grid_index(x, parse(cells.at(0)));
      const int j = grid_index(y, parse(cells.at(1)));
      if (i < 0 || j < 0) throw std::invalid_argument("sweep row off the grid: " + cells.at(0));
      const std::size_t c = static_cast<std::size_t>(j) * x.size() + static_cast<std::size_t>(i);
      map.value[c] = parse(cells.at(2 + m));
      if (diverged_column) map.diverged[c] = !cells.at(*diverged_column).empty();
    }
    maps.push_back(std::move(map));
  }
  return maps;
}

}  // namespace bookspin::charts
