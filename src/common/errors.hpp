#pragma once
// The error types every stage shares, and what the command line makes of them
// (docs/architecture.md, "Errors"):
//   InputError  — bad input (scene file, mesh, command line): exit status 2;
//   OutputError — an output could not be written: exit status 1;
//   anything else that escapes a command is a bug: "internal error", exit status 70.
// Internal invariants are checked with BOOKSPIN_ASSERT, never with an input error.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace bookspin {

/// Bad input. what() is one line: "FILE:LINE: KEY: reason" where the file, line and key are
/// known, "--set KEY: reason" for a command-line override, or a message formatted by the
/// thrower (for instance "FILE: scene file not found").
class InputError : public std::runtime_error {
 public:
  /// A message already formatted as one line.
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  /// "file:line: key: reason"; `line` ≤ 0 and an empty `key` are left out.
  InputError(const std::string& file, int line, const std::string& key, std::string_view reason);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }

 private:
  std::string file_;
  int line_ = 0;
  std::string key_;
};

/// A file or directory could not be created, written, renamed or removed.
/// what() is one line: `<action> "<path>": <reason>`.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws OutputError `<action> "<path>": <reason>`.
[[noreturn]] void throw_output_error(std::string_view action, const std::filesystem::path& path,
                                     std::string_view reason);
/// Throws OutputError `<action> "<path>": strerror(errno_value)`.
[[noreturn]] void throw_output_error(std::string_view action, const std::filesystem::path& path,
                                     int errno_value);

/// A broken internal invariant: a bug, never bad input. Reported as "internal error".
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// Throws InternalError "FILE:LINE: check failed: CONDITION".
[[noreturn]] void fail_assertion(const char* condition, const char* file, int line);

}  // namespace bookspin

/// Checks an internal invariant in every build type (these checks are cheap and guard
/// against silent wrong pictures); a failure is a bug, reported with exit status 70.
#define BOOKSPIN_ASSERT(condition) \
  ((condition) ? static_cast<void>(0) : ::bookspin::fail_assertion(#condition, __FILE__, __LINE__))
