#include "cli/subcommand.hpp"

namespace bookspin::cli {

void add_freshness_flags(CLI::App* cmd, bool& force, bool& verify, const std::string& manifest) {
  cmd->add_flag("--force", force,
                "Make the outputs even when " + manifest + " says they are up to date");
  cmd->add_flag("--verify", verify,
                "Up-to-date check: compare every output's SHA-256 with the manifest, not only "
                "its size");
}

void frames_as_override(int frames, std::vector<std::string>& overrides) {
  if (frames > 0) overrides.push_back("time.frames=" + std::to_string(frames));
}

}  // namespace bookspin::cli
