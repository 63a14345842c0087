#include "fit/mixed_units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "fit/median.hpp"
#include "fit/pool.hpp"
#include "fit/toss_flags.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::fit {
namespace {

/// A share of |ω| under which the flights with the candidate axes converted fit a free rigid body
/// as a clean toss does (the flags' "no fit" bound, docs/phone-lab.md, "Flags").
constexpr double kConvertedFitsClean = 0.05;

constexpr double kPi = 3.14159265358979323846;

std::string fixed_share(double share) {
  char text[40];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
  return text;
}

}  // namespace

double residual_share(const GyroRecording& recording, const FitResult& fit) {
  std::vector<double> shares;
  for (const TossFit& toss : fit.tosses) {
    const Eigen::Vector3d bias = part_at(fit.parts, toss.flight.t_start).bias_in_flight();
    double omega2 = 0.0;
    for (int i = toss.flight.first; i <= toss.flight.last; ++i)
      omega2 += (recording.omega[i] - bias).squaredNorm();
    const int n = toss.flight.last - toss.flight.first + 1;
    if (omega2 > 0.0) shares.push_back(toss.residual_rms / std::sqrt(omega2 / n));
  }
  return shares.empty() ? 1.0 : median_of(shares);
}

int scattered_axes(const GyroRecording& recording) {
  const std::size_t n = recording.t.size();
  if (n < 20) return 0;
  const double span = recording.t.back() - recording.t.front();
  const std::size_t window = std::max<std::size_t>(10, static_cast<std::size_t>(0.3 * n / span));
  std::vector<std::pair<double, Eigen::Vector3d>> windows;  // median σ, σ per axis
  for (std::size_t start = 0; start + window <= n; start += window / 2) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), square = Eigen::Vector3d::Zero();
    for (std::size_t i = start; i < start + window; ++i) {
      mean += recording.omega[i];
      square += recording.omega[i].cwiseAbs2();
    }
    mean /= static_cast<double>(window);
    const Eigen::Vector3d sigma =
        (square / static_cast<double>(window) - mean.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
    std::vector<double> sorted{sigma[0], sigma[1], sigma[2]};
    std::sort(sorted.begin(), sorted.end());
    if (sorted[0] > 0.0) windows.emplace_back(sorted[1], sigma);
  }
  if (windows.size() < 5) return 0;
  std::sort(windows.begin(), windows.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  const std::size_t quiet = std::max<std::size_t>(3, windows.size() / 5);
  int mask = 0;
  for (int c = 0; c < 3; ++c) {
    std::vector<double> ratios;
    for (std::size_t w = 0; w < quiet; ++w)
      ratios.push_back(windows[w].second[c] / windows[w].second.minCoeff());
    if (median_of(ratios) > kUnitsScatter) mask |= 1 << c;
  }
  return mask == 7 ? 0 : mask;
}

std::string units_cause(const GyroRecording& recording, const FlightSearch& search,
                        const FitSettings& settings, std::optional<double> share,
                        const Refit& refit) {
  if (recording.parts.size() != 1) return {};
  const int mask = scattered_axes(recording);
  if (mask == 0) return {};
  GyroRecording scaled = recording;
  const double to_rad = kPi / 180.0;
  for (int c = 0; c < 3; ++c) {
    if (!(mask & (1 << c))) continue;
    for (Eigen::Vector3d& w : scaled.omega) w[c] *= to_rad;
    for (RecordingPart& part : scaled.parts) {
      part.bias[c] *= to_rad;
      part.rest.mean[c] *= to_rad;
      part.rest.sigma[c] *= to_rad;
      part.rest.standard_error[c] *= to_rad;
    }
  }
  // Flights found: found again in the new units (the torque-free stretches are others); flights
  // by hand: the user's.
  const FlightSearch flights = settings.trim_ends ? find_flights(scaled) : search;
  if (flights.flights.empty()) return {};
  FitSettings as_given = settings;
  as_given.trim_ends = false;
  double fitted = 0.0;
  try {
    fitted = residual_share(scaled, refit(scaled, flights, as_given));
  } catch (const InputError&) {
    return {};
  } catch (const physics::ExactHorizonError&) {
    // Taken as °/s, the flights drove the body's moments so far apart that the motion passes
    // its time horizon (docs/physics.md §8): no fit in those units either.
    return {};
  }
  // Under half the share left as read, or a clean toss's share outright: the share as read is of
  // an |ω| the axis in °/s inflates 57-fold, so a fit as read may leave a small share of it.
  if (share && !(fitted < *share / 2.0 || fitted < kConvertedFitsClean)) return {};
  static const char* const kAxis[3] = {"ω_x", "ω_y", "ω_z"};
  std::string degrees, radians;
  int count = 0;
  for (int c = 0; c < 3; ++c) {
    std::string& list = mask & (1 << c) ? degrees : radians;
    list += std::string(list.empty() ? "" : " and ") + kAxis[c];
    count += mask & (1 << c) ? 1 : 0;
  }
  char line[500];
  std::snprintf(line, sizeof line,
                "%s: %s %s in °/s while %s %s in rad/s (mixed units?): %s %s about 57 times "
                "the other%s where the phone turns least, and taken as °/s the flights fit a "
                "free rigid body to %.1f %% of |ω|%s",
                recording.source.c_str(), degrees.c_str(),
                count == 1 ? "looks like it is" : "look like they are", radians.c_str(),
                count == 1 ? "are" : "is", count == 1 ? "it" : "they",
                count == 1 ? "scatters" : "scatter", count == 1 ? "s" : "", 100.0 * fitted,
                share ? (" (as read: " + fixed_share(*share) + ")").c_str() : "");
  return line;
}

}  // namespace bookspin::fit
