#pragma once
// SIGINT/SIGTERM/SIGHUP: the handler only records the signal; every long loop of a command that
// writes polls it (common/stop.hpp), stops cleanly, removes its temporaries and the command exits
// 128 + signal (130 / 143 / 129). docs/outputs.md, "Signals".
#include "common/stop.hpp"

namespace bookspin::cli {

/// Installs the handlers (idempotent).
void install_interrupt_handlers();
/// The signal received so far, or 0.
int interrupt_signal();

/// The StopPoll every command hands its product: interrupt_signal() at any stage. Two test
/// hooks (environment variables, not for users) let a test send its signal at a known point:
/// with BOOKSPIN_TEST_REPORT_STAGES set it writes "bookspin: stage: <stage>" to stderr the
/// first time each stage is polled, after reading the signal (so a test that signals on reading
/// the line meets the work that follows that poll, not the poll); with
/// BOOKSPIN_TEST_HOLD_AT=<stage> it writes that line at the stage's first poll and waits there
/// until a signal arrives (at most a minute; a stage too short to signal in flight).
StopPoll stop_poll();

}  // namespace bookspin::cli
