#pragma once
// Timing for the bench: CPU time of the calling thread (physics: best of several runs, so
// that other processes on a shared machine disturb the numbers as little as possible) and
// of the whole process (pipeline: every thread, the encoder's and the GL driver's too).
#include <ctime>

namespace bookspin::bench {

inline double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// CPU seconds used so far by every thread of this process (user + system).
inline double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// Fewest nanoseconds per call of `run(steps)` (which performs `steps` steps) over
/// `repetitions` runs, each after `reset()`.
template <typename Reset, typename Run>
double best_ns_per_step(long steps, int repetitions, Reset&& reset, Run&& run) {
  double best = 0.0;
  for (int r = 0; r < repetitions; ++r) {
    reset();
    const double start = thread_cpu_seconds();
    run(steps);
    const double ns = (thread_cpu_seconds() - start) * 1e9 / static_cast<double>(steps);
    if (r == 0 || ns < best) best = ns;
  }
  return best;
}

}  // namespace bookspin::bench
