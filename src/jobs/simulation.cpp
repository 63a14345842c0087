#include "jobs/simulation.hpp"

#include <limits>

#include "analysis/frame_source.hpp"
#include "common/errors.hpp"
#include "output/diagnostics_csv.hpp"

namespace bookspin::jobs {

SimulationResult write_diagnostics_rows(const scene::Scene& scene, std::ostream& out,
                                        const StopPoll& stop) {
  out << output::diagnostics_csv_header() << '\n';
  analysis::FrameSource source(scene);
  physics::Pose pose;
  for (stop_if_asked(stop, "simulate rows"); source.next(pose);
       stop_if_asked(stop, "simulate rows"))
    out << output::diagnostics_csv_row(source.frame(), pose.diagnostics) << '\n';
  return {source.diverged_at(), source.frame() + 1, source.divergence_reason()};
}

DiagnosticsTable diagnostics_table(const scene::Scene& scene, const StopPoll& stop) {
  DiagnosticsTable table;
  table.columns = output::diagnostics_columns();
  table.values.resize(table.columns.size());
  analysis::FrameSource source(scene);
  physics::Pose pose;
  for (stop_if_asked(stop, "simulate rows"); source.next(pose);
       stop_if_asked(stop, "simulate rows")) {
    // The CSV row's own check: a number that is not finite is an internal error there too.
    output::diagnostics_csv_row(source.frame(), pose.diagnostics);
    const auto row = output::diagnostics_values(source.frame(), pose.diagnostics);
    for (std::size_t i = 0; i < row.size(); ++i)
      table.values[i].push_back(row[i].value_or(std::numeric_limits<double>::quiet_NaN()));
  }
  table.result = {source.diverged_at(), source.frame() + 1, source.divergence_reason()};
  return table;
}

void require_one_run(const scene::Scene& scene) {
  if (scene.compare.empty()) return;
  // Several runs do not fit one CSV; `render` writes one per panel.
  throw InputError(scene.source.string() +
                   ": a comparison scene ([[compare]]) has one run per panel: `bookspin "
                   "render` writes OUT/<scene>/diagnostics-<panel>.csv for each");
}

}  // namespace bookspin::jobs
