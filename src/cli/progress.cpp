#include "cli/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace bookspin::cli {

namespace {
using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
}  // namespace

Progress::Progress(std::string label, int total_frames)
    : label_(std::move(label)),
      total_(total_frames),
      terminal_(isatty(STDERR_FILENO) == 1),
      start_(Clock::now()),
      last_print_(start_) {}

void Progress::update(int done) {
  // A terminal gets ~10 redraws a second; a log gets a line every 5 seconds.
  const double interval = terminal_ ? 0.1 : 5.0;
  if (seconds(Clock::now() - last_print_) >= interval) print(done, false);
}

void Progress::finish(int done) { print(done, true); }

void Progress::print(int done, bool final) {
  last_print_ = Clock::now();
  const double elapsed = seconds(last_print_ - start_);
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const double eta = rate > 0 ? (total_ - done) / rate : 0.0;
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = total_ > 0 ? done * kWidth / total_ : kWidth;
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "\r%s [%s] %d/%d frames  %.1f frames/s  ETA %.0f s ", label_.c_str(),
                 bar.c_str(), done, total_, rate, eta);
    if (final) std::fputc('\n', stderr);
  } else {
    std::fprintf(stderr, "%s: %d/%d frames, %.1f frames/s, %s %.0f s\n", label_.c_str(), done,
                 total_, rate, final ? "took" : "ETA", final ? elapsed : eta);
  }
  std::fflush(stderr);
}

}  // namespace bookspin::cli
