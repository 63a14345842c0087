#include "fit/saturation.hpp"

#include <algorithm>
#include <cmath>

namespace bookspin::fit {

Saturation find_saturation(const GyroRecording& recording) {
  Saturation found;
  found.at_range.assign(recording.omega.size(), false);
  double top = 0.0;
  for (const Eigen::Vector3d& w : recording.omega) top = std::max(top, w.cwiseAbs().maxCoeff());
  if (!(top > 0.0)) return found;
  const double near = top * (1.0 - 1e-6);
  int longest = 0;
  for (int c = 0; c < 3; ++c) {
    int run = 0;
    for (const Eigen::Vector3d& w : recording.omega) {
      run = std::abs(w[c]) >= near ? run + 1 : 0;
      longest = std::max(longest, run);
    }
  }
  if (longest < kMinFlatSamples) return found;
  found.range = top;
  for (std::size_t i = 0; i < recording.omega.size(); ++i)
    found.at_range[i] = recording.omega[i].cwiseAbs().maxCoeff() >= near;
  return found;
}

}  // namespace bookspin::fit
