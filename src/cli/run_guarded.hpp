#pragma once
// The one place where an error becomes an exit status (docs/architecture.md, "Errors").
#include <functional>

namespace bookspin::cli {

/// Exit statuses: 0 success; 1 an output could not be written or the machine lacks what the
/// run needs (no EGL, no encoder); 2 bad input (scene file, command line); 3 a motion judged
/// FAIL (`flipcheck judge`: its verdict printed and its CSV written, so that a CI job that runs
/// it fails on a broken engine); 70 a bug (internal error); 130/143 interrupted (128 + signal).
enum ExitCode {
  kExitOk = 0,
  kExitFailure = 1,
  kExitUsage = 2,
  kExitJudgedFail = 3,
  kExitInternal = 70
};

/// Runs `command` and returns its status; an exception that escapes it is printed as one
/// line on stderr and mapped: Interrupted (a signal stopped the run before it put anything in
/// place) → "bookspin: interrupted; nothing written", 128 + signal; InputError → "bookspin: error:
/// …", 2; OutputError, render::RenderError, video::EncoderError → "bookspin: error: …", 1;
/// anything else → "bookspin: internal error: …", 70.
int run_guarded(const std::function<int()>& command);

}  // namespace bookspin::cli
