#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/subcommand.hpp"
#include "jobs/page_replay.hpp"
#include "products/explorer.hpp"

namespace bookspin::cli {
namespace {

struct ExploreOptions {
  std::vector<std::string> scene_paths;  ///< the page's scenes, in this order
  std::string out_dir = "out";
  std::string shell;     ///< the page without data; empty: web/explorer-shell.html beside bookspin
  bool engines = false;  ///< also the JavaScript engines (explorer-engines.js beside the shell)
  bool force = false;    ///< write the page even when OUT/explorer-manifest.json says up to date
  bool verify = false;   ///< up-to-date check hashes the page (else its size only)
};

/// Writes OUT/explorer.html (products::write_explorer_page): the explorer page with these scenes.
/// The default shell missing (the page's program not built: web/build.sh) is exit 1 with a
/// line saying how to build it; a --shell that is not one is an input error.
int explore_command(const ExploreOptions& options) {
  products::ExplorerPageRequest request;
  request.out_dir = options.out_dir;
  request.stop_signal = stop_poll();
  request.freshness = {options.force, options.verify, remake_note};
  if (options.shell.empty()) {
    request.shell = products::default_explorer_shell();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(request.shell, ec)) {
      std::cerr << "bookspin: error: the explorer page's program is not built: no "
                << request.shell.string()
                << " (run web/build.sh with the build folder; it needs emscripten and npm, which "
                   "scripts/install-deps.sh installs)\n";
      return kExitFailure;
    }
  } else {
    request.shell = options.shell;
  }
  if (options.engines) {
    request.engines = products::explorer_engines_beside(request.shell);
    std::error_code ec;
    if (options.shell.empty() && !std::filesystem::is_regular_file(request.engines, ec)) {
      std::cerr << "bookspin: error: the explorer's JavaScript engines are not built: no "
                << request.engines.string() << " (run web/build.sh with the build folder)\n";
      return kExitFailure;
    }
  }
  for (const std::string& path : options.scene_paths) {
    scene::Scene scene = scene::parse_scene(path);
    for (const std::string& warning : scene.warnings)
      std::cerr << "bookspin: warning: " << warning << '\n';
    request.scenes.push_back(std::move(scene));
  }
  // The value the page reads, with the replays of the tiles it cannot step: made only when
  // the page is written.
  request.scene_data = [stop = request.stop_signal](const scene::Scene& scene) {
    return jobs::explorer_scene_data(scene, stop);
  };
  const products::ExplorerOutcome done = products::make_explorer_page(request);
  if (done.outcome == cache::Outcome::up_to_date) {
    std::cout << "explorer: up to date: " << done.result.path.string() << std::endl;
    return kExitOk;
  }
  std::cout << "explorer: " << done.result.path.string() << " (" << request.scenes.size()
            << " scenes, " << done.result.bytes << " bytes)" << std::endl;
  return kExitOk;
}

}  // namespace

Subcommand add_explore(CLI::App& cli) {
  const auto stored = std::make_shared<ExploreOptions>();
  ExploreOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "explore",
      "Write OUT/explorer.html: the physics in the browser, one file that opens from "
      "disk, with these scenes (docs/explorer.md)");
  cmd->add_option("SCENE", options.scene_paths, "Scene files (TOML)")->required();
  add_out_option(cmd, options.out_dir, "Output directory");
  cmd->add_option("--shell", options.shell,
                  "The page without its scenes, as web/build.sh writes it (default: "
                  "web/explorer-shell.html beside the bookspin program)");
  cmd->add_flag("--engines", options.engines,
                "Also run the JavaScript engines cannon-es, Rapier and Jolt in the page, as "
                "models (about 8 MB more; docs/explorer.md)");
  add_freshness_flags(cmd, options.force, options.verify, "OUT/explorer-manifest.json");
  return {cmd, [stored] { return explore_command(*stored); }};
}

}  // namespace bookspin::cli
