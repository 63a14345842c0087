#pragma once
// The exact motion's flips in closed form (docs/physics.md §8, §14), computed from the
// invariants with the standard library's elliptic integrals, not by physics::ExactRotation:
// the tests' independent numbers for the flip counts and columns.
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

namespace bookspin::test {

struct ClosedFormFlips {
  double half_period = 0.0;  ///< T/2 = 2K(k)/λ: the spacing of the flips (time units)
  double first_flip = 0.0;   ///< the first zero of ω about the intermediate axis after t = 0
};

/// The flips of the torque-free body with principal `moments` (body x, y, z) spun at
/// body-frame `omega` (not steady, not on the separatrix). Case A or B by the sign of
/// L² − 2E·I2 (docs/physics.md §8): ω about the intermediate axis is A2·sn(λt + u0), so its
/// zeros are 2K/λ apart. Where the first lies follows from |sn u0| = |ω_mid(0)|/A2, |cn u0|
/// (likewise from the cn axis) and
/// whether |ω_mid| grows at t = 0 (Euler's equations, I ω̇ = (I ω) × ω, in the body frame):
/// growing, the last zero was F(atan2(|sn u0|, |cn u0|))/λ ago, else the next one is that far
/// ahead.
inline ClosedFormFlips closed_form_flips(const Eigen::Vector3d& moments,
                                         const Eigen::Vector3d& omega) {
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return moments[a] < moments[b]; });
  const long double I1 = moments[order[0]], I2 = moments[order[1]], I3 = moments[order[2]];
  long double L2 = 0, E2 = 0;
  for (int i = 0; i < 3; ++i) {
    L2 += static_cast<long double>(moments[i]) * moments[i] * omega[i] * omega[i];
    E2 += static_cast<long double>(moments[i]) * omega[i] * omega[i];
  }
  // The squared amplitudes of ω about the sn axis (the intermediate) and the cn axis.
  long double lambda = 0, k2 = 0, amplitude2 = 0, cn_amplitude2 = 0;
  int cn_axis = 0;
  if (L2 > E2 * I2) {  // Case A: ω circles the largest axis
    lambda = std::sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3));
    k2 = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1));
    amplitude2 = (E2 * I3 - L2) / (I2 * (I3 - I2));
    cn_axis = order[0];
    cn_amplitude2 = (E2 * I3 - L2) / (I1 * (I3 - I1));
  } else {  // Case B: ω circles the smallest axis
    lambda = std::sqrt((I2 - I1) * (E2 * I3 - L2) / (I1 * I2 * I3));
    k2 = (I3 - I2) * (L2 - E2 * I1) / ((I2 - I1) * (E2 * I3 - L2));
    amplitude2 = (L2 - E2 * I1) / (I2 * (I2 - I1));
    cn_axis = order[2];
    cn_amplitude2 = (L2 - E2 * I1) / (I3 * (I3 - I1));
  }
  const long double k = std::sqrt(k2);
  const long double K = std::comp_ellint_1(k);
  const int mid = order[1];
  const Eigen::Vector3d momentum = moments.cwiseProduct(omega);
  const double rate = momentum.cross(omega).cwiseQuotient(moments)[mid];
  // |sn u0| and |cn u0| from their two axes, so that the angle keeps its digits near K.
  const long double sn0 = std::abs(omega[mid]) / std::sqrt(amplitude2);
  const long double cn0 = std::abs(omega[cn_axis]) / std::sqrt(cn_amplitude2);
  const long double u = std::ellint_1(k, std::atan2(sn0, cn0));  // in [0, K]
  const bool growing = omega[mid] * rate >= 0.0;                 // ω_mid = 0: a flip at t = 0
  return {static_cast<double>(2.0L * K / lambda),
          static_cast<double>((growing ? 2.0L * K - u : u) / lambda)};
}

}  // namespace bookspin::test
