#include "golden_store.hpp"

#include <cstdlib>
#include <iostream>
#include <set>

#include "output/png_writer.hpp"
#include "support/scratch.hpp"

#ifndef GTEST_FLAG_GET  // GoogleTest before 1.12
#define GTEST_FLAG_GET(name) ::testing::GTEST_FLAG(name)
#endif

namespace bookspin::picture {

namespace {

constexpr int kGoldenCompression = 9;  // goldens live in git: smallest files

std::set<std::string>& used_goldens() {
  static std::set<std::string> used;
  return used;
}

std::filesystem::path golden_path(const std::string& name) {
  return golden_dir() / (name + ".png");
}

/// Update mode: (re)writes the golden and says what changed.
::testing::AssertionResult update_golden(const std::string& name, const RgbaImage& actual,
                                         const Tolerance& tolerance) {
  const auto path = golden_path(name);
  std::string status = "new";
  if (std::filesystem::exists(path)) {
    const RgbaImage old = output::read_png(path);
    if (old.width == actual.width && old.height == actual.height && old.pixels == actual.pixels) {
      std::cout << "golden " << name << ".png: unchanged\n";
      return ::testing::AssertionSuccess();
    }
    const Comparison c = compare_images(actual, old, tolerance);
    status = std::string("changed: ") + c.summary(tolerance) +
             (c.passed ? " (within tolerance)" : " (beyond tolerance)");
  }
  output::write_png(path, actual, kGoldenCompression);
  std::cout << "golden " << name << ".png: " << status << '\n';
  return ::testing::AssertionSuccess();
}

/// Lists goldens no test used, at the end of a full update run.
class UnusedGoldenReport : public ::testing::Environment {
 public:
  void TearDown() override {
    if (!update_mode() || GTEST_FLAG_GET(filter) != "*") return;
    for (const auto& entry : std::filesystem::directory_iterator(golden_dir())) {
      const std::string file = entry.path().filename().string();
      if (!used_goldens().count(file)) {
        std::cout << "golden " << file << ": used by no test any more; delete it\n";
      }
    }
  }
};

[[maybe_unused]] auto* const unused_golden_report =
    ::testing::AddGlobalTestEnvironment(new UnusedGoldenReport);

}  // namespace

bool update_mode() {
  const char* value = std::getenv("BOOKSPIN_UPDATE_GOLDENS");
  return value != nullptr && std::string(value) == "1";
}

std::filesystem::path golden_dir() {
  return std::filesystem::path(BOOKSPIN_SOURCE_DIR) / "tests" / "golden";
}

void note_golden_used(const std::string& file) { used_goldens().insert(file); }

std::string write_failure_images(const std::filesystem::path& dir, const RgbaImage& actual,
                                 const RgbaImage& expected, const Tolerance& tolerance) {
  output::write_png(dir / "actual.png", actual);
  std::string message = "\n  actual:   " + (dir / "actual.png").string();
  output::write_png(dir / "expected.png", expected);
  message += "\n  expected: " + (dir / "expected.png").string();
  if (compare_images(actual, expected, tolerance).same_size) {
    output::write_png(dir / "diff.png", diff_image(actual, expected, tolerance));
    message += "\n  diff:     " + (dir / "diff.png").string() +
               "  (red: differs beyond the threshold, blue: tolerated)";
  }
  return message;
}

RgbaImage read_golden(const std::string& name) {
  note_golden_used(name + ".png");
  return output::read_png(golden_path(name));
}

::testing::AssertionResult matches_golden(const std::string& name, const RgbaImage& actual,
                                          const Tolerance& tolerance) {
  note_golden_used(name + ".png");
  if (update_mode()) return update_golden(name, actual, tolerance);
  const auto dir = test::fresh_dir("picture/" + name);
  if (!std::filesystem::exists(golden_path(name))) {
    output::write_png(dir / "actual.png", actual);
    return ::testing::AssertionFailure()
           << "no golden " << golden_path(name).string()
           << "; run `make update-goldens` to create it, "
           << "look at it, and commit it\n  actual:   " << (dir / "actual.png").string();
  }
  const RgbaImage expected = output::read_png(golden_path(name));
  const Comparison c = compare_images(actual, expected, tolerance);
  if (c.passed) {
    std::filesystem::remove_all(dir);
    return ::testing::AssertionSuccess() << c.summary(tolerance);
  }
  return ::testing::AssertionFailure()
         << name << " differs from its golden: " << c.summary(tolerance)
         << write_failure_images(dir, actual, expected, tolerance)
         << "\n  if the change is intended: make update-goldens";
}

}  // namespace bookspin::picture
