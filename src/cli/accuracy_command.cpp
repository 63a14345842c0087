// `bookspin accuracy`: builds the request and prints what the pipeline measures.
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "products/accuracy.hpp"

namespace bookspin::cli {

int accuracy_command(const AccuracyOptions& options) {
  products::AccuracyJob job;
  job.request.scene = scene::parse_scene(options.scene_path, options.overrides);
  job.request.flips = options.flips;
  job.request.dts = options.dts;
  job.request.on_line = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  job.request.stop_signal = stop_poll();
  job.out_dir = options.out_dir;
  for (const auto& path : products::make_accuracy(job)) std::printf("wrote %s\n", path.c_str());
  return kExitOk;
}

}  // namespace bookspin::cli
