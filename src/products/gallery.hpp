#pragma once
// The gallery product (`bookspin gallery`): OUT/index.html over what the other products wrote
// under OUT (found through their layouts: clip.hpp, plot.hpp, sweep.hpp, gltf.hpp,
// explorer.hpp), with its manifest. The page's HTML is gallery_page.hpp's.
#include <filesystem>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "common/stop.hpp"

namespace bookspin::products {

/// OUT/index.html and OUT/gallery-manifest.json.
struct GalleryLayout {
  std::filesystem::path page;
  std::filesystem::path manifest;
};

/// The layout of the gallery in `out_dir`. No I/O.
GalleryLayout gallery_layout(const std::filesystem::path& out_dir);

/// What `bookspin gallery` asks for.
struct GalleryJob {
  std::filesystem::path out_dir;
  std::vector<std::string> scene_paths;  ///< every scene on the page
  cache::Freshness freshness;            ///< --force (write it even when up to date), note
  /// Polled before each scene ("gallery scenes") and before the page is written ("gallery
  /// write"): a signal throws Interrupted; the earlier page and its manifest stay.
  StopPoll stop_signal;
};

struct GalleryOutcome {
  cache::Outcome outcome = cache::Outcome::made;
  std::size_t entries = 0;  ///< scenes on the page
};

/// (OUT, scenes) => OUT/index.html + manifest.
/// Parses every scene first (a bad one fails before anything is written), then writes the
/// page unless its manifest says the same page (but for its date) is there. Throws
/// InputError, OutputError.
GalleryOutcome make_gallery(const GalleryJob& job);

}  // namespace bookspin::products
