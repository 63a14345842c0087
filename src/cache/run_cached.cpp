#include "cache/run_cached.hpp"

#include "output/manifest.hpp"

namespace bookspin::cache {

CacheOutcome run_cached(const CachedJob& job,
                        const std::function<void(const std::string& reason)>& on_remake) {
  if (!job.force) {
    const std::optional<std::string> stale =
        output::manifest_stale(job.manifest, job.head, job.out_dir, job.verify);
    if (!stale) return CacheOutcome::up_to_date;
    std::error_code ec;
    if (on_remake && std::filesystem::exists(job.manifest, ec)) on_remake(*stale);
  }
  std::optional<JobOutputs> made;
  try {
    made = job.make();
  } catch (...) {
    std::error_code ec;
    if (!job.all_or_nothing) std::filesystem::remove(job.manifest, ec);
    throw;
  }
  if (!made) return CacheOutcome::interrupted;
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
