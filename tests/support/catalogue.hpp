#pragma once
// The bad-input catalogues (tests/bad_scenes/, tests/bad_meshes/): one case per input file
// NAME.<ext> with NAME.expected, the exact line bookspin must print after "bookspin: error: ",
// placeholders standing for the paths the test passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "support/cli_runner.hpp"

namespace bookspin::test {

struct CatalogueCase {
  std::string name;            ///< file stem, e.g. "dt-zero"
  std::filesystem::path file;  ///< the bad input
  std::string expected;        ///< the full stderr line, placeholders substituted
};
// gtest prints parameters into the names ctest registers; print a stable text, not bytes.
[[maybe_unused]] inline void PrintTo(const CatalogueCase& c, std::ostream* out) { *out << c.name; }

inline std::string trim_line_end(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

inline void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

/// Placeholder → text pairs for one case's .expected line.
using Placeholders = std::vector<std::pair<std::string, std::string>>;

/// Every case of `folder` (tests/<folder>) whose file `is_case` accepts, sorted by name. A
/// case without its .expected file gets an impossible line, so it fails loudly.
inline std::vector<CatalogueCase> load_catalogue(
    const std::string& folder, const std::function<bool(const std::filesystem::path&)>& is_case,
    const std::function<Placeholders(const std::filesystem::path&)>& placeholders) {
  namespace fs = std::filesystem;
  std::vector<CatalogueCase> cases;
  std::error_code ec;
  for (const auto& entry :
       fs::directory_iterator(fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / folder, ec)) {
    if (!is_case(entry.path())) continue;
    CatalogueCase c{entry.path().stem().string(), entry.path(), {}};
    const fs::path expected = fs::path(c.file).replace_extension(".expected");
    if (fs::exists(expected)) {
      std::string line = trim_line_end(read_file(expected));
      for (const auto& [from, to] : placeholders(c.file)) replace_all(line, from, to);
      c.expected = "bookspin: error: " + line + "\n";
    } else {
      c.expected = "(missing " + expected.string() + ")";
    }
    cases.push_back(std::move(c));
  }
  std::sort(cases.begin(), cases.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  return cases;
}

/// At least `minimum` cases, each with its .expected file next to it.
template <typename Case>
void expect_complete(const std::vector<Case>& cases, std::size_t minimum) {
  EXPECT_GE(cases.size(), minimum);
  for (const CatalogueCase& c : cases) {
    EXPECT_TRUE(
        std::filesystem::exists(std::filesystem::path(c.file).replace_extension(".expected")))
        << c.name;
  }
}

/// GoogleTest names allow only letters, digits and '_'.
inline std::string case_test_name(const ::testing::TestParamInfo<CatalogueCase>& info) {
  std::string name = info.param.name;
  std::replace_if(
      name.begin(), name.end(), [](unsigned char ch) { return !std::isalnum(ch); }, '_');
  return name;
}

/// Single-quoted for the shell. Built with append: GCC 12 warns falsely (-Wrestrict) on
/// "literal" + std::string.
inline std::string quoted(const std::filesystem::path& path) {
  std::string out;
  return out.append("'").append(path.string()).append("'");
}

}  // namespace bookspin::test
