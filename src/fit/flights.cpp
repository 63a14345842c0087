#include "fit/flights.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "fit/flight_bridge.hpp"
#include "fit/median.hpp"
#include "fit/pool.hpp"
#include "fit/rigid_bounds.hpp"
#include "fit/saturation.hpp"

namespace bookspin::fit {
namespace {

constexpr double kHalfWindowTime = 0.005;  // s each side: more samples where they are denser
constexpr double kGapFactor = 5.0;         // a step this many typical steps long is a gap
// s: and longer than this. An Android phone delivering a nominal 415 Hz may leave 21 ms
// between two samples inside a flight; the exact motion bridges that (a body at 35 rad/s turns
// under 1 rad in 25 ms) and so does the derivative, taken with each sample's own dt.
constexpr double kMinGap = 0.025;
constexpr int kMinFitSamples = 10;  // a flight shorter than this cannot be fitted
constexpr int kIsolated = 2;        // samples: a run this short over the torque threshold is noise
// A flight holding a bridged stretch (flight_bridge.hpp) is kept only as a rigid body's
// (rigid_bridge): its Euler inertia no needle (rigid_bounds.hpp's, which says why the triangle
// inequality is not asked here), and the torque left on each of its pieces between bridges within
// kBridgeNoise times the quietest piece's. Measured on the re-stamped lone flights of
// tests/fit/lone_flight_test.cpp: the loudest piece 3.6 times the quietest at most.
constexpr double kBridgeNoise = 6.0;

std::string seconds(double value) {
  std::ostringstream text;
  text.precision(3);
  text << std::fixed << value;
  return text.str();
}

/// Index ranges [begin, end) of samples with no pause and no gap inside.
std::vector<std::pair<int, int>> segments(const GyroRecording& recording) {
  const std::vector<double>& t = recording.t;
  const int n = static_cast<int>(t.size());
  std::vector<double> steps;
  for (int i = 1; i < n; ++i) steps.push_back(t[i] - t[i - 1]);
  // The typical step: the 90th percentile, not the median, so that an app that delivers the
  // gyroscope in bursts (steps of 2 ms, then 12 ms) has no gap at every burst.
  const std::size_t p90 = steps.size() * 9 / 10;
  std::nth_element(steps.begin(), steps.begin() + p90, steps.end());
  const double gap = std::max(kGapFactor * steps[p90], kMinGap);
  std::vector<std::pair<int, int>> result;
  int begin = 0;
  for (int i = 1; i < n; ++i) {
    bool cut = t[i] - t[i - 1] > gap;
    for (double pause : recording.pauses)
      if (t[i - 1] < pause && t[i] >= pause) cut = true;
    if (cut) {
      result.emplace_back(begin, i);
      begin = i;
    }
  }
  result.emplace_back(begin, n);
  return result;
}

/// Runs [first, last] (inclusive) of consecutive `true` within each segment.
std::vector<std::pair<int, int>> runs(const std::vector<char>& mask,
                                      const std::vector<std::pair<int, int>>& segs) {
  std::vector<std::pair<int, int>> result;
  for (const auto& [begin, end] : segs) {
    int start = -1;
    for (int i = begin; i <= end; ++i) {
      const bool on = i < end && mask[i];
      if (on && start < 0) start = i;
      if (!on && start >= 0) {
        result.emplace_back(start, i - 1);
        start = -1;
      }
    }
  }
  return result;
}

/// The samples with each recording's own bias removed (RecordingPart::bias).
std::vector<Eigen::Vector3d> without_bias(const GyroRecording& recording) {
  check_pooled(recording);
  std::vector<Eigen::Vector3d> omega(recording.omega.size());
  for (const RecordingPart& part : recording.parts)
    for (int i = part.first; i <= part.last; ++i) omega[i] = recording.omega[i] - part.bias;
  return omega;
}

/// |I ω̇ + ω × I ω| / |ω|² at sample i: the torque Euler's equations leave (I scaled to a
/// largest moment of 1), which free flight keeps at the noise's level.
double torque_residual(const Eigen::Matrix3d& I, const Eigen::Vector3d& w,
                       const Eigen::Vector3d& w_dot) {
  return (I * w_dot + w.cross(I * w)).norm() / std::max(w.squaredNorm(), 1e-12);
}

/// Whether flight [first, last], holding samples bridged by bridge_conserved (`bridged`), is a
/// rigid body's free flight (docs/phone-lab.md, "Stamps off their samples"): the inertia that
/// Euler's equations fit on its samples (clipped and bridged ones left out) no needle (its
/// smallest moment over rigid_bounds.hpp's kNeedle of the largest), and the torque it leaves on
/// each piece between its bridges (the median of torque_residual) within kBridgeNoise times the
/// quietest piece's: a hand's swing that keeps |I ω| and ω·I ω joined on by a bridge makes the one
/// or the other fail.
bool rigid_bridge(const std::vector<Eigen::Vector3d>& omega,
                  const std::vector<Eigen::Vector3d>& rate, const std::vector<char>& clipped,
                  const std::vector<char>& bridged, int first, int last) {
  std::vector<int> indices;
  for (int i = first; i <= last; ++i)
    if (!clipped[i] && !bridged[i]) indices.push_back(i);
  if (static_cast<int>(indices.size()) < kMinFitSamples) return false;
  const Eigen::Matrix3d I = euler_inertia(omega, rate, indices);
  const Eigen::Vector3d m = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  std::vector<double> medians;
  for (int i = first; i <= last;) {
    std::vector<double> piece;
    for (; i <= last && !bridged[i]; ++i)
      if (!clipped[i]) piece.push_back(torque_residual(I, omega[i], rate[i]));
    if (static_cast<int>(piece.size()) >= kBridgeSamples)
      medians.push_back(median_of(std::move(piece)));
    while (i <= last && bridged[i]) ++i;
  }
  const double quietest = medians.empty() ? 0.0 : *std::min_element(medians.begin(), medians.end());
  const double loudest = medians.empty() ? 0.0 : *std::max_element(medians.begin(), medians.end());
  if (!(m[2] > 0.0) || needle(m)) return false;
  return loudest <= kBridgeNoise * quietest;
}

}  // namespace

std::vector<Eigen::Vector3d> omega_rate(const std::vector<double>& t,
                                        const std::vector<Eigen::Vector3d>& omega) {
  const int n = static_cast<int>(t.size());
  std::vector<Eigen::Vector3d> rate(n, Eigen::Vector3d::Zero());
  for (int i = 0; i < n; ++i) {
    // ±2 samples, or every sample within ±5 ms where there are more (above 400 Hz): at
    // 10 kHz five samples span 0.4 ms, over which the noise, not the motion, makes the slope.
    int lo = std::max(0, i - kHalfWindow), hi = std::min(n - 1, i + kHalfWindow);
    while (lo > 0 && t[i] - t[lo - 1] <= kHalfWindowTime) --lo;
    while (hi < n - 1 && t[hi + 1] - t[i] <= kHalfWindowTime) ++hi;
    const int m = hi - lo + 1;
    if (m < 2) continue;
    // Least squares ω ≈ a + b τ + c τ² (τ = t − t_i); a line where there are only 2 points.
    const int terms = m >= 3 ? 3 : 2;
    Eigen::MatrixXd A(m, terms);
    Eigen::MatrixXd y(m, 3);
    for (int k = 0; k < m; ++k) {
      const double tau = t[lo + k] - t[i];
      A(k, 0) = 1.0;
      A(k, 1) = tau;
      if (terms == 3) A(k, 2) = tau * tau;
      y.row(k) = omega[lo + k].transpose();
    }
    const Eigen::MatrixXd coeffs = A.colPivHouseholderQr().solve(y);
    rate[i] = coeffs.row(1).transpose();
  }
  return rate;
}

Eigen::Matrix3d euler_inertia(const std::vector<Eigen::Vector3d>& omega,
                              const std::vector<Eigen::Vector3d>& omega_dot,
                              const std::vector<int>& indices) {
  // The six symmetric basis matrices: xx, yy, zz, xy, xz, yz.
  std::array<Eigen::Matrix3d, 6> basis;
  for (auto& b : basis) b.setZero();
  basis[0](0, 0) = basis[1](1, 1) = basis[2](2, 2) = 1.0;
  basis[3](0, 1) = basis[3](1, 0) = 1.0;
  basis[4](0, 2) = basis[4](2, 0) = 1.0;
  basis[5](1, 2) = basis[5](2, 1) = 1.0;
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i : indices) {
    const Eigen::Vector3d& w = omega[i];
    const double scale = 1.0 / std::max(w.squaredNorm(), 1e-12);
    Eigen::Matrix<double, 3, 6> rows;
    for (int k = 0; k < 6; ++k)
      rows.col(k) = scale * (basis[k] * omega_dot[i] + w.cross(basis[k] * w));
    normal += rows.transpose() * rows;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> solver(normal);
  const Eigen::Matrix<double, 6, 1> v = solver.eigenvectors().col(0);
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 6; ++k) I += v[k] * basis[k];
  if (I.trace() < 0) I = -I;
  const double largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues().maxCoeff();
  return largest > 0 ? Eigen::Matrix3d(I / largest) : I;
}

Rest measure_rest(const GyroRecording& recording, const FinderSettings& settings) {
  RestSettings still;
  still.max_omega = settings.rest_omega;
  return find_rest(recording.t, recording.omega, segments(recording), still);
}

namespace {

/// Part `p` of pooled `recording` alone, a pool of one on the pooled clock.
GyroRecording part_alone(const GyroRecording& recording, std::size_t p) {
  const RecordingPart& part = recording.parts[p];
  GyroRecording alone;
  alone.name = part.name;
  alone.source = part.source;
  alone.t.assign(recording.t.begin() + part.first, recording.t.begin() + part.last + 1);
  alone.omega.assign(recording.omega.begin() + part.first, recording.omega.begin() + part.last + 1);
  for (double pause : recording.pauses)
    if (pause > alone.t.front() && pause <= alone.t.back()) alone.pauses.push_back(pause);
  alone.gyroscope_range = part.gyroscope_range;
  alone.parts = {part};
  alone.parts[0].first = 0;
  alone.parts[0].last = part.last - part.first;
  return alone;
}

}  // namespace

FlightSearch find_flights(const GyroRecording& recording, const FinderSettings& settings) {
  // Several recordings: each one's flights found as if it were alone (its own inertia cuts
  // them), so that pooling it changes none of its tosses.
  if (recording.parts.size() >= 2) {
    FlightSearch search;
    for (std::size_t p = 0; p < recording.parts.size(); ++p) {
      FlightSearch own = find_flights(part_alone(recording, p), settings);
      for (Flight& f : own.flights) {
        f.first += recording.parts[p].first;
        f.last += recording.parts[p].first;
        search.flights.push_back(f);
      }
      search.dropped.insert(search.dropped.end(), own.dropped.begin(), own.dropped.end());
    }
    return search;
  }
  FlightSearch search;
  const std::vector<Eigen::Vector3d> omega = without_bias(recording);
  const std::vector<std::pair<int, int>> segs = segments(recording);
  const int n = static_cast<int>(recording.t.size());
  const std::vector<double>& t = recording.t;
  // The rate within each segment only (a derivative never reaches across a pause).
  std::vector<Eigen::Vector3d> rate(n);
  for (const auto& [begin, end] : segs) {
    const std::vector<double> ts(t.begin() + begin, t.begin() + end);
    const std::vector<Eigen::Vector3d> ws(omega.begin() + begin, omega.begin() + end);
    const std::vector<Eigen::Vector3d> rs = omega_rate(ts, ws);
    std::copy(rs.begin(), rs.end(), rate.begin() + begin);
  }
  // Samples where the gyroscope read its range, and their neighbours (whose rates reach them):
  // the range, not the motion, so no evidence of torque either way (fit/saturation.hpp). The
  // finder lets a flight run through them; the fit leaves them out.
  const Saturation saturation = find_saturation(recording);
  std::vector<char> clipped(n, 0);
  for (int i = 0; i < n; ++i)
    if (saturation.at_range[i])
      for (int k = std::max(0, i - 2); k <= std::min(n - 1, i + 2); ++k) clipped[k] = 1;
  // Steps 1–3, bridging (1b and each pass's) or not: the free stretches, each sample bridged
  // marked in `bridged`.
  const auto free_stretches = [&](bool bridge, std::vector<char>& bridged) {
    // 1. Candidates: fast enough, and |ω̇| within what Euler's equations allow a body whose
    // moments obey the triangle inequality, |ω̇| ≤ |ω|²/√3 (docs/physics.md §8), plus noise.
    std::vector<char> candidate(n);
    for (int i = 0; i < n; ++i) {
      const double w2 = omega[i].squaredNorm();
      candidate[i] = std::sqrt(w2) >= settings.flight_omega &&
                     (clipped[i] || rate[i].norm() <= 0.6 * w2 + 3.0);
    }
    // 1b. A flight whose stamps lie off its samples (a phone stamping when it delivers) has its
    // derivative off by as much, here and there over the bound: its candidates are bridged where
    // the body keeps |I ω| and ω·I ω across (bridge_conserved), I fitted on the runs long enough
    // to fit a flight. A catch between two runs changes both at once and is never bridged.
    std::fill(bridged.begin(), bridged.end(), 0);
    std::vector<char> fast_and_unclipped(n);
    for (int k = 0; k < n; ++k)
      fast_and_unclipped[k] = !clipped[k] && omega[k].norm() >= settings.flight_omega;
    {
      std::vector<int> indices;
      for (const auto& [first, last] : runs(candidate, segs))
        if (last - first + 1 >= kMinFitSamples)
          for (int i = first; i <= last; ++i)
            if (!clipped[i]) indices.push_back(i);
      if (bridge && !indices.empty()) {
        const Eigen::Matrix3d I0 = euler_inertia(omega, rate, indices);
        for (const auto& [begin, end] : segs)
          bridge_conserved(candidate, 0, begin, end - 1, bridged, I0, omega, t, fast_and_unclipped);
      }
    }
    std::vector<std::pair<int, int>> kept;
    for (const auto& [first, last] : runs(candidate, segs)) {
      if (t[last] - t[first] < settings.min_flight) continue;
      kept.emplace_back(first, last);
    }
    // 2. Torque-free: the inertia that Euler's equations fit best on the candidates, then each
    // candidate cut to its longest stretch whose torque residual stays at the noise's level;
    // three times, each cutting the candidates anew with the inertia of the stretches the
    // previous pass kept (so that a first inertia spoilt by a wind-up cuts nothing for good).
    const std::vector<std::pair<int, int>> candidates = kept;
    Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    double threshold = 0.0;
    for (int pass = 0; pass < 3 && !kept.empty(); ++pass) {
      std::vector<int> indices;
      for (const auto& [first, last] : kept)
        for (int i = first; i <= last; ++i)
          if (!clipped[i] && !bridged[i]) indices.push_back(i);
      if (indices.empty()) break;
      I = euler_inertia(omega, rate, indices);
      std::vector<double> residuals;
      for (int i : indices) residuals.push_back(torque_residual(I, omega[i], rate[i]));
      threshold = std::max(6.0 * median_of(std::move(residuals)), 0.01);
      std::vector<std::pair<int, int>> next;
      for (const auto& [first, last] : candidates) {
        // Each sample torque-free or not; a run of clipped samples counts as torque-free only
        // between two torque-free samples (a flight runs through its gyroscope's range, never
        // into a throw or a catch that also reads it).
        std::vector<char> ok(last - first + 1, 0);
        for (int i = first; i <= last; ++i)
          ok[i - first] = !clipped[i] && torque_residual(I, omega[i], rate[i]) <= threshold;
        for (int i = first; i <= last;) {
          if (!clipped[i]) {
            ++i;
            continue;
          }
          int end = i;
          while (end + 1 <= last && clipped[end + 1]) ++end;
          const bool bridged = i > first && end < last && ok[i - 1 - first] && ok[end + 1 - first];
          for (int k = i; k <= end; ++k) ok[k - first] = bridged;
          i = end + 1;
        }
        // One or two samples over the threshold between torque-free ones are the derivative's
        // noise (larger where the steps are uneven), not a throw or a catch, which run longer.
        for (int i = first + 1; i < last; ++i) {
          if (ok[i - first]) continue;
          int end = i;
          while (end < last && !ok[end - first] && end - i < kIsolated) ++end;
          if (ok[i - 1 - first] && end <= last && ok[end - first] && end - i <= kIsolated &&
              !clipped[i])
            for (int k = i; k < end; ++k) ok[k - first] = 1;
          i = end;
        }
        // Longer stretches whose derivative the stamps spoil, as in step 1b, by this pass's I.
        if (bridge)
          bridge_conserved(ok, first, first, last, bridged, I, omega, t, fast_and_unclipped);
        int best_first = first, best_last = first - 1, start = -1;
        for (int i = first; i <= last + 1; ++i) {
          const bool good = i <= last && ok[i - first];
          if (good && start < 0) start = i;
          if (!good && start >= 0) {
            if (i - 1 - start > best_last - best_first) best_first = start, best_last = i - 1;
            start = -1;
          }
        }
        if (best_last >= best_first) next.emplace_back(best_first, best_last);
      }
      kept = next;
    }
    // 3. Each torque-free stretch grown over its neighbours while they stay torque-free by the
    // inertia and threshold of the last pass: the bound of step 1 is a body's in exact
    // arithmetic, which a flat body's flip nears (|ω̇|/|ω|² up to 1/√3) and a real gyroscope's
    // gain and cross-axis errors or a derivative over uneven steps exceed for a while; Euler's
    // equations with the fitted inertia, not that bound, say where the flight ends.
    if (threshold > 0.0)
      for (std::size_t k = 0; k < kept.size(); ++k) {
        auto& [first, last] = kept[k];
        const int low = k > 0 ? kept[k - 1].second + 1 : 0;
        const int high = k + 1 < kept.size() ? kept[k + 1].first - 1 : n - 1;
        int begin = 0, end = n;
        for (const auto& [b, e] : segs)
          if (first >= b && first < e) begin = b, end = e;
        const auto free_at = [&](int i) {
          return !clipped[i] && omega[i].norm() >= settings.flight_omega &&
                 torque_residual(I, omega[i], rate[i]) <= threshold;
        };
        while (first - 1 >= std::max(low, begin) && free_at(first - 1)) --first;
        while (last + 1 <= std::min(high, end - 1) && free_at(last + 1)) ++last;
      }
    // Two stretches grown into each other within a segment are one flight (the bound of step 1
    // had cut it); a pause or a gap still parts them.
    const auto segment_of = [&](int i) {
      for (std::size_t s = 0; s < segs.size(); ++s)
        if (i >= segs[s].first && i < segs[s].second) return s;
      return segs.size();
    };
    std::vector<std::pair<int, int>> merged;
    for (const auto& stretch : kept)
      if (!merged.empty() && merged.back().second + 1 >= stretch.first &&
          segment_of(merged.back().second) == segment_of(stretch.first))
        merged.back().second = stretch.second;
      else
        merged.push_back(stretch);
    kept = merged;
    return kept;
  };
  std::vector<char> bridged(n, 0);
  std::vector<std::pair<int, int>> kept = free_stretches(true, bridged);
  // A stretch bridged into a flight is kept only where the flight it makes is a rigid body's
  // free flight (rigid_bridge): else its flights are those found without bridging.
  std::optional<std::vector<std::pair<int, int>>> unbridged;
  std::vector<std::pair<int, int>> checked;
  for (const auto& [first, last] : kept) {
    if (std::find(bridged.begin() + first, bridged.begin() + last + 1, 1) ==
            bridged.begin() + last + 1 ||
        rigid_bridge(omega, rate, clipped, bridged, first, last)) {
      checked.emplace_back(first, last);
      continue;
    }
    if (!unbridged) {
      std::vector<char> none(n, 0);
      unbridged = free_stretches(false, none);
    }
    for (const auto& [a, b] : *unbridged)
      if (a >= first && b <= last) checked.emplace_back(a, b);
  }
  kept = checked;
  // 4. What was kept, and why the other moving stretches were dropped.
  std::vector<char> moving(n);
  for (int i = 0; i < n; ++i) moving[i] = omega[i].norm() >= settings.rest_omega;
  for (const auto& [first, last] : kept) {
    if (t[last] - t[first] < settings.min_flight || last - first + 1 < kMinFitSamples) continue;
    search.flights.push_back({first, last, t[first], t[last]});
  }
  for (const auto& [first, last] : runs(moving, segs)) {
    bool has_flight = false;
    for (const Flight& f : search.flights)
      if (f.first >= first && f.last <= last) has_flight = true;
    if (has_flight) continue;
    double peak = 0.0;
    for (int i = first; i <= last; ++i) peak = std::max(peak, omega[i].norm());
    std::string reason;
    if (peak < settings.flight_omega)
      reason = kTooSlowReason + seconds(settings.flight_omega) + " rad/s";
    else
      reason = "no torque-free stretch of " + seconds(settings.min_flight) +
               " s or longer (held, or a flight too short to fit)";
    search.dropped.push_back({t[first], t[last], reason});
  }
  return search;
}

FlightSearch hand_flights(const GyroRecording& recording,
                          const std::vector<std::pair<double, double>>& ranges,
                          const std::string& option) {
  check_pooled(recording);
  FlightSearch search;
  const std::vector<std::pair<int, int>> segs = segments(recording);
  const std::vector<double>& t = recording.t;
  // In time order (the tosses are numbered so), none overlapping another or given twice.
  check_toss_ranges(ranges, option);  // every door's ranges judged alike (fit_options.hpp)
  std::vector<std::pair<double, double>> sorted = ranges;
  std::stable_sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    const auto& [a, b] = sorted[k];
    const std::string range = toss_time_text(a) + ":" + toss_time_text(b);
    if (!(b > a)) throw InputError(option + " " + range + ": the end is not after the start");
    if (k == 0) continue;
    const auto& [a0, b0] = sorted[k - 1];
    if (a0 == a && b0 == b) throw InputError(option + " " + range + ": given twice");
    if (a <= b0)
      throw InputError(option + " " + range + ": overlaps " + toss_time_text(a0) + ":" +
                       toss_time_text(b0) + " (a sample belongs to one toss at most)");
  }
  for (const auto& [a, b] : sorted) {
    const std::string range = toss_time_text(a) + ":" + toss_time_text(b);
    const int first = static_cast<int>(std::lower_bound(t.begin(), t.end(), a) - t.begin());
    const int last = static_cast<int>(std::upper_bound(t.begin(), t.end(), b) - t.begin()) - 1;
    if (last - first + 1 < kMinFitSamples)
      throw InputError(option + " " + range + ": " + std::to_string(std::max(0, last - first + 1)) +
                       " samples of " + recording.source + " in it; a toss needs at least " +
                       std::to_string(kMinFitSamples));
    for (const auto& [begin, end] : segs)
      if (first < begin && last >= begin)
        throw InputError(option + " " + range + ": spans a pause or a gap of " + recording.source +
                         " (at " + seconds(t[begin]) + " s)");
    search.flights.push_back({first, last, t[first], t[last]});
  }
  return search;
}

[[noreturn]] void throw_no_flight(const GyroRecording& recording, const FlightSearch& search,
                                  const std::string& remedy) {
  std::string why;
  for (const DroppedStretch& d : search.dropped)
    why += (why.empty() ? " (" : "; ") + std::to_string(d.t_start) + "–" + std::to_string(d.t_end) +
           " s: " + d.reason;
  if (!why.empty()) why += ")";
  throw InputError(recording.source + ": no free flight found" + why +
                   (remedy.empty() ? "" : "; " + remedy));
}

}  // namespace bookspin::fit
