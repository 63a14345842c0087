#pragma once
// The values the fit's stages hand each other (docs/phone-lab.md, "The fit"): which bias
// corrections the joint fit frees, and each toss's σ as the stages after it widen them
// (toss_fit.cpp assembles them; end_spread.hpp widens them).
#include <Eigen/Dense>
#include <optional>
#include <vector>

namespace bookspin::fit {

/// Which recordings' bias corrections the joint fit frees, and within what (docs/phone-lab.md,
/// "The bias"): a recording's correction is fitted from two or more of its flights, within its
/// still rest's Rest::bound() where it has one, freely where it has none.
struct BiasFreedom {
  std::vector<std::optional<Eigen::Vector3d>> bound;  ///< rad/s per recording, or nullopt
  /// Per recording: fitted by the joint fit; fitted with no bound; held at zero (its flights'
  /// bias noise).
  std::vector<bool> fitted, free, held;
  bool any_bound = false;
  int fitted_groups = 0;
};

/// Each toss's ω0 (rad/s, phone frame) and drag rate's standard deviations, one per toss; none
/// where the covariance cannot be computed (a rate's none without drag).
struct TossSigmas {
  std::vector<std::optional<Eigen::Vector3d>> omega0;
  std::vector<std::optional<double>> rate;
};

}  // namespace bookspin::fit
