#include "jobs/simulation.hpp"

#include "analysis/frame_source.hpp"
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

}  // namespace bookspin::jobs
