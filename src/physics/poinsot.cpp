#include "physics/poinsot.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "physics/body.hpp"  // principal_order
#include "physics/polar.hpp"
#include "physics/polhode.hpp"

namespace bookspin::physics {

namespace {

void check_moments(const Eigen::Vector3d& moments) {
  if (!moments.allFinite() || (moments.array() <= 0).any())
    throw std::invalid_argument("Poinsot construction: principal moments must be finite and > 0");
}

}  // namespace

PoinsotState poinsot_state(const Eigen::Vector3d& moments, const Eigen::Matrix3d& rotation,
                           const Eigen::Vector3d& L) {
  check_moments(moments);
  const double L_norm = L.norm();
  if (!(L_norm > 0) || !std::isfinite(L_norm))
    throw std::invalid_argument("Poinsot construction: L must be finite and not zero");
  PoinsotState s;
  s.rotation = rotation;
  s.normal = L / L_norm;
  const Eigen::Vector3d L_body = rotation.transpose() * L;
  const Eigen::Vector3d omega_body = L_body.cwiseQuotient(moments);
  s.energy = 0.5 * L_body.dot(omega_body);
  const double root = std::sqrt(2.0 * s.energy);
  // ρ = ω/√(2E) satisfies ρᵀIρ = 1 and ρ·L/|L| = 2E/(√(2E)|L|) = √(2E)/|L| (§16).
  s.plane_distance = root / L_norm;
  s.contact = rotation * omega_body / root;
  s.semi_axes = moments.cwiseSqrt().cwiseInverse();
  return s;
}

double inertia_ellipsoid_value(const PoinsotState& s, const Eigen::Vector3d& moments,
                               const Eigen::Vector3d& x_world) {
  const Eigen::Vector3d x = s.rotation.transpose() * x_world;
  return x.cwiseAbs2().dot(moments);
}

Eigen::Vector3d inertia_ellipsoid_normal(const PoinsotState& s, const Eigen::Vector3d& moments,
                                         const Eigen::Vector3d& x_world) {
  const Eigen::Vector3d x = s.rotation.transpose() * x_world;
  return (s.rotation * x.cwiseProduct(moments)).normalized();
}

HerpolhodeBounds herpolhode_bounds(const Eigen::Vector3d& moments, double L_norm, double energy) {
  check_moments(moments);
  if (!(L_norm > 0) || !(energy > 0) || !std::isfinite(L_norm) || !std::isfinite(energy))
    throw std::invalid_argument("herpolhode_bounds: |L| and E must be finite and > 0");
  const double L2 = L_norm * L_norm, two_e = 2.0 * energy;
  const double d2 = two_e / L2;  // squared plane distance
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const double tol = 1e-12 * L2;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    // s_i + s_j = L², s_i/I_i + s_j/I_j = 2E  →  s_i = (2E − L²/I_j)/(1/I_i − 1/I_j).
    const double den = 1.0 / moments[i] - 1.0 / moments[j];
    if (std::abs(den) < 1e-14 / std::min(moments[i], moments[j])) continue;
    const double si = (two_e - L2 / moments[j]) / den, sj = L2 - si;
    if (si < -tol || sj < -tol) continue;
    const double w2 = std::max(si, 0.0) / (moments[i] * moments[i]) +
                      std::max(sj, 0.0) / (moments[j] * moments[j]);
    const double r2 = std::max(0.0, w2 / two_e - d2);
    lo = std::min(lo, r2);
    hi = std::max(hi, r2);
  }
  if (!(lo <= hi)) {
    // No end found: a symmetric body's motion (|ω| constant), or a steady spin.
    lo = hi = 0.0;
  }
  return {std::sqrt(lo), std::sqrt(hi)};
}

std::vector<Eigen::Vector3d> polhode_on_ellipsoid(const Eigen::Vector3d& moments,
                                                  const Eigen::Vector3d& u_in, double max_step) {
  check_moments(moments);
  if (!u_in.allFinite() || !(u_in.norm() > 0) || !(max_step > 0))
    throw std::invalid_argument("polhode_on_ellipsoid: u must be finite and not zero");
  const Eigen::Vector3d u0 = u_in.normalized();
  const Eigen::Vector3d inv = moments.cwiseInverse();
  const double c = energy_ratio(moments, u0);  // 2E/|L|²
  // ρ_body = I⁻¹ L_body/√(2E) = I⁻¹ u/√c for |L| = 1 (the shape does not depend on |L|).
  const auto to_ellipsoid = [&](const Eigen::Vector3d& u) -> Eigen::Vector3d {
    return u.cwiseProduct(inv) / std::sqrt(c);
  };
  const auto [lo, mid, hi] = principal_order(moments);
  const int pole = c > inv[mid] ? lo : hi;
  const int b = pole == lo ? mid : lo, d = pole == lo ? hi : mid;
  const double gap = std::abs(c - inv[pole]);
  const double db = std::abs(inv[b] - inv[pole]), dd = std::abs(inv[d] - inv[pole]);
  if (gap <= 1e-12 * inv[pole] || db <= 1e-12 * inv[pole] || dd <= 1e-12 * inv[pole])
    return {to_ellipsoid(u0)};  // a steady spin (or a symmetric body's circle: not drawn)
  const double sign = u0[pole] < 0 ? -1.0 : 1.0;
  const std::vector<Eigen::Vector3d> sphere = polhode_about(moments, pole, b, d, c, sign, max_step);
  std::vector<Eigen::Vector3d> out;
  out.reserve(sphere.size());
  for (const auto& u : sphere) out.push_back(to_ellipsoid(u));
  return out;
}

Eigen::Matrix3d rotation_from_corners(const Corners& corners) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (int p = 0; p < 8; ++p)
    for (int d = 0; d < 3; ++d) m.col(d) += ((p >> d) & 1 ? 0.25 : -0.25) * corners.col(p);
  for (int d = 0; d < 3; ++d) {
    const double n = m.col(d).norm();
    if (!(n > 0) || !std::isfinite(n))
      throw std::invalid_argument("rotation_from_corners: degenerate corners");
    m.col(d) /= n;
  }
  return nearest_rotation(m);
}

}  // namespace bookspin::physics
