#include "fit/saturation.hpp"

#include <algorithm>
#include <cmath>

#include "fit/pool.hpp"

namespace bookspin::fit {

namespace {

/// True when `value` (rad/s, ≥ 0) lies in `scale`'s band, [1 − kFullScaleBelow,
/// 1 + kFullScaleAbove] × scale.
bool in_band(double value, double scale) {
  return value >= (1.0 - kFullScaleBelow) * scale && value <= (1.0 + kFullScaleAbove) * scale;
}

/// The standard full scale (rad/s) whose band holds `top`, the recording's largest |ω_i|, or
/// nullopt.
std::optional<double> full_scale_of(double top) {
  for (double scale : kFullScales)
    if (in_band(top, scale)) return scale;
  return std::nullopt;
}

/// A clipped gyroscope without a stated range (docs/phone-lab.md, "Saturation"): where the top
/// lies in a standard full scale's band (kFullScaleBelow, kFullScaleAbove), each run of consecutive
/// samples with one component in that band (the same sign) is clipped when it is a spike cut flat
/// (the samples on both sides of the run read under kSpikeEdge of the scale: a smooth peak passes
/// through the band, its neighbours near it) or a plateau (kMinFlatSamples or more: two straddle
/// any smooth peak; the component changing by under kPlateauShare of what the other components
/// change over the run, as no rigid motion does: with one component fixed, |L| and the energy hold
/// the others' squares fixed; a clipped axis drifts only by its calibration's cross-axis terms).
/// Marks those samples in `at_range`; returns the scale, or nullopt when no run clips.
std::optional<double> clipped_full_scale(const std::vector<Eigen::Vector3d>& omega, double top,
                                         std::vector<bool>& at_range) {
  const std::optional<double> scale = full_scale_of(top);
  if (!scale) return std::nullopt;
  const int n = static_cast<int>(omega.size());
  const auto clips = [&](int i, int c, double sign) { return in_band(sign * omega[i][c], *scale); };
  bool any = false;
  for (int c = 0; c < 3; ++c)
    for (double sign : {1.0, -1.0})
      for (int i = 0; i < n;) {
        if (!clips(i, c, sign)) {
          ++i;
          continue;
        }
        int last = i;
        while (last + 1 < n && clips(last + 1, c, sign)) ++last;
        const auto low = [&](int k) {
          return k < 0 || k >= n || std::abs(omega[k][c]) < kSpikeEdge * *scale;
        };
        const bool spike = low(i - 1) && low(last + 1);
        bool plateau = false;
        if (last - i + 1 >= kMinFlatSamples) {
          Eigen::Vector3d lo = omega[i], hi = omega[i];
          for (int k = i; k <= last; ++k) {
            lo = lo.cwiseMin(omega[k]);
            hi = hi.cwiseMax(omega[k]);
          }
          double others = 0.0;
          for (int o = 0; o < 3; ++o)
            if (o != c) others = std::max(others, hi[o] - lo[o]);
          plateau = hi[c] - lo[c] <= kPlateauShare * others;
        }
        if (spike || plateau) {
          for (int k = i; k <= last; ++k) at_range[k] = true;
          any = true;
        }
        i = last + 1;
      }
  return any ? scale : std::nullopt;
}

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
  // A standard full scale (kFullScales) whose band holds the top: the samples that clip there,
  // as spikes cut flat or as plateaus that drift while the other axes swing.
  if (std::optional<double> scale = clipped_full_scale(omega, top, found.at_range)) {
    found.range = scale;
    return found;
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
  check_pooled(recording);
  // Each recording's own gyroscope, on its samples as measured.
  Saturation found;
  found.at_range.assign(recording.omega.size(), false);
  for (const RecordingPart& part : recording.parts) {
    const std::vector<Eigen::Vector3d> own(recording.omega.begin() + part.first,
                                           recording.omega.begin() + part.last + 1);
    const Saturation its = saturation_of(own, part.gyroscope_range);
    for (std::size_t k = 0; k < own.size(); ++k) found.at_range[part.first + k] = its.at_range[k];
    if (its.range && (!found.range || *its.range > *found.range)) found.range = its.range;
  }
  return found;
}

}  // namespace bookspin::fit
