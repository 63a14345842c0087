#pragma once
// The explorer product (`bookspin explore`): the explorer page (docs/explorer.md) for a set of
// scenes. The page's program (the physics compiled to WebAssembly, the app bundled with three.js)
// is built once by web/build.sh into a shell file; this writes the scenes into it and the result is
// one self-contained HTML file that opens from disk with the network off.
#include <cstdint>
#include <filesystem>
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

/// One scene as the page reads it (web/src/main.js, window.BOOKSPIN_SCENES[i]), as a plain value
/// that json_text writes: a JSON object with name, title, description, `state` (the page's
/// state, web/src/state.js: body, model, integrator, normalize, damping, k, cells, dt, axis
/// "custom" with ω0 `w` (body frame, rad per time unit), jiggle, seed, speed in time units per
/// second, the markers; a
/// [[compare]] scene compares its first tile with its last, of those the page can run: the
/// other engines' tiles are left out, docs/engines.md; `left_out` lists the labels of the tiles
/// it does not run, where there are any), `book` (size, mass), `duration` (the scene's run,
/// (frames − 1)·dt·steps_per_frame time units: the page's time slider spans it) and, for
/// other bodies, `body`: the Body itself as simulate builds it (shape, mass, principal moments
/// about x, y, z, cage size, volume, surface 3×V principal frame flattened column by column,
/// triangles 3×N, face colours 3×N, smooth), so that the page's physics starts from the
/// same doubles (written in shortest round-trip form) and needs no mesh reader; with
/// `measured.omega`, `measured`: its samples {t, w: 3×N body-frame ω flattened, ut, u: the
/// times and body-frame L/|L| (L = I·ω, the body's moments) of the samples with L ≠ 0}, which
/// the page draws beside its runs (docs/explorer.md). No I/O (the scene reader read the file).
JsonObject explorer_scene_data(const scene::Scene& scene);

struct ExplorerPageRequest {
  std::vector<scene::Scene> scenes;  ///< in the page's order; names must differ
  std::filesystem::path shell;       ///< the page without data (web/build.sh)
  /// The JavaScript engines' bundle to write into the page (explorer_engines_beside); empty:
  /// none, and the page offers bookspin's own models only.
  std::filesystem::path engines;
  std::filesystem::path out_dir;  ///< writes OUT/explorer.html
  /// Polled before each scene and each face image ("explore scenes") and before the page is
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
/// script that sets window.BOOKSPIN_SCENES (explorer_scene_data of each scene, one a line) and
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
