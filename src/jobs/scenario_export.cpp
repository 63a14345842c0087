#include "jobs/scenario_export.hpp"

#include "analysis/conformance.hpp"

namespace bookspin::jobs {

ExportFiles scenario_export(const scene::Scene& scene, const StopPoll& stop) {
  return export_files(exact_motion(analysis::scenario_of(scene), stop), stop);
}

}  // namespace bookspin::jobs
