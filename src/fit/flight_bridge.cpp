#include "fit/flight_bridge.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace bookspin::fit {

bool conserved(const Eigen::Matrix3d& I, const std::vector<Eigen::Vector3d>& omega, int from,
               int to) {
  const Eigen::Vector3d L0 = I * omega[from];
  const double l0 = L0.norm(), e0 = omega[from].dot(L0);
  for (int k = from + 1; k <= to; ++k) {
    const Eigen::Vector3d L = I * omega[k];
    if (std::abs(L.norm() - l0) > kConserved * l0 ||
        std::abs(omega[k].dot(L) - e0) > kConserved * e0)
      return false;
  }
  return true;
}

void bridge_conserved(std::vector<char>& mask, int offset, int first, int last,
                      std::vector<char>& bridged, const Eigen::Matrix3d& I,
                      const std::vector<Eigen::Vector3d>& omega, const std::vector<double>& t,
                      const std::vector<char>& allowed) {
  // |I ω| and ω·I ω say where ω may be in free flight only for a positive definite I.
  if (!(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues().minCoeff() > 0.0)) return;
  const auto marked = [&](int i) { return mask[i - offset] != 0; };
  for (int i = first + 1; i < last; ++i) {
    if (marked(i) || !marked(i - 1)) continue;
    int end = i;  // the first marked sample after the stretch
    while (end <= last && !marked(end)) ++end;
    bool bridge = end <= last && (end - i <= kBridgeSamples || t[end] - t[i - 1] <= kBridgeTime);
    for (int k = i; k < end && bridge; ++k) bridge = allowed[k] != 0;
    int reach = end;
    while (bridge && reach < std::min(last, end + kHalfWindow) && marked(reach + 1)) ++reach;
    if (bridge && conserved(I, omega, i - 1, reach))
      for (int k = i; k < end; ++k) mask[k - offset] = bridged[k] = 1;
    i = end;
  }
}

}  // namespace bookspin::fit
