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

/// The samples of `recording` flat at its range: the largest |ω_i| of the whole recording, any
/// component and sign, is taken as the range when one component reads it (within 1e-6,
/// relative) at kMinFlatSamples consecutive samples or more; a smooth peak reaches its top at
/// one sample, a clipped one stays there. No range, no sample marked.
Saturation find_saturation(const GyroRecording& recording);

/// Consecutive samples flat at the largest |ω_i| that make it a range rather than a peak.
inline constexpr int kMinFlatSamples = 3;

}  // namespace bookspin::fit
