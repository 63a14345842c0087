#include "cli/subcommand.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "common/errors.hpp"

namespace bookspin::cli {

void add_freshness_flags(CLI::App* cmd, bool& force, bool& verify, const std::string& manifest) {
  cmd->add_flag("--force", force,
                "Make the outputs even when " + manifest + " says they are up to date");
  cmd->add_flag("--verify", verify,
                "Up-to-date check: compare every output's SHA-256 with the manifest, not only "
                "its size");
}

CLI::Option* add_out_option(CLI::App* cmd, std::string& out_dir, const std::string& help) {
  const std::string fallback = out_dir;
  return cmd->add_option("-o,--out", out_dir, help)
      ->capture_default_str()
      ->check(CLI::Validator(
          [fallback](const std::string& text) -> std::string {
            if (!text.empty()) return {};
            return "expected a directory, got an empty name (leave it out for " + fallback + ")";
          },
          "DIR"));
}

CLI::Validator no_empty_output(const std::string& what, const std::string& hint) {
  return CLI::Validator(
      [what, hint](const std::string& text) -> std::string {
        if (!text.empty()) return {};
        return "expected " + what + ", got an empty name (" + hint + ")";
      },
      "");
}

void flush_standard_output() {
  errno = 0;
  std::cout.flush();
  int error = errno;
  // std::cout writes through C's stdout (synchronised with stdio): a line that did not fit its
  // buffer failed at fwrite, marking either stream, its errno long since overwritten.
  bool failed = !std::cout || std::ferror(stdout);
  errno = 0;
  if (std::fflush(stdout) != 0) {
    failed = true;
    if (error == 0) error = errno;
  }
  if (!failed) return;
  if (error == 0) {
    // The cause, asked of the output again: one more byte, to an output already broken.
    std::clearerr(stdout);
    errno = 0;
    if (std::fputc('\n', stdout) == EOF || std::fflush(stdout) != 0) error = errno;
  }
  throw OutputError(std::string("cannot write the standard output: ") +
                    (error != 0 ? std::strerror(error) : "the write failed"));
}

void frames_as_override(int frames, std::vector<std::string>& overrides) {
  if (frames > 0) overrides.push_back("time.frames=" + std::to_string(frames));
}

}  // namespace bookspin::cli
