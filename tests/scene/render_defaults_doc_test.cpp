// The x264 preset a scene without `render.preset` gets, against where the docs state it:
// scenes/README.md's row of the key and docs/performance-video.md, "The default x264 preset" (the
// measurement that chose it). The numeric defaults are limits_doc_test.cpp's.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "scene_text.hpp"

namespace bookspin::scene {
namespace {

std::string read_doc(const std::string& path) {
  std::ifstream in(std::string(BOOKSPIN_SOURCE_DIR) + "/" + path);
  EXPECT_TRUE(in.good()) << path;
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The text between `open` and the next `close` after the first `open` in `text`, or "".
std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const auto at = text.find(open);
  if (at == std::string::npos) return "";
  const auto begin = at + open.size();
  const auto end = text.find(close, begin);
  return end == std::string::npos ? "" : text.substr(begin, end - begin);
}

TEST(RenderDefaultsDoc, TheX264PresetOfASceneWithoutTheKeyIsTheDocumentedOne) {
  // scenes/README.md: | `render.preset` | string | `"faster"` | x264 preset: ...
  const std::string readme = read_doc("scenes/README.md");
  const std::string row = between(readme, "| `render.preset` |", "\n");
  const std::string readme_default = between(row, "| `\"", "\"` |");
  ASSERT_FALSE(readme_default.empty()) << "no default in the render.preset row: " << row;
  // docs/performance-video.md: `render.preset` and `render.crf` default to **`faster` at CRF 16**
  const std::string performance = read_doc("docs/performance-video.md");
  const std::string chosen = between(performance, "default to **`", "`");
  ASSERT_FALSE(chosen.empty()) << "docs/performance-video.md states no default preset";
  EXPECT_EQ(readme_default, chosen);

  // A scene with no [render] table, and one with the table but not the key.
  EXPECT_EQ(testing::parse("[time]\nframes = 10\n").render.preset, readme_default);
  EXPECT_EQ(testing::parse("[render]\nfps = 30\n").render.preset, readme_default);
}

}  // namespace
}  // namespace bookspin::scene
