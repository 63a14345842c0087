#pragma once
// The gallery page (OUT/index.html): pure text generation, no file access.
#include <string>
#include <string_view>
#include <vector>

namespace bookspin::cli {

/// One clip on the page. Paths are relative to the page's folder; empty: not there.
struct GalleryEntry {
  std::string name;               ///< scene.name
  std::string title;              ///< scene.title (plain text; escaped on the page)
  std::string description;        ///< scene.description
  std::string video;              ///< "<name>.mp4"
  std::string poster;             ///< a frame PNG shown before the clip plays
  std::string plot;               ///< "<name>-plot.png"
  std::string sweep;              ///< "<name>-sweep.png" (`bookspin sweep`)
  std::string sweep_csv;          ///< "<name>-sweep.csv"
  std::vector<std::string> csvs;  ///< diagnostics CSVs
};

/// `text` with &, <, >, " and ' replaced by character references, safe in element text and
/// in quoted attribute values.
std::string html_escape(std::string_view text);

/// A self-contained HTML5 page (inline CSS, no scripts) listing `entries` in order.
std::string gallery_html(const std::vector<GalleryEntry>& entries);

}  // namespace bookspin::cli
