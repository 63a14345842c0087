#pragma once
// Whole renders timed in this process, shared by the sections that time them (pipeline.cpp,
// presets.cpp): exactly what `bookspin render` does, through clip::render_clip.
#include <chrono>
#include <string>
#include <vector>

#include "bench/clock.hpp"
#include "bench/sections.hpp"
#include "clip/clip_request.hpp"

namespace bookspin::bench {

/// One timed run: wall time and the CPU time of every thread of this process meanwhile.
struct Timing {
  double wall = 1e300, cpu = 0.0;
  /// Keeps `run` when its wall time is shorter: the best run, and that run's CPU time.
  void keep_best(const Timing& run) {
    if (run.wall < wall) *this = run;
  }
};

class Stopwatch {
 public:
  Timing elapsed() const {
    return {std::chrono::duration<double>(Clock::now() - wall_start_).count(),
            process_cpu_seconds() - cpu_start_};
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point wall_start_ = Clock::now();
  double cpu_start_ = process_cpu_seconds();
};

/// What `render SCENE --set render.width=W --set render.height=H --frames N [--no-png] -o
/// SCRATCH/NAME` asks of the pipeline (SCENE: the bench's scene), plus `extra` overrides.
clip::ClipRequest clip_request(const BenchContext& c, const std::string& name, int width,
                               int height, int frames, bool png,
                               std::vector<std::string> extra = {});

/// Wall and CPU time of a whole clip (start-up, every frame, finishing the files); its
/// outputs are removed afterwards.
Timing timed_render(const clip::ClipRequest& request);

}  // namespace bookspin::bench
