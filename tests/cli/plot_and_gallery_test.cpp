// `bookspin plot` and `bookspin gallery` (the page's text alone:
// tests/products/gallery_page_test.cpp).
#include <gtest/gtest.h>

#include <cctype>

#include "output/png_writer.hpp"
#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

TEST(PlotCommand, WritesAPngOfTheRequestedSize) {
  const fs::path out = fresh_dir("plot_size");
  const CliResult r = run_bookspin("plot " + scene_path("fig09-matrix-unstable-x") +
                                   " --set time.frames=60 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const RgbaImage image = output::read_png(out / "fig09-matrix-unstable-x-plot.png");
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 800);
  const CliResult small =
      run_bookspin("plot " + scene_path("compare-normalization") +
                   " --set time.frames=30 --width 800 --height 500 -o " + out.string());
  ASSERT_EQ(small.status, 0) << small.output;
  const RgbaImage compare = output::read_png(out / "compare-normalization-plot.png");
  EXPECT_EQ(compare.width, 800);
  EXPECT_EQ(compare.height, 500);
}

TEST(PlotCommand, BadSceneExitsTwoAndWritesNothing) {
  const fs::path out = fresh_dir("plot_bad");
  const CliResult r = run_bookspin("plot " + scene_path("fig09-matrix-unstable-x") +
                                   " --set time.dt=-1 -o " + out.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(fs::is_empty(out));
}

/// Every src=, poster= and href= value of `html` that names a file (not a data: URL or #anchor).
/// (A plain scan: GCC 12's std::regex trips -Wmaybe-uninitialized in its own headers.)
std::vector<std::string> linked_files(const std::string& html) {
  std::vector<std::string> files;
  for (const std::string attribute : {"src=\"", "poster=\"", "href=\""}) {
    for (std::size_t at = html.find(attribute); at != std::string::npos;
         at = html.find(attribute, at + 1)) {
      if (at > 0 && std::isalnum(static_cast<unsigned char>(html[at - 1])))
        continue;  // e.g. data-src=
      const std::size_t begin = at + attribute.size(), end = html.find('"', begin);
      const std::string value = html.substr(begin, end - begin);
      if (value.rfind("data:", 0) != 0 && value.rfind("#", 0) != 0) files.push_back(value);
    }
  }
  return files;
}

TEST(Gallery, EveryListedVideoAndImageExists) {
  const fs::path out = fresh_dir("gallery");
  const fs::path odd = out / "odd-title.toml";
  std::ofstream(odd) << R"toml([scene]
title = "Book <&> \"spin\""
[model]
kind = "rigid-matrix"
normalize = true
[render]
panel = true
)toml";
  const std::vector<std::string> scenes{odd.string(), scene_path("compare-methods-x")};
  for (const auto& scene : scenes) {
    const std::string size =
        " --set render.width=64 --set render.height=64 --set 'render.preset=\"ultrafast\"'";
    const std::string formats = scene == odd.string() ? " --format mp4,webm,gif" : "";
    ASSERT_EQ(
        run_bookspin("render " + scene + size + formats + " --frames 5 --jobs 2 -o " + out.string())
            .status,
        0);
    ASSERT_EQ(run_bookspin("plot " + scene + " --set time.frames=5 --width 640 --height 400 -o " +
                           out.string())
                  .status,
              0);
  }
  ASSERT_EQ(run_bookspin("export " + odd.string() + " --gltf --frames 5 -o " + out.string()).status,
            0);
  const CliResult r = run_bookspin("gallery " + out.string() + " " + scenes[0] + " " + scenes[1]);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string html = read_file(out / "index.html");
  EXPECT_NE(html.find("Book &lt;&amp;&gt; &quot;spin&quot;"), std::string::npos);
  const auto files = linked_files(html);
  for (const char* expected :
       {"odd-title.mp4", "odd-title.webm", "odd-title.gif", "odd-title.glb", "odd-title-plot.png",
        "compare-methods-x.mp4", "compare-methods-x/frames/frame_00002.png"}) {
    EXPECT_NE(std::find(files.begin(), files.end(), expected), files.end()) << expected << '\n'
                                                                            << html;
  }
  for (const auto& file : files) EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
}

TEST(Gallery, ListsAnUnrenderedSceneWithoutBrokenLinks) {
  const fs::path out = fresh_dir("gallery_empty");
  ASSERT_EQ(
      run_bookspin("gallery " + out.string() + " " + scene_path("fig03-particle-stable-z")).status,
      0);
  const std::string html = read_file(out / "index.html");
  EXPECT_NE(html.find("Figure 3"), std::string::npos);
  EXPECT_TRUE(linked_files(html).empty()) << html;
}

// The page in a real browser (headless Chromium): tests/browser/gallery_test.py.

}  // namespace
}  // namespace bookspin::cli
