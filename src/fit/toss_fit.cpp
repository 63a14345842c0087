// The assembly of a FitResult (docs/phone-lab.md, "The fit"): each stage a named call over the
// unknowns (toss_parameters.hpp), the least squares and its covariances (toss_solve.hpp), the
// joint fit (joint_fit.hpp) and its restart from rigid bodies (rigid_restart.hpp), the
// flight ends' spread (end_spread.hpp), the half periods (half_period.hpp), the predictions'
// calibration (prediction_calibration.hpp), the flags (toss_flags.hpp), the body's notes
// (body_notes.hpp) and mixed units (mixed_units.hpp).
#include "fit/toss_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "common/errors.hpp"
#include "fit/body_notes.hpp"
#include "fit/end_spread.hpp"
#include "fit/fit_stages.hpp"
#include "fit/flight_trim.hpp"
#include "fit/folds.hpp"
#include "fit/half_period.hpp"
#include "fit/joint_fit.hpp"
#include "fit/mixed_units.hpp"
#include "fit/pool.hpp"
#include "fit/prediction_calibration.hpp"
#include "fit/prediction_sigma.hpp"
#include "fit/rigid_bounds.hpp"
#include "fit/rigid_restart.hpp"
#include "fit/saturation.hpp"
#include "fit/toss_flags.hpp"
#include "fit/toss_parameters.hpp"
#include "fit/toss_solve.hpp"
#include "physics/damped_exact.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::fit {
namespace {

constexpr double kStableDegrees = 25.0;
/// The note and the predictions' word where the fit ends far from rigid (rigid_bounds.hpp).
std::string no_rigid_body_note() {
  return "the fit ends at no rigid body (" + far_from_rigid_words() +
         ") from every start: the moments are not determined, no uncertainties and no "
         "predictions";
}
constexpr double kPi = 3.14159265358979323846;

/// Uncertainties (docs/phone-lab.md, "Error bars"): (JᵀJ)⁻¹ scaled by the residual variance and
/// by the residual's correlation, into the body's σ (the folds' spread widens them later), each
/// freely fitted bias correction's (into `parts`) and each toss's; a note where the covariance
/// cannot be computed.
TossSigmas uncertainties(const std::vector<TossData>& data, const Parameters& p,
                         const Solved& solved, const BiasFreedom& bias,
                         const std::vector<std::vector<Eigen::Vector3d>>& residuals,
                         physics::DragLaw law, bool fixed, BodyEstimate& body,
                         std::vector<RecordingPart>& parts) {
  const bool dragged = law != physics::DragLaw::none;
  TossSigmas sigmas;
  sigmas.omega0.resize(data.size());
  sigmas.rate.resize(data.size());
  const int parameter_count =
      (fixed ? 3 : 5) + 3 * bias.fitted_groups + (dragged ? 4 : 3) * static_cast<int>(data.size());
  const double variance = 2.0 * solved.cost / std::max(1, solved.residuals - parameter_count) *
                          correlation_inflation(residuals);
  const std::optional<Covariances> covariance = covariances(data, p, fixed, bias.fitted, law);
  if (!covariance) {
    body.notes.push_back("the fit cannot tell every value apart: no uncertainties");
    return sigmas;
  }
  const Eigen::MatrixXd& c = covariance->body;
  body_sigmas(c, variance, body.ratios, fixed, body.axis_sigma_deg, body.ratio_sigma);
  for (std::size_t g = 0; g < parts.size(); ++g) {
    if (!bias.free[g]) continue;
    const int e = covariance->bias_row[g];
    parts[g].bias_fitted_sigma =
        Eigen::Vector3d(std::sqrt(variance * c(e, e)), std::sqrt(variance * c(e + 1, e + 1)),
                        std::sqrt(variance * c(e + 2, e + 2)));
  }
  for (std::size_t k = 0; k < data.size(); ++k) {
    const Eigen::MatrixXd& ck = covariance->omega0[k];
    sigmas.omega0[k] = (variance * ck.diagonal().head<3>()).cwiseSqrt();
    if (dragged) sigmas.rate[k] = std::sqrt(variance * ck(3, 3));
  }
  return sigmas;
}

/// Toss k's prediction (TossFit::half_period_predicted, what it rests on, or why none): its fold's
/// body and drag rate (fit/prediction_sigma.hpp); a note where they are too little flight.
Prediction predict(const std::vector<TossData>& data, std::size_t k, const Folds& folds,
                   const FlightSearch& search, const FitSettings& settings,
                   const PredictionInputs& inputs, std::vector<TossFit>& tosses,
                   BodyEstimate& body) {
  const TossData& d = data[k];
  TossFit& toss = tosses[k];
  const std::size_t fold = k % folds.count;
  const std::optional<Parameters>& held_out = folds.body[fold];
  // A body fitted on stable tosses alone cannot tell its moments apart: no prediction.
  bool flips = settings.moments.has_value();
  for (std::size_t j = 0; j < tosses.size(); ++j)
    flips = flips || (j % folds.count != fold && !tosses[j].stable);
  if (!held_out || !flips) {
    toss.not_predicted = data.size() < 2 && !settings.moments
                             ? "one toss: no other tosses' body to predict from"
                         : !held_out ? "the other tosses' body could not be fitted"
                                     : "every other toss is stable: their body cannot tell its "
                                       "moments apart";
    return {};
  }
  // The drag rate: the other tosses' (their fold fit's) weighted by their σ (the joint fit's).
  std::vector<TossData> rest;
  std::vector<std::optional<double>> rate_sigmas;
  for (std::size_t j = 0; j < data.size(); ++j)
    if (j % folds.count != fold)
      rest.push_back(data[j]), rate_sigmas.push_back(tosses[j].drag_rate_sigma);
  const HeldRate rate =
      held_rate(rest, *held_out, settings.moments.has_value(), settings.drag, rate_sigmas);
  Parameters others = *held_out;
  others.omega0 = {{d.omega[0][0], d.omega[0][1], d.omega[0][2], rate.rate}};
  SolveOptions options;
  options.stop = &settings.stop;
  // One toss with --moments: its axes too from the first predict_window s alone.
  options.body_fixed = data.size() >= 2;
  options.moments_fixed = true;
  options.drag = settings.drag;
  options.rates_fixed = true;
  options.window = settings.predict_window;
  // What it rests on: the tosses of the other folds (none with one toss and --moments).
  int from = 0;
  double seconds = 0.0, all = 0.0;
  for (std::size_t j = 0; j < data.size(); ++j) {
    const double span = search.flights[j].t_end - search.flights[j].t_start;
    all += span;
    if (data.size() >= 2 && j % folds.count != fold) ++from, seconds += span;
  }
  // Its body is fitted on `seconds` of flight, not all: the joint σ times √(all/seconds).
  PredictionInputs held = inputs;
  held.rate_sigma = rate.sigma;
  if (held.ratio_sigma) held.ratio_sigma = held_out_ratio_sigma(*held.ratio_sigma, all, seconds);
  const Prediction prediction = predict_half_period(d, others, options, held);
  toss.half_period_predicted = prediction.half;
  toss.half_period_predicted_sigma = prediction.sigma;
  toss.predicted_window = prediction.window;
  toss.not_predicted = prediction.withheld;
  toss.half_period_propagated_sigma = prediction.sigma;
  if (!prediction.half) return prediction;
  toss.predicted_from_tosses = from;
  toss.predicted_from_seconds = seconds;
  if (from > 0 && seconds < kShortBasis) {
    char line[300];
    std::snprintf(line, sizeof line,
                  "toss %zu's half_period_predicted rests on %d other toss(es), %.2f s of "
                  "flight in all, under the %.1f s that pin a body: too little flight to pin "
                  "it well (more tosses of this body, fitted together, or %s)",
                  k + 1, from, seconds, kShortBasis, kGiveMoments);
    body.notes.push_back(line);
  }
  return prediction;
}

/// Toss k's values from the joint fit: ω0, drag rate and their σ, the half periods fitted and
/// measured, its residual, |L|'s decay, whether it is stable, its flag (toss_flags.hpp).
TossFit toss_values(const std::vector<TossData>& data, std::size_t k, const Parameters& joint,
                    const TossSigmas& sigmas, const std::vector<Eigen::Vector3d>& residual,
                    const Flight& flight, const Saturation& saturation, std::optional<double> noise,
                    physics::DragLaw law, BodyEstimate& body) {
  const TossData& d = data[k];
  TossFit toss;
  toss.flight = flight;
  toss.omega0 = Eigen::Vector3d(joint.omega0[k][0], joint.omega0[k][1], joint.omega0[k][2]);
  toss.omega0_sigma = sigmas.omega0[k];
  toss.drag_rate = law != physics::DragLaw::none ? joint.omega0[k][3] : 0.0;
  toss.drag_rate_sigma = sigmas.rate[k];
  const physics::DampedExactRotation exact(body.ratios, body.axes.transpose() * toss.omega0,
                                           physics::Drag{law, toss.drag_rate},
                                           physics::ExactParts::omega_only);
  toss.half_period_fitted = motion_half_period(exact, body.axes, d.tau);
  // Residual, |L| (L = I ω, principal frame), the angle to the circled axis.
  double sum2 = 0.0, max_angle = 0.0;
  const int circled = exact.free().motion_case() == physics::ExactCase::around_smallest ? 0 : 2;
  std::vector<double> L(d.tau.size()), along(d.tau.size());
  for (std::size_t i = 0; i < d.tau.size(); ++i) {
    const Eigen::Vector3d w_fit = body.axes * exact.omega_body(d.tau[i]);
    sum2 += (w_fit - d.omega[i]).squaredNorm();
    const Eigen::Vector3d w_principal = body.axes.transpose() * d.omega[i];
    L[i] = body.ratios.cwiseProduct(w_principal).norm();
    along[i] = w_principal[1];
    const Eigen::Vector3d wf = body.axes.transpose() * w_fit;
    max_angle = std::max(max_angle, std::acos(std::min(1.0, std::abs(wf[circled]) / wf.norm())));
  }
  toss.residual_rms = std::sqrt(sum2 / d.tau.size());
  double mean_omega = 0.0;
  for (const Eigen::Vector3d& w : d.omega) mean_omega += w.norm() / d.omega.size();
  toss.residual_share = mean_omega > 0.0 ? toss.residual_rms / mean_omega : 0.0;
  toss.saturated = d.at_range;
  toss.flag = toss_flag(d, residual, saturation, noise,
                        body.axes * body.ratios.asDiagonal() * body.axes.transpose());
  toss.poor_fit = !toss.flag.empty();
  if (toss.poor_fit)
    body.notes.push_back("toss " + std::to_string(k + 1) + " flagged: " + toss.flag +
                         "; its values are not to be trusted");
  toss.stable = exact.free().motion_case() == physics::ExactCase::steady ||
                max_angle * 180.0 / kPi < kStableDegrees;
  toss.L_decay = L_decay(d.tau, L);
  // The measured flips: sign changes of ω about the intermediate axis.
  double peak = 0.0;
  for (double v : along) peak = std::max(peak, std::abs(v));
  const std::vector<double> crossings = sign_changes(d.tau, along, 0.2 * peak);
  if (crossings.size() >= 2)
    toss.half_period_measured =
        (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  return toss;
}

}  // namespace

Eigen::Vector3d fitted_omega(const FitResult& fit, int toss, double t) {
  const TossFit& f = fit.tosses.at(toss);
  const physics::DampedExactRotation exact(fit.body.ratios, fit.body.axes.transpose() * f.omega0,
                                           physics::Drag{fit.drag, f.drag_rate},
                                           physics::ExactParts::omega_only);
  return fit.body.axes * exact.omega_body(t - f.flight.t_start);
}

void measured_omega(const GyroRecording& recording, const FitResult& fit, int toss,
                    std::vector<double>& t, std::vector<Eigen::Vector3d>& omega) {
  const Flight& flight = fit.tosses.at(toss).flight;
  t.assign(recording.t.begin() + flight.first, recording.t.begin() + flight.last + 1);
  omega.clear();
  const Eigen::Vector3d bias = part_at(fit.parts, flight.t_start).bias_in_flight();
  for (int i = flight.first; i <= flight.last; ++i) omega.push_back(recording.omega[i] - bias);
}

namespace {

/// Where the gyroscope read its range: the fit's note, with how many samples each recording's
/// tosses left out, and the range (FitResult::saturation_range).
void note_saturation(const Saturation& saturation, const std::vector<RecordingPart>& parts,
                     const std::vector<TossData>& data, FitResult& result) {
  if (!saturation.range) return;
  std::vector<int> in_tosses(parts.size(), 0);
  for (const TossData& d : data) in_tosses[d.group] += d.saturated;
  result.body.notes.push_back(saturation_note(saturation, parts, in_tosses));
  result.saturation_range = saturation.range;
}

/// The bias in flight: each recording's rest plus its fitted correction (`p`'s, into `parts`,
/// then zero in `p`); the samples corrected by it, so that what follows (and measured_omega)
/// sees them as the fit did. Returns each recording's correction (rad/s).
std::vector<Eigen::Vector3d> correct_bias(Parameters& p, std::vector<TossData>& data,
                                          std::vector<RecordingPart>& parts) {
  std::vector<Eigen::Vector3d> correction(parts.size());
  for (std::size_t g = 0; g < correction.size(); ++g) {
    correction[g] = Eigen::Vector3d(p.e[g][0], p.e[g][1], p.e[g][2]);
    parts[g].bias_correction = correction[g];
  }
  for (TossData& d : data)
    for (Eigen::Vector3d& w : d.omega) w -= correction[d.group];
  p.e.assign(parts.size(), {0.0, 0.0, 0.0});
  return correction;
}

/// fit_recording with the bias corrections of the recordings `held` (by part) held at zero.
FitResult fit_holding(const GyroRecording& recording, const FlightSearch& search,
                      const FitSettings& settings, const std::vector<bool>& held,
                      const FlightSearch* found) {
  FitResult result;
  result.parts = recording.parts;
  result.search = search;
  result.drag = settings.drag;
  BodyEstimate& body = result.body;
  const Saturation saturation = find_saturation(recording);
  std::vector<TossData> data = toss_data(recording, search, saturation);
  note_saturation(saturation, recording.parts, data, result);
  const bool fixed = settings.moments.has_value();
  Parameters p = start(data, settings);
  p.e.assign(recording.parts.size(), {0.0, 0.0, 0.0});
  const BiasFreedom bias = bias_freedom(recording.parts, data, held);
  std::vector<bool> rate_held;
  Solved solved = joint_fit(data, p, bias, settings, recording.source, rate_held);
  if (!fixed && suspect_body(p))
    refit_from_bodies(data, bias, settings, recording, p, solved, rate_held);
  // An axis far beyond any gyroscope's range beside two within it: say which, once.
  if (const std::string cause = scale_cause(data); !cause.empty()) body.notes.push_back(cause);
  const std::vector<Eigen::Vector3d> correction = correct_bias(p, data, result.parts);
  body.ratios = p.moments();
  body.axes = p.axes();
  body.moments_fixed = fixed;
  const std::vector<std::vector<Eigen::Vector3d>> residuals = residuals_of(data, p, settings.drag);
  TossSigmas sigmas =
      uncertainties(data, p, solved, bias, residuals, settings.drag, fixed, body, result.parts);
  const Folds folds = fold_bodies(data, p, bias, correction, settings);
  widen_by_folds(folds, fixed, body);
  if (found)
    widen_by_ends(data, p, end_shifts(search.flights, found), settings, rate_held, bias, correction,
                  body, sigmas);
  // Moments the restarts left far past a rigid body (rigid_bounds.hpp's far_from_rigid: a
  // needle of I1/I3 under 0.01, or 5 % past the triangle inequality) lie where a flat cost let
  // the solver stop: which needle follows its round-off, so the page and the command line part
  // there. Their σ (the covariance of a degenerate body: I2/I3 ± 150 seen) and predictions
  // (from folds as degenerate) are withheld, alike in both (docs/phone-lab.md, "The fit"). A
  // body merely at the edges (a racquet's 0.1 : 0.9 : 1) keeps them.
  const bool no_rigid_body = !fixed && fitted_no_rigid_body(p);
  if (no_rigid_body) {
    body.ratio_sigma.reset();
    body.axis_sigma_deg.reset();
    body.notes.push_back(no_rigid_body_note());
  }
  const std::optional<double> noise = rest_noise(recording, search);
  for (std::size_t k = 0; k < data.size(); ++k)
    result.tosses.push_back(toss_values(data, k, p, sigmas, residuals[k], search.flights[k],
                                        saturation, noise, settings.drag, body));
  std::vector<Prediction> predictions;
  for (std::size_t k = 0; k < data.size(); ++k) {
    if (no_rigid_body) {
      result.tosses[k].not_predicted = no_rigid_body_note();
      predictions.emplace_back();
      continue;
    }
    const PredictionInputs inputs{settings.drag, body.ratio_sigma,
                                  bias_sigma(result.parts.at(data[k].group))};
    predictions.push_back(predict(data, k, folds, search, settings, inputs, result.tosses, body));
  }
  calibrate_predictions(predictions, result.tosses);
  body_notes(result, settings, body);
  return result;
}

/// fit_holding, the bias of each recording with no rest held at zero where it is noise.
FitResult fit_with_bias_rule(const GyroRecording& recording, const FlightSearch& search,
                             const FitSettings& settings, const FlightSearch* found) {
  // A bias fitted from the flights of a recording with no still rest is applied only where it
  // differs from zero significantly (docs/phone-lab.md, "The bias"): else it is the flights'
  // noise, held at zero, and its σ stays as the bound the flights set on it.
  FitResult result = fit_holding(recording, search, settings, {}, found);
  std::vector<bool> held(result.parts.size(), false);
  bool any = false;
  for (std::size_t g = 0; g < held.size(); ++g) {
    const RecordingPart& part = result.parts[g];
    if (part.rest.samples > 0 || !part.bias_fitted_sigma) continue;
    held[g] = !bias_significant(part.bias_correction, *part.bias_fitted_sigma);
    any = any || held[g];
  }
  if (!any) return result;
  FitResult again = fit_holding(recording, search, settings, held, found);
  for (std::size_t g = 0; g < held.size(); ++g)
    if (held[g]) {
      again.parts[g].bias_not_applied = result.parts[g].bias_correction;
      again.parts[g].bias_fitted_sigma = result.parts[g].bias_fitted_sigma;
    }
  return again;
}

/// The flights as given, no ends' term: the fit mixed units tries (units_cause).
FitResult refit_as_given(const GyroRecording& recording, const FlightSearch& search,
                         const FitSettings& settings) {
  return fit_with_bias_rule(recording, search, settings, nullptr);
}

}  // namespace

FitResult fit_recording(const GyroRecording& recording, const FlightSearch& search,
                        const FitSettings& settings) {
  check_pooled(recording);
  if (search.flights.empty()) throw_no_flight(recording, search);
  // Flights by hand are the user's, fitted as given: the ends' term weighs the finder's ends.
  FitResult fit;
  try {
    try {
      fit = fit_with_bias_rule(recording, search, settings, settings.trim_ends ? &search : nullptr);
    } catch (const InputError& e) {
      const std::string cause = units_cause(recording, search, settings, nullptr, refit_as_given);
      if (cause.empty()) throw;
      throw InputError(std::string(e.what()) + "; " + cause);
    }
    if (settings.trim_ends)
      fit = trim_to_free_flight(recording, std::move(fit), [&](const FlightSearch& trimmed) {
        return fit_with_bias_rule(recording, trimmed, settings, &search);
      });
  } catch (const physics::ExactHorizonError& e) {
    // Moments given so far apart that the exact motion about the smallest turns past its time
    // horizon within a flight (docs/physics.md §8, "How far in time"): the ratio is the cause.
    if (!settings.moments) throw;
    const Eigen::Vector3d& m = *settings.moments;
    char ratio[80];
    std::snprintf(ratio, sizeof ratio, "%.3g", m.minCoeff() / m.maxCoeff());
    throw InputError(recording.source +
                     ": the moments given are too far apart to fit (the smallest " + ratio +
                     " of the largest): " + e.what());
  }
  // Mixed units, where an axis scatters as one in °/s does and taking it as °/s explains the
  // flights (flagged or not: a bare CSV says nothing of units).
  const std::string cause = units_cause(recording, fit.search, settings, &fit, refit_as_given);
  if (!cause.empty()) fit.body.notes.push_back(cause);
  return fit;
}

}  // namespace bookspin::fit
