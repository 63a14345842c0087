#pragma once
// The fit's least squares (docs/phone-lab.md, "The fit"; "Error bars"): the closed-form ω of
// each toss (toss_model.hpp) against its samples, solved by Ceres with what each stage holds
// fixed; and the covariance of the unknowns at the solution, with the inflation the residual's
// correlation calls for.
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "common/stop.hpp"
#include "fit/toss_parameters.hpp"
#include "physics/drag.hpp"

namespace bookspin::fit {

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
  /// Per group: its bias correction held (at its value) whatever else is asked; none: none.
  std::vector<bool> bias_group_held;
  std::vector<Eigen::Vector3d> bias_offset;
};

struct Solved {
  double cost = 0.0;    ///< half the sum of the squared residuals, (rad/s)²
  int residuals = 0;    ///< how many (three per sample fitted)
  bool usable = false;  ///< the solver's solution is usable and finite
};

/// Fits `p` to `data` under `options` (Ceres, one thread: the same input gives the same bytes).
/// Throws Interrupted when options.stop answers a signal.
Solved solve(const std::vector<TossData>& data, Parameters& p, const SolveOptions& options);

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
                                       physics::DragLaw law);

/// The residual ω_fitted − ω_measured of each toss of `data` at each of its samples (rad/s),
/// under `p` and the drag law `law`.
std::vector<std::vector<Eigen::Vector3d>> residuals_of(const std::vector<TossData>& data,
                                                       const Parameters& p, physics::DragLaw law);

/// The body's σ from its covariance `c` (Covariances::body, unscaled) times `variance`: each
/// axis's direction (degrees: it turns by the rotation's components about the other two) and
/// each of `ratios`' (0 with the moments `fixed`; the third always 0).
void body_sigmas(const Eigen::MatrixXd& c, double variance, const Eigen::Vector3d& ratios,
                 bool fixed, std::optional<Eigen::Vector3d>& axis_sigma_deg,
                 std::optional<Eigen::Vector3d>& ratio_sigma);

/// The correlation inflation of a least-squares variance: with residuals correlated from
/// sample to sample (lag-1 autocorrelation ρ, each component), a variance from (JᵀJ)⁻¹ is
/// (1 + ρ)/(1 − ρ) times too small (an AR(1) residual); 1 for white residuals, capped at 400.
double correlation_inflation(const std::vector<std::vector<Eigen::Vector3d>>& residuals);

}  // namespace bookspin::fit
