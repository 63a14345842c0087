#pragma once
// The gallery page (OUT/index.html): pure text generation, no file access.
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace bookspin::products {

/// The page's groups, in page order.
enum class GalleryGroup { paper_figure, exact, comparison, other, sweep };

/// One clip on the page. Paths are relative to the page's folder; empty: not there.
struct GalleryEntry {
  GalleryGroup group =
      GalleryGroup::other;  ///< its group (gallery_rank): its heading in the contents
  std::string name;         ///< scene.name
  std::string title;        ///< scene.title (plain text; escaped on the page)
  std::string description;  ///< scene.description
  std::string video;        ///< "<name>.mp4", or "<name>.webm" where there is no MP4
  std::string mp4;          ///< "<name>.mp4" if rendered (linked)
  std::string webm;         ///< "<name>.webm" if rendered (linked)
  std::string gif;          ///< "<name>.gif" if rendered (linked)
  std::string glb;          ///< "<name>.glb" from `bookspin export --gltf` (linked)
  /// "explorer.html?scene=<name>" where OUT/explorer.html exists (`bookspin explore`, which
  /// carries every body, meshes included); else empty.
  std::string explorer;
  std::string poster;     ///< a frame PNG shown before the clip plays
  std::string plot;       ///< "<name>-plot.png"
  std::string sweep;      ///< "<name>-sweep.png" (`bookspin sweep`)
  std::string sweep_csv;  ///< "<name>-sweep.csv"
  /// The accuracy report's charts (`bookspin accuracy`: "<name>-accuracy.png",
  /// "<name>-work-precision.png", …) and its tables ("<name>-accuracy.csv", …), as its
  /// manifest lists them.
  std::vector<std::string> report_charts;
  std::vector<std::string> report_csvs;
  std::vector<std::string> csvs;  ///< diagnostics CSVs
};

/// One toss of a phone-toss lab fit (`bookspin fit`, docs/phone-lab.md) on the page. Paths are
/// relative to the page's folder; empty: not there.
struct GalleryToss {
  int number = 0;        ///< N of "<recording>-toss<N>", from 1
  std::string chart;     ///< "<recording>-toss<N>.png": measured ω, fitted lines, the sphere
  std::string video;     ///< "<recording>-toss<N>.mp4" (or .webm) with --render
  std::string explorer;  ///< "explorer.html?scene=<recording>-toss<N>" where both are there
};

/// A fitted recording on the page: its tables and its tosses, as the fit's manifest lists them.
struct GalleryFit {
  std::string recording;  ///< the recording's name, as it names the outputs
  std::string csv;        ///< "<recording>-fit.csv": one row per toss
  std::string body_csv;   ///< "<recording>-fit-body.csv": the body's row
  std::vector<GalleryToss> tosses;
};

/// An image's size in pixels.
struct ImageSize {
  int width = 0;
  int height = 0;
};

/// What the page says about how it was made.
struct GalleryHeader {
  std::string version;   ///< bookspin's version
  std::string build_id;  ///< SHA-256 of the bookspin executable (the first 12 digits are shown)
  std::string date;      ///< when the page was written, e.g. "2026-11-22 01:50 UTC"
  std::string machine;   ///< host name, CPU model and cores
  /// The conformance kit's league table ("flipcheck-league.html", and its CSV) where their
  /// manifest lists them (`bookspin flipcheck league`, docs/flipcheck.md); else empty.
  std::string flipcheck_league;
  std::string flipcheck_league_csv;
  /// "explorer.html#judge", the explorer page's "Judge a motion" panel (docs/flipcheck.md),
  /// where OUT/explorer.html is there; else empty.
  std::string flipcheck_judge_page;
  /// "explorer.html#lab", the explorer page's "Phone-toss lab" panel (docs/phone-lab.md), where
  /// OUT/explorer.html is there; else empty. Linked from the phone-toss lab's section.
  std::string phone_lab_page;
  /// The phone-toss lab's fits in OUT (one per OUT/<recording>/fit-manifest.json, by name),
  /// shown in a "Phone-toss lab" section after the league; none: no section.
  std::vector<GalleryFit> fits;
  /// The size of every image the page shows (posters, plots, sweeps, the report's and the
  /// tosses' charts), by its path as the entries give it: written as the <img>'s width and
  /// height, so that the page keeps its layout while lazy images load and a chart is shown no
  /// larger than drawn (its text at the size it was drawn for). An image without its size is
  /// shown as wide as its column.
  std::map<std::string, ImageSize> image_sizes;
};

/// Where a scene goes on the page, by this rule on its name and kind:
///  1. `figNN-…`: the paper's figures, by NN;
///  2. the exact motion: a single scene of the book with model kind `exact`, or named
///     `exact-…`;
///  3. comparisons: a scene with [[compare]] entries or named `compare-…`;
///  4. every other scene (other bodies, …);
///  5. sweeps: a scene with a parameter sweep's outputs (`<name>-sweep.png` or `.csv`), a
///     scene file in a `sweeps/` folder, or one named `sweep-…`.
/// Within a group, by figure number, then by name. Returns a key that sorts in page order.
struct GalleryRank {
  GalleryGroup group = GalleryGroup::other;
  int figure = 0;  ///< NN of figNN-…, 0 elsewhere
  std::string name;
  bool operator<(const GalleryRank& o) const;
};
GalleryRank gallery_rank(const std::string& name, bool is_comparison, bool is_exact,
                         bool is_sweep = false);

/// `text` with &, <, >, " and ' replaced by character references, safe in element text and
/// in quoted attribute values.
std::string html_escape(std::string_view text);

/// A self-contained HTML5 page (inline CSS, no scripts): a header saying what the page is, in
/// what order, and how it was made, its contents (a link to each section, the clips under
/// their groups' names), the league table's and the phone-toss lab's sections where `header`
/// has them, then `entries` in the order given.
std::string gallery_html(const std::vector<GalleryEntry>& entries, const GalleryHeader& header);

}  // namespace bookspin::products
