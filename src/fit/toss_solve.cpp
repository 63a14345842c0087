#include "fit/toss_solve.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "common/errors.hpp"
#include "fit/toss_model.hpp"

namespace bookspin::fit {
namespace {

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

/// One solve of `data` from `p`, unbounded: each group's bias components marked in `wall` held
/// at their value (solve()'s active set).
Solved solve_once(const std::vector<TossData>& data, Parameters& p, const SolveOptions& options,
                  const std::vector<std::array<bool, 3>>& wall) {
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
    const bool group_held = g < options.bias_group_held.size() && options.bias_group_held[g];
    if (options.body_fixed || options.bias_held || group_held || in_group[g] < 2) {
      problem->SetParameterBlockConstant(e);
      continue;
    }
    std::vector<int> held;
    for (int i = 0; i < 3; ++i)
      if (g < wall.size() && wall[g][i]) held.push_back(i);
    if (held.size() == 3)
      problem->SetParameterBlockConstant(e);
    else if (!held.empty())
      problem->SetManifold(e, new ceres::SubsetManifold(3, held));
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
  // time was its wall time already, docs/performance-physics.md, "The phone-toss fit").
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

}  // namespace

Solved solve(const std::vector<TossData>& data, Parameters& p, const SolveOptions& options) {
  // A bounded bias correction (docs/phone-lab.md, "The bias") by an active set, not by Ceres's
  // bounds: Ceres's projected steps along a wall that a component presses on stalled, declaring
  // convergence while the cost still fell (a restart lowered it again, five times over), and
  // where they stopped followed a few samples more or less at a flight's end by up to 3σ of
  // I1/I3 (docs/phone-lab.md, "Error bars"). So: solve with the correction free; any component
  // past its bound is set on it and held there; solve again, until none is past.
  std::vector<std::array<bool, 3>> wall(p.e.size(), {false, false, false});
  const auto bound_of = [&](std::size_t g, int i, double& low, double& high) {
    if (g >= options.bias_bound.size() || !options.bias_bound[g]) return false;
    const double offset = g < options.bias_offset.size() ? options.bias_offset[g][i] : 0.0;
    // A rest without scatter (a synthetic one) allows 1e-9 rad/s at most.
    const double bound = std::max((*options.bias_bound[g])[i], 1e-9);
    low = -bound - offset, high = bound - offset;
    return true;
  };
  for (std::size_t g = 0; g < p.e.size(); ++g)
    for (int i = 0; i < 3; ++i)
      if (double low, high; bound_of(g, i, low, high)) p.e[g][i] = std::clamp(p.e[g][i], low, high);
  for (;;) {
    const Solved solved = solve_once(data, p, options, wall);
    if (!solved.usable) return solved;
    bool past = false;
    for (std::size_t g = 0; g < p.e.size(); ++g)
      for (int i = 0; i < 3; ++i) {
        double low, high;
        if (wall[g][i] || !bound_of(g, i, low, high)) continue;
        if (p.e[g][i] >= low && p.e[g][i] <= high) continue;
        p.e[g][i] = std::clamp(p.e[g][i], low, high);
        wall[g][i] = past = true;
      }
    if (!past) return solved;
  }
}

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

std::vector<std::vector<Eigen::Vector3d>> residuals_of(const std::vector<TossData>& data,
                                                       const Parameters& p, physics::DragLaw law) {
  std::vector<std::vector<Eigen::Vector3d>> residuals(data.size());
  for (std::size_t k = 0; k < data.size(); ++k) {
    const TossModel model(p.R0, p.aa.data(), p.log_ratios.data(), p.omega0[k].data(), law, false);
    for (std::size_t i = 0; i < data[k].tau.size(); ++i)
      residuals[k].push_back(model.omega(data[k].tau[i]) - data[k].omega[i]);
  }
  return residuals;
}

void body_sigmas(const Eigen::MatrixXd& c, double variance, const Eigen::Vector3d& ratios,
                 bool fixed, std::optional<Eigen::Vector3d>& axis_sigma_deg,
                 std::optional<Eigen::Vector3d>& ratio_sigma) {
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  Eigen::Vector3d axis_sigma;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    axis_sigma[i] = std::sqrt(variance * (c(j, j) + c(k, k))) * kDegrees;
  }
  axis_sigma_deg = axis_sigma;
  ratio_sigma = fixed ? Eigen::Vector3d::Zero()
                      : Eigen::Vector3d(ratios[0] * std::sqrt(variance * c(3, 3)),
                                        ratios[1] * std::sqrt(variance * c(4, 4)), 0.0);
}

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

}  // namespace bookspin::fit
