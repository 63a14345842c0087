#pragma once
// A gyroscope's saturation (docs/phone-lab.md, "Saturation"): a phone's gyroscope stops at its
// range (±2000 °/s, 34.9 rad/s, on most phones), and a fast throw reads flat there for several
// samples. Those samples are the range, not the motion: the fit leaves them out.
#include <optional>
#include <string>
#include <vector>

#include "fit/recording.hpp"

namespace bookspin::fit {

/// Where a recording's gyroscope saturated, found from the samples alone.
struct Saturation {
  /// rad/s: the range the gyroscope stopped at (stated, a standard full scale, or the largest
  /// |ω_i| of the recording), or nullopt when nothing clips there.
  std::optional<double> range;
  /// One per sample of the recording: true where some component reads the range.
  std::vector<bool> at_range;
  /// One per recording pooled (GyroRecording::parts, in order): where its gyroscope saturated.
  struct Part {
    std::optional<double> range;  ///< rad/s, or nullopt where it did not
    bool stated = false;          ///< the range its export states, not found from its samples
    int samples = 0;              ///< its samples at the range
  };
  std::vector<Part> parts;
};

/// The samples of `recording` at its gyroscope's range. Where the export states the range
/// (GyroRecording::gyroscope_range) and no sample exceeds it, every sample with some |ω_i|
/// within kStatedRangeTolerance of it is marked, however short the run. Otherwise (or when no
/// sample reads the stated range) the range is found from the samples: a standard full scale
/// (kFullScales) whose band (kFullScaleBelow, kFullScaleAbove) holds the largest |ω_i|, where a
/// component clips there (fit/saturation.cpp, clipped_full_scale: a spike cut flat or a drifting
/// plateau); else the largest |ω_i| of the whole recording, any component and sign, when one
/// component reads it (within 1e-6, relative) at kMinFlatSamples consecutive samples or more; a
/// smooth peak reaches its top at one sample, a clipped one stays there. No range, no sample
/// marked. Searched recording by recording (its `parts`: pool_recordings), each on its samples
/// as measured with its own stated range; `range` is then the largest found. A range found from
/// one recording's samples (none stated) is refuted, and its samples unmarked, where another
/// recording pooled with it that states no range either reads past its band (above
/// 1 + kFullScaleAbove times it): recordings pooled as one body's with no stated range are taken
/// as one phone's, and a gyroscope that read 33.7 rad/s did not stop at 17.45 (a peak of one
/// sample at a full scale's band is otherwise a clip). Throws std::logic_error for a recording
/// not pooled.
Saturation find_saturation(const GyroRecording& recording);

/// The fit's note on `saturation` (docs/phone-lab.md, "Saturation"): each recording of `parts`
/// that saturated named, with its samples at the range, the range (rad/s and °/s) and how it was
/// known (its export states it, a standard full scale, or its top read flat), then how many of
/// them lie in the tosses (`in_tosses`, one count per part), left out of the fit; recordings
/// alike in range and how it was known named together: "the gyroscope saturated at ±34.9066
/// rad/s (2000 °/s, a standard full scale) in 12-10-56 (1 sample) and 12-13-01 (2 samples); 0 of
/// them in the tosses, left out of the fit". Empty where nothing saturated.
std::string saturation_note(const Saturation& saturation, const std::vector<RecordingPart>& parts,
                            const std::vector<int>& in_tosses);

/// rad/s: the standard full scales of MEMS gyroscopes, ±250, 500, 1000, 2000 and 4000 °/s.
inline constexpr double kFullScales[] = {4.363323129985824, 8.726646259971648, 17.453292519943297,
                                         34.906585039886594, 69.81317007977319};

/// Relative: how far below and above a standard full scale a clipped axis may read (its
/// calibration: the iPhone 13 Pro of the development recordings reads 34.63–35.60 rad/s clipped
/// at ±2000 °/s, −0.8 % to +2.0 %). The band is narrow below: a smooth peak or an impact's
/// spike that happens to top out near a full scale is not taken for a clip.
inline constexpr double kFullScaleBelow = 0.01;
inline constexpr double kFullScaleAbove = 0.03;

/// Relative to the full scale: a spike cut flat has its neighbours below this (a smooth peak
/// of a component turning at the sampling rate's tenth still reads 0.94 of its top beside it).
inline constexpr double kSpikeEdge = 0.9;

/// A plateau's own change over its run, at most this share of the other components' change.
inline constexpr double kPlateauShare = 0.05;

/// Consecutive samples flat at the largest |ω_i| that make it a range rather than a peak.
inline constexpr int kMinFlatSamples = 3;

/// Relative: how near the stated range a reading counts as at it (0.035 rad/s at 34.9 rad/s, a
/// few of a phone gyroscope's least steps, e.g. 0.0011 rad/s on Android's 16-bit ±2000 °/s).
inline constexpr double kStatedRangeTolerance = 1e-3;

}  // namespace bookspin::fit
