// One colour per component everywhere (common/colour.hpp, kComponentColours): the explorer page's
// web/src/colours.js and the notebook's plot of a fitted toss hold the same three colours, each
// channel × 255 rounded, as hex; x red, y green, z blue.
#include "common/colour.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace bookspin {
namespace {

std::string text_of(const std::string& relative) {
  std::ifstream file(std::string(BOOKSPIN_SOURCE_DIR) + "/" + relative);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// The "#rrggbb" colours of `text` in order.
std::vector<std::string> hex_colours(const std::string& text) {
  std::vector<std::string> found;
  const std::regex hex("#[0-9a-f]{6}");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), hex); it != std::sregex_iterator();
       ++it)
    found.push_back(it->str());
  return found;
}

TEST(ComponentColours, ThePageAndTheNotebookDrawOmegaInTheClipsColours) {
  std::vector<std::string> expected;
  for (const Rgb& c : kComponentColours) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", static_cast<int>(std::lround(255 * c.r)),
                  static_cast<int>(std::lround(255 * c.g)),
                  static_cast<int>(std::lround(255 * c.b)));
    expected.push_back(hex);
  }
  // x red, y green, z blue: each component's own channel the largest.
  for (int i = 0; i < 3; ++i) {
    const Rgb& c = kComponentColours[static_cast<std::size_t>(i)];
    const double own = i == 0 ? c.r : i == 1 ? c.g : c.b;
    EXPECT_EQ(own, std::max({c.r, c.g, c.b})) << i;
  }
  EXPECT_EQ(hex_colours(text_of("web/src/colours.js")), expected);
  // The notebook names them once and draws both of its ω plots (the exact motion's, a fitted
  // toss's) with them.
  const std::string notebook = text_of("examples/intermediate-axis.ipynb");
  const auto at = notebook.find("OMEGA_COLOURS = [");
  ASSERT_NE(at, std::string::npos) << "the notebook's ω colours";
  EXPECT_EQ(hex_colours(notebook.substr(at, 60)), expected);
  EXPECT_NE(notebook.find("color=OMEGA_COLOURS[i]"), std::string::npos) << "the exact motion's";
  EXPECT_NE(notebook.find("enumerate(OMEGA_COLOURS)"), std::string::npos) << "a fitted toss's";
}

}  // namespace
}  // namespace bookspin
