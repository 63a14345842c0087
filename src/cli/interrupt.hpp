#pragma once
// SIGINT/SIGTERM: the handler only records the signal; the render loop polls it, stops
// cleanly, removes its temporaries and exits 128 + signal (130 / 143).
namespace bookspin::cli {

/// Installs the handlers (idempotent).
void install_interrupt_handlers();
/// The signal received so far, or 0.
int interrupt_signal();

}  // namespace bookspin::cli
