#include "products/outcome.hpp"

#include "cache/manifest_head.hpp"

namespace bookspin::products {

CachedOutcome make_cached(const CachedOutputs& cached, const Freshness& freshness,
                          const std::function<std::optional<Made>()>& make) {
  CachedOutcome done;
  cache::CachedJob job{cached.manifest,  cached.head, cached.out_dir,       freshness.force,
                       freshness.verify, {},          cached.all_or_nothing};
  job.make = [&]() -> std::optional<cache::JobOutputs> {
    std::optional<Made> made;
    try {
      made = make();
    } catch (const Interrupted& stop) {
      done.signal = stop.signal();
    }
    if (!made) return std::nullopt;
    cache::JobOutputs recorded{
        (cached.scene ? cache::manifest_note(*cached.scene) : std::string()) + made->note, {}};
    for (const auto& path : made->outputs)
      recorded.outputs.push_back(path.lexically_relative(cached.out_dir).generic_string());
    return recorded;
  };
  std::function<void(const std::string&)> on_remake;
  if (freshness.on_remake)
    on_remake = [&](const std::string& reason) { freshness.on_remake(cached.name, reason); };
  done.outcome = cache::run_cached(job, on_remake);
  return done;
}

}  // namespace bookspin::products
