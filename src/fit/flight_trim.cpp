#include "fit/flight_trim.hpp"

#include <algorithm>
#include <vector>

#include "fit/median.hpp"
#include "fit/toss_flags.hpp"

namespace bookspin::fit {
std::optional<FlightSearch> trimmed_flights(const GyroRecording& recording, const FitResult& fit,
                                            const FlightSearch& found,
                                            const FinderSettings& settings) {
  FlightSearch search = fit.search;
  const Eigen::Matrix3d inertia =
      fit.body.axes * fit.body.ratios.asDiagonal() * fit.body.axes.transpose();
  bool moved = false;
  const std::size_t count =
      std::min({fit.tosses.size(), search.flights.size(), found.flights.size()});
  for (std::size_t k = 0; k < count; ++k) {
    std::vector<double> t;
    std::vector<Eigen::Vector3d> omega;
    measured_omega(recording, fit, static_cast<int>(k), t, omega);
    const int n = static_cast<int>(t.size());
    if (n < 3) continue;
    std::vector<double> residual(t.size());
    for (int i = 0; i < n; ++i)
      residual[i] = (omega[i] - fitted_omega(fit, static_cast<int>(k), t[i])).norm();
    const double threshold = kTrimFactor * median_of(residual);
    // The torque the samples need (toss_flags.hpp), each sample the larger of its two steps'.
    const std::vector<double> step = step_torque(t, omega, inertia);
    const double torque_threshold = kTrimFactor * median_of(step);
    const auto thrown_or_caught = [&](int i) {
      const double torque = std::max(i > 0 ? step[i - 1] : 0.0, i + 1 < n ? step[i] : 0.0);
      return residual[i] > threshold && torque > torque_threshold;
    };
    // Each end moves in while its sample is the throw's or the catch's and the next one in is
    // still within kMaxTrim of the found flight's end.
    const Flight& limit = found.flights[k];
    int first = 0, last = n - 1;
    while (first < last && thrown_or_caught(first) && t[first + 1] - limit.t_start <= kMaxTrim)
      ++first;
    while (last > first && thrown_or_caught(last) && limit.t_end - t[last - 1] <= kMaxTrim) --last;
    if (first == 0 && last == n - 1) continue;
    if (t[last] - t[first] < settings.min_flight || last - first + 1 < 10) continue;
    Flight& flight = search.flights[k];
    flight.first += first;
    flight.last = flight.first + (last - first);
    flight.t_start = recording.t[flight.first];
    flight.t_end = recording.t[flight.last];
    moved = true;
  }
  if (!moved) return std::nullopt;
  return search;
}

FitResult trim_to_free_flight(const GyroRecording& recording, FitResult fit,
                              const std::function<FitResult(const FlightSearch&)>& refit,
                              const FinderSettings& settings) {
  const FlightSearch found = fit.search;
  for (int pass = 0; pass < kMaxTrimPasses; ++pass) {
    const std::optional<FlightSearch> trimmed = trimmed_flights(recording, fit, found, settings);
    if (!trimmed) break;
    fit = refit(*trimmed);
  }
  return fit;
}

}  // namespace bookspin::fit
