// `bookspin plot`: the panel's curves over a whole run, as a PNG for papers and slides.
#include <iostream>

#include "cli/commands.hpp"
#include "output/manifest.hpp"
#include "cache/manifests.hpp"
#include "charts/plot_sheet.hpp"

namespace bookspin::cli {

int plot_command(const PlotOptions& options) {
  charts::PlotRequest request;
  request.scene = scene::parse_scene(options.scene_path, options.overrides);
  request.out_dir = options.out_dir;
  request.width = options.width;
  request.height = options.height;
  const auto manifest = cache::plot_manifest_path(options.out_dir, request.scene.name);
  const std::string head = cache::plot_manifest_head(request);
  if (!options.force && skip_if_up_to_date(manifest, head, options.out_dir,
                                           request.scene.name + "-plot", options.verify))
    return kExitOk;
  const auto written = charts::write_plot_sheet(request);
  output::write_manifest(manifest, head, cache::manifest_note(request.scene), options.out_dir,
                         cache::plot_outputs(request));
  std::cout << "wrote " << written.string() << '\n';
  return kExitOk;
}

}  // namespace bookspin::cli
