#pragma once
// A shard of a sweep (`bookspin sweep --shard K/N`, docs/sweeps.md, docs/physics.md §14): its
// CSV with a first line "# bookspin sweep shard K of N: …" recording the sweep, and a
// grid_index column before the full CSV's; and the shards of one sweep read back into its
// table, checked to be one sweep's and to cover its grid exactly once.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "jobs/sweep_csv.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

/// The text of shard k of n (k from 0) of `table`: the first line "# bookspin sweep shard K
/// of N: " then the scene name, the SHA-256 of `scene` (the resolved scene after --set, before
/// the grid's values) in canonical form (scene::canonical_json, as in the manifests),
/// bookspin's build id, `grid_points` (the whole grid's size), each range (VaryRange::spec)
/// and the measures; then the header with grid_index first, then one line per row. No I/O.
std::string sweep_shard_text(const SweepTable& table, const scene::Scene& scene,
                             std::size_t grid_points, int k, int n);

/// Where shard k of n of the sweep of the scene called `scene_name` would be: named when it
/// is missing.
using ShardPath = std::function<std::filesystem::path(const std::string& scene_name, int k, int n)>;

/// Reads shard CSVs (LF or CRLF line endings), checks they are shards of one sweep (same
/// scene name, scene SHA-256, build, grid, measures and N; same header) that cover its grid
/// exactly once, and returns the sweep's table, rows in grid order. Throws InputError naming
/// the file (and line): no shards given, unreadable, not a shard, a shard line without scene
/// hash or build, another sweep (naming the first field that differs), a mismatched header, a
/// row of another shard or an index outside the grid, a quoted cell not closed, a cell that is
/// not a finite number (empty is allowed for a measure, not for a varied value; `refused` is
/// text), a refused point's row with a measure, a duplicate grid point, a missing
/// one (naming the shard file that should hold it: the given one, else `missing`'s).
SweepTable read_sweep_shards(const std::vector<std::filesystem::path>& shards,
                             const ShardPath& missing);

}  // namespace bookspin::jobs
