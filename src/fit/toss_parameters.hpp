#pragma once
// The fit's unknowns (docs/phone-lab.md, "The fit"): the body's principal axes and two log
// moment ratios shared by every toss, each toss's ω0 and drag rate, each recording's bias
// correction; the samples they are fitted to (one toss's, bias removed); and their start, from
// Euler's equations on the flights (flights.hpp: euler_inertia).
#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <vector>

#include "fit/saturation.hpp"
#include "fit/toss_fit.hpp"
#include "fit/toss_model.hpp"

namespace bookspin::fit {

/// The samples of one toss, bias removed, times from the toss's start.
struct TossData {
  std::vector<double> tau;             ///< s since t_start
  std::vector<Eigen::Vector3d> omega;  ///< rad/s, phone frame
  int samples = 0;                     ///< the flight's samples, those left out included
  int at_range = 0;   ///< the flight's samples that read the gyroscope's range (fit/saturation.hpp)
  int saturated = 0;  ///< of those, the samples left out (all, or none where too few remain)
  /// Whose bias correction the toss shares: its recording's among those pooled (0 for one
  /// recording).
  int group = 0;
};

/// Fewer samples than this left of a flight once its saturated ones are out, and they stay in
/// (flagged): a fit needs something to fit.
constexpr int kMinSamplesLeft = 10;

/// The fit's parameters: the shared body, then each toss's ω0 and drag rate (ω0x, ω0y, ω0z, r).
struct Parameters {
  Eigen::Matrix3d R0 = Eigen::Matrix3d::Identity();
  std::array<double, 3> aa{0, 0, 0};
  std::array<double, 2> log_ratios{0, 0};
  std::vector<std::array<double, 4>> omega0;
  /// rad/s, phone frame: each group's bias correction (TossCost's e; TossData::group).
  std::vector<std::array<double, 3>> e{{0, 0, 0}};
  Eigen::Matrix3d axes() const { return R0 * rotation_from_angle_axis(aa.data()); }
  Eigen::Vector3d moments() const {
    return {std::exp(log_ratios[0]), std::exp(log_ratios[1]), 1.0};
  }
};

/// Sorts the moments ascending with the largest 1, the axes with them (right-handed, the sign
/// convention of BodyEstimate::axes), and moves the rotation into R0 (aa = 0); the motion is the
/// same.
void normalise(Parameters& p);

/// Starting values: the inertia that Euler's equations fit best on every flight's samples
/// (flights.hpp: euler_inertia), or the moments given (settings.moments); each ω0 the first
/// sample's, each drag rate 0.
Parameters start(const std::vector<TossData>& data, const FitSettings& settings);

/// Each of `search`'s flights of `recording` (pooled) as the fit takes it: its samples, its
/// recording's bias removed, its times from its start; the samples where the gyroscope read its
/// range (`saturation`) left out (docs/phone-lab.md, "Saturation") unless too few would be
/// left. Each toss's group is its recording (its bias correction is that recording's).
std::vector<TossData> toss_data(const GyroRecording& recording, const FlightSearch& search,
                                const Saturation& saturation);

/// How many of `data`'s tosses are in each of `groups` groups (TossData::group).
std::vector<int> tosses_per_group(const std::vector<TossData>& data, std::size_t groups);

}  // namespace bookspin::fit
