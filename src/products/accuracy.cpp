#include "products/accuracy.hpp"

namespace bookspin::products {

jobs::AccuracyPaths accuracy_paths(const std::filesystem::path& out_dir,
                                   const scene::Scene& scene) {
  const auto file = [&](const char* suffix) { return out_dir / (scene.name + suffix); };
  return {file("-accuracy.csv"),
          file("-accuracy.png"),
          {file("-work-precision.png"), file("-energy.png"), file("-energy.csv")}};
}

std::vector<std::filesystem::path> make_accuracy(const AccuracyJob& job) {
  jobs::AccuracyRequest request = job.request;
  request.paths = accuracy_paths(job.out_dir, request.scene);
  return jobs::run_accuracy(request);
}

}  // namespace bookspin::products
