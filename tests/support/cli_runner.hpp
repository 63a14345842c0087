#pragma once
// Runs a built program (bookspin, bookspin-bench, an example) and captures its exit status
// and output.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/text_file.hpp"
#include "support/scratch.hpp"

namespace bookspin::test {

struct CliResult {
  int status = -1;     ///< exit status, or 128 + signal
  std::string output;  ///< stdout and stderr together
};

/// Runs a shell `command`, appending its standard output to `out`; returns the exit status
/// (128 + signal if a signal ended it, -1 if it could not start).
inline int run_shell(const std::string& command, std::string& out) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) out += buffer.data();
  const int raw = pclose(pipe);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

/// Runs `env PROGRAM args` through the shell (args are shell words, quote as needed; env is
/// "" or "NAME=value ...").
inline CliResult run_program(const std::string& env, const std::string& program,
                             const std::string& args) {
  CliResult result;
  result.status = run_shell(env + " " + program + " " + args + " 2>&1", result.output);
  return result;
}

/// Runs the built bookspin (BOOKSPIN_EXE) with `env` and `args`.
inline CliResult run_bookspin_env(const std::string& env, const std::string& args) {
  return run_program(env, BOOKSPIN_EXE, args);
}

inline CliResult run_bookspin(const std::string& args) { return run_bookspin_env("", args); }

struct SplitResult {
  int status = -1;
  std::string out;  ///< standard output alone
  std::string err;  ///< standard error alone
};

inline std::string read_file(const std::filesystem::path& path) {
  return try_read_text_file(path).value_or(std::string());
}

/// Runs the built bookspin with `args`, keeping stdout and stderr apart (stderr through a
/// file named after this process, so parallel tests do not share it).
inline SplitResult run_bookspin_split(const std::string& args) {
  const auto dir = std::filesystem::path(BOOKSPIN_BINARY_DIR) / "test-output";
  std::filesystem::create_directories(dir);
  const auto err_file = dir / ("stderr-" + std::to_string(getpid()) + ".txt");
  const std::string command =
      std::string(BOOKSPIN_EXE) + " " + args + " 2>'" + err_file.string() + "'";
  SplitResult result;
  result.status = run_shell(command, result.out);
  result.err = read_file(err_file);
  std::filesystem::remove(err_file);
  return result;
}

inline std::string scene_path(const std::string& name) {
  return std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/" + name + ".toml";
}

}  // namespace bookspin::test
