#include "cli/subcommand.hpp"

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

void frames_as_override(int frames, std::vector<std::string>& overrides) {
  if (frames > 0) overrides.push_back("time.frames=" + std::to_string(frames));
}

}  // namespace bookspin::cli
