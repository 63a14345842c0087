#include "physics/polhode.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace bookspin::physics {

namespace {

/// Appends the points of curve(φ) for φ in (a, b], halving an interval while its chord is
/// longer than `max_step` (depth-limited: 2^20 points per initial interval at most).
void refine(const std::function<Eigen::Vector3d(double)>& curve, double a, double b,
            const Eigen::Vector3d& pa, const Eigen::Vector3d& pb, double max_step, int depth,
            std::vector<Eigen::Vector3d>& out) {
  if (depth < 20 && (pb - pa).norm() > max_step) {
    const double m = 0.5 * (a + b);
    const Eigen::Vector3d pm = curve(m);
    refine(curve, a, m, pa, pm, max_step, depth + 1, out);
    refine(curve, m, b, pm, pb, max_step, depth + 1, out);
    return;
  }
  out.push_back(pb);
}

}  // namespace

std::vector<Eigen::Vector3d> sample_closed_curve(
    const std::function<Eigen::Vector3d(double)>& curve, double max_step) {
  constexpr int kStart = 64;
  constexpr double kTwoPi = 6.283185307179586;
  std::vector<Eigen::Vector3d> points{curve(0.0)};
  for (int i = 0; i < kStart; ++i) {
    const double a = kTwoPi * i / kStart, b = kTwoPi * (i + 1) / kStart;
    refine(curve, a, b, points.back(), i + 1 == kStart ? points.front() : curve(b), max_step, 0,
           points);
  }
  return points;
}

double energy_ratio(const Eigen::Vector3d& moments, const Eigen::Vector3d& u) {
  return u.cwiseAbs2().cwiseQuotient(moments).sum();
}

std::vector<Eigen::Vector3d> polhode_about(const Eigen::Vector3d& moments, int pole, int b, int d,
                                           double c, double sign, double max_step) {
  const Eigen::Vector3d inv = moments.cwiseInverse();
  const double gap = std::abs(c - inv[pole]);
  const double rb = std::sqrt(gap / std::abs(inv[b] - inv[pole]));
  const double rd = std::sqrt(gap / std::abs(inv[d] - inv[pole]));
  const auto curve = [&](double phi) {
    Eigen::Vector3d u;
    u[b] = rb * std::cos(phi);
    u[d] = rd * std::sin(phi);
    u[pole] = sign * std::sqrt(std::max(0.0, 1.0 - u[b] * u[b] - u[d] * u[d]));
    return u;
  };
  return sample_closed_curve(curve, max_step);
}

std::vector<Polhode> polhode_family(const Eigen::Vector3d& moments, int levels, double max_step) {
  if (!moments.allFinite() || (moments.array() <= 0).any())
    throw std::invalid_argument("polhode_family: principal moments must be finite and > 0");
  if (levels < 1 || !(max_step > 0))
    throw std::invalid_argument("polhode_family: levels ≥ 1 and max_step > 0 required");
  const auto [lo, mid, hi] = principal_order(moments);
  const Eigen::Vector3d inv = moments.cwiseInverse();
  std::vector<Polhode> curves;

  // A family around `pole`: with u_pole² = 1 − u_b² − u_d², Σ u_i²/I_i = c becomes the
  // ellipse u_b²·|1/I_b − 1/I_pole| + u_d²·|1/I_d − 1/I_pole| = |c − 1/I_pole| in the
  // other two components (docs/physics.md §15), parametrized by φ.
  const auto family = [&](int pole, int b, int d, double c_sep) {
    const double width = std::abs(inv[pole] - c_sep);
    if (!(width > 1e-12 * inv[pole])) return;  // degenerate: symmetric about this pair
    for (int j = 0; j < levels; ++j) {
      const double f = (j + 0.5) / levels;
      const double c = c_sep + f * (inv[pole] - c_sep);
      for (const double sign : {1.0, -1.0})
        curves.push_back({polhode_about(moments, pole, b, d, c, sign, max_step), c, false, pole});
    }
  };
  family(lo, mid, hi, inv[mid]);
  family(hi, lo, mid, inv[mid]);

  // The separatrices: Σ u_i²(1/I_i − 1/I_mid) = 0 factors into two planes through the
  // intermediate axis, u_lo·√(1/I_lo − 1/I_mid) = ±u_hi·√(1/I_mid − 1/I_hi).
  const double a = std::sqrt(std::max(0.0, inv[lo] - inv[mid]));
  const double b = std::sqrt(std::max(0.0, inv[mid] - inv[hi]));
  if (a + b > 0) {
    for (const double sign : {1.0, -1.0}) {
      Eigen::Vector3d e_mid = Eigen::Vector3d::Zero(), in_plane = Eigen::Vector3d::Zero();
      e_mid[mid] = 1.0;
      in_plane[lo] = b;  // orthogonal to the plane's normal (a, 0, −sign·b) and to e_mid
      in_plane[hi] = sign * a;
      in_plane.normalize();
      const auto curve = [&](double phi) {
        return Eigen::Vector3d(std::cos(phi) * e_mid + std::sin(phi) * in_plane);
      };
      curves.push_back({sample_closed_curve(curve, max_step), inv[mid], true, -1});
    }
  }
  return curves;
}

Eigen::Vector3d momentum_direction_body(const Diagnostics& d) {
  const double n = d.cos_axis_L.norm();
  if (!(n > 0) || !std::isfinite(n)) return Eigen::Vector3d::Zero();
  return d.cos_axis_L / n;
}

MomentumDirections momentum_directions(const Eigen::Vector3d& moments,
                                       const Eigen::Matrix3Xd& omega) {
  MomentumDirections out;
  std::vector<Eigen::Vector3d> u;
  for (Eigen::Index i = 0; i < omega.cols(); ++i) {
    const Eigen::Vector3d L = moments.cwiseProduct(omega.col(i));
    const double norm = L.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) continue;
    out.samples.push_back(i);
    u.push_back(L / norm);
  }
  out.u.resize(3, static_cast<Eigen::Index>(u.size()));
  for (std::size_t k = 0; k < u.size(); ++k) out.u.col(static_cast<Eigen::Index>(k)) = u[k];
  return out;
}

}  // namespace bookspin::physics
