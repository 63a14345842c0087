// make_gallery over an OUT laid out by hand: it links a product's files only where they exist
// and the product's last manifest lists them (docs/outputs.md, "Gallery"), takes the middle
// listed frame as the poster, orders the scenes by the page's rule, writes its manifest and
// is up to date the second time.
#include "products/gallery.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "output/manifest.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& file) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << file.filename().string();
}

/// A manifest of bookspin's format at `manifest` listing `outputs` (relative to `out`).
void list_in_manifest(const fs::path& out, const fs::path& manifest,
                      const std::vector<std::string>& outputs) {
  fs::create_directories(manifest.parent_path());
  output::write_manifest(manifest, "  \"manifest\": 1,\n", "", out, outputs);
}

TEST(Gallery, LinksOnlyWhatTheManifestsListAndExists) {
  test::ScratchDir dir;
  const fs::path out = dir / "out";
  fs::create_directories(dir / "scenes");
  std::ofstream(dir / "scenes" / "demo.toml") << "[scene]\ntitle = \"Demo <1>\"\n";
  std::ofstream(dir / "scenes" / "bare.toml") << "[scene]\ntitle = \"Nothing yet\"\n";
  // The clip's last render: the MP4, three frames and the CSV. A GIF and a fourth frame from
  // an earlier run are there but not listed.
  for (const char* file :
       {"demo.mp4", "demo.gif", "demo/frames/frame_00000.png", "demo/frames/frame_00001.png",
        "demo/frames/frame_00002.png", "demo/frames/frame_00003.png", "demo/diagnostics.csv",
        "demo.glb", "demo-plot.png", "demo-sweep.png", "demo-sweep.csv"})
    touch(out / file);
  list_in_manifest(out, out / "demo" / "manifest.json",
                   {"demo.mp4", "demo/frames/frame_00000.png", "demo/frames/frame_00001.png",
                    "demo/frames/frame_00002.png", "demo/diagnostics.csv"});
  list_in_manifest(out, out / "demo" / "gltf-manifest.json", {"demo.glb"});
  // demo-plot.png has no manifest: not linked. The sweep's files are linked where they are.

  GalleryJob job;
  job.out_dir = out;
  job.scene_paths = {(dir / "scenes" / "demo.toml").string(),
                     (dir / "scenes" / "bare.toml").string()};
  const GalleryOutcome made = make_gallery(job);
  EXPECT_EQ(made.outcome, cache::Outcome::made);
  EXPECT_EQ(made.entries, 2u);
  const std::string html = test::read_file(out / "index.html");
  for (const char* linked :
       {"src=\"demo.mp4\"", "poster=\"demo/frames/frame_00001.png\"", "href=\"demo.mp4\">MP4</a>",
        "href=\"demo.glb\">glTF</a>", "href=\"demo/diagnostics.csv\"", "src=\"demo-sweep.png\"",
        "href=\"demo-sweep.csv\"", "<h2>Demo &lt;1&gt;</h2>", "not rendered yet (no bare.mp4)"})
    EXPECT_NE(html.find(linked), std::string::npos) << linked << '\n' << html;
  for (const char* unlisted : {"demo.gif", "demo-plot.png", "frame_00003.png", "demo.webm"})
    EXPECT_EQ(html.find(unlisted), std::string::npos) << unlisted << '\n' << html;
  // "bare" is another scene; "demo", with a sweep's outputs, goes with the sweeps, last.
  EXPECT_LT(html.find("id=\"bare\""), html.find("id=\"demo\""));
  // The page's manifest lists the page.
  EXPECT_EQ(output::read_manifest(out / "gallery-manifest.json").outputs,
            (std::vector<std::string>{"index.html"}));

  // Nothing changed: up to date. The plot listed now: the page changes, made again.
  EXPECT_EQ(make_gallery(job).outcome, cache::Outcome::up_to_date);
  list_in_manifest(out, out / "demo" / "plot-manifest.json", {"demo-plot.png"});
  EXPECT_EQ(make_gallery(job).outcome, cache::Outcome::made);
  EXPECT_NE(test::read_file(out / "index.html").find("src=\"demo-plot.png\""), std::string::npos);
}

// The conformance kit's league table (`bookspin flipcheck league`) is linked, page and CSV, once
// its manifest lists them; an HTML file by that name without the manifest is not.
TEST(Gallery, LinksTheLeagueTableItsManifestLists) {
  test::ScratchDir dir;
  const fs::path out = dir / "out";
  fs::create_directories(dir / "scenes");
  std::ofstream(dir / "scenes" / "demo.toml") << "[scene]\ntitle = \"Demo\"\n";
  touch(out / "flipcheck-league.html");
  touch(out / "flipcheck-league.csv");
  GalleryJob job;
  job.out_dir = out;
  job.scene_paths = {(dir / "scenes" / "demo.toml").string()};
  make_gallery(job);
  EXPECT_EQ(test::read_file(out / "index.html").find("flipcheck-league"), std::string::npos);
  list_in_manifest(out, out / "flipcheck-league-manifest.json",
                   {"flipcheck-league.csv", "flipcheck-league.html"});
  EXPECT_EQ(make_gallery(job).outcome, cache::Outcome::made);
  const std::string html = test::read_file(out / "index.html");
  for (const char* linked :
       {"id=\"flipcheck-league\"", "href=\"flipcheck-league.html\">the league table</a>",
        "href=\"flipcheck-league.csv\">its CSV</a>"})
    EXPECT_NE(html.find(linked), std::string::npos) << linked << '\n' << html;
  // The page's judge panel is linked once the explorer page is there.
  EXPECT_EQ(html.find("#judge"), std::string::npos) << html;
  touch(out / "explorer.html");
  make_gallery(job);
  const std::string with_page = test::read_file(out / "index.html");
  EXPECT_NE(with_page.find("href=\"explorer.html#judge\">judge a motion</a>"), std::string::npos)
      << with_page;
}

// The phone-toss lab (`bookspin fit`): no section without a fit's manifest; with one, its CSVs
// and each toss's chart and clip as the manifest lists them (a toss chart left from an earlier
// run with more tosses is not shown), and each toss opened in the explorer once the page is
// there and the manifest lists the toss's scene.
TEST(Gallery, ShowsThePhoneLabItsFitManifestLists) {
  test::ScratchDir dir;
  const fs::path out = dir / "out";
  fs::create_directories(dir / "scenes");
  std::ofstream(dir / "scenes" / "demo.toml") << "[scene]\ntitle = \"Demo\"\n";
  const std::vector<std::string> files{"rec-fit.csv",   "rec-fit-body.csv",      "rec-toss1.png",
                                       "rec-toss2.png", "rec-toss1.toml",        "rec-toss2.toml",
                                       "rec-toss1.mp4", "rec-toss2.mp4",         "rec-toss3.png",
                                       "rec-toss3.mp4", "rec-toss1-measured.csv"};
  for (const std::string& file : files) touch(out / file);
  GalleryJob job;
  job.out_dir = out;
  job.scene_paths = {(dir / "scenes" / "demo.toml").string()};
  // The files without the fit's manifest: no section.
  make_gallery(job);
  EXPECT_EQ(test::read_file(out / "index.html").find("phone-lab"), std::string::npos);
  // The last fit: two tosses, the first with its scene; toss 3's files are an earlier run's.
  list_in_manifest(out, out / "rec" / "fit-manifest.json",
                   {"rec-fit.csv", "rec-fit-body.csv", "rec-toss1.png", "rec-toss2.png",
                    "rec-toss1.toml", "rec-toss1-measured.csv", "rec-toss1.mp4", "rec-toss2.mp4"});
  EXPECT_EQ(make_gallery(job).outcome, cache::Outcome::made);
  std::string html = test::read_file(out / "index.html");
  for (const char* shown :
       {"id=\"phone-lab\"", "<h3>rec</h3>", "href=\"rec-fit.csv\"", "href=\"rec-fit-body.csv\"",
        "src=\"rec-toss1.png\"", "src=\"rec-toss2.png\"",
        "<video controls preload=\"metadata\" "
        "src=\"rec-toss1.mp4\"",
        "src=\"rec-toss2.mp4\"", "href=\"rec-toss2.mp4\">clip</a>"})
    EXPECT_NE(html.find(shown), std::string::npos) << shown << '\n' << html;
  for (const char* unlisted : {"rec-toss3", "explorer.html"})
    EXPECT_EQ(html.find(unlisted), std::string::npos) << unlisted << '\n' << html;
  // The lab comes before the scenes.
  EXPECT_LT(html.find("id=\"phone-lab\""), html.find("id=\"demo\""));
  // The explorer page made: the toss whose scene is listed opens in it, the other does not.
  touch(out / "explorer.html");
  EXPECT_EQ(make_gallery(job).outcome, cache::Outcome::made);
  html = test::read_file(out / "index.html");
  EXPECT_NE(html.find("href=\"explorer.html?scene=rec-toss1\">open in the explorer</a>"),
            std::string::npos)
      << html;
  EXPECT_EQ(html.find("scene=rec-toss2"), std::string::npos) << html;
  // ... and the section links the page's lab panel (explorer.html#lab).
  EXPECT_NE(html.find("href=\"explorer.html#lab\">the Phone-toss lab</a>"), std::string::npos)
      << html;
}

// An accuracy report (`bookspin accuracy`, e.g. the engines' energy against the step of `make
// figures`) shows its four charts and links its two tables, as its manifest lists them; it is
// not "not rendered yet".
TEST(Gallery, ShowsAnAccuracyReportsChartsAndTables) {
  test::ScratchDir dir;
  const fs::path out = dir / "out";
  fs::create_directories(dir / "sweeps");
  std::ofstream(dir / "sweeps" / "report.toml") << "[scene]\ntitle = \"A report\"\n";
  const std::vector<std::string> files{"report-accuracy.csv",       "report-accuracy.png",
                                       "report-work-precision.png", "report-energy-vs-dt.png",
                                       "report-turnovers.png",      "report-energy.png",
                                       "report-energy.csv"};
  for (const std::string& file : files) touch(out / file);
  GalleryJob job;
  job.out_dir = out;
  job.scene_paths = {(dir / "sweeps" / "report.toml").string()};
  // No manifest yet: nothing linked.
  make_gallery(job);
  EXPECT_NE(test::read_file(out / "index.html").find("not rendered yet"), std::string::npos);
  list_in_manifest(out, out / "report" / "accuracy-manifest.json", files);
  make_gallery(job);
  const std::string html = test::read_file(out / "index.html");
  EXPECT_EQ(html.find("not rendered yet"), std::string::npos) << html;
  std::size_t at = 0;
  for (const char* chart : {"src=\"report-accuracy.png\"", "src=\"report-work-precision.png\"",
                            "src=\"report-energy-vs-dt.png\"", "src=\"report-turnovers.png\"",
                            "src=\"report-energy.png\""}) {
    const std::size_t found = html.find(chart, at);
    EXPECT_NE(found, std::string::npos) << chart << " in this order\n" << html;
    at = found == std::string::npos ? at : found;
  }
  for (const char* table : {"href=\"report-accuracy.csv\"", "href=\"report-energy.csv\""})
    EXPECT_NE(html.find(table), std::string::npos) << table << '\n' << html;
}

TEST(Gallery, ABadSceneFailsBeforeAnythingIsWritten) {
  test::ScratchDir dir;
  std::ofstream(dir / "bad.toml") << "[time]\ndt = -1.0\n";
  GalleryJob job;
  job.out_dir = dir / "out";
  job.scene_paths = {(dir / "bad.toml").string()};
  EXPECT_THROW(make_gallery(job), InputError);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace bookspin::products
