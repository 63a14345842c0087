#include "fit/mixed_units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "fit/median.hpp"
#include "fit/pool.hpp"
#include "fit/toss_flags.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::fit {
namespace {

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

double residual_rms(const FitResult& fit) {
  std::vector<double> rms;
  for (const TossFit& toss : fit.tosses) rms.push_back(toss.residual_rms);
  return rms.empty() ? 0.0 : median_of(rms);
}

std::string units_cause(const GyroRecording& recording, const FlightSearch& search,
                        const FitSettings& settings, const FitResult* as_read, const Refit& refit) {
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
  double fitted = 0.0, fitted_rms = 0.0;
  try {
    const FitResult converted = refit(scaled, flights, as_given);
    fitted = residual_share(scaled, converted);
    fitted_rms = residual_rms(converted);
  } catch (const InputError&) {
    return {};
  } catch (const physics::ExactHorizonError&) {
    // Taken as °/s, the flights drove the body's moments so far apart that the motion passes
    // its time horizon (docs/physics.md §8): no fit in those units either.
    return {};
  }
  // Under half the residual left as read, both in rad/s as the samples were read: a share of |ω|
  // would judge them against an |ω| the axis in °/s inflates 57-fold, and a share under a clean
  // toss's alone is no cause, since an axis in rad/s shrunk 57 times may fit a free body about as
  // well as read (a clean recording thinned to 50 Hz was named so).
  // On the same flights: those found in the new units may be others (a hand's turn dropped),
  // and the fit as read of the flights it kept is judged beside the converted fit of its own.
  std::optional<double> share;
  if (as_read) {
    share = residual_share(recording, *as_read);
    double read_rms = residual_rms(*as_read);
    const auto same = [](const Flight& a, const Flight& b) {
      return a.first == b.first && a.last == b.last;
    };
    if (!std::equal(flights.flights.begin(), flights.flights.end(), as_read->search.flights.begin(),
                    as_read->search.flights.end(), same)) {
      try {
        read_rms = residual_rms(refit(recording, flights, as_given));
      } catch (const InputError&) {
        read_rms = std::numeric_limits<double>::infinity();  // as read, those flights fit no body
      } catch (const physics::ExactHorizonError&) {
        read_rms = std::numeric_limits<double>::infinity();
      }
    }
    if (!(fitted_rms < read_rms / 2.0)) return {};
  }
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
