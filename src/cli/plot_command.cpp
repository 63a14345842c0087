// `bookspin plot`: the panel's curves over a whole run, as a PNG for papers and slides.
#include <iostream>

#include "cli/commands.hpp"
#include "pipeline/plot_sheet_run.hpp"

namespace bookspin::cli {

int plot_command(const PlotOptions& options) {
  pipeline::PlotRequest request;
  request.scene = scene::parse_scene(options.scene_path, options.overrides);
  request.out_dir = options.out_dir;
  request.width = options.width;
  request.height = options.height;
  std::cout << "wrote " << pipeline::write_plot_sheet(request).string() << '\n';
  return kExitOk;
}

}  // namespace bookspin::cli
