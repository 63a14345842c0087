#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/frame_source.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/subcommand.hpp"
#include "jobs/lattice_note.hpp"
#include "jobs/simulation.hpp"
#include "output/atomic_output.hpp"

namespace bookspin::cli {

namespace {

struct SimulateOptions {
  std::string scene_path;
  std::vector<std::string> overrides;  ///< "key=value", value in TOML syntax
  std::string csv_path = "-";          ///< "-" is standard output
};

void warn_diverged(const scene::Scene& scene, const jobs::SimulationResult& result) {
  std::cerr << "bookspin: warning: "
            << analysis::divergence_warning(
                   scene.name + ": simulation", *result.diverged_at, result.divergence_reason,
                   "kept the " + std::to_string(result.rows) + " rows before it")
            << '\n';
}

int simulate_command(const SimulateOptions& options) {
  const scene::Scene scene = scene::parse_scene(options.scene_path, options.overrides);
  for (const std::string& warning : scene.warnings)
    std::cerr << "bookspin: warning: " << warning << '\n';
  if (const std::string note = jobs::lattice_note(scene); !note.empty())
    std::cerr << "bookspin: " << note << '\n';
  jobs::require_one_run(scene);
  jobs::SimulationResult result;
  if (options.csv_path == "-") {
    result = jobs::write_diagnostics_rows(scene, std::cout, stop_poll());
    std::cout.flush();
  } else {
    output::AtomicTextFile file(options.csv_path);
    result = jobs::write_diagnostics_rows(scene, file.stream(), stop_poll());
    file.commit();
  }
  if (result.diverged_at) warn_diverged(scene, result);
  return kExitOk;
}

}  // namespace

Subcommand add_simulate(CLI::App& cli) {
  const auto stored = std::make_shared<SimulateOptions>();
  SimulateOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "simulate", "Run a scene's simulation without rendering and write the diagnostics CSV");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML)")->required();
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  cmd->add_option("--csv", options.csv_path,
                  "Output CSV, one row per frame (frame 0 = initial state); '-' for stdout")
      ->capture_default_str()
      ->check(no_empty_output("a file name", "'-' for the standard output"));
  return {cmd, [stored] { return simulate_command(*stored); }};
}

}  // namespace bookspin::cli
