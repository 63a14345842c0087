#pragma once
// What every cached product shares: how its command wants an up-to-date output treated
// (Freshness), what its manifest holds (CachedOutputs) and make_cached(), the one "check the
// manifest, make the outputs, record them" of every product (over cache::run_cached), with
// what it did (up to date: nothing made; made; or interrupted: nothing put in place). The
// products' callers see these names, not the cache stage's.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cache/run_cached.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {

using Outcome = cache::CacheOutcome;

/// Told why an existing manifest did not match, before the output is made again: the
/// output's name ("fig09", "fig09-plot", "fig09-sweep", "index.html") and the reason.
using RemakeNote = std::function<void(const std::string& name, const std::string& reason)>;

/// How a command wants its product's outputs treated when its manifest says they are up to
/// date (`--force`, `--verify`; docs/outputs.md).
struct Freshness {
  bool force = false;    ///< make them even when up to date
  bool verify = false;   ///< the up-to-date check hashes every output (else sizes only)
  RemakeNote on_remake;  ///< why a manifest did not match (may be empty)
};

/// One product's cached outputs: what its manifest is called and holds.
struct CachedOutputs {
  std::string name;                ///< the outputs' name in notes ("fig09", "fig09-plot")
  std::filesystem::path manifest;  ///< the manifest file (the product's layout names it)
  std::string head;                ///< what the outputs depend on (cache/manifest_head.hpp)
  std::filesystem::path out_dir;   ///< OUT: the manifest lists outputs relative to it
  /// The scene they are made from: its file's path and SHA-256 open the manifest's note
  /// (cache::manifest_note). None for a product of many scenes.
  const scene::Scene* scene = nullptr;
  /// make() puts its outputs in place together or not at all (output::OutputSet): see
  /// cache::CachedJob::all_or_nothing.
  bool all_or_nothing = false;
};

/// What a product's make() put in place.
struct Made {
  std::vector<std::filesystem::path> outputs;  ///< every file, under CachedOutputs::out_dir
  std::string note = {};  ///< more of the manifest's note (recorded, not compared), JSON members
};

/// What make_cached() did, and the signal that stopped make() (when interrupted).
struct CachedOutcome {
  Outcome outcome = Outcome::made;
  int signal = 0;
};

/// Unless `freshness.force`, nothing is made when `cached`'s manifest matches its head and
/// lists outputs that are all there (cache::run_cached). Otherwise tells
/// `freshness.on_remake` why (if a manifest was there), runs `make` and records what it made
/// in the manifest. `make` returns nothing, or throws Interrupted, when a signal stopped it
/// before it put anything in place: the outcome is then `interrupted`, with the signal, and
/// the earlier outputs and manifest are untouched. Throws what `make` throws (InputError,
/// OutputError, …) and OutputError when the manifest cannot be written.
CachedOutcome make_cached(const CachedOutputs& cached, const Freshness& freshness,
                          const std::function<std::optional<Made>()>& make);

}  // namespace bookspin::products
