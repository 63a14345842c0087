#include "fit/saturation.hpp"

#include <algorithm>
#include <cmath>

namespace bookspin::fit {

namespace {

/// find_saturation on the samples `omega` (as measured, bias included) of one gyroscope whose
/// stated range is `stated` (or nullopt).
Saturation saturation_of(const std::vector<Eigen::Vector3d>& omega, std::optional<double> stated) {
  Saturation found;
  found.at_range.assign(omega.size(), false);
  double top = 0.0;
  for (const Eigen::Vector3d& w : omega) top = std::max(top, w.cwiseAbs().maxCoeff());
  if (!(top > 0.0)) return found;
  // The stated range: every sample reading it, however short the run.
  if (stated && top <= *stated * (1.0 + kStatedRangeTolerance)) {
    const double near = *stated * (1.0 - kStatedRangeTolerance);
    bool any = false;
    for (std::size_t i = 0; i < omega.size(); ++i) {
      found.at_range[i] = omega[i].cwiseAbs().maxCoeff() >= near;
      any = any || found.at_range[i];
    }
    if (any) {
      found.range = *stated;
      return found;
    }
  }
  // Found from the samples: the top, read flat.
  const double near = top * (1.0 - 1e-6);
  int longest = 0;
  for (int c = 0; c < 3; ++c) {
    int run = 0;
    for (const Eigen::Vector3d& w : omega) {
      run = std::abs(w[c]) >= near ? run + 1 : 0;
      longest = std::max(longest, run);
    }
  }
  if (longest < kMinFlatSamples) return found;
  found.range = top;
  for (std::size_t i = 0; i < omega.size(); ++i)
    found.at_range[i] = omega[i].cwiseAbs().maxCoeff() >= near;
  return found;
}

}  // namespace

Saturation find_saturation(const GyroRecording& recording) {
  if (recording.parts.empty()) return saturation_of(recording.omega, recording.gyroscope_range);
  // Pooled: each recording's own gyroscope, on its samples as measured (its bias put back).
  Saturation found;
  found.at_range.assign(recording.omega.size(), false);
  for (const RecordingPart& part : recording.parts) {
    std::vector<Eigen::Vector3d> own;
    for (int i = part.first; i <= part.last; ++i) own.push_back(recording.omega[i] + part.bias);
    const Saturation its = saturation_of(own, part.gyroscope_range);
    for (std::size_t k = 0; k < own.size(); ++k) found.at_range[part.first + k] = its.at_range[k];
    if (its.range && (!found.range || *its.range > *found.range)) found.range = its.range;
  }
  return found;
}

}  // namespace bookspin::fit
