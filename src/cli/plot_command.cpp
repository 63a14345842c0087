// `bookspin plot`: the panel's curves over a whole run, as a PNG for papers and slides.
#include <iostream>

#include "cache/manifests.hpp"
#include "charts/plot_sheet.hpp"
#include "cli/commands.hpp"
#include "output/manifest.hpp"

namespace bookspin::cli {

int plot_command(const PlotOptions& options) {
  charts::PlotRequest request;
  request.scene = scene::parse_scene(options.scene_path, options.overrides);
  request.out_dir = options.out_dir;
  request.width = options.width;
  request.height = options.height;
  std::filesystem::path written;
  const cache::CacheOutcome outcome = run_cached(
      {cache::plot_manifest_path(options.out_dir, request.scene.name),
       cache::plot_manifest_head(request), options.out_dir, options.force, options.verify,
       [&]() -> std::optional<cache::JobOutputs> {
         written = charts::write_plot_sheet(request);
         return cache::JobOutputs{cache::manifest_note(request.scene),
                                  cache::plot_outputs(request)};
       }},
      request.scene.name + "-plot");
  if (outcome == cache::CacheOutcome::made) std::cout << "wrote " << written.string() << '\n';
  return kExitOk;
}

}  // namespace bookspin::cli
