#include <iostream>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "products/explorer.hpp"

namespace bookspin::cli {

int explore_command(const ExploreOptions& options) {
  products::ExplorerPageRequest request;
  request.out_dir = options.out_dir;
  request.stop_signal = stop_poll();
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
  const products::ExplorerOutcome done = products::make_explorer_page(request);
  if (done.outcome == cache::Outcome::up_to_date) {
    std::cout << "explorer: up to date: " << done.result.path.string() << std::endl;
    return kExitOk;
  }
  std::cout << "explorer: " << done.result.path.string() << " (" << request.scenes.size()
            << " scenes, " << done.result.bytes << " bytes)" << std::endl;
  return kExitOk;
}

}  // namespace bookspin::cli
