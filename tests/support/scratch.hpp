#pragma once
// The tests' one scratch directory: build/test-output/<name>, emptied when a test asks for it
// (so a failed test's files stay there to look at until the next run) and never outside the
// build tree.
#include <filesystem>
#include <string>

namespace bookspin::test {

/// A fresh, empty directory for one test: BUILD/test-output/`name` (`name` may hold '/').
inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::path(BOOKSPIN_BINARY_DIR) / "test-output" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace bookspin::test
