#pragma once
// The tests' one scratch directory: BUILD/test-output/<name>, never outside the build tree.
// fresh_dir() empties it when a test asks for it (so a failed test's files stay there to look
// at until the next run); ScratchDir is a fresh_dir named after the running test, removed
// when the test passed.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace bookspin::test {

/// A fresh, empty directory for one test: BUILD/test-output/`name` (`name` may hold '/').
inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::path(BOOKSPIN_BINARY_DIR) / "test-output" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Every file and folder under `dir`, hidden ones included, as path relative to `dir` ('/'
/// separated) → the file's bytes ("<dir>" for a folder): two calls compare equal only when
/// nothing under `dir` was added, removed or changed.
inline std::map<std::string, std::string> tree_of(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string name = e.path().lexically_relative(dir).generic_string();
    if (e.is_directory()) {
      files[name] = "<dir>";
    } else {
      std::ifstream in(e.path(), std::ios::binary);
      files[name].assign(std::istreambuf_iterator<char>(in), {});
    }
  }
  return files;
}

/// fresh_dir("scratch/<Suite>.<Test>") of the running GoogleTest test, removed again at the
/// end of the scope unless the test has failed.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fresh_dir("scratch/" + std::string(info->test_suite_name()) + "." + info->name());
  }
  ~ScratchDir() {
    if (!::testing::Test::HasFailure()) {
      std::error_code ec;
      std::filesystem::remove_all(path_, ec);
    }
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  /// Every name in the directory, hidden ones included, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace bookspin::test
