// `bookspin bench`: every number in one run, so that ratios compare like with like.
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>

#include "app/bench_sections.hpp"
#include "app/commands.hpp"
#include "scene/scene.hpp"
#include "video/atomic_output.hpp"

namespace bookspin::app {

namespace {

/// A private directory under the system's temporary directory, removed with everything in
/// it when the bench ends (also on an exception).
class ScratchDirectory {
 public:
  ScratchDirectory() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "bookspin-bench-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr)
      video::throw_output_error("cannot create a scratch directory", pattern, errno);
    path_ = pattern;
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

bool wanted(const BenchOptions& options, const std::string& section) {
  if (options.only.empty()) return true;
  for (const auto& name : options.only)
    if (name == section) return true;
  return false;
}

/// "Intel(R) Xeon(R) Processor, 2 cores": the machine the numbers belong to.
std::string machine_description() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
}

}  // namespace

int bench_command(const BenchOptions& options) {
  // Checked up front: a bad scene fails with its own message (the memory section's child
  // renders could only report that they failed), and an oversized run before minutes of work.
  (void)scene::parse_scene(options.scene_path, {});
  if (wanted(options, "pipeline")) check_pipeline_memory(options);
  if (!options.out_dir.empty()) std::filesystem::create_directories(options.out_dir);
  ScratchDirectory scratch;
  BenchReport report;
  report.remark("bookspin bench on " + machine_description());
  const BenchContext context{options, scratch.path(), &report};
  // Memory first: a forked child starts with the bench's resident pages counted in its
  // peak (until it execs), so it must fork while the bench is still small.
  if (wanted(options, "memory")) bench_memory(context);
  if (wanted(options, "pipeline")) bench_pipeline(context);
  if (wanted(options, "resolution")) bench_resolution(context);
  if (wanted(options, "physics")) bench_physics(context);
  if (!options.out_dir.empty()) {
    const auto csv = std::filesystem::path(options.out_dir) / "bench.csv";
    report.write_csv(csv);
    report.remark("wrote " + csv.string());
  }
  return kExitOk;
}

}  // namespace bookspin::app
