#pragma once
// A sweep over two keys drawn as maps (docs/sweeps.md): one heat map per measure, the first
// key on x, the second on y, a colour bar with the measure's unit, diverged cells marked.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "analysis/measures.hpp"
#include "common/rgba_image.hpp"
#include "overlay/heat_map.hpp"

namespace bookspin::charts {

// The maps' description and drawing are the overlay stage's (overlay/heat_map.hpp).
using overlay::colour_bar_ticks;
using overlay::heat_colour;
using overlay::heat_map_cells;
using overlay::heat_map_sheet;
using overlay::HeatMapSpec;
using overlay::MapRect;

/// The maps of a sweep's table (header and rows as written: %.17g cells, empty where a measure
/// is undefined; keys in columns 0 and 1, then the measures in order): one per measure, the
/// cell of each row placed at its two key values. A cell is diverged where the table has a
/// non-empty diverged_at column. Throws std::invalid_argument for a row whose key values are
/// not on the grid (`x`, `y` of the ranges).
std::vector<HeatMapSpec> sweep_heat_maps(const std::vector<std::string>& header,
                                         const std::vector<std::vector<std::string>>& rows,
                                         const std::vector<double>& x, bool log_x,
                                         const std::vector<double>& y, bool log_y,
                                         const std::vector<const analysis::Measure*>& measures);
/// The same with the keys' captions given (scene::key_caption of columns 0 and 1).
std::vector<HeatMapSpec> captioned_heat_maps(const std::string& x_caption,
                                             const std::string& y_caption,
                                             const std::vector<std::vector<std::string>>& rows,
                                             const std::vector<double>& x, bool log_x,
                                             const std::vector<double>& y, bool log_y,
                                             const std::vector<const analysis::Measure*>& measures);

}  // namespace bookspin::charts
