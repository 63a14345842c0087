#include <fstream>
#include <iostream>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/frame_source.hpp"
#include "video/atomic_output.hpp"
#include "video/diagnostics_csv.hpp"

namespace bookspin::app {

namespace {

struct RunResult {
  std::optional<double> diverged_at;
  int rows = 0;
};

/// Writes every frame's row until the clip ends or the simulation diverges.
RunResult write_rows(const scene::Scene& scene, std::ostream& out) {
  out << video::diagnostics_csv_header() << '\n';
  FrameSource source(scene);
  physics::BookPose pose;
  while (source.next(pose))
    out << video::diagnostics_csv_row(source.frame(), pose.diagnostics) << '\n';
  return {source.diverged_at(), source.frame() + 1};
}

void warn_diverged(const scene::Scene& scene, double t, int rows) {
  std::cerr << "bookspin: warning: " << scene.name << ": simulation diverged at t = " << t
            << "; kept the " << rows << " rows before it\n";
}

}  // namespace

int simulate_command(const SimulateOptions& options) {
  const scene::Scene scene = scene::parse_scene(options.scene_path, options.overrides);
  if (!scene.compare.empty()) {
    // Several runs do not fit one CSV; `render` writes one per panel.
    throw std::invalid_argument(
        options.scene_path +
        ": a comparison scene ([[compare]]) has one run per panel: `bookspin "
        "render` writes OUT/<scene>/diagnostics-<panel>.csv for each");
  }
  RunResult result;
  if (options.csv_path == "-") {
    result = write_rows(scene, std::cout);
    std::cout.flush();
  } else {
    video::AtomicFile file(options.csv_path);
    std::ofstream out(file.temp_path(), std::ios::binary);
    if (!out) video::throw_output_error("cannot create", options.csv_path, errno);
    result = write_rows(scene, out);
    out.close();
    if (!out) video::throw_output_error("cannot write", options.csv_path, errno);
    file.commit();
  }
  if (result.diverged_at) warn_diverged(scene, *result.diverged_at, result.rows);
  return kExitOk;
}

}  // namespace bookspin::app
