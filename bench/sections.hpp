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
  int preset_frames = 90;        ///< frames of each clip the presets section encodes
  std::vector<int> preset_crfs = {14, 15, 16, 17, 18};  ///< CRFs of every preset (18 always)
  std::vector<std::string> preset_scenes = {
      "scenes/fig05-particle-unstable-x.toml", "scenes/fig09-matrix-unstable-x.toml",
      "scenes/t-handle-dzhanibekov.toml", "scenes/compare-methods-x.toml"};
  std::string gif_scene = "scenes/fig05-particle-unstable-x.toml";  ///< the GIF memory runs
  int gif_frames = 0;             ///< frames of the GIF memory runs; 0: the scene's own
  double fit_minutes = 10.0;      ///< minutes of the fit section's 500 Hz recording
  std::vector<std::string> only;  ///< sections to run (pipeline, peer, resolution, physics,
                                  ///< exact, memory, gif-memory, explorer, presets, fit)
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
/// µs per row of the exact motion (ExactRotation::state) against its evaluation as it was
/// (ExactRotation::BoostReference), on the same rows in this run, and of jobs::exact_motion_at
/// (Python's work).
void bench_exact(const BenchContext& context);
/// ns per step of the explorer page's methods natively (`rounds` timings, the best kept), the
/// loop of web/bindings.cpp's Session::step; bench/explorer_bench.py pairs them with the page's.
void bench_explorer(const BenchContext& context);
/// bookspin's draw + read-back against MuJoCo's renderer (mjr_render, mjr_readPixels) on the
/// same poses at 1280×720, alone and with the encoder; skipped without MuJoCo.
void bench_peer(const BenchContext& context);
/// Peak resident memory of a short and a long render, each in a child process.
void bench_memory(const BenchContext& context);
/// Peak resident memory of `render --format gif` and `--format mp4` of `gif_scene`, each in a
/// child process, and their ratio.
void bench_gif_memory(const BenchContext& context);
/// Every x264 preset from ultrafast to medium × `preset_crfs` on `preset_frames` frames of
/// each of `preset_scenes`: SSIM, PSNR, size and encoding CPU time against medium/CRF 18
/// (OUT/presets.csv), the pair the default rule picks, and `frames` frames of the bench's
/// scene rendered with the old default and the pick.
void bench_presets(const BenchContext& context);
/// `bookspin fit`'s read, flight search and fit of a synthetic phyphox recording of
/// `fit_minutes` minutes at 500 Hz (the exact motion with noise and bias) against reading the
/// file alone.
void bench_fit(const BenchContext& context);

}  // namespace bookspin::bench
