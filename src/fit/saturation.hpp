#pragma once
// A gyroscope's saturation (docs/phone-lab.md, "Saturation"): a phone's gyroscope stops at its
// range (±2000 °/s, 34.9 rad/s, on most phones), and a fast throw reads flat there for several
// samples. Those samples are the range, not the motion: the fit leaves them out.
#include <optional>
#include <vector>

#include "fit/recording.hpp"

namespace bookspin::fit {

/// Where a recording's gyroscope saturated, found from the samples alone.
struct Saturation {
  /// rad/s: the range the gyroscope stopped at (the largest |ω_i| of the recording), or nullopt
  /// when nothing is flat there.
  std::optional<double> range;
  /// One per sample of the recording: true where some component reads the range (|ω_i| within
  /// 1e-6 of it, relative).
  std::vector<bool> at_range;
};

/// The samples of `recording` at its gyroscope's range. Where the export states the range
/// (GyroRecording::gyroscope_range) and no sample exceeds it, every sample with some |ω_i|
/// within kStatedRangeTolerance of it is marked, however short the run. Otherwise (or when no
/// sample reads the stated range) the range is found from the samples: the largest |ω_i| of the
/// whole recording, any component and sign, when one component reads it (within 1e-6, relative)
/// at kMinFlatSamples consecutive samples or more; a smooth peak reaches its top at one sample,
/// a clipped one stays there. No range, no sample marked. A pooled recording (its `parts`) is
/// searched recording by recording, each on its samples as measured (its bias put back) with
/// its own stated range; `range` is then the largest found.
Saturation find_saturation(const GyroRecording& recording);

/// Consecutive samples flat at the largest |ω_i| that make it a range rather than a peak.
inline constexpr int kMinFlatSamples = 3;

/// Relative: how near the stated range a reading counts as at it (0.035 rad/s at 34.9 rad/s, a
/// few of a phone gyroscope's least steps, e.g. 0.0011 rad/s on Android's 16-bit ±2000 °/s).
inline constexpr double kStatedRangeTolerance = 1e-3;

}  // namespace bookspin::fit
