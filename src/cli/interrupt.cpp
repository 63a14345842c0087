#include "cli/interrupt.hpp"

#include <csignal>

namespace bookspin::cli {

namespace {
volatile std::sig_atomic_t received = 0;
extern "C" void on_signal(int signal) { received = signal; }
}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() { return received; }

}  // namespace bookspin::cli
