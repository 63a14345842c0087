#pragma once
// The golden files in tests/golden/ and the one switch that rewrites them:
// BOOKSPIN_UPDATE_GOLDENS=1 (what `make update-goldens` sets). Without it the tests only
// compare; a missing golden is a failure, never created silently.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/rgba_image.hpp"
#include "image_compare.hpp"

namespace bookspin::picture {

/// True when BOOKSPIN_UPDATE_GOLDENS=1: goldens are rewritten instead of checked.
bool update_mode();

/// tests/golden/ in the source tree.
std::filesystem::path golden_dir();

/// Records that a test uses tests/golden/<file>, so that update mode can name goldens no
/// test uses any more.
void note_golden_used(const std::string& file);

/// Writes actual.png, expected.png and diff.png into `dir`; returns a message naming them.
std::string write_failure_images(const std::filesystem::path& dir, const RgbaImage& actual,
                                 const RgbaImage& expected, const Tolerance& tolerance);

/// Checks `actual` against tests/golden/<name>.png within `tolerance`. On a mismatch writes
/// actual/expected/diff PNGs under BUILD/test-output/picture/<name>/ and names them in the
/// failure message. In update mode writes the golden instead (PNG level 9) and prints
/// whether it is new, unchanged or changed (with PSNR and differing share).
::testing::AssertionResult matches_golden(const std::string& name, const RgbaImage& actual,
                                          const Tolerance& tolerance = {});

/// The golden image tests/golden/<name>.png (for tests that compare on their own).
RgbaImage read_golden(const std::string& name);

}  // namespace bookspin::picture
