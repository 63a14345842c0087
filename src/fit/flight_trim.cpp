#include "fit/flight_trim.hpp"

#include <algorithm>
#include <vector>

namespace bookspin::fit {

std::optional<FlightSearch> trimmed_flights(const GyroRecording& recording, const FitResult& fit,
                                            const FinderSettings& settings) {
  FlightSearch search = fit.search;
  bool moved = false;
  for (std::size_t k = 0; k < fit.tosses.size() && k < search.flights.size(); ++k) {
    std::vector<double> t;
    std::vector<Eigen::Vector3d> omega;
    measured_omega(recording, fit, static_cast<int>(k), t, omega);
    const int n = static_cast<int>(t.size());
    if (n < 3) continue;
    std::vector<double> residual(t.size());
    for (int i = 0; i < n; ++i)
      residual[i] = (omega[i] - fitted_omega(fit, static_cast<int>(k), t[i])).norm();
    std::vector<double> sorted = residual;
    std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
    const double threshold = kTrimFactor * sorted[n / 2];
    int first = 0, last = n - 1;
    while (first < last && residual[first] > threshold && t[first] - t[0] < kMaxTrim) ++first;
    while (last > first && residual[last] > threshold && t[n - 1] - t[last] < kMaxTrim) --last;
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

}  // namespace bookspin::fit
