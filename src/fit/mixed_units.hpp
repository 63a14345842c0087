#pragma once
// Mixed units (docs/phone-lab.md, "Flags", mixed units): a recording whose one or two axes read
// °/s beside the others' rad/s, told by their scatter where the phone turns least and by how well
// the flights fit once those axes are taken as °/s; and the fit's residual as a share of |ω|,
// which judges it. Reads the recording (recording.hpp) and a fit of it (toss_fit.hpp).
#include <functional>
#include <optional>
#include <string>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"

namespace bookspin::fit {

/// The fit's residual as a share of |ω|: each toss's rms residual over its rms |ω|, the median
/// over the tosses (a bounce or a knocked flight does not decide it); 1 where no toss turns.
double residual_share(const GyroRecording& recording, const FitResult& fit);

/// How many times the quietest axis's scatter marks an axis as read in °/s (scattered_axes).
inline constexpr double kUnitsScatter = 15.0;

/// The axes whose scatter, where the phone turns least, is many times the quietest axis's: each
/// 0.3 s window's three standard deviations, the fifth of the windows with the smallest median
/// one, and in them each axis's over the smallest one (their median over those windows). A
/// gyroscope's axes scatter alike (within a few times) at rest or in the hand; an axis in °/s
/// scatters 57 times more. Bit c set: axis c over kUnitsScatter; 0 where all three are, or
/// where the recording is too short to tell (under 20 samples, under 5 windows).
int scattered_axes(const GyroRecording& recording);

/// A fit of `recording`'s `search` flights with `settings`, as fit_recording makes it.
using Refit = std::function<FitResult(const GyroRecording& recording, const FlightSearch& search,
                                      const FitSettings& settings)>;

/// Mixed units (docs/phone-lab.md, "Flags", mixed units): where one or two axes scatter many
/// times the others where the phone turns least (scattered_axes), the flights fitted again with
/// those axes taken from °/s to rad/s; where the fit as read failed (`as_read` null) and that
/// fits, or where it leaves under half the fit `as_read`'s residual in rad/s as read
/// (residual_rms) and under 5 % of |ω| (a clean toss's share), the line naming those axes and the
/// file; else empty. One recording only (a pooled set's parts may differ in units: each is
/// checked alone). `refit`: the fit of the flights as given (no ends' term), throwing
/// InputError where it fails.
std::string units_cause(const GyroRecording& recording, const FlightSearch& search,
                        const FitSettings& settings, const FitResult* as_read, const Refit& refit);

/// The fit's residual in rad/s as its samples were read: the median over the tosses of each
/// one's rms residual (TossFit::residual_rms); 0 without a toss.
double residual_rms(const FitResult& fit);

}  // namespace bookspin::fit
