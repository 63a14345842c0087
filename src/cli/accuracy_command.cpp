// `bookspin accuracy`: builds the request and prints what the pipeline measures.
#include <cstdio>

#include "cli/commands.hpp"
#include "jobs/accuracy_report.hpp"

namespace bookspin::cli {

int accuracy_command(const AccuracyOptions& options) {
  jobs::AccuracyRequest request;
  request.scene = scene::parse_scene(options.scene_path, options.overrides);
  request.out_dir = options.out_dir;
  request.flips = options.flips;
  request.dts = options.dts;
  request.on_line = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  for (const auto& path : jobs::run_accuracy(request)) std::printf("wrote %s\n", path.c_str());
  return kExitOk;
}

}  // namespace bookspin::cli
