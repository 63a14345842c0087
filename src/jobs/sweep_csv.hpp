#pragma once
// A sweep's table and its CSV (docs/physics.md §14, docs/sweeps.md): the measures parsed from
// --measure, the columns they make (the varied keys, the measures, their exact columns), one
// row of cells per grid point and the CSV written from them. Shards add a grid_index column
// before these (sweep_shard.hpp).
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "analysis/measures.hpp"
#include "jobs/sweep_grid.hpp"

namespace bookspin::jobs {

/// The measures a sweep writes, in the order given: rows of analysis::measure_table().
using MeasureList = std::vector<const analysis::Measure*>;

/// Parses "first_flip,flip_period,…" (comma-separated names of analysis::measure_table(), no
/// repeats). Throws InputError ("--measure TEXT: reason") on an unknown or repeated name or
/// an empty list.
MeasureList parse_measures(const std::string& text);

/// A sweep's table: the varied keys, the measures, and the exact reference columns
/// (`first_flip_exact` where first_flip is measured, `flip_period_exact` likewise).
struct SweepTable {
  std::string scene_name;
  std::string scene_title;  ///< scene.title: the picture's heading (empty: the name alone)
  std::vector<VaryRange> ranges;
  MeasureList measures;
  std::vector<std::string> header;  ///< CSV column names, in order
  /// (grid index, cells) per row, cells as written (%.17g or empty), sorted by index.
  std::vector<std::pair<std::size_t, std::vector<std::string>>> rows;
};

/// The full CSV's column names, in order: the varied keys (VaryRange::key), the measures'
/// names, the exact columns (Measure::exact_name) of the measures that have one, then
/// `refused` (kRefusedColumn).
std::vector<std::string> sweep_csv_header(const std::vector<VaryRange>& ranges,
                                          const MeasureList& measures);

/// The last column: empty where the point ran, else why its model's engine refused it
/// ("KEY: reason", scene::EngineRefusal), its measures and exact columns then empty.
inline constexpr const char* kRefusedColumn = "refused";

/// One grid point's cells in sweep_csv_header's order: `point`'s values (one per range), then
/// each measure of `m`, then the exact columns, then an empty `refused`; each %.17g, a measure
/// empty where the run does not reach it (no flip). Throws an internal error
/// (common/number_text.hpp) for a value that is not finite.
std::vector<std::string> sweep_row_cells(const std::vector<double>& point,
                                         const MeasureList& measures,
                                         const analysis::RunMeasures& m);

/// A grid point the engine refused: `point`'s values, every measure and exact column empty,
/// then `reason` in `refused`.
std::vector<std::string> sweep_refused_cells(const std::vector<double>& point,
                                             const MeasureList& measures,
                                             const std::string& reason);

/// `first`, then `cells`: a shard's line, its grid index first (common/csv_writer.hpp's
/// csv_row writes it).
std::vector<std::string> after(const std::string& first, const std::vector<std::string>& cells);

/// Writes the full CSV (header, then one line per row without the grid index) to `out`.
void write_sweep_csv(const SweepTable& table, std::ostream& out);

}  // namespace bookspin::jobs
