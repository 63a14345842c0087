#pragma once
// The real recordings the fit's rules are held to (docs/phone-lab.md): one phone's session in
// ../shared/recordings-real/ beside the checkout (CI has it), and the skip where it is absent.
#include <gtest/gtest.h>

#include <filesystem>

namespace bookspin::fit {

/// The folder of the development session's recordings (phyphox exports, one folder each).
inline std::filesystem::path real_dir() {
  return std::filesystem::path(BOOKSPIN_SOURCE_DIR) / ".." / "shared" / "recordings-real" /
         "dvarkian-2022-05-03";
}

}  // namespace bookspin::fit

/// Skips the test (one line saying why) where the real recordings are not beside the checkout.
#define REQUIRE_REAL_RECORDINGS()                                                  \
  if (!std::filesystem::is_directory(::bookspin::fit::real_dir()))                 \
  GTEST_SKIP() << "no real recordings at " << ::bookspin::fit::real_dir().string() \
               << " (../shared/recordings-real/ beside the checkout; CI has it)"
