#include "fit/rest.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bookspin::fit {

Eigen::Vector3d Rest::bound() const {
  if (samples == 0) return Eigen::Vector3d::Zero();
  return 3.0 * standard_error + Eigen::Vector3d::Constant(kBiasDrift + kHandTurn);
}

namespace {

constexpr int kBatches = 6;  ///< the still samples' consecutive blocks of batch_standard_error

/// rad/s per axis: the batch-means standard error of the still samples' mean, the samples of
/// `runs` in time order dealt into kBatches consecutive blocks of equal count: s_B/√B, s_B the
/// blocks' means' standard deviation. A slow wobble (a hand, a settling phone) is correlated far
/// beyond one sample, which ρ from one sample to the next misses (at 10 kHz it counts thousands
/// of independent samples where the wobble gives a few); 0 with fewer than 2 samples a block.
Eigen::Vector3d batch_standard_error(const std::vector<Eigen::Vector3d>& omega,
                                     const std::vector<std::pair<int, int>>& runs,
                                     const Eigen::Vector3d& mean) {
  std::vector<int> index;
  for (const auto& [first, last] : runs)
    for (int i = first; i <= last; ++i) index.push_back(i);
  const int per = static_cast<int>(index.size()) / kBatches;
  if (per < 2) return Eigen::Vector3d::Zero();
  Eigen::Vector3d sum2 = Eigen::Vector3d::Zero();
  for (int b = 0; b < kBatches; ++b) {
    Eigen::Vector3d block = Eigen::Vector3d::Zero();
    for (int j = b * per; j < (b + 1) * per; ++j) block += omega[index[j]];
    sum2 += (block / per - mean).cwiseAbs2();
  }
  return (sum2 / ((kBatches - 1.0) * kBatches)).cwiseSqrt();
}

}  // namespace

Rest find_rest(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& omega,
               const std::vector<std::pair<int, int>>& segments, const RestSettings& settings) {
  const int n = static_cast<int>(t.size());
  // Prefix sums: ω, ω² per axis, and the samples turning at max_omega or faster.
  std::vector<Eigen::Vector3d> sum(n + 1, Eigen::Vector3d::Zero()),
      squares(n + 1, Eigen::Vector3d::Zero());
  std::vector<int> fast(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    sum[i + 1] = sum[i] + omega[i];
    squares[i + 1] = squares[i] + omega[i].cwiseAbs2();
    fast[i + 1] = fast[i] + (omega[i].norm() >= settings.max_omega ? 1 : 0);
  }
  // Each window: samples first … last, the shortest from `first` spanning `window` s, within one
  // segment and every sample slow; its scatter the largest axis's standard deviation.
  struct Window {
    int first, last;
    double scatter;
  };
  std::vector<Window> windows;
  for (const auto& [begin, end] : segments) {
    int last = begin;
    for (int first = begin; first < end; ++first) {
      last = std::max(last, first);
      while (last < end && t[last] - t[first] < settings.window) ++last;
      if (last >= end) break;
      if (fast[last + 1] - fast[first] > 0) continue;
      const double count = last - first + 1;
      const Eigen::Vector3d mean = (sum[last + 1] - sum[first]) / count;
      const Eigen::Vector3d variance =
          ((squares[last + 1] - squares[first]) / count - mean.cwiseAbs2()).cwiseMax(0.0);
      windows.push_back({first, last, std::sqrt(variance.maxCoeff() * count / (count - 1))});
    }
  }
  Rest rest;
  if (windows.empty()) return rest;
  double quietest = std::numeric_limits<double>::infinity();
  for (const Window& w : windows) quietest = std::min(quietest, w.scatter);
  const double limit = std::min(settings.max_scatter,
                                std::max(settings.floor_factor * quietest, settings.min_scatter));
  std::vector<char> still(n, 0);
  for (const Window& w : windows)
    if (w.scatter <= limit) std::fill(still.begin() + w.first, still.begin() + w.last + 1, 1);
  // The still runs (each at least one window long, so at least `window` s).
  std::vector<std::pair<int, int>> runs;
  for (const auto& [begin, end] : segments)
    for (int i = begin; i < end;) {
      if (!still[i]) {
        ++i;
        continue;
      }
      int last = i;
      while (last + 1 < end && still[last + 1]) ++last;
      runs.emplace_back(i, last);
      i = last + 1;
    }
  if (runs.empty()) return rest;
  for (const auto& [first, last] : runs) {
    rest.stretches.emplace_back(t[first], t[last]);
    for (int i = first; i <= last; ++i) rest.mean += omega[i];
    rest.samples += last - first + 1;
  }
  rest.mean /= rest.samples;
  // The scatter, and the correlation from one sample to the next within each run.
  Eigen::Vector3d deviations = Eigen::Vector3d::Zero(), lagged = Eigen::Vector3d::Zero();
  for (const auto& [first, last] : runs)
    for (int i = first; i <= last; ++i) {
      const Eigen::Vector3d d = omega[i] - rest.mean;
      deviations += d.cwiseAbs2();
      if (i < last) lagged += d.cwiseProduct(omega[i + 1] - rest.mean);
    }
  if (rest.samples > 1) rest.sigma = (deviations / (rest.samples - 1)).cwiseSqrt();
  for (int c = 0; c < 3; ++c) {
    const double rho = deviations[c] > 0.0 ? std::clamp(lagged[c] / deviations[c], 0.0, 0.95) : 0.0;
    const double effective = rest.samples * (1.0 - rho) / (1.0 + rho);
    rest.standard_error[c] = rest.sigma[c] / std::sqrt(std::max(effective, 1.0));
  }
  rest.standard_error = rest.standard_error.cwiseMax(batch_standard_error(omega, runs, rest.mean));
  return rest;
}

bool bias_significant(const Eigen::Vector3d& bias, const Eigen::Vector3d& sigma) {
  return bias_chi_square(bias, sigma) > kBiasChiSquare;
}

double bias_chi_square(const Eigen::Vector3d& bias, const Eigen::Vector3d& sigma) {
  double chi2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (!(sigma[i] > 0)) return std::numeric_limits<double>::infinity();
    chi2 += (bias[i] / sigma[i]) * (bias[i] / sigma[i]);
  }
  return chi2;
}

}  // namespace bookspin::fit
