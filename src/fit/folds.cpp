#include "fit/folds.hpp"

#include <algorithm>
#include <cmath>

#include "fit/toss_solve.hpp"

namespace bookspin::fit {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

Folds fold_bodies(const std::vector<TossData>& data, const Parameters& joint,
                  const BiasFreedom& bias, const std::vector<Eigen::Vector3d>& correction,
                  const FitSettings& settings) {
  Folds folds;
  folds.count = std::max<std::size_t>(1, std::min<std::size_t>(data.size(), 5));
  folds.body.resize(folds.count);
  if (data.size() < 2) {
    if (settings.moments) folds.body[0] = joint;
    return folds;
  }
  for (std::size_t f = 0; f < folds.count; ++f) {
    std::vector<TossData> rest;
    Parameters q = joint;
    q.omega0.clear();
    for (std::size_t j = 0; j < data.size(); ++j)
      if (j % folds.count != f) rest.push_back(data[j]), q.omega0.push_back(joint.omega0[j]);
    SolveOptions options;
    options.stop = &settings.stop;
    options.moments_fixed = settings.moments.has_value();
    options.drag = settings.drag;
    options.spacing = 0.01;  // at 100 Hz whatever the rate: five fits of nearly every toss
    options.bias_group_held = bias.held;
    if (bias.any_bound) {
      options.bias_held = true;
      if (!solve(rest, q, options).usable) continue;
      options.bias_held = false;
      options.bias_bound = bias.bound;
      options.bias_offset = correction;
    }
    if (!solve(rest, q, options).usable) continue;
    normalise(q);
    folds.body[f] = q;
  }
  return folds;
}

void widen_by_folds(const Folds& folds, bool fixed, BodyEstimate& body) {
  if (folds.count < 3 || !body.ratio_sigma || !body.axis_sigma_deg) return;
  std::vector<Eigen::Vector3d> ratios, turns;
  for (const std::optional<Parameters>& q : folds.body) {
    if (!q) continue;
    ratios.push_back(q->moments());
    Eigen::Vector3d turn;
    const Eigen::Matrix3d a = q->axes();
    for (int i = 0; i < 3; ++i)
      turn[i] = std::acos(std::min(1.0, std::abs(a.col(i).dot(body.axes.col(i))))) * 180.0 / kPi;
    turns.push_back(turn);
  }
  if (ratios.size() < 3) return;
  const double g = static_cast<double>(ratios.size());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), spread = Eigen::Vector3d::Zero(),
                  turn2 = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& r : ratios) mean += r / g;
  for (std::size_t i = 0; i < ratios.size(); ++i) {
    spread += (ratios[i] - mean).cwiseAbs2();
    turn2 += turns[i].cwiseAbs2();
  }
  const double factor = (g - 1.0) / g;
  if (!fixed) body.ratio_sigma = body.ratio_sigma->cwiseMax((factor * spread).cwiseSqrt());
  body.ratio_sigma->z() = 0.0;
  body.axis_sigma_deg = body.axis_sigma_deg->cwiseMax((factor * turn2).cwiseSqrt());
}

}  // namespace bookspin::fit
