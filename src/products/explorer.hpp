#pragma once
// The explorer product (`bookspin explore`): the explorer page (docs/explorer.md) for a set of
// scenes. The page's program (the physics compiled to WebAssembly, the app bundled with three.js)
// is built once by web/build.sh into a shell file; this writes the scenes into it and the result is
// one self-contained HTML file that opens from disk with the network off.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "common/json_writer.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {

/// Where the shell of the page (web/build.sh BUILD_DIR writes BUILD_DIR/web/) is looked for.
inline constexpr const char* kExplorerShellName = "explorer-shell.html";

/// web/explorer-shell.html in the folder of the running program (the build folder, where
/// web/build.sh BUILD_DIR writes it): the shell `bookspin explore` uses by default.
std::filesystem::path default_explorer_shell();

/// OUT/explorer.html, the one file the page's product writes.
std::filesystem::path explorer_page_path(const std::filesystem::path& out_dir);

/// The marker in the shell that the scenes' data replaces (web/src/index.html).
inline constexpr const char* kExplorerDataMarker = "<!--BOOKSPIN_DATA-->";

/// The JavaScript engines' bundle (cannon-es, Rapier, Jolt: web/src/engines/), which web/build.sh
/// writes beside the shell, and the shell's marker it replaces with `--engines` (else removed).
inline constexpr const char* kExplorerEnginesName = "explorer-engines.js";
inline constexpr const char* kExplorerEnginesMarker = "<!--BOOKSPIN_ENGINES-->";

/// explorer-engines.js in the folder of `shell`: the engines' bundle that goes with that shell.
std::filesystem::path explorer_engines_beside(const std::filesystem::path& shell);

struct ExplorerPageRequest {
  std::vector<scene::Scene> scenes;  ///< in the page's order; names must differ
  /// The values the page reads for one of `scenes` (jobs::explorer_scene_data: scene::page_data,
  /// with the replays of the tiles it cannot step), made by the pure stage; called for each
  /// scene, in order, only when the page is written (an up-to-date page runs no replay). Unset:
  /// an internal error.
  std::function<JsonObject(const scene::Scene&)> scene_data;
  std::filesystem::path shell;  ///< the page without data (web/build.sh)
  /// The JavaScript engines' bundle to write into the page (explorer_engines_beside); empty:
  /// none, and the page offers bookspin's own models only.
  std::filesystem::path engines;
  std::filesystem::path out_dir;  ///< writes OUT/explorer.html
  /// Polled before each face image ("explore scenes") and before the page is
  /// written ("explore write"): a signal throws Interrupted; the earlier page and its manifest
  /// stay.
  StopPoll stop_signal;
  cache::Freshness freshness;  ///< --force, --verify and the remake note (make_explorer_page)
};

struct ExplorerPageResult {
  std::filesystem::path path;  ///< OUT/explorer.html
  std::uintmax_t bytes = 0;    ///< its size
};

/// Writes explorer_page_path(request.out_dir): the shell with its data marker replaced by one
/// script that sets window.BOOKSPIN_SCENES (request.scene_data, one a line: each scene's
/// jobs::explorer_scene_data, docs/explorer.md "Comparison") and
/// window.BOOKSPIN_BOOK_ART (the book's four default face images, render::generate_face_image, as
/// PNG data: URLs); the engines' marker replaced by request.engines as one script (it sets
/// window.BOOKSPIN_ENGINES) or, without engines, by nothing. Throws InputError when two scenes
/// share a name, the shell is missing, unreadable or lacks the marker (naming the shell), or the
/// engines' bundle is missing or unreadable or the shell has no place for it (naming the file),
/// render::RenderError when the fonts of the covers are missing, OutputError when the page cannot
/// be written (atomic: an earlier page stays until the new one is complete).
ExplorerPageResult write_explorer_page(const ExplorerPageRequest& request);

/// OUT/explorer-manifest.json.
std::filesystem::path explorer_manifest_path(const std::filesystem::path& out_dir);

struct ExplorerOutcome {
  cache::Outcome outcome = cache::Outcome::made;
  ExplorerPageResult result;  ///< the page (its size only when made)
};

/// (scenes, shell, engines) => OUT/explorer.html + manifest.
/// write_explorer_page(request) unless the page's manifest says it is up to date
/// (request.freshness: --force makes it anyway, --verify hashes the page): its head
/// holds the shell's SHA-256 (the web sources, lockfile and physics built into it), the engines'
/// bundle's when there is one, and every
/// scene's manifest head (cache::manifest_head: the program, the resolved scene and its input
/// files), so an unchanged set of inputs leaves the page's bytes and modification time alone.
/// Same errors as write_explorer_page.
ExplorerOutcome make_explorer_page(const ExplorerPageRequest& request);

}  // namespace bookspin::products
