#include "fit/toss_fit.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "common/errors.hpp"
#include "fit/pool.hpp"
#include "fit/saturation.hpp"
#include "fit/toss_model.hpp"
#include "physics/damped_exact.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::fit {
namespace {

constexpr double kStableDegrees = 25.0;
constexpr double kPi = 3.14159265358979323846;
// The flags (docs/phone-lab.md, "Flags"): a 50 ms block of the residual over kBlockFactor times
// both the flight's median block and the noise at rest; or the whole residual over kNoFit of |ω|.
constexpr double kBlock = 0.05;
// The widest range of a phone's or a consumer IMU's gyroscope: ±4000 °/s (69.8 rad/s; most
// phones stop at ±2000 °/s, 34.9 rad/s). A sample beyond it cannot be a measurement: the
// recording is in other units (°/s) or scaled (docs/phone-lab.md, "Flags").
constexpr double kGyroRangeMax = 4000.0 * 3.14159265358979323846 / 180.0;
constexpr double kBlockFactor = 4.0;
// 5 %: between the clean throws of a bare phone in real air (1.0–1.8 % of |ω| with drag) and a
// fit with its flips visibly mistimed (8.8 %); the gyroscope's noise (0.005–0.03 rad/s) is 10–40
// times below a clean throw's residual, so it cannot set this one (docs/phone-lab.md, "Flags").
constexpr double kNoFit = 0.05;

/// The samples of one toss, bias removed, times from the toss's start.
struct TossData {
  std::vector<double> tau;             ///< s since t_start
  std::vector<Eigen::Vector3d> omega;  ///< rad/s, phone frame
  int samples = 0;                     ///< the flight's samples, those left out included
  int saturated = 0;  ///< samples left out: the gyroscope at its range (fit/saturation.hpp)
  /// Whose bias correction the toss shares: its recording's among those pooled (0 for one
  /// recording).
  int group = 0;
};

/// Fewer samples than this left of a flight once its saturated ones are out, and they stay in
/// (flagged): a fit needs something to fit.
constexpr int kMinSamplesLeft = 10;

/// s: a prediction whose held-out body rests on less flight time than this (a bounce, not a
/// throw) is said to be poorly founded.
constexpr double kShortBasis = 0.6;

/// Residuals ω_fitted(τ_i) − ω_measured(τ_i) + e, three per sample, rad/s, and their derivatives
/// with respect to the body's axes (aa), its log moment ratios, the toss's ω0 and drag rate
/// (TossModel) and e, the correction to the gyroscope's bias measured at rest (the bias in
/// flight is bias + e; docs/phone-lab.md, "The bias").
class TossCost : public ceres::CostFunction {
 public:
  /// The first `samples` of `data`, every `stride`-th of them.
  TossCost(const TossData* data, int samples, int stride, const Eigen::Matrix3d& R0,
           physics::DragLaw law)
      : data_(data), samples_(samples), stride_(stride), R0_(R0), law_(law) {
    set_num_residuals(3 * ((samples + stride - 1) / stride));
    *mutable_parameter_block_sizes() = {3, 2, 4, 3};
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    try {
      const TossModel model(R0_, parameters[0], parameters[1], parameters[2], law_,
                            jacobians != nullptr);
      TossModel::Jacobian J;
      constexpr int kSizes[3] = {3, 2, 4}, kOffsets[3] = {0, 3, 5};
      for (int i = 0, n = 0; i < samples_; i += stride_, ++n) {
        const Eigen::Vector3d r =
            model.omega(data_->tau[i], jacobians ? &J : nullptr) - data_->omega[i] +
            Eigen::Vector3d(parameters[3][0], parameters[3][1], parameters[3][2]);
        for (int c = 0; c < 3; ++c) residuals[3 * n + c] = r[c];
        if (!jacobians) continue;
        if (jacobians[3])  // the bias correction: ∂r/∂e = I
          for (int c = 0; c < 3; ++c)
            for (int j = 0; j < 3; ++j) jacobians[3][(3 * n + c) * 3 + j] = c == j ? 1.0 : 0.0;
        for (int block = 0; block < 3; ++block) {
          if (!jacobians[block]) continue;
          for (int c = 0; c < 3; ++c)
            for (int j = 0; j < kSizes[block]; ++j)
              jacobians[block][(3 * n + c) * kSizes[block] + j] = J(c, kOffsets[block] + j);
        }
      }
      return true;
    } catch (const std::invalid_argument&) {
      return false;  // a step to non-finite values: Ceres tries a shorter one
    }
  }

 private:
  const TossData* data_;
  int samples_;  ///< the first `samples` of the toss
  int stride_;   ///< every stride-th of them
  Eigen::Matrix3d R0_;
  physics::DragLaw law_;
};

/// The fit's parameters: the shared body, then each toss's ω0 and drag rate (ω0x, ω0y, ω0z, r).
struct Parameters {
  Eigen::Matrix3d R0 = Eigen::Matrix3d::Identity();
  std::array<double, 3> aa{0, 0, 0};
  std::array<double, 2> log_ratios{0, 0};
  std::vector<std::array<double, 4>> omega0;
  /// rad/s, phone frame: each group's bias correction (TossCost's e; TossData::group).
  std::vector<std::array<double, 3>> e{{0, 0, 0}};
  Eigen::Matrix3d axes() const { return R0 * rotation_from_angle_axis(aa.data()); }
  Eigen::Vector3d moments() const {
    return {std::exp(log_ratios[0]), std::exp(log_ratios[1]), 1.0};
  }
};

/// Sorts the moments ascending with the largest 1, the axes with them (right-handed, the sign
/// convention of BodyEstimate::axes), and moves the rotation into R0 (aa = 0); the motion is the
/// same.
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

/// Starting values: the inertia that Euler's equations fit best on every flight's samples
/// (flights.hpp: euler_inertia), or the moments given; each ω0 the first sample's.
Parameters start(const std::vector<TossData>& data, const FitSettings& settings,
                 const std::vector<double>& times_unused) {
  (void)times_unused;
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

struct SolveOptions {
  bool body_fixed = false;                         ///< axes and moments held (only the ω0 fitted)
  bool moments_fixed = false;                      ///< moments held (axes and ω0 fitted)
  physics::DragLaw drag = physics::DragLaw::none;  ///< the law the rates are of
  bool rates_fixed = false;     ///< each toss's drag rate held (always under DragLaw::none)
  std::vector<bool> rate_held;  ///< per toss: its drag rate held (at 0: see fit_recording)
  double fraction = 1.0;        ///< each toss's first fraction of samples only
  double window = 0.0;          ///< > 0: each toss's first `window` seconds only
  /// > 0: every sample within this many seconds of the last one kept is left out (the start's
  /// rough stages at 100 Hz whatever the rate; the final fit sees every sample).
  double spacing = 0.0;
  const StopPoll* stop = nullptr;  ///< FitSettings::stop, polled every iteration
  /// The bias corrections held at their values.
  bool bias_held = false;
  /// Per group, rad/s: its bias correction kept within what its rest allows, −bound ≤ e + offset
  /// ≤ bound on each axis (offset: a correction the samples already had removed); nullopt, or
  /// no entries: free.
  std::vector<std::optional<Eigen::Vector3d>> bias_bound;
  std::vector<Eigen::Vector3d> bias_offset;
};

/// How many of `data`'s tosses are in each of `groups` groups.
std::vector<int> tosses_per_group(const std::vector<TossData>& data, std::size_t groups) {
  std::vector<int> count(groups, 0);
  for (const TossData& d : data) ++count.at(d.group);
  return count;
}

/// Asks `stop` at every iteration of the solver; a signal aborts the solve, and solve() throws
/// Interrupted once Ceres has returned (not through its frames).
class StopCallback : public ceres::IterationCallback {
 public:
  explicit StopCallback(const StopPoll* stop) : stop_(stop) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    signal_ = stop_ ? stop_signal(*stop_, "fit") : 0;
    return signal_ ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }
  int signal() const { return signal_; }

 private:
  const StopPoll* stop_;
  int signal_ = 0;
};

struct Solved {
  double cost = 0.0;
  int residuals = 0;
  bool usable = false;
};

Solved solve(const std::vector<TossData>& data, Parameters& p, const SolveOptions& options) {
  ceres::Problem::Options problem_options;
  auto problem = std::make_unique<ceres::Problem>(problem_options);
  int residual_count = 0;
  for (std::size_t k = 0; k < data.size(); ++k) {
    const TossData& d = data[k];
    int samples = static_cast<int>(std::ceil(options.fraction * d.tau.size()));
    if (options.window > 0)
      samples = static_cast<int>(std::upper_bound(d.tau.begin(), d.tau.end(), options.window) -
                                 d.tau.begin());
    samples = std::clamp(samples, std::min<int>(4, d.tau.size()), static_cast<int>(d.tau.size()));
    int stride = 1;
    if (options.spacing > 0 && d.tau.size() >= 2) {
      const double step = d.tau.back() / static_cast<double>(d.tau.size() - 1);
      stride = std::max(1, static_cast<int>(options.spacing / step));
    }
    auto* cost = new TossCost(&d, samples, stride, p.R0, options.drag);
    problem->AddResidualBlock(cost, nullptr, p.aa.data(), p.log_ratios.data(), p.omega0[k].data(),
                              p.e.at(d.group).data());
    const bool rate_held = k < options.rate_held.size() && options.rate_held[k];
    if (options.drag == physics::DragLaw::none || options.rates_fixed || rate_held)
      problem->SetManifold(p.omega0[k].data(), new ceres::SubsetManifold(4, {3}));
    residual_count += cost->num_residuals();
  }
  if (options.body_fixed || options.moments_fixed)
    problem->SetParameterBlockConstant(p.log_ratios.data());
  if (options.body_fixed) problem->SetParameterBlockConstant(p.aa.data());
  // A group's bias correction is shared by its tosses: fitted with two or more, within its
  // rest's bound where it has one, held otherwise (docs/phone-lab.md, "The bias").
  const std::vector<int> in_group = tosses_per_group(data, p.e.size());
  for (std::size_t g = 0; g < p.e.size(); ++g) {
    if (in_group[g] == 0) continue;  // not in this problem
    double* e = p.e[g].data();
    if (options.body_fixed || options.bias_held || in_group[g] < 2) {
      problem->SetParameterBlockConstant(e);
    } else if (g < options.bias_bound.size() && options.bias_bound[g]) {
      const Eigen::Vector3d offset =
          g < options.bias_offset.size() ? options.bias_offset[g] : Eigen::Vector3d::Zero();
      for (int i = 0; i < 3; ++i) {
        // A rest without scatter (a synthetic one) allows 1e-9 rad/s at most.
        const double bound = std::max((*options.bias_bound[g])[i], 1e-9);
        e[i] = std::clamp(e[i], -bound - offset[i], bound - offset[i]);
        problem->SetParameterLowerBound(e, i, -bound - offset[i]);
        problem->SetParameterUpperBound(e, i, bound - offset[i]);
      }
    }
  }
  ceres::Solver::Options solver_options;
  // The tosses' ω0 blocks are independent given the body: eliminated (Schur complement), the
  // linear system is the body's five parameters, however many tosses there are.
  solver_options.linear_solver_type = ceres::DENSE_SCHUR;
  solver_options.max_num_iterations = 200;
  solver_options.function_tolerance = 1e-10;
  solver_options.gradient_tolerance = 1e-12;
  solver_options.parameter_tolerance = 1e-10;
  solver_options.logging_type = ceres::SILENT;
  // Ceres reports a failed step through glog (its "Linear solver failure" warnings and the
  // "Terminating" error) whatever logging_type says; the fit says what failed in its own one
  // line (docs/architecture.md, "Errors"), so glog keeps only FATAL. The explorer's Ceres logs
  // through its own miniglog, built to keep only FATAL (web/build-wasm-deps.sh).
#ifndef BOOKSPIN_MINIGLOG
  static std::once_flag quiet;
  std::call_once(quiet, [] { FLAGS_minloglevel = google::GLOG_FATAL; });
#endif
  // One thread: with several, Ceres hands the residual blocks to its threads as they come free
  // and each thread sums its own cost and gradient, so the order of the sums, and the last bits
  // of every number after them, followed the machine's load (ten runs at once differed by up to
  // 3e-9 relative). The same input gives the same bytes; the fit's time hardly changes (its CPU
  // time was its wall time already, docs/performance.md, "The phone-toss fit").
  solver_options.num_threads = 1;
  StopCallback stop(options.stop);
  solver_options.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, problem.get(), &summary);
  if (stop.signal()) throw Interrupted(stop.signal());
  Solved solved{summary.final_cost, residual_count,
                summary.IsSolutionUsable() && std::isfinite(summary.final_cost)};
  return solved;
}

/// The fit's covariance (JᵀJ)⁻¹ at `p`, unscaled, in the blocks the report needs: the body's
/// (aa then the log ratios; aa alone with the moments fixed) and each toss's (ω0, then its drag
/// rate where a law is fitted). J is TossModel's over every sample. The ω0 blocks are eliminated as
/// the solver does (Schur complement S = B − Σ E_k C_k⁻¹ E_kᵀ of the normal matrix [B E; Eᵀ
/// diag(C_k)]): cov(body) = S⁻¹, cov(ω0_k) = C_k⁻¹ + C_k⁻¹ E_kᵀ S⁻¹ E_k C_k⁻¹; O(tosses) rather
/// than the O(tosses³) of the whole matrix. nullopt when S or a C_k is singular to working
/// precision (reciprocal condition below 1e-14: the fit cannot tell every value apart).
struct Covariances {
  /// aa, the log ratios unless fixed, then each fitted group's e (in group order).
  Eigen::MatrixXd body;
  std::vector<Eigen::MatrixXd> omega0;  ///< 3×3, or 4×4 with the drag rate last
  /// Per group: the row of its e in `body`, or −1 where its e is not fitted.
  std::vector<int> bias_row;
};
std::optional<Covariances> covariances(const std::vector<TossData>& data, const Parameters& p,
                                       bool moments_fixed, const std::vector<bool>& bias_fitted,
                                       physics::DragLaw law) {
  // The body's columns of [J_θ | I] (θ: TossModel's nine, then the toss's group's bias
  // correction e): aa, the log ratios unless fixed, e where its group's is fitted; the toss's:
  // ω0, its rate. The body's rows: those, with one e block per fitted group.
  std::vector<int> shared{0, 1, 2}, toss{5, 6, 7};
  if (!moments_fixed) shared.insert(shared.end(), {3, 4});
  if (law != physics::DragLaw::none) toss.push_back(8);
  std::vector<int> bias_row(bias_fitted.size(), -1);
  int nb = static_cast<int>(shared.size());
  for (std::size_t g = 0; g < bias_fitted.size(); ++g)
    if (bias_fitted[g]) bias_row[g] = nb, nb += 3;
  // Toss k's body columns in its own 12 and their rows in the body's.
  const auto columns_of = [&](int group, std::vector<int>& local, std::vector<int>& rows) {
    local = shared;
    rows.clear();
    for (std::size_t i = 0; i < shared.size(); ++i) rows.push_back(static_cast<int>(i));
    if (bias_row[group] >= 0)
      for (int c = 0; c < 3; ++c) local.push_back(9 + c), rows.push_back(bias_row[group] + c);
  };
  constexpr double kMinReciprocalCondition = 1e-14;
  const auto well_conditioned = [&](const Eigen::MatrixXd& m) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(m, Eigen::EigenvaluesOnly);
    const Eigen::VectorXd v = eigen.eigenvalues();
    return v.minCoeff() > kMinReciprocalCondition * v.cwiseAbs().maxCoeff();
  };
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(nb, nb);
  std::vector<Eigen::MatrixXd> E(data.size());
  std::vector<Eigen::MatrixXd> C_inverse(data.size());
  std::vector<std::vector<int>> rows_of(data.size());
  for (std::size_t k = 0; k < data.size(); ++k) {
    std::vector<int> body;
    columns_of(data[k].group, body, rows_of[k]);
    const TossModel model(p.R0, p.aa.data(), p.log_ratios.data(), p.omega0[k].data(), law, true);
    Eigen::Matrix<double, 12, 12> full = Eigen::Matrix<double, 12, 12>::Zero();
    Eigen::Matrix<double, 3, 12> J = Eigen::Matrix<double, 3, 12>::Zero();
    J.rightCols<3>().setIdentity();
    TossModel::Jacobian J_theta;
    for (double tau : data[k].tau) {
      model.omega(tau, &J_theta);
      J.leftCols<TossModel::kParameters>() = J_theta;
      full.selfadjointView<Eigen::Upper>().rankUpdate(J.transpose());
    }
    full = full.selfadjointView<Eigen::Upper>();
    const Eigen::MatrixXd B = full(body, body);
    const Eigen::MatrixXd C = full(toss, toss);
    if (!well_conditioned(C)) return std::nullopt;
    C_inverse[k] = C.inverse();
    E[k] = full(body, toss);
    S(rows_of[k], rows_of[k]) += B - E[k] * C_inverse[k] * E[k].transpose();
  }
  S = 0.5 * (S + S.transpose());
  if (!well_conditioned(S)) return std::nullopt;
  Covariances result;
  result.body = S.inverse();
  result.bias_row = bias_row;
  for (std::size_t k = 0; k < data.size(); ++k) {
    const Eigen::MatrixXd G = E[k] * C_inverse[k];  // its body columns × nt
    const Eigen::MatrixXd body_k = result.body(rows_of[k], rows_of[k]);
    result.omega0.push_back(C_inverse[k] + G.transpose() * body_k * G);
  }
  if (!result.body.allFinite() || (result.body.diagonal().array() <= 0.0).any())
    return std::nullopt;
  for (const Eigen::MatrixXd& c : result.omega0)
    if (!c.allFinite() || (c.diagonal().array() <= 0.0).any()) return std::nullopt;
  return result;
}

/// Times of the sign changes of `values` (hysteresis at ±`band`), by linear interpolation.
std::vector<double> sign_changes(const std::vector<double>& t, const std::vector<double>& values,
                                 double band) {
  std::vector<double> crossings;
  int sign = 0;
  int last_index = -1;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const int s = values[i] > band ? 1 : values[i] < -band ? -1 : 0;
    if (s == 0) continue;
    if (sign != 0 && s != sign) {
      // The crossing: the last zero of the line between the samples around it.
      std::size_t j = static_cast<std::size_t>(last_index);
      for (std::size_t k = j; k < i; ++k)
        if ((values[k] > 0) != (values[k + 1] > 0)) j = k;
      const double a = values[j], b = values[j + 1];
      crossings.push_back(t[j] + (t[j + 1] - t[j]) * a / (a - b));
    }
    sign = s;
    last_index = static_cast<int>(i);
  }
  return crossings;
}

/// The mean spacing of the sign changes of the component along `axis` (phone frame) of
/// `omega(τ)` sampled at `tau` (s): the estimator half_period_measured uses, applied to a
/// model; nullopt with fewer than two sign changes.
template <typename OmegaAt>
std::optional<double> mean_flip_spacing(const std::vector<double>& tau, const Eigen::Vector3d& axis,
                                        OmegaAt omega) {
  std::vector<double> along(tau.size());
  double peak = 0.0;
  for (std::size_t i = 0; i < tau.size(); ++i) {
    along[i] = axis.dot(omega(tau[i]));
    peak = std::max(peak, std::abs(along[i]));
  }
  const std::vector<double> crossings = sign_changes(tau, along, 0.2 * peak);
  if (crossings.size() < 2) return std::nullopt;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

/// T/2 of a (damped) exact motion over a flight sampled at `tau`: the mean spacing of its flips
/// there, or its T/2 at the flight's middle where it flips fewer than twice (docs/physics.md
/// §21); nullopt for a steady motion or one the drag stops before a flip.
std::optional<double> motion_half_period(const physics::DampedExactRotation& motion,
                                         const Eigen::Matrix3d& axes,
                                         const std::vector<double>& tau) {
  if (!std::isfinite(motion.free().flip_period())) return std::nullopt;
  if (!motion.drag().active()) return motion.free().flip_period();  // T/2 exactly
  const std::optional<double> spacing = mean_flip_spacing(
      tau, axes.col(1), [&](double t) { return Eigen::Vector3d(axes * motion.omega_body(t)); });
  if (spacing) return spacing;
  const double middle = 0.5 * (tau.front() + tau.back());
  const double half = motion.flip_period_at(middle);
  if (!std::isfinite(half)) return std::nullopt;
  return half;
}

/// The gyroscope's scatter at rest (rad/s, per component, RMS): the samples outside every
/// flight within rest_omega/2 of the bias; nullopt with fewer than 20 such samples.
std::optional<double> rest_noise(const GyroRecording& recording, const FlightSearch& search) {
  const double rest = 0.5 * FinderSettings{}.rest_omega;
  std::size_t flight = 0;
  double sum2 = 0.0;
  int count = 0;
  for (int i = 0; i < static_cast<int>(recording.t.size()); ++i) {
    while (flight < search.flights.size() && search.flights[flight].last < i) ++flight;
    if (flight < search.flights.size() && search.flights[flight].first <= i) continue;
    const Eigen::Vector3d d = recording.omega[i] - search.bias;
    if (d.norm() > rest) continue;
    sum2 += d.squaredNorm();
    ++count;
  }
  if (count < 20) return std::nullopt;
  return std::sqrt(sum2 / (3.0 * count));
}

/// The flag of one toss from its residual r_i = ω_fitted − ω_measured (docs/phone-lab.md,
/// "Flags"): 50 ms blocks' RMS against the median block and the noise at rest; empty for a
/// toss whose residual looks like noise and an unmodelled smooth remainder.
std::string flag_of(const std::vector<double>& tau, const std::vector<Eigen::Vector3d>& residual,
                    double mean_omega, std::optional<double> noise) {
  const double duration = tau.back() - tau.front();
  double total2 = 0.0;
  for (const Eigen::Vector3d& r : residual) total2 += r.squaredNorm();
  const double rms = std::sqrt(total2 / residual.size());
  const auto fixed = [](double value, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return std::string(text);
  };
  // Blocks of 50 ms (at least 4 samples each).
  const int blocks = std::max(1, static_cast<int>(duration / kBlock));
  std::vector<double> block2(blocks, 0.0);
  std::vector<int> block_n(blocks, 0);
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const int b =
        std::min(blocks - 1, static_cast<int>((tau[i] - tau.front()) / duration * blocks));
    block2[b] += residual[i].squaredNorm();
    ++block_n[b];
  }
  std::vector<double> block_rms;
  for (int b = 0; b < blocks; ++b)
    block_rms.push_back(block_n[b] ? std::sqrt(block2[b] / block_n[b]) : 0.0);
  std::vector<double> sorted = block_rms;
  std::nth_element(sorted.begin(), sorted.begin() + blocks / 2, sorted.end());
  const double median = sorted[blocks / 2];
  const double floor = noise ? std::sqrt(3.0) * 5.0 * *noise : 0.0;  // |r| of 5σ per component
  int worst = 0;
  for (int b = 1; b < blocks; ++b)
    if (block_rms[b] > block_rms[worst]) worst = b;
  if (blocks >= 4 && block_rms[worst] > kBlockFactor * median && block_rms[worst] > floor) {
    const double at = tau.front() + (worst + 0.5) * duration / blocks;
    const std::string where = "the residual jumps to " + fixed(block_rms[worst], 2) +
                              " rad/s near t = " + fixed(at, 2) + " s of the flight (typical " +
                              fixed(median, 2) + ")";
    if (worst >= blocks - 2) return "a catch inside the flight? " + where;
    if (worst <= 1) return "the throw inside the flight? " + where;
    return "a knock, or the phone slipping on the body? " + where;
  }
  if (rms > kNoFit * mean_omega)
    return "a body that flexes, or not a free flight: the residual is " +
           fixed(100 * rms / mean_omega, 1) + " % of |ω| throughout";
  return {};
}

/// The correlation inflation of a least-squares variance: with residuals correlated from
/// sample to sample (lag-1 autocorrelation ρ, each component), a variance from (JᵀJ)⁻¹ is
/// (1 + ρ)/(1 − ρ) times too small (an AR(1) residual); 1 for white residuals, capped at 400.
double correlation_inflation(const std::vector<std::vector<Eigen::Vector3d>>& residuals) {
  double lag0 = 0.0, lag1 = 0.0;
  for (const std::vector<Eigen::Vector3d>& r : residuals)
    for (std::size_t i = 0; i < r.size(); ++i) {
      lag0 += r[i].squaredNorm();
      if (i + 1 < r.size()) lag1 += r[i].dot(r[i + 1]);
    }
  if (!(lag0 > 0.0)) return 1.0;
  const double rho = std::clamp(lag1 / lag0, 0.0, 0.995);
  return (1.0 + rho) / (1.0 - rho);
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
  // Pooled: its recording's correction removed too.
  const RecordingPart* part = part_at(fit.parts, flight.t_start);
  const Eigen::Vector3d bias =
      fit.search.bias + (part ? part->bias_correction : Eigen::Vector3d::Zero());
  for (int i = flight.first; i <= flight.last; ++i) omega.push_back(recording.omega[i] - bias);
}

FitResult fit_recording(const GyroRecording& recording, const FlightSearch& search,
                        const FitSettings& settings) {
  FitResult result;
  result.parts = recording.parts;
  result.search = search;
  result.drag = settings.drag;
  if (search.flights.empty()) {
    std::string why;
    for (const DroppedStretch& d : search.dropped)
      why += (why.empty() ? " (" : "; ") + std::to_string(d.t_start) + "–" +
             std::to_string(d.t_end) + " s: " + d.reason;
    if (!why.empty()) why += ")";
    throw InputError(recording.source + ": no free flight found" + why);
  }
  // The samples where the gyroscope read its range are its range, not the motion: left out
  // (docs/phone-lab.md, "Saturation").
  const Saturation saturation = find_saturation(recording);
  // Pooled, each recording's tosses share its bias correction: one group per recording.
  const std::size_t groups = std::max<std::size_t>(1, recording.parts.size());
  std::vector<TossData> data;
  for (const Flight& f : search.flights) {
    TossData d;
    if (const RecordingPart* part = part_at(recording.parts, f.t_start))
      d.group = static_cast<int>(part - recording.parts.data());
    d.samples = f.last - f.first + 1;
    for (int i = f.first; i <= f.last; ++i) d.saturated += saturation.at_range[i] ? 1 : 0;
    const bool drop = d.samples - d.saturated >= kMinSamplesLeft;
    for (int i = f.first; i <= f.last; ++i) {
      if (drop && saturation.at_range[i]) continue;
      d.tau.push_back(recording.t[i] - f.t_start);
      d.omega.push_back(recording.omega[i] - search.bias);
    }
    if (!drop) d.saturated = 0;  // kept: none left out
    data.push_back(std::move(d));
  }
  if (saturation.range) {
    int count = 0, clipped = 0;
    for (const TossData& d : data) count += d.saturated;
    for (bool at : saturation.at_range) clipped += at ? 1 : 0;
    char line[300];
    std::snprintf(line, sizeof line,
                  "the gyroscope saturated: %d sample(s) of the recording read its range, "
                  "±%.6g rad/s (%.0f °/s); %d of them in the tosses, left out of the fit",
                  clipped, *saturation.range, *saturation.range * 180.0 / kPi, count);
    result.body.notes.push_back(line);
    result.saturation_range = saturation.range;
  }
  const bool fixed = settings.moments.has_value();
  const physics::DragLaw law = settings.drag;
  const bool dragged = law != physics::DragLaw::none;
  Parameters p = start(data, settings, recording.t);
  p.e.assign(groups, {0.0, 0.0, 0.0});
  // The bias: the still rest's mean, corrected by the flights (two or more) within Rest::bound()
  // (3 standard errors of the mean and the drift's allowance) on each axis; with no still rest,
  // fitted from the flights freely (docs/phone-lab.md, "The bias"); pooled, each recording's by its
  // own flights within its own rest's bound. Bounded, the correction is held while the body settles
  // and freed after: a bounded solve from a body still far off leaves it at the bound's wall.
  std::vector<std::optional<Eigen::Vector3d>> bias_bound(groups);
  if (recording.parts.empty()) {
    if (search.rest.samples > 0) bias_bound[0] = search.rest.bound();
  } else {
    for (std::size_t g = 0; g < groups; ++g)
      if (recording.parts[g].rest.samples > 0) bias_bound[g] = recording.parts[g].rest.bound();
  }
  const std::vector<int> group_tosses = tosses_per_group(data, groups);
  std::vector<bool> bias_fitted(groups), bias_free(groups);
  bool any_bound = false;
  int fitted_groups = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    bias_fitted[g] = group_tosses[g] >= 2;
    bias_free[g] = bias_fitted[g] && !bias_bound[g];
    any_bound = any_bound || (bias_fitted[g] && bias_bound[g]);
    fitted_groups += bias_fitted[g];
  }
  // Grown over each toss, so that a rough start does not lock onto a wrong phase; the drag
  // rates join once the phases are found (the last stage).
  for (double fraction : {0.3, 0.6, 1.0}) {
    SolveOptions options;
    options.stop = &settings.stop;
    options.moments_fixed = fixed;
    options.fraction = fraction;
    options.spacing = 0.01;
    options.drag = law;
    options.rates_fixed = fraction < 1.0;
    if (!solve(data, p, options).usable)
      throw InputError(recording.source + ": the fit did not converge");
    normalise(p);
  }
  SolveOptions full;
  full.stop = &settings.stop;
  full.moments_fixed = fixed;
  full.drag = law;
  if (any_bound) {
    for (std::size_t g = 0; g < groups; ++g)
      if (bias_bound[g])
        for (int i = 0; i < 3; ++i)
          p.e[g][i] = std::clamp(p.e[g][i], -(*bias_bound[g])[i], (*bias_bound[g])[i]);
    full.bias_held = true;
    if (!solve(data, p, full).usable)
      throw InputError(recording.source + ": the fit did not converge");
    full.bias_held = false;
    full.bias_bound = bias_bound;
  }
  Solved solved = solve(data, p, full);
  if (!solved.usable) throw InputError(recording.source + ": the fit did not converge");
  // Air cannot speed a body up (docs/phone-lab.md, "Drag"): a toss whose rate came out below 0
  // is fitted again with its rate held at 0. Held, not bounded: a bound that a rate meets from
  // its start at 0 stalled Ceres's bounded steps far from the fit.
  if (dragged) {
    full.rate_held.assign(data.size(), false);
    bool any = false;
    for (std::size_t k = 0; k < data.size(); ++k)
      if (p.omega0[k][3] < 0.0) {
        p.omega0[k][3] = 0.0;
        full.rate_held[k] = any = true;
      }
    if (any) {
      solved = solve(data, p, full);
      if (!solved.usable) throw InputError(recording.source + ": the fit did not converge");
    }
  }
  // The bias in flight: the rest's plus the fitted correction (pooled: each recording's own);
  // the samples corrected by it, so that what follows (and measured_omega) sees them as the fit
  // did.
  std::vector<Eigen::Vector3d> correction(groups);
  for (std::size_t g = 0; g < groups; ++g)
    correction[g] = Eigen::Vector3d(p.e[g][0], p.e[g][1], p.e[g][2]);
  if (recording.parts.empty()) {
    result.search.bias += correction[0];
    result.bias_correction = correction[0];
  } else {
    for (std::size_t g = 0; g < groups; ++g) result.parts[g].bias_correction = correction[g];
  }
  for (TossData& d : data)
    for (Eigen::Vector3d& w : d.omega) w -= correction[d.group];
  p.e.assign(groups, {0.0, 0.0, 0.0});

  BodyEstimate& body = result.body;
  body.ratios = p.moments();
  body.axes = p.axes();
  body.moments_fixed = fixed;
  // The residuals of the joint fit, per toss.
  std::vector<std::vector<Eigen::Vector3d>> residuals(data.size());
  for (std::size_t k = 0; k < data.size(); ++k) {
    const TossModel model(p.R0, p.aa.data(), p.log_ratios.data(), p.omega0[k].data(), law, false);
    for (std::size_t i = 0; i < data[k].tau.size(); ++i)
      residuals[k].push_back(model.omega(data[k].tau[i]) - data[k].omega[i]);
  }
  // Uncertainties: (JᵀJ)⁻¹ scaled by the residual variance and by the residual's correlation
  // (docs/phone-lab.md, "Error bars"); the body's then widened to the folds' spread below.
  const int parameter_count =
      (fixed ? 3 : 5) + 3 * fitted_groups + (dragged ? 4 : 3) * static_cast<int>(data.size());
  const double variance = 2.0 * solved.cost / std::max(1, solved.residuals - parameter_count) *
                          correlation_inflation(residuals);
  const std::optional<Covariances> covariance = covariances(data, p, fixed, bias_fitted, law);
  std::vector<std::optional<Eigen::Vector3d>> omega0_sigma(data.size());
  std::vector<std::optional<double>> rate_sigma(data.size());
  if (covariance) {
    const Eigen::MatrixXd& c = covariance->body;
    Eigen::Vector3d axis_sigma;
    for (int i = 0; i < 3; ++i) {
      // Axis i turns by the rotation's components about the other two axes.
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      axis_sigma[i] = std::sqrt(variance * (c(j, j) + c(k, k))) * 180.0 / kPi;
    }
    body.axis_sigma_deg = axis_sigma;
    if (fixed)
      body.ratio_sigma = Eigen::Vector3d::Zero();
    else
      body.ratio_sigma = Eigen::Vector3d(body.ratios[0] * std::sqrt(variance * c(3, 3)),
                                         body.ratios[1] * std::sqrt(variance * c(4, 4)), 0.0);
    for (std::size_t g = 0; g < groups; ++g) {
      if (!bias_free[g]) continue;
      const int e = covariance->bias_row[g];
      const Eigen::Vector3d sigma(std::sqrt(variance * c(e, e)),
                                  std::sqrt(variance * c(e + 1, e + 1)),
                                  std::sqrt(variance * c(e + 2, e + 2)));
      if (recording.parts.empty())
        result.bias_fitted_sigma = sigma;
      else
        result.parts[g].bias_fitted_sigma = sigma;
    }
    for (std::size_t k = 0; k < data.size(); ++k) {
      const Eigen::MatrixXd& ck = covariance->omega0[k];
      omega0_sigma[k] = (variance * ck.diagonal().head<3>()).cwiseSqrt();
      if (dragged) rate_sigma[k] = std::sqrt(variance * ck(3, 3));
    }
  } else {
    body.notes.push_back("the fit cannot tell every value apart: no uncertainties");
  }

  const Parameters joint = p;
  // The body each toss's prediction uses, fitted without it: the tosses are dealt into at most
  // five folds (toss k into fold k mod folds) and each fold's body is fitted on the tosses of
  // the other folds, so that with up to five tosses it is the body of all the others, and with
  // more the fits stay five, not one per toss. With --moments and one toss, the moments given,
  // and the axes fitted with ω0 on the toss's first predict_window s below. None when a fold's
  // fit fails: no prediction then. The same fold bodies give the moments' jackknife spread.
  const std::size_t folds = std::max<std::size_t>(1, std::min<std::size_t>(data.size(), 5));
  std::vector<std::optional<Parameters>> fold_body(folds);
  std::vector<double> fold_rate(folds, 0.0);  // the mean drag rate of each fold body's tosses
  if (data.size() >= 2) {
    for (std::size_t f = 0; f < folds; ++f) {
      std::vector<TossData> rest;
      Parameters q = joint;
      q.omega0.clear();
      for (std::size_t j = 0; j < data.size(); ++j)
        if (j % folds != f) rest.push_back(data[j]), q.omega0.push_back(joint.omega0[j]);
      SolveOptions options;
      options.stop = &settings.stop;
      options.moments_fixed = fixed;
      options.drag = law;
      options.spacing = 0.01;  // at 100 Hz whatever the rate: five fits of nearly every toss
      if (any_bound) {
        options.bias_held = true;
        if (!solve(rest, q, options).usable) continue;
        options.bias_held = false;
        options.bias_bound = bias_bound;
        options.bias_offset = correction;
      }
      if (!solve(rest, q, options).usable) continue;
      normalise(q);
      fold_body[f] = q;
      for (const std::array<double, 4>& w : q.omega0)
        fold_rate[f] += std::max(w[3], 0.0) / static_cast<double>(q.omega0.size());
    }
  } else if (fixed) {
    fold_body[0] = joint;
  }
  // The grouped jackknife over the folds: σ² = (G − 1)/G Σ (θ_g − θ̄)², each axis's turn from the
  // joint axes; the larger of it and the covariance's σ (docs/phone-lab.md, "Error bars").
  if (folds >= 3 && body.ratio_sigma && body.axis_sigma_deg) {
    std::vector<Eigen::Vector3d> ratios, turns;
    for (const std::optional<Parameters>& q : fold_body) {
      if (!q) continue;
      ratios.push_back(q->moments());
      Eigen::Vector3d turn;
      const Eigen::Matrix3d a = q->axes();
      for (int i = 0; i < 3; ++i)
        turn[i] = std::acos(std::min(1.0, std::abs(a.col(i).dot(body.axes.col(i))))) * 180.0 / kPi;
      turns.push_back(turn);
    }
    const double g = static_cast<double>(ratios.size());
    if (ratios.size() >= 3) {
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
  }
  const std::optional<double> noise = rest_noise(recording, search);
  int stable_count = 0;
  for (std::size_t k = 0; k < data.size(); ++k) {
    const TossData& d = data[k];
    TossFit toss;
    toss.flight = search.flights[k];
    toss.omega0 = Eigen::Vector3d(joint.omega0[k][0], joint.omega0[k][1], joint.omega0[k][2]);
    toss.omega0_sigma = omega0_sigma[k];
    toss.drag_rate = dragged ? joint.omega0[k][3] : 0.0;
    toss.drag_rate_sigma = rate_sigma[k];
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
    double peak_omega = 0.0;  // the largest component measured, rad/s
    for (const Eigen::Vector3d& w : d.omega)
      peak_omega = std::max(peak_omega, w.cwiseAbs().maxCoeff());
    toss.saturated = d.saturated;
    int at_range = 0;  // the flight's samples at the range, left out or not
    for (int i = toss.flight.first; i <= toss.flight.last; ++i) at_range += saturation.at_range[i];
    if (peak_omega > kGyroRangeMax) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "ω reaches %.4g rad/s, beyond any gyroscope's range (phones: ±2000 °/s, "
                    "34.9 rad/s; at most ±4000 °/s, 69.8 rad/s): a recording in °/s, or scaled?",
                    peak_omega);
      toss.flag = text;
    } else if (at_range > 0 && 4 * (d.samples - at_range) < d.samples) {  // under a quarter left
      char text[200];
      std::snprintf(text, sizeof text,
                    "gyroscope saturated: %d of the flight's %d samples read its range (±%.4g "
                    "rad/s), under a quarter left: too much of the motion is missing to trust "
                    "the fit",
                    at_range, d.samples, *saturation.range);
      toss.flag = text;
    } else {
      toss.flag = flag_of(d.tau, residuals[k], mean_omega, noise);
      if (!toss.flag.empty() && d.saturated > 0)  // the clip named beside what the rest shows
        toss.flag += " (the gyroscope saturated: " + std::to_string(d.saturated) +
                     " of its samples read its range, left out)";
    }
    toss.poor_fit = !toss.flag.empty();
    if (toss.poor_fit)
      body.notes.push_back("toss " + std::to_string(k + 1) + " flagged: " + toss.flag +
                           "; its values are not to be trusted");
    toss.stable = exact.free().motion_case() == physics::ExactCase::steady ||
                  max_angle * 180.0 / kPi < kStableDegrees;
    if (toss.stable) ++stable_count;
    // L_decay: −slope/intercept of the least-squares line through |L|(τ).
    {
      const double n = static_cast<double>(d.tau.size());
      double st = 0, sl = 0, stt = 0, stl = 0;
      for (std::size_t i = 0; i < d.tau.size(); ++i) {
        st += d.tau[i], sl += L[i], stt += d.tau[i] * d.tau[i], stl += d.tau[i] * L[i];
      }
      const double slope = (n * stl - st * sl) / (n * stt - st * st);
      const double intercept = (sl - slope * st) / n;
      toss.L_decay = intercept > 0 ? -slope / intercept : 0.0;
    }
    // The measured flips: sign changes of ω about the intermediate axis.
    double peak = 0.0;
    for (double v : along) peak = std::max(peak, std::abs(v));
    const std::vector<double> crossings = sign_changes(d.tau, along, 0.2 * peak);
    if (crossings.size() >= 2)
      toss.half_period_measured =
          (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    // Prediction: the body and drag rate from the other tosses (or --moments), ω0 from this
    // toss's first predict_window s; its flips over the flight's times.
    const std::size_t fold = k % folds;
    const std::optional<Parameters>& held_out = fold_body[fold];
    if (held_out) {
      Parameters others = *held_out;
      std::vector<TossData> alone{d};
      others.omega0 = {
          {d.omega[0][0], d.omega[0][1], d.omega[0][2], data.size() >= 2 ? fold_rate[fold] : 0.0}};
      SolveOptions options;
      options.stop = &settings.stop;
      // One toss with --moments: its axes too from the first predict_window s alone.
      options.body_fixed = data.size() >= 2;
      options.moments_fixed = true;
      options.drag = law;
      options.rates_fixed = true;
      options.window = settings.predict_window;
      if (solve(alone, others, options).usable) {
        const Eigen::Matrix3d axes = others.axes();
        const physics::DampedExactRotation predicted(
            others.moments(),
            axes.transpose() *
                Eigen::Vector3d(others.omega0[0][0], others.omega0[0][1], others.omega0[0][2]),
            physics::Drag{law, others.omega0[0][3]}, physics::ExactParts::omega_only);
        toss.half_period_predicted = motion_half_period(predicted, axes, d.tau);
        // What it rests on: the tosses of the other folds (none with one toss and --moments).
        int from = 0;
        double seconds = 0.0;
        if (data.size() >= 2)
          for (std::size_t j = 0; j < data.size(); ++j)
            if (j % folds != fold) {
              ++from;
              seconds += search.flights[j].t_end - search.flights[j].t_start;
            }
        toss.predicted_from_tosses = from;
        toss.predicted_from_seconds = seconds;
        if (from > 0 && seconds < kShortBasis) {
          char line[220];
          std::snprintf(line, sizeof line,
                        "toss %zu's half_period_predicted rests on %d other toss(es), %.2f s of "
                        "flight in all: a short bounce alone pins the body poorly (fit the "
                        "recordings of one body together, or give --moments)",
                        k + 1, from, seconds);
          body.notes.push_back(line);
        }
      }
    }
    result.tosses.push_back(toss);
  }
  if (stable_count == static_cast<int>(data.size()) && !fixed) {
    body.moments_determined = false;
    body.notes.push_back(
        "every toss is stable (no flip): the moment ratios are poorly determined; give "
        "--moments I1,I2,I3 to fix them");
  } else if (stable_count > 0) {
    body.notes.push_back(std::to_string(stable_count) +
                         " stable toss(es) (no flip) fitted with the body the others determine");
  }
  // What the body rests on: the tosses that flip and fit cleanly, and their flight time. None,
  // or under kShortBasis s of them, pins no body (docs/phone-lab.md, "Flags").
  if (!fixed && stable_count < static_cast<int>(data.size())) {
    int good = 0;
    double good_seconds = 0.0;
    for (const TossFit& toss : result.tosses)
      if (!toss.stable && !toss.poor_fit)
        ++good, good_seconds += toss.flight.t_end - toss.flight.t_start;
    char line[240];
    if (good == 0) {
      body.moments_determined = false;
      body.notes.push_back(
          "no toss both flips and fits cleanly (every flipping toss is flagged): the moment "
          "ratios are poorly determined");
    } else if (good_seconds < kShortBasis) {
      body.moments_determined = false;
      std::snprintf(line, sizeof line,
                    "the body rests on %d clean flipping toss(es), %.2f s of flight (under %.1f "
                    "s): the moment ratios are poorly determined",
                    good, good_seconds, kShortBasis);
      body.notes.push_back(line);
    }
  }
  if (data.size() < 2 && !fixed)
    body.notes.push_back("one toss: no half_period_predicted (it needs the other tosses' body)");
  if (fixed) {
    // Two equal moments: a symmetric body, whose ω only circles its axis; there is no
    // intermediate axis, so no flip to fit or time (docs/physics.md §8).
    Eigen::Vector3d given = settings.moments->cwiseAbs();
    std::sort(given.data(), given.data() + 3);
    const double scale = given[2];
    if (given[1] - given[0] <= 1e-9 * scale || given[2] - given[1] <= 1e-9 * scale)
      body.notes.push_back(
          "--moments: two of the given moments are equal: a symmetric body has no intermediate "
          "axis, so nothing here flips and no half period is timed");
  }
  return result;
}

}  // namespace bookspin::fit
