#pragma once
// The one "check the manifest, make the outputs, write the manifest" of every cached product
// (through products::make_cached): an output whose manifest matches is not made again
// (output/manifest.hpp has the file format and what "matches" means).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace bookspin::cache {

/// What a job made: the manifest's note (recorded, not compared) and its outputs, as paths
/// relative to the job's out_dir.
struct JobOutputs {
  std::string note;
  std::vector<std::string> outputs;
};

/// One cached job.
struct CachedJob {
  std::filesystem::path manifest;  ///< the manifest file
  std::string head;                ///< what the outputs depend on (compared)
  std::filesystem::path out_dir;   ///< the outputs' folder
  bool force = false;              ///< make them even when up to date
  bool verify = false;             ///< also compare the outputs' SHA-256
  /// Makes the outputs; empty when interrupted (nothing was put in place).
  std::function<std::optional<JobOutputs>()> make;
  /// make() puts its outputs in place together or not at all (output::OutputSet), so when it
  /// throws, the earlier outputs and their manifest are still true and the manifest is kept.
  bool all_or_nothing = false;
};

enum class CacheOutcome {
  up_to_date,   ///< nothing made
  made,         ///< made, manifest written
  interrupted,  ///< make() returned empty: the old manifest (if any) still tells the truth
};

/// Unless `job.force`, returns up_to_date when the manifest matches job.head and every listed
/// output is there (output::manifest_stale). Otherwise runs job.make() (after telling
/// `on_remake`, if given, why a manifest that was there did not match, e.g. "scene changed");
/// if it throws, the manifest is removed (some outputs may have been replaced; kept for an
/// `all_or_nothing` job) and the exception goes on; if it returns outputs, removes the files
/// the earlier manifest listed that this run did not make (plain paths inside out_dir only,
/// and the folders that leaves empty: out_dir holds one run's outputs, docs/outputs.md), then
/// writes the manifest last. Throws OutputError when the manifest cannot be written (the earlier
/// manifest, which no longer tells the truth, is then removed).
CacheOutcome run_cached(const CachedJob& job,
                        const std::function<void(const std::string& reason)>& on_remake = {});

}  // namespace bookspin::cache
