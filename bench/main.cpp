// bookspin-bench: every number in one run, so that ratios compare like with like. It prints
// measured figures and ratios only; what they should be is docs/performance.md's business.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>

#include "bench/sections.hpp"
#include "common/errors.hpp"
#include "output/atomic_output.hpp"
#include "scene/scene.hpp"

namespace bookspin::bench {

namespace {

/// A private directory under the system's temporary directory, removed with everything in
/// it when the bench ends (also on an exception).
class ScratchDirectory {
 public:
  ScratchDirectory() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "bookspin-bench-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr)
      throw_output_error("cannot create a scratch directory", pattern, errno);
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

void add_options(CLI::App& cmd, BenchOptions& options) {
  cmd.add_option("SCENE", options.scene_path, "Scene for the 1280x720 pipeline runs")
      ->capture_default_str();
  cmd.add_option("-o,--out", options.out_dir, "Also write OUT/bench.csv");
  cmd.add_option("--frames", options.frames, "Frames of each 1280x720 pipeline run")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  cmd.add_option("--memory-frames", options.memory_frames, "Frames of the long memory run")
      ->check(CLI::Range(100, 100000))
      ->capture_default_str();
  cmd.add_option("--rounds", options.rounds,
                 "Pipeline runs alternated (explorer timings repeated) this many times; each "
                 "timing keeps its best")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  cmd.add_option("-j,--jobs", options.jobs, "As render --jobs (default: all cores)")
      ->check(CLI::Range(1, 256));
  cmd.add_option("--explorer-steps", options.explorer_steps,
                 "Steps of each explorer timing (ns per step of the page's methods, natively)")
      ->check(CLI::Range(1L, 100000000L))
      ->capture_default_str();
  cmd.add_option("--preset-frames", options.preset_frames,
                 "Frames of each clip the presets section encodes")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  cmd.add_option("--preset-crfs", options.preset_crfs, "CRFs the presets section tries (18 always)")
      ->check(CLI::Range(0, 51))
      ->capture_default_str();
  cmd.add_option("--preset-scenes", options.preset_scenes, "Clips the presets section encodes")
      ->capture_default_str();
  cmd.add_option("--gif-scene", options.gif_scene, "Scene of the GIF memory runs")
      ->capture_default_str();
  cmd.add_option("--gif-frames", options.gif_frames,
                 "Frames of the GIF memory runs (0: the scene's own)")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  cmd.add_option("--fit-minutes", options.fit_minutes,
                 "Minutes of the fit section's 500 Hz recording")
      ->check(CLI::Range(0.1, 60.0))
      ->capture_default_str();
  cmd.add_option("--only", options.only,
                 "Run only these sections: pipeline, peer, resolution, physics, exact, memory, "
                 "gif-memory, explorer, presets, fit (gif-memory, explorer, presets and fit run "
                 "only when named)")
      ->check(CLI::IsMember({"pipeline", "peer", "resolution", "physics", "exact", "memory",
                             "gif-memory", "explorer", "presets", "fit"}))
      ->take_all();
}

}  // namespace

int bench_command(const BenchOptions& options) {
  // Checked up front: a bad scene fails with its own message (the memory section's child
  // renders could only report that they failed), and an oversized run before minutes of work.
  (void)scene::parse_scene(options.scene_path, {});
  if (!options.only.empty() && wanted(options, "presets"))
    for (const auto& path : options.preset_scenes) (void)scene::parse_scene(path, {});
  if (!options.only.empty() && wanted(options, "gif-memory"))
    (void)scene::parse_scene(options.gif_scene, {});
  if (wanted(options, "pipeline")) check_pipeline_memory(options);
  if (!options.out_dir.empty()) std::filesystem::create_directories(options.out_dir);
  ScratchDirectory scratch;
  BenchReport report;
  report.remark("bookspin bench on " + machine_description());
  const BenchContext context{options, scratch.path(), &report};
  // Memory first: a forked child starts with the bench's resident pages counted in its
  // peak (until it execs), so it must fork while the bench is still small.
  if (wanted(options, "memory")) bench_memory(context);
  // Two whole renders of the GIF scene: only when named (docs/performance-video.md).
  if (!options.only.empty() && wanted(options, "gif-memory")) bench_gif_memory(context);
  if (wanted(options, "pipeline")) bench_pipeline(context);
  if (wanted(options, "peer")) bench_peer(context);
  if (wanted(options, "resolution")) bench_resolution(context);
  if (wanted(options, "physics")) bench_physics(context);
  if (wanted(options, "exact")) bench_exact(context);
  // Not part of a plain bench: bench/explorer_bench.py (make bench-explorer) asks for it.
  if (!options.only.empty() && wanted(options, "explorer")) bench_explorer(context);
  // Minutes of encoding: only when named (docs/performance-video.md, "The default x264 preset").
  if (!options.only.empty() && wanted(options, "presets")) bench_presets(context);
  // A long recording's fit: only when named (docs/performance-physics.md, "The phone-toss fit").
  if (!options.only.empty() && wanted(options, "fit")) bench_fit(context);
  if (!options.out_dir.empty()) {
    const auto csv = std::filesystem::path(options.out_dir) / "bench.csv";
    report.write_csv(csv);
    report.remark("wrote " + csv.string());
  }
  return 0;
}

}  // namespace bookspin::bench

int main(int argc, char** argv) {
  using namespace bookspin;
  CLI::App cli{
      "bookspin-bench: time the render pipeline against the encoder alone, "
      "MuJoCo's renderer, resolutions, the physics against MuJoCo, and memory; print ratios",
      "bookspin-bench"};
  bench::BenchOptions options;
  bench::add_options(cli, options);
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "bookspin-bench: error: " << e.what() << " (see bookspin-bench --help)\n";
    return 2;
  }
  const auto fail = [](const char* kind, const char* message, int status) {
    std::cerr << "bookspin-bench: " << kind << ": " << message << '\n';
    return status;
  };
  try {
    return bench::bench_command(options);
  } catch (const InputError& e) {
    return fail("error", e.what(), 2);
  } catch (const OutputError& e) {
    return fail("error", e.what(), 1);
  } catch (const bench::BenchLimitError& e) {
    return fail("error", e.what(), 1);
  } catch (const std::exception& e) {
    return fail("internal error", e.what(), 70);
  }
}
