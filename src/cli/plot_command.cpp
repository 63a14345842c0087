// `bookspin plot`: the panel's curves over a whole run, as a PNG for papers and slides.
#include <iostream>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "products/plot.hpp"

namespace bookspin::cli {

int plot_command(const PlotOptions& options) {
  products::PlotJob job;
  job.scene = scene::parse_scene(options.scene_path, options.overrides);
  job.out_dir = options.out_dir;
  job.width = options.width;
  job.height = options.height;
  job.freshness = {options.force, options.verify, remake_note};
  const std::string name = job.scene.name + "-plot";
  const cache::Outcome outcome = products::make_plot(job);
  if (outcome == cache::Outcome::up_to_date) std::cout << "up to date: " << name << std::endl;
  if (outcome == cache::Outcome::made)
    std::cout << "wrote " << products::plot_layout(job.out_dir, job.scene).png.string() << '\n';
  return kExitOk;
}

}  // namespace bookspin::cli
