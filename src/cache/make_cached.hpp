#pragma once
// The one "check the manifest, make the outputs, record them" of every cached product: an
// output whose manifest matches is not made again (output/manifest.hpp has the file format
// and what "matches" means; manifest_head.hpp what a product's head holds).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "common/json_writer.hpp"
#include "scene/scene.hpp"

namespace bookspin::cache {

/// One product's cached outputs: what its manifest is called and holds. Its head, what the
/// outputs depend on, is cached_head(): the product says its command and options, and
/// make_cached() builds the head from them (manifest_head.hpp).
struct CachedOutputs {
  std::string name;                ///< the outputs' name in notes ("fig09", "fig09-plot")
  std::filesystem::path manifest;  ///< the manifest file (the product's layout names it)
  std::string command;             ///< the head's command ("render", "plot", "gallery", …)
  /// With a `scene`: the output options (manifest_head(command, options, scene)). Without:
  /// every member of the head after the command (manifest_head(command, options)).
  JsonObject options;
  std::filesystem::path out_dir;  ///< OUT: the manifest lists outputs relative to it
  /// The scene they are made from: its canonical form and input files' SHA-256 go in the head,
  /// its file's path and SHA-256 open the manifest's note (manifest_note). None for a product
  /// of many scenes.
  const scene::Scene* scene = nullptr;
  /// make() puts its outputs in place together or not at all (output::OutputSet), so when it
  /// throws, the earlier outputs and their manifest are still true and the manifest is kept.
  bool all_or_nothing = false;
  /// Files the outputs are read from besides the scene's own (the motion files a judgement
  /// reads): the head's options gain `input_files`, each file's name and SHA-256
  /// (manifest_head.hpp, input_files_json).
  std::vector<std::filesystem::path> input_files = {};
};

/// What a product's make() put in place.
struct Made {
  std::vector<std::filesystem::path> outputs;  ///< every file, under CachedOutputs::out_dir
  std::string note = {};  ///< more of the manifest's note (recorded, not compared), JSON members
};

/// The head of `cached`'s manifest (manifest_head.hpp): command, options and, with a scene, the
/// program, the resolved scene and its input files' SHA-256, and the SHA-256 of
/// `cached.input_files`. Throws InputError when an input file cannot be read.
std::string cached_head(const CachedOutputs& cached);

/// (cached, freshness, make) => the outputs make() puts in place + their manifest, or nothing
/// when they are up to date.
///
/// Unless `freshness.force`, returns up_to_date when `cached`'s manifest matches its head and
/// every listed output is there (output::manifest_stale), after removing the temporaries a
/// killed run left beside them (output::remove_dead_temporaries). Otherwise tells
/// `freshness.on_remake` why (if a manifest was there), runs `make`, removes the files the
/// earlier manifest listed that this run did not make (plain paths inside out_dir only, and
/// the folders that leaves empty: out_dir holds one run's outputs, docs/outputs.md), then
/// writes the manifest last and returns made.
///
/// `make` throws Interrupted (common/stop.hpp) when a signal stopped it before it put anything
/// in place: the earlier outputs and their manifest are untouched and Interrupted goes on.
/// Any other exception goes on too, after removing the manifest (some outputs may have been
/// replaced; kept when `cached.all_or_nothing`). Throws OutputError when the manifest cannot
/// be written (the earlier manifest, which no longer tells the truth, is then removed).
Outcome make_cached(const CachedOutputs& cached, const Freshness& freshness,
                    const std::function<Made()>& make);

/// make_cached() of each of `each` in turn, their outputs put in place together (all of them or
/// none, for a command of many scenes): `make(i)` stages the outputs of `each[i]` where they are
/// not up to date, in the order of `each`; once every make has run, `put_in_place()` puts every
/// staged output in place at once, and then every manifest is written, the last one's first.
/// Each of `each` must be `all_or_nothing` (otherwise InternalError, before anything): a check,
/// make or `put_in_place` that throws leaves every output and manifest as it was, and the
/// exception goes on. Returns each one's Outcome, in the order of `each`.
std::vector<Outcome> make_cached_together(const std::vector<CachedOutputs>& each,
                                          const Freshness& freshness,
                                          const std::function<Made(std::size_t)>& make,
                                          const std::function<void()>& put_in_place);

}  // namespace bookspin::cache
