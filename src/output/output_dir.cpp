#include "output/output_dir.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <mutex>
#include <vector>

#include "common/errors.hpp"

namespace bookspin::output {

namespace fs = std::filesystem;

namespace {

std::mutex made_mutex;
std::vector<fs::path>& made_directories() {
  static std::vector<fs::path> made;
  return made;
}

}  // namespace

void make_directories(const fs::path& dir, std::error_code& ec) {
  ec.clear();
  if (dir.empty()) return;
  // The missing ancestors, outermost last; found before creating so that only ours are noted.
  std::vector<fs::path> missing;
  fs::path start = dir.lexically_normal();
  if (!start.has_filename() && start.has_parent_path()) start = start.parent_path();  // "a/b/"
  for (fs::path p = start; !p.empty(); p = p.parent_path()) {
    std::error_code status_ec;
    if (fs::exists(fs::symlink_status(p, status_ec))) break;
    missing.push_back(p);
    if (p == p.parent_path() || !p.has_relative_path()) break;
  }
  fs::create_directories(dir, ec);
  if (ec) return;
  std::lock_guard lock(made_mutex);
  for (auto& p : missing) {
    std::error_code status_ec;
    if (fs::is_directory(fs::symlink_status(p, status_ec))) made_directories().push_back(p);
  }
}

void remove_empty_made_directories() noexcept {
  try {
    std::lock_guard lock(made_mutex);
    auto& made = made_directories();
    // Deepest first: a child's path is longer than its parent's.
    std::sort(made.begin(), made.end(), [](const fs::path& a, const fs::path& b) {
      return a.native().size() > b.native().size();
    });
    for (const auto& p : made) ::rmdir(p.c_str());  // fails, as meant, on a non-empty one
    made.clear();
  } catch (...) {
  }
}

void prepare_output_dir(const fs::path& dir) {
  std::error_code ec;
  make_directories(dir, ec);
  if (ec) throw_output_error("cannot create output directory", dir, ec.value());
  if (access(dir.c_str(), W_OK) != 0) throw_output_error("cannot write to", dir, errno);
}

}  // namespace bookspin::output
