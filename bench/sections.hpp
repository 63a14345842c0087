#pragma once
// The sections of bookspin-bench (main.cpp runs them in order).
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/report.hpp"

namespace bookspin::bench {

struct BenchOptions {
  std::string scene_path = "scenes/fig09-matrix-unstable-x.toml";  ///< the 720p pipeline scene
  std::string out_dir;           ///< non-empty: also write OUT/bench.csv
  int frames = 150;              ///< pipeline frames at 1280×720
  int memory_frames = 10000;     ///< the long run of the memory check
  int rounds = 3;                ///< pipeline runs alternated this many times; best of each kept
  int jobs = 0;                  ///< as render --jobs
  long explorer_steps = 100000;  ///< steps of each explorer timing
  std::vector<std::string>
      only;  ///< sections to run (pipeline, peer, resolution, physics, memory, explorer)
};

/// The machine cannot hold what the bench was asked to measure (exit status 1).
class BenchLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct BenchContext {
  BenchOptions options;
  std::filesystem::path scratch;  ///< a private temporary directory, removed afterwards
  BenchReport* report = nullptr;
};

/// Throws BenchLimitError when the pipeline section's pre-rendered frames (1280×720
/// RGBA, `options.frames` of them, held in memory for the encoder floor) would not fit in
/// the memory this machine has available (MemAvailable in /proc/meminfo). Checked before
/// any section runs, so a bench that cannot finish stops at once.
void check_pipeline_memory(const BenchOptions& options);
/// render --no-png and with PNGs at 1280×720 against encoding the same frames alone.
void bench_pipeline(const BenchContext& context);
/// Frames per second of render --no-png from 640×360 to 3840×2160.
void bench_resolution(const BenchContext& context);
/// ns per step and accuracy of every model × integrator, and of MuJoCo's mj_step.
void bench_physics(const BenchContext& context);
/// ns per step of the explorer page's methods natively (`rounds` timings, the best kept), the
/// loop of web/bindings.cpp's Session::step; bench/explorer_bench.py pairs them with the page's.
void bench_explorer(const BenchContext& context);
/// bookspin's draw + read-back against MuJoCo's renderer (mjr_render, mjr_readPixels) on the
/// same poses at 1280×720, alone and with the encoder; skipped without MuJoCo.
void bench_peer(const BenchContext& context);
/// Peak resident memory of a short and a long render, each in a child process.
void bench_memory(const BenchContext& context);

}  // namespace bookspin::bench
