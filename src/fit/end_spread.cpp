#include "fit/end_spread.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "fit/toss_solve.hpp"

namespace bookspin::fit {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

EndShifts end_shifts(const std::vector<Flight>& flights, const FlightSearch* found) {
  if (!found) return {};
  EndShifts shifts;
  const bool trimmed = found->flights.size() == flights.size();
  for (std::size_t k = 0; k < flights.size(); ++k) {
    const Flight& f = flights[k];
    const double most = kEndShare * (f.t_end - f.t_start);
    double start = kEndUncertainty, end = kEndUncertainty;
    if (trimmed) {
      start = std::max(start, f.t_start - found->flights[k].t_start);
      end = std::max(end, found->flights[k].t_end - f.t_end);
    }
    shifts.start.push_back(std::min(start, most));
    shifts.end.push_back(std::min(end, most));
  }
  return shifts;
}

void widen_by_ends(const std::vector<TossData>& data, const Parameters& p, const EndShifts& shifts,
                   const FitSettings& settings, const std::vector<bool>& rate_held,
                   const BiasFreedom& bias, const std::vector<Eigen::Vector3d>& correction,
                   BodyEstimate& body, TossSigmas& sigmas) {
  if (!body.ratio_sigma || !body.axis_sigma_deg) return;
  const bool fixed = settings.moments.has_value();
  const bool dragged = settings.drag != physics::DragLaw::none;
  Eigen::Vector3d ratio2 = Eigen::Vector3d::Zero(), turn2 = Eigen::Vector3d::Zero();
  std::vector<double> rate2(data.size(), 0.0);
  for (int side = 0; side < 2; ++side) {
    std::vector<TossData> moved = data;
    for (std::size_t k = 0; k < moved.size(); ++k) {
      TossData& d = moved[k];
      const double span = d.tau.empty() ? 0.0 : data[k].tau.back();
      TossData kept = d;
      kept.tau.clear(), kept.omega.clear();
      for (std::size_t i = 0; i < d.tau.size(); ++i) {
        const bool in = side == 0 ? d.tau[i] >= shifts.start[k] : d.tau[i] <= span - shifts.end[k];
        if (in) kept.tau.push_back(d.tau[i]), kept.omega.push_back(d.omega[i]);
      }
      if (kept.tau.size() < static_cast<std::size_t>(kMinSamplesLeft)) kept = d;
      d = std::move(kept);
    }
    Parameters q = p;
    SolveOptions options;
    options.stop = &settings.stop;
    options.moments_fixed = fixed;
    options.drag = settings.drag;
    // The bias corrections refitted as the joint fit fits them, within their bounds about the
    // correction the samples carry already: the ends move them too.
    options.bias_group_held = bias.held;
    if (bias.any_bound) {
      options.bias_bound = bias.bound;
      options.bias_offset = correction;
    }
    options.rate_held = rate_held;
    if (!solve(moved, q, options).usable) return;
    normalise(q);
    if (!fixed) ratio2 += (q.moments() - p.moments()).cwiseAbs2();
    const Eigen::Matrix3d a = q.axes();
    for (int i = 0; i < 3; ++i) {
      const double turn =
          std::acos(std::min(1.0, std::abs(a.col(i).dot(body.axes.col(i))))) * 180.0 / kPi;
      turn2[i] += turn * turn;
    }
    if (dragged)
      for (std::size_t k = 0; k < data.size(); ++k) {
        const double d = q.omega0[k][3] - p.omega0[k][3];
        rate2[k] += d * d;
      }
  }
  body.ratio_sigma = (body.ratio_sigma->cwiseAbs2() + ratio2).cwiseSqrt();
  body.ratio_sigma->z() = 0.0;
  body.axis_sigma_deg = (body.axis_sigma_deg->cwiseAbs2() + turn2).cwiseSqrt();
  for (std::size_t k = 0; k < data.size(); ++k)
    if (sigmas.rate[k]) sigmas.rate[k] = std::sqrt(*sigmas.rate[k] * *sigmas.rate[k] + rate2[k]);
}

}  // namespace bookspin::fit
