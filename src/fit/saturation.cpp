#include "fit/saturation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>

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
          // A smooth peak rises to its top inside the run and falls again: the top stands
          // above both of the run's ends by most of what the component changes over it. A
          // clipped axis reads the range, drifting one way (or not at all): its top is at an
          // end, or above both ends by no more than half its spread (docs/phone-lab.md,
          // "Saturation"). The spread of a smooth peak's top shrinks as fewer samples catch
          // it (at a browser's 50 Hz, under kPlateauShare of the others' swing), its shape
          // does not.
          const double higher_end =
              sign * omega[i][c] > sign * omega[last][c] ? omega[i][c] : omega[last][c];
          const double peak = sign > 0 ? hi[c] : lo[c];
          const bool hump = sign * (peak - higher_end) > 0.5 * (hi[c] - lo[c]);
          plateau = hi[c] - lo[c] <= kPlateauShare * others && !hump;
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
  std::vector<double> tops;  // rad/s: each recording's largest |ω_i|
  for (const RecordingPart& part : recording.parts) {
    const std::vector<Eigen::Vector3d> own(recording.omega.begin() + part.first,
                                           recording.omega.begin() + part.last + 1);
    const Saturation its = saturation_of(own, part.gyroscope_range);
    for (std::size_t k = 0; k < own.size(); ++k) found.at_range[part.first + k] = its.at_range[k];
    Saturation::Part p;
    p.range = its.range;
    p.stated = its.range && part.gyroscope_range && *its.range == *part.gyroscope_range;
    found.parts.push_back(p);
    double top = 0.0;
    for (const Eigen::Vector3d& w : own) top = std::max(top, w.cwiseAbs().maxCoeff());
    tops.push_back(top);
  }
  // A range found from one recording's samples, refuted by another with no stated range that
  // reads past its band: one phone's gyroscope has one range.
  for (std::size_t a = 0; a < found.parts.size(); ++a) {
    Saturation::Part& p = found.parts[a];
    if (!p.range || p.stated) continue;
    for (std::size_t b = 0; b < found.parts.size(); ++b)
      if (b != a && !recording.parts[b].gyroscope_range &&
          tops[b] > (1.0 + kFullScaleAbove) * *p.range) {
        p.range.reset();
        const RecordingPart& part = recording.parts[a];
        std::fill(found.at_range.begin() + part.first, found.at_range.begin() + part.last + 1,
                  false);
        break;
      }
  }
  for (std::size_t a = 0; a < found.parts.size(); ++a) {
    const RecordingPart& part = recording.parts[a];
    found.parts[a].samples = static_cast<int>(std::count(
        found.at_range.begin() + part.first, found.at_range.begin() + part.last + 1, true));
    const std::optional<double>& range = found.parts[a].range;
    if (range && (!found.range || *range > *found.range)) found.range = range;
  }
  return found;
}

std::string saturation_note(const Saturation& saturation, const std::vector<RecordingPart>& parts,
                            const std::vector<int>& in_tosses) {
  // How each recording's range was known, and the recordings named under each range in turn.
  const auto how = [](const Saturation::Part& p) -> std::string {
    if (p.stated) return "as its export states";
    const bool full_scale = std::find(std::begin(kFullScales), std::end(kFullScales), *p.range) !=
                            std::end(kFullScales);
    return full_scale ? "a standard full scale" : "its top read flat";
  };
  const std::size_t n = std::min(saturation.parts.size(), parts.size());
  std::vector<bool> told(n, false);
  std::string text;
  int tossed = 0;
  for (std::size_t g = 0; g < n; ++g) {
    const Saturation::Part& p = saturation.parts[g];
    if (!p.range || told[g]) continue;
    std::vector<std::size_t> alike;
    for (std::size_t h = g; h < n; ++h)
      if (!told[h] && saturation.parts[h].range == p.range && how(saturation.parts[h]) == how(p)) {
        alike.push_back(h);
        told[h] = true;
      }
    char range[120];
    std::snprintf(range, sizeof range, "±%.6g rad/s (%.0f °/s, %s) in ", *p.range,
                  *p.range * 180.0 / std::numbers::pi, how(p).c_str());
    text += (text.empty() ? "" : "; ") + std::string(range);
    for (std::size_t k = 0; k < alike.size(); ++k) {
      const int samples = saturation.parts[alike[k]].samples;
      char count[40];
      std::snprintf(count, sizeof count, " (%d sample%s)", samples, samples == 1 ? "" : "s");
      text += (k == 0 ? "" : k + 1 == alike.size() ? " and " : ", ") + parts[alike[k]].name + count;
      if (alike[k] < in_tosses.size()) tossed += in_tosses[alike[k]];
    }
  }
  if (text.empty()) return {};
  char tail[80];
  std::snprintf(tail, sizeof tail, "; %d of them in the tosses, left out of the fit", tossed);
  return "the gyroscope saturated at " + text + tail;
}

}  // namespace bookspin::fit
