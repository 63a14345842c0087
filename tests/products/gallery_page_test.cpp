// The gallery page's text (products/gallery_page.hpp, no file access): escaping, the order of
// the scenes (docs/outputs.md, "Gallery order"), the header, and what an entry shows.
#include "products/gallery_page.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace bookspin::products {
namespace {

TEST(GalleryPage, EscapesTitlesAndAttributes) {
  EXPECT_EQ(html_escape("a <b> & \"c\" 'd'"), "a &lt;b&gt; &amp; &quot;c&quot; &#39;d&#39;");
  GalleryEntry e;
  e.name = "x";
  e.title = "<script>alert(1)</script>";
  const std::string html = gallery_html({e}, {});
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
}

TEST(GalleryPage, PaperFiguresFirstThenExactComparisonsOthersAndSweeps) {
  struct Scene {
    std::string name;
    bool comparison = false, exact = false, sweep = false;
  };
  const std::vector<Scene> given{{"sweep-dt"},
                                 {"compare-methods-x", true},
                                 {"fig12-quaternion-pulsating-z"},
                                 {"mesh-teapot"},
                                 {"exact-unstable-x", false, true},
                                 {"fig03-particle-stable-z"},
                                 {"tennis-racket", false, true},
                                 {"fig10-matrix-no-normalization"},
                                 {"many-methods", true},
                                 {"fig9-short"},
                                 {"aaa-body"},
                                 {"flip-time-vs-perturbation", false, false, true}};
  std::vector<std::pair<GalleryRank, std::string>> ranked;
  for (const auto& s : given)
    ranked.emplace_back(gallery_rank(s.name, s.comparison, s.exact, s.sweep), s.name);
  std::sort(ranked.begin(), ranked.end());
  std::vector<std::string> order;
  for (const auto& [rank, name] : ranked) order.push_back(name);
  const std::vector<std::string> expected{"fig03-particle-stable-z",
                                          "fig9-short",
                                          "fig10-matrix-no-normalization",
                                          "fig12-quaternion-pulsating-z",
                                          "exact-unstable-x",
                                          "tennis-racket",
                                          "compare-methods-x",
                                          "many-methods",
                                          "aaa-body",
                                          "mesh-teapot",
                                          "flip-time-vs-perturbation",
                                          "sweep-dt"};
  EXPECT_EQ(order, expected);
}

TEST(GalleryPage, HeaderSaysWhatAndHowItWasMade) {
  GalleryHeader header;
  header.version = "1.2.3";
  header.build_id = std::string(64, 'a');
  header.date = "2026-11-22 01:50 UTC";
  header.machine = "host <x>, Some CPU, 2 cores";
  const std::string html = gallery_html({}, header);
  // The intro states the page's order: no league and no fit here, the figures first.
  EXPECT_NE(html.find("first the paper's figures 3–12, the exact motion"), std::string::npos)
      << html;
  EXPECT_NE(html.find("bookspin 1.2.3 (build aaaaaaaaaaaa)"), std::string::npos) << html;
  EXPECT_NE(html.find("2026-11-22 01:50 UTC"), std::string::npos) << html;
  EXPECT_NE(html.find("host &lt;x&gt;, Some CPU, 2 cores"), std::string::npos) << html;
}

// The contents list every section in the page's order, the clips under their group's name,
// and the intro names the sections before the clips in that order too.
TEST(GalleryPage, ContentsAndIntroFollowThePagesOrder) {
  GalleryHeader header;
  header.flipcheck_league = "flipcheck-league.html";
  header.fits.push_back({"lab", "lab-fit.csv", "", {{1, "lab-toss1.png", "lab-toss1.mp4", ""}}});
  std::vector<GalleryEntry> entries(3);
  entries[0].name = "fig09-x";
  entries[0].title = "Figure 9";
  entries[0].group = GalleryGroup::paper_figure;
  entries[1].name = "exact-x";
  entries[1].title = "Exact";
  entries[1].group = GalleryGroup::exact;
  entries[2].name = "sweep-dt";
  entries[2].title = "Sweep";
  entries[2].group = GalleryGroup::sweep;
  const std::string html = gallery_html(entries, header);
  const auto at = [&html](const std::string& text, std::size_t from = 0) {
    const std::size_t i = html.find(text, from);
    EXPECT_NE(i, std::string::npos) << text;
    return i;
  };
  at("first the conformance kit's league table and the phone-toss lab's fitted tosses, then the "
     "paper's figures 3–12");
  // Contents: the league, the lab, then each group's clips, before the first section.
  const std::size_t nav = at("<nav class=\"contents\"");
  const std::size_t league = at("href=\"#flipcheck-league\"", nav);
  const std::size_t lab = at("href=\"#phone-lab\"", league);
  const std::size_t figures = at("The paper's figures", lab);
  const std::size_t fig09 = at("href=\"#fig09-x\">Figure 9</a>", figures);
  const std::size_t exact = at("The exact motion", fig09);
  const std::size_t sweeps = at("Sweeps", at("href=\"#exact-x\"", exact));
  at("href=\"#sweep-dt\"", sweeps);
  EXPECT_LT(at("</nav>"), at("id=\"flipcheck-league\""));
  EXPECT_LT(at("id=\"flipcheck-league\""), at("id=\"phone-lab\""));
  EXPECT_LT(at("id=\"phone-lab\""), at("id=\"fig09-x\""));
  // A toss's clip shows its chart before it plays, not its first frame's empty panels.
  at("<video controls preload=\"metadata\" src=\"lab-toss1.mp4\" poster=\"lab-toss1.png\">");
}

// An entry with nothing rendered says so, naming the MP4 it lacks; a sweep's picture stands
// in for the clip; a poster alone is shown as an image.
TEST(GalleryPage, AnEntryWithoutAClipSaysNotRenderedYetUnlessItHasASweepOrAFrame) {
  GalleryEntry bare;
  bare.name = "fig03";
  bare.title = "Figure 3";
  EXPECT_NE(
      gallery_html({bare}, {}).find("<p class=\"missing\">not rendered yet (no fig03.mp4)</p>"),
      std::string::npos);
  GalleryEntry sweep = bare;
  sweep.sweep = "fig03-sweep.png";
  const std::string with_sweep = gallery_html({sweep}, {});
  EXPECT_EQ(with_sweep.find("not rendered yet"), std::string::npos) << with_sweep;
  EXPECT_NE(with_sweep.find("<img class=\"plot\" loading=\"lazy\" src=\"fig03-sweep.png\""),
            std::string::npos)
      << with_sweep;
  GalleryEntry poster = bare;
  poster.poster = "fig03/frames/frame_00001.png";
  const std::string with_poster = gallery_html({poster}, {});
  EXPECT_EQ(with_poster.find("not rendered yet"), std::string::npos);
  EXPECT_NE(
      with_poster.find("<img src=\"fig03/frames/frame_00001.png\" alt=\"frame of Figure 3\">"),
      std::string::npos)
      << with_poster;
  GalleryEntry clip = poster;
  clip.video = clip.mp4 = "fig03.mp4";
  clip.csvs = {"fig03/diagnostics.csv"};
  const std::string with_clip = gallery_html({clip}, {});
  EXPECT_NE(with_clip.find("<video controls preload=\"metadata\" src=\"fig03.mp4\" "
                           "poster=\"fig03/frames/frame_00001.png\"></video>"),
            std::string::npos)
      << with_clip;
  EXPECT_NE(with_clip.find("<a href=\"fig03/diagnostics.csv\">diagnostics.csv</a>"),
            std::string::npos);
}

// A chart is on a row of its own with its size (so it is shown no larger than drawn, and the page
// keeps its layout while it loads); a poster gives its clip's size; an image of unknown size has
// none.
TEST(GalleryPage, ImagesCarryTheirSizesAndAChartHasARowOfItsOwn) {
  GalleryEntry e;
  e.name = "fig03";
  e.title = "Figure 3";
  e.video = e.mp4 = "fig03.mp4";
  e.poster = "fig03/poster.png";
  e.plot = "fig03-plot.png";
  e.report_charts = {"fig03-accuracy.png"};
  GalleryHeader header;
  header.image_sizes = {{"fig03/poster.png", {1280, 720}}, {"fig03-plot.png", {1600, 1000}}};
  const std::string html = gallery_html({e}, header);
  EXPECT_NE(html.find("poster=\"fig03/poster.png\" width=\"1280\" height=\"720\"></video>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<a class=\"plot\" href=\"fig03-plot.png\"><img class=\"plot\" "
                      "loading=\"lazy\" src=\"fig03-plot.png\" width=\"1600\" height=\"1000\" "
                      "alt=\"diagnostics of Figure 3\"></a>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("src=\"fig03-accuracy.png\" alt="), std::string::npos) << html;
  // One picture a row; its width is its own (the attribute), never stretched: at most 100%.
  EXPECT_NE(html.find("grid-template-columns: minmax(0, 1fr)"), std::string::npos);
  EXPECT_NE(html.find(".media video, .media img { max-width: 100%; height: auto;"),
            std::string::npos);
}

}  // namespace
}  // namespace bookspin::products
