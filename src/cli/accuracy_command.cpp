// `bookspin accuracy`: builds the request and prints what the pipeline measures.
#include <cstdio>

#include "analysis/accuracy.hpp"
#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "products/accuracy.hpp"

namespace bookspin::cli {

int accuracy_command(const AccuracyOptions& options) {
  products::AccuracyJob job;
  job.request.scene = scene::parse_scene(options.scene_path, options.overrides);
  job.request.flips = options.flips;
  job.request.dts = options.dts;
  job.request.methods = analysis::parse_methods(options.methods);
  job.request.on_line = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  job.request.stop_signal = stop_poll();
  job.out_dir = options.out_dir;
  job.freshness = {options.force, options.verify, remake_note};
  const cache::Outcome outcome = products::make_accuracy(job);
  if (outcome == cache::Outcome::up_to_date)
    std::printf("up to date: %s-accuracy\n", job.request.scene.name.c_str());
  if (outcome == cache::Outcome::made)
    for (const auto& path : products::accuracy_layout(job.out_dir, job.request.scene).outputs())
      std::printf("wrote %s\n", path.c_str());
  return kExitOk;
}

}  // namespace bookspin::cli
