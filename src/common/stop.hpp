#pragma once
// Stopping a run on request (SIGINT, SIGTERM; docs/outputs.md, "Signals"). The command line's
// handler only records the signal; every long loop of a command that writes (a clip's frames,
// the encoders' finishing passes, a sweep point's steps, an accuracy run, an export's frames,
// the explorer's and the gallery's scenes) polls a StopPoll between units of work and, when it
// answers a signal, throws Interrupted before anything is put in place. Interrupted goes up
// through the product untouched (cache::make_cached keeps the previous outputs and their
// manifest as they were) to the command line, which catches it once and exits 128 + signal
// (130, 143).
#include <exception>
#include <functional>
#include <string>
#include <string_view>

namespace bookspin {

/// Asked by a long loop between units of work: the signal that asks the run to stop (SIGINT,
/// SIGTERM), or 0. `stage` names the loop ("export frames", "gif palette", …; the command
/// line's test hook reports each stage once). Called from any thread; an empty StopPoll never
/// stops.
using StopPoll = std::function<int(std::string_view stage)>;

/// A run stopped by `signal` before it put its outputs in place: not an error. Caught once, by
/// the command line (cli/run_guarded.hpp), which maps it to 128 + signal.
class Interrupted : public std::exception {
 public:
  explicit Interrupted(int signal)
      : signal_(signal), what_("interrupted by signal " + std::to_string(signal)) {}
  int signal() const { return signal_; }
  const char* what() const noexcept override { return what_.c_str(); }

 private:
  int signal_;
  std::string what_;
};

/// The signal `poll` answers at `stage`, or 0 (also when `poll` is empty).
inline int stop_signal(const StopPoll& poll, std::string_view stage) {
  return poll ? poll(stage) : 0;
}

/// Throws Interrupted when `poll` answers a signal at `stage`.
inline void stop_if_asked(const StopPoll& poll, std::string_view stage) {
  if (const int signal = stop_signal(poll, stage)) throw Interrupted(signal);
}

}  // namespace bookspin
