#include "physics/shape.hpp"

#include <Eigen/SVD>
#include <cmath>

namespace bookspin::physics {

const std::array<std::pair<int, int>, 28>& corner_pairs() {
  static const auto pairs = [] {
    std::array<std::pair<int, int>, 28> out{};
    int n = 0;
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j < 8; ++j) out[n++] = {i, j};
    return out;
  }();
  return pairs;
}

double strain_max(const Corners& corners, const Corners& rest) {
  double worst = 0.0;
  for (const auto& [i, j] : corner_pairs()) {
    const double len = (corners.col(i) - corners.col(j)).norm();
    const double rest_len = (rest.col(i) - rest.col(j)).norm();
    worst = std::max(worst, std::abs(len / rest_len - 1.0));
  }
  return worst;
}

Eigen::Matrix3d best_fit_rotation(const Corners& current, const Corners& rest) {
  const Eigen::Matrix3d H = current * rest.transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d fix = Eigen::Matrix3d::Identity();
  fix(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * fix * svd.matrixV().transpose();
}

double orthogonality_error(const Eigen::Matrix3d& m) {
  return (m.transpose() * m - Eigen::Matrix3d::Identity()).norm();
}

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& w) {
  Eigen::Matrix3d s;
  s << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  return s;
}

Eigen::Vector3d principal_cosines(const Eigen::Vector3d& cos_axis_L,
                                  const Eigen::Vector3d& moments) {
  const std::array<int, 3> order = principal_order(moments);
  return {cos_axis_L[order[0]], cos_axis_L[order[1]], cos_axis_L[order[2]]};
}

Diagnostics rigid_diagnostics(const Book& book, const Eigen::Matrix3d& M, const Eigen::Vector3d& L,
                              double t) {
  return rigid_diagnostics(book_body(book), M, L, t);
}

Diagnostics prescribed_diagnostics(const Body& body, const Eigen::Matrix3d& R,
                                   const Eigen::Vector3d& L, double t,
                                   const Eigen::Vector3d& omega_body, double energy_kinetic) {
  Diagnostics d = rigid_diagnostics(body, R, L, t);
  d.omega_body = omega_body;
  d.energy_kinetic = energy_kinetic;
  d.energy_potential = 0.0;
  d.energy_total = energy_kinetic;
  d.quaternion_norm = 1.0;
  if (!d.cos_axis_L.allFinite()) {  // L = 0: no direction to compare
    d.cos_axis_L.setZero();
    d.cos_principal_L.setZero();
  }
  return d;
}

Diagnostics rigid_diagnostics(const Body& body, const Eigen::Matrix3d& M, const Eigen::Vector3d& L,
                              double t) {
  const Eigen::Vector3d& moments = body.moments;
  const Eigen::Matrix3d inertia_world = M * moments.asDiagonal() * M.transpose();
  const Eigen::Matrix3d inertia_inv_world = M * moments.cwiseInverse().asDiagonal() * M.transpose();
  const Eigen::Vector3d omega_world = inertia_inv_world * L;
  Diagnostics d;
  d.t = t;
  d.omega_body = M.transpose() * omega_world;
  d.L = L;
  d.energy_kinetic = 0.5 * omega_world.dot(inertia_world * omega_world);
  d.energy_potential = 0.0;
  d.energy_total = d.energy_kinetic;
  for (int axis = 0; axis < 3; ++axis) d.cos_axis_L[axis] = axis_cosine(M, L, axis);
  d.cos_principal_L = principal_cosines(d.cos_axis_L, moments);
  const Corners corners = body.cage.body_corners();
  d.strain_max = strain_max(M * corners, corners);
  d.orthogonality_error = orthogonality_error(M);
  return d;
}

// The diagonal I_body as a full 3×3 matrix times ω0: the same operations (and so the same
// bits, signed zeros included) as the book's inertia_body() * ω0 always had.
Eigen::Vector3d initial_angular_momentum(const Eigen::Vector3d& moments,
                                         const InitialState& initial) {
  const Eigen::Matrix3d inertia = moments.asDiagonal();
  return inertia * initial.omega0_body + jiggle_delta_L(initial.seed, initial.jiggle);
}

Eigen::Vector3d initial_angular_momentum(const Book& book, const InitialState& initial) {
  return initial_angular_momentum(book.principal_moments(), initial);
}

}  // namespace bookspin::physics
