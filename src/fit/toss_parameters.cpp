#include "fit/toss_parameters.hpp"

#include <algorithm>

#include "fit/flights.hpp"
#include "fit/pool.hpp"

namespace bookspin::fit {

std::vector<TossData> toss_data(const GyroRecording& recording, const FlightSearch& search,
                                const Saturation& saturation) {
  std::vector<TossData> data;
  for (const Flight& f : search.flights) {
    TossData d;
    d.group = static_cast<int>(part_index(recording.parts, f.t_start));
    const Eigen::Vector3d bias = recording.parts[d.group].bias;
    d.samples = f.last - f.first + 1;
    for (int i = f.first; i <= f.last; ++i) d.at_range += saturation.at_range[i] ? 1 : 0;
    const bool drop = d.samples - d.at_range >= kMinSamplesLeft;
    d.saturated = drop ? d.at_range : 0;  // kept where too few would remain: none left out
    for (int i = f.first; i <= f.last; ++i) {
      if (drop && saturation.at_range[i]) continue;
      d.tau.push_back(recording.t[i] - f.t_start);
      d.omega.push_back(recording.omega[i] - bias);
    }
    data.push_back(std::move(d));
  }
  return data;
}

void normalise(Parameters& p) {
  const Eigen::Vector3d m = p.moments();
  Eigen::Matrix3d axes = p.axes();
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return m[a] < m[b]; });
  Eigen::Matrix3d sorted;
  for (int k = 0; k < 3; ++k) sorted.col(k) = axes.col(order[k]);
  for (int k = 0; k < 2; ++k) {
    Eigen::Index big = 0;
    sorted.col(k).cwiseAbs().maxCoeff(&big);
    if (sorted(big, k) < 0) sorted.col(k) = -sorted.col(k);
  }
  sorted.col(2) = sorted.col(0).cross(sorted.col(1));
  p.R0 = sorted;
  p.aa = {0, 0, 0};
  p.log_ratios = {std::log(m[order[0]] / m[order[2]]), std::log(m[order[1]] / m[order[2]])};
}

Parameters start(const std::vector<TossData>& data, const FitSettings& settings) {
  std::vector<Eigen::Vector3d> omega, rate;
  std::vector<int> indices;
  for (const TossData& d : data) {
    const std::vector<Eigen::Vector3d> r = omega_rate(d.tau, d.omega);
    for (std::size_t i = 0; i < d.omega.size(); ++i) {
      indices.push_back(static_cast<int>(omega.size()));
      omega.push_back(d.omega[i]);
      rate.push_back(r[i]);
    }
  }
  const Eigen::Matrix3d I = euler_inertia(omega, rate, indices);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(I);
  Parameters p;
  p.R0 = eigen.eigenvectors();
  if (p.R0.determinant() < 0) p.R0.col(0) = -p.R0.col(0);
  Eigen::Vector3d m = eigen.eigenvalues() / eigen.eigenvalues().maxCoeff();
  if (settings.moments) {
    Eigen::Vector3d given = *settings.moments;
    std::sort(given.data(), given.data() + 3);
    m = given / given[2];
  }
  // The Euler estimate's start is kept off a degenerate body; given moments are used as given.
  if (!settings.moments) m = m.cwiseMax(0.02);
  p.log_ratios = {std::log(m[0]), std::log(m[1])};
  for (const TossData& d : data)
    p.omega0.push_back({d.omega[0][0], d.omega[0][1], d.omega[0][2], 0.0});
  normalise(p);
  return p;
}

std::vector<int> tosses_per_group(const std::vector<TossData>& data, std::size_t groups) {
  std::vector<int> count(groups, 0);
  for (const TossData& d : data) ++count.at(d.group);
  return count;
}

}  // namespace bookspin::fit
