#include "cli/interrupt.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <set>
#include <string>
#include <thread>

namespace bookspin::cli {

namespace {
volatile std::sig_atomic_t received = 0;
extern "C" void on_signal(int signal) { received = signal; }

/// The test hooks' line for `stage`, written once per process (any thread); true the first
/// time.
bool report_stage(std::string_view stage) {
  static std::mutex mutex;
  static std::set<std::string, std::less<>> reported;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!reported.emplace(stage).second) return false;
  std::fprintf(stderr, "bookspin: stage: %.*s\n", static_cast<int>(stage.size()), stage.data());
  std::fflush(stderr);
  return true;
}

/// Waits until a signal has arrived, at most a minute.
void hold_for_signal() {
  for (int ms = 0; ms < 60000 && interrupt_signal() == 0; ++ms)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}
}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGHUP, &action, nullptr);  // a closed terminal: stopped like Ctrl-C, exit 129
}

int interrupt_signal() { return received; }

StopPoll stop_poll() {
  const char* hold = std::getenv("BOOKSPIN_TEST_HOLD_AT");
  if (hold != nullptr) {
    return [hold_at = std::string(hold)](std::string_view stage) {
      if (stage == hold_at && report_stage(stage)) hold_for_signal();
      return interrupt_signal();
    };
  }
  if (std::getenv("BOOKSPIN_TEST_REPORT_STAGES") != nullptr) {
    // The signal as it was before the line: a test that signals on reading the line meets
    // the loop after this poll, never this poll itself, whatever the threads' timing.
    return [](std::string_view stage) {
      const int signal = interrupt_signal();
      report_stage(stage);
      return signal;
    };
  }
  return [](std::string_view) { return interrupt_signal(); };
}

}  // namespace bookspin::cli
