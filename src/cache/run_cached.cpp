#include "cache/run_cached.hpp"

#include <algorithm>
#include <set>

#include "output/manifest.hpp"

namespace bookspin::cache {

namespace fs = std::filesystem;

namespace {

/// Removes the files an earlier run listed in its manifest (`earlier`, relative to OUT) that
/// this run (`now`) did not make, e.g. the GIF of a run with another render.formats, and the
/// folders that leaves empty: OUT holds the outputs of one run only (docs/outputs.md). Only
/// plain relative paths inside OUT are touched; errors are ignored (an output left behind is
/// no longer listed, so nothing links it).
void remove_outputs_of_earlier_run(const fs::path& out_dir, const std::vector<std::string>& earlier,
                                   const std::vector<std::string>& now) {
  const std::set<std::string> kept(now.begin(), now.end());
  std::set<fs::path> folders;
  for (const std::string& listed : earlier) {
    const fs::path relative(listed);
    if (kept.count(listed) != 0 || relative.empty() || relative.is_absolute() ||
        relative.lexically_normal() != relative ||
        std::find(relative.begin(), relative.end(), "..") != relative.end())
      continue;
    std::error_code ec;
    const fs::path file = out_dir / relative;
    if (!fs::is_regular_file(fs::symlink_status(file, ec)) || !fs::remove(file, ec)) continue;
    for (fs::path folder = relative.parent_path(); !folder.empty(); folder = folder.parent_path())
      folders.insert(folder);
  }
  // Deepest first: a folder's subfolders go before it.
  for (auto it = folders.rbegin(); it != folders.rend(); ++it) {
    std::error_code ec;
    if (fs::is_empty(out_dir / *it, ec) && !ec) fs::remove(out_dir / *it, ec);
  }
}

}  // namespace

CacheOutcome run_cached(const CachedJob& job,
                        const std::function<void(const std::string& reason)>& on_remake) {
  if (!job.force) {
    const std::optional<std::string> stale =
        output::manifest_stale(job.manifest, job.head, job.out_dir, job.verify);
    if (!stale) return CacheOutcome::up_to_date;
    std::error_code ec;
    if (on_remake && std::filesystem::exists(job.manifest, ec)) on_remake(*stale);
  }
  const std::vector<std::string> earlier = output::manifest_outputs(job.manifest);
  std::optional<JobOutputs> made;
  try {
    made = job.make();
  } catch (...) {
    std::error_code ec;
    if (!job.all_or_nothing) std::filesystem::remove(job.manifest, ec);
    throw;
  }
  if (!made) return CacheOutcome::interrupted;
  remove_outputs_of_earlier_run(job.out_dir, earlier, made->outputs);
  try {
    output::write_manifest(job.manifest, job.head, made->note, job.out_dir, made->outputs);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(job.manifest, ec);  // it describes the outputs just replaced
    throw;
  }
  return CacheOutcome::made;
}

}  // namespace bookspin::cache
