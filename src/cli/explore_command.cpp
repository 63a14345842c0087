#include <iostream>

#include "cache/manifests.hpp"
#include "cache/run_cached.hpp"
#include "cli/commands.hpp"
#include "clip/explorer_page.hpp"
#include "output/output_dir.hpp"
#include "output/sha256.hpp"

namespace bookspin::cli {

namespace {

/// web/explorer-shell.html in the folder of the running program (the build folder, where
/// web/build.sh BUILD_DIR writes it).
std::filesystem::path default_shell() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return (ec ? std::filesystem::path(".") : exe.parent_path()) / "web" / clip::kExplorerShellName;
}

}  // namespace

int explore_command(const ExploreOptions& options) {
  clip::ExplorerPageRequest request;
  request.out_dir = options.out_dir;
  if (options.shell.empty()) {
    request.shell = default_shell();
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
  for (const std::string& path : options.scene_paths) {
    scene::Scene scene = scene::parse_scene(path);
    for (const std::string& warning : scene.warnings)
      std::cerr << "bookspin: warning: " << warning << '\n';
    request.scenes.push_back(std::move(scene));
  }
  // Cached like every output (cache/run_cached.hpp): the page depends on the shell (the web
  // sources, lockfile and physics built into it), the program and the scenes with their inputs.
  std::string scenes;
  for (const scene::Scene& scene : request.scenes)
    scenes += cache::manifest_head("explore", "", scene);
  const std::string head =
      "  \"manifest\": 1,\n  \"command\": \"explore\",\n  \"shell\": \"sha256:" +
      output::sha256_file(request.shell).value_or("unreadable") +
      "\",\n  \"scenes\": \"sha256:" + output::sha256_text(scenes) + "\",\n";
  const std::filesystem::path out(request.out_dir);
  const cache::CacheOutcome outcome = cache::run_cached(
      {out / "explorer-manifest.json", head, out, false, false,
       [&]() -> std::optional<cache::JobOutputs> {
         output::prepare_output_dir(request.out_dir);
         const clip::ExplorerPageResult result = clip::write_explorer_page(request);
         std::cout << "explorer: " << result.path.string() << " (" << request.scenes.size()
                   << " scenes, " << result.bytes << " bytes)" << std::endl;
         return cache::JobOutputs{"", {result.path.filename().string()}};
       }});
  if (outcome == cache::CacheOutcome::up_to_date)
    std::cout << "explorer: up to date: " << (out / "explorer.html").string() << std::endl;
  return kExitOk;
}

}  // namespace bookspin::cli
