#include "fit/live_fit.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "fit/half_period.hpp"
#include "fit/joint_fit.hpp"
#include "fit/rigid_bounds.hpp"
#include "fit/toss_solve.hpp"
#include "physics/damped_exact.hpp"

namespace bookspin::fit {
namespace {

/// `given` in their canonical order (fit/pool.hpp: by name, then by source), each source once.
std::vector<const PreparedRecording*> canonical(
    const std::vector<const PreparedRecording*>& given) {
  if (given.empty()) throw InputError("live fit: give one or more prepared recordings");
  std::vector<const PreparedRecording*> order = given;
  std::sort(order.begin(), order.end(), [](const PreparedRecording* a, const PreparedRecording* b) {
    return a->name != b->name ? a->name < b->name : a->source < b->source;
  });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (order[k]->source == order[k - 1]->source)
      throw InputError(order[k]->source + ": given twice");
  return order;
}

/// The solve from `start`'s body (its moments, unless settings.moments fixes them), every
/// flight's ω0 and rate and each bias correction as `p` holds them: one solve of everything,
/// no stages. A drag rate below 0 is held at 0 (air cannot speed a body up, docs/phone-lab.md,
/// "Drag"), as the exact fit holds it, from the start and after the solve.
Solved warm_solve(const std::vector<TossData>& data, const LiveFit& start, const BiasFreedom& bias,
                  const FitSettings& settings, const std::string& source, Parameters& p) {
  p.R0 = start.axes;
  p.aa = {0, 0, 0};
  p.log_ratios = settings.moments
                     ? fit::start(data, settings).log_ratios
                     : std::array<double, 2>{std::log(start.ratios[0]), std::log(start.ratios[1])};
  SolveOptions options;
  options.stop = &settings.stop;
  options.moments_fixed = settings.moments.has_value();
  options.drag = settings.drag;
  options.bias_group_held = bias.held;
  options.bias_bound = bias.bound;
  for (std::size_t g = 0; g < bias.bound.size(); ++g)
    if (bias.bound[g])
      for (int i = 0; i < 3; ++i)
        p.e[g][i] = std::clamp(p.e[g][i], -(*bias.bound[g])[i], (*bias.bound[g])[i]);
  options.rate_held.assign(data.size(), false);
  const bool dragged = settings.drag != physics::DragLaw::none;
  const auto hold_negative_rates = [&] {
    bool any = false;
    for (std::size_t k = 0; k < data.size() && dragged; ++k)
      if (p.omega0[k][3] < 0.0) p.omega0[k][3] = 0.0, options.rate_held[k] = any = true;
    return any;
  };
  hold_negative_rates();
  Solved solved = solve(data, p, options);
  if (solved.usable && hold_negative_rates()) solved = solve(data, p, options);
  if (!solved.usable) throw InputError(source + ": the live fit did not converge");
  return solved;
}

/// With no live fit to start from: the exact fit's joint fit (joint_fit.hpp: grown over each
/// flight from Euler's equations' body, so that a rough start does not lock onto a wrong
/// phase), each flight's ω0 from its own fit; once, the first of a class's live fits.
Solved cold_solve(const std::vector<TossData>& data, const BiasFreedom& bias,
                  const FitSettings& settings, const std::string& source, Parameters& p) {
  const Parameters euler = fit::start(data, settings);
  p.R0 = euler.R0;
  p.aa = euler.aa;
  p.log_ratios = euler.log_ratios;
  std::vector<bool> rate_held;
  return joint_fit(data, p, bias, settings, source, rate_held);
}

/// Toss `k`'s row from the solved body (`ratios`, `axes`) and its ω0 and rate in `p`.
LiveToss toss_row(const TossData& d, const Parameters& p, std::size_t k,
                  const Eigen::Vector3d& ratios, const Eigen::Matrix3d& axes,
                  physics::DragLaw law) {
  LiveToss toss;
  toss.omega0 = Eigen::Vector3d(p.omega0[k][0], p.omega0[k][1], p.omega0[k][2]);
  toss.drag_rate = law != physics::DragLaw::none ? p.omega0[k][3] : 0.0;
  const physics::DampedExactRotation exact(ratios, axes.transpose() * toss.omega0,
                                           physics::Drag{law, toss.drag_rate},
                                           physics::ExactParts::omega_only);
  toss.half_period_fitted = motion_half_period(exact, axes, d.tau);
  double sum2 = 0.0, peak = 0.0;
  std::vector<double> along(d.tau.size());
  for (std::size_t i = 0; i < d.tau.size(); ++i) {
    sum2 += (axes * exact.omega_body(d.tau[i]) - d.omega[i]).squaredNorm();
    along[i] = (axes.transpose() * d.omega[i])[1];
    peak = std::max(peak, std::abs(along[i]));
  }
  toss.residual_rms = d.tau.empty() ? 0.0 : std::sqrt(sum2 / d.tau.size());
  const std::vector<double> crossings = sign_changes(d.tau, along, 0.2 * peak);
  if (crossings.size() >= 2)
    toss.half_period_measured =
        (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  return toss;
}

/// The body's σ from the covariance at `p` (toss_fit.cpp's uncertainties, without the folds).
void body_sigma(const std::vector<TossData>& data, const Parameters& p, const Solved& solved,
                const BiasFreedom& bias, const FitSettings& settings, LiveFit& fit) {
  const bool fixed = settings.moments.has_value();
  const bool dragged = settings.drag != physics::DragLaw::none;
  const std::vector<std::vector<Eigen::Vector3d>> residuals = residuals_of(data, p, settings.drag);
  const int parameter_count =
      (fixed ? 3 : 5) + 3 * bias.fitted_groups + (dragged ? 4 : 3) * static_cast<int>(data.size());
  const double variance = 2.0 * solved.cost / std::max(1, solved.residuals - parameter_count) *
                          correlation_inflation(residuals);
  const std::optional<Covariances> covariance =
      covariances(data, p, fixed, bias.fitted, settings.drag);
  if (!covariance) return;
  body_sigmas(covariance->body, variance, fit.ratios, fixed, fit.axis_sigma_deg, fit.ratio_sigma);
}

}  // namespace

LiveFit live_fit(const std::vector<const PreparedRecording*>& recordings, const LiveFit* start,
                 const FitSettings& settings) {
  const std::vector<const PreparedRecording*> order = canonical(recordings);
  std::map<std::string, const LiveFit::Start*> earlier;
  if (start)
    for (const LiveFit::Start& s : start->starts) earlier[s.name] = &s;
  // Every flight, its recording its group; each starting where the last live fit left it, or
  // where its own fit did.
  std::vector<TossData> data;
  std::vector<RecordingPart> parts;
  Parameters p;
  std::size_t started = 0;  // flights the start holds
  p.omega0.clear();
  p.e.clear();
  for (std::size_t g = 0; g < order.size(); ++g) {
    const PreparedRecording& r = *order[g];
    const auto found = earlier.find(r.name);
    const bool again = found != earlier.end() && found->second->omega0.size() == r.data.size();
    if (again) started += r.data.size();
    for (std::size_t k = 0; k < r.data.size(); ++k) {
      data.push_back(r.data[k]);
      data.back().group = static_cast<int>(g);
      p.omega0.push_back(again ? found->second->omega0[k] : r.omega0[k]);
    }
    p.e.push_back(again ? found->second->e : r.bias_correction);
    parts.push_back(r.part);
  }
  if (data.empty())
    throw InputError(order.front()->source + (order.size() > 1 ? " and the others" : "") +
                     ": no free flight found");
  const BiasFreedom bias = bias_freedom(parts, data, {});
  const std::string source = order.front()->source;
  // Warm where the start holds most of the flights: a body fitted on a few recordings is far
  // from that of many (from one recording's, 350's took 22 s and ended at no rigid body), so a
  // set mostly new to it, or a warm solve that ends far from rigid, is solved cold.
  const Parameters given = p;
  Solved solved;
  bool warm = start && 2 * started >= data.size();
  if (warm) {
    try {
      solved = warm_solve(data, *start, bias, settings, source, p);
      warm = settings.moments || !far_from_rigid(p.moments());
    } catch (const InputError&) {
      warm = false;  // did not converge from there: cold
    }
  }
  if (!warm) {
    p = given;
    solved = cold_solve(data, bias, settings, source, p);
  }
  normalise(p);
  LiveFit fit;
  fit.recordings = static_cast<int>(order.size());
  fit.ratios = p.moments();
  fit.axes = p.axes();
  body_sigma(data, p, solved, bias, settings, fit);
  std::size_t k = 0;
  for (std::size_t g = 0; g < order.size(); ++g) {
    const PreparedRecording& r = *order[g];
    LiveFit::Start next{r.name, {}, p.e[g]};
    for (std::size_t f = 0; f < r.data.size(); ++f, ++k) {
      LiveToss toss = toss_row(data[k], p, k, fit.ratios, fit.axes, settings.drag);
      toss.recording = r.name;
      toss.flight = static_cast<int>(f) + 1;
      toss.toss = static_cast<int>(k) + 1;
      toss.t_start = r.search.flights[f].t_start;
      toss.t_end = r.search.flights[f].t_end;
      fit.tosses.push_back(std::move(toss));
      next.omega0.push_back(p.omega0[k]);
    }
    fit.starts.push_back(std::move(next));
  }
  return fit;
}

}  // namespace bookspin::fit
