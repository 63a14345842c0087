#pragma once
// The sections of `bookspin bench` (bench_command.cpp runs them in order).
#include <filesystem>

#include "app/bench_report.hpp"
#include "app/commands.hpp"

namespace bookspin::app {

struct BenchContext {
  BenchOptions options;
  std::filesystem::path scratch;  ///< a private temporary directory, removed afterwards
  BenchReport* report = nullptr;
};

/// Throws std::invalid_argument when the pipeline section's pre-rendered frames (1280×720
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
/// Peak resident memory of a short and a long render, each in a child process.
void bench_memory(const BenchContext& context);

}  // namespace bookspin::app
