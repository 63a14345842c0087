#pragma once
// Physics only: a scene's simulation, frame by frame, as diagnostics rows (`bookspin
// simulate`).
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

struct SimulationResult {
  std::optional<double> diverged_at;  ///< time units
  int rows = 0;                       ///< rows written (frame 0 = the initial state)
  std::string divergence_reason;      ///< the simulator's own words, where it gave any
};

/// Writes the diagnostics CSV header and one row per frame (docs/physics.md §9) to `out`
/// until the clip ends or the simulation diverges. `stop` is polled before every frame
/// ("simulate rows"): a signal throws Interrupted, the rows written so far left to the caller
/// (an atomic file it does not commit).
SimulationResult write_diagnostics_rows(const scene::Scene& scene, std::ostream& out,
                                        const StopPoll& stop = {});

/// The diagnostics CSV as a value (the Python module's `simulate`, docs/python.md): a column
/// per name of output::diagnostics_columns(), a number per frame in each, the very doubles the
/// CSV spells (read back, they are its cells); NaN where the CSV has an empty cell.
struct DiagnosticsTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  ///< values[column][frame]
  SimulationResult result;
};

/// The rows write_diagnostics_rows() would write, as a table; `stop` as there.
DiagnosticsTable diagnostics_table(const scene::Scene& scene, const StopPoll& stop = {});

/// Throws InputError for a comparison scene ([[compare]]): its runs do not fit one table.
void require_one_run(const scene::Scene& scene);

}  // namespace bookspin::jobs
