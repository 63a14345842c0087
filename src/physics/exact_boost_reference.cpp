// ExactRotation::BoostReference: the exact motion evaluated as it was before the per-motion
// constants (docs/physics.md §8, "How the code evaluates ω(t)"), the reference the tests and
// `make bench` hold state() against.
#include <Eigen/Geometry>
#include <stdexcept>

#include "physics/exact_solution.hpp"

namespace bookspin::physics {

// The evaluation as it was: S(u0) by Boost once, then per row R(t) and ω(t) each from their own
// Boost jacobi_elliptic and ψ by Boost's ellint_rj.
ExactRotation::BoostReference ExactRotation::boost_reference() const {
  const bool periodic = case_ != ExactCase::steady && case_ != ExactCase::separatrix &&
                        parts_ == ExactParts::omega_and_orientation;
  return {*this, periodic ? periodic_S(u0_, jacobi_boost(u0_), Evaluation::boost) : 0.0L};
}

ExactState ExactRotation::BoostReference::state(double t) const {
  const ExactRotation& e = *exact_;
  e.check_horizon(t);
  if (e.case_ == ExactCase::steady) return e.state(t);
  if (e.parts_ == ExactParts::omega_only)
    throw std::logic_error("ExactRotation: built for omega alone, it has no orientation");
  ExactState state;
  state.t = t;
  const Eigen::Matrix3d R = e.orientation_at(t, e.jacobi_boost(e.phase(t)), Evaluation::boost, S0_);
  Eigen::Quaterniond q(R);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  state.q = Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
  state.omega_body = e.to_sorted_.transpose() * e.sorted_omega(e.jacobi_boost(e.phase(t)));
  state.omega_world = R * state.omega_body;
  state.L = R * e.moments_.cwiseProduct(state.omega_body);
  state.E = 0.5 * state.omega_body.dot(e.moments_.cwiseProduct(state.omega_body));
  return state;
}

double ExactRotation::BoostReference::precession_angle(double t) const {
  const ExactRotation& e = *exact_;
  e.check_horizon(t);
  if (e.case_ == ExactCase::steady) return e.precession_angle(t);
  if (e.parts_ == ExactParts::omega_only)
    throw std::logic_error("ExactRotation: built for omega alone, it has no orientation");
  return static_cast<double>(
      e.precession_at(t, e.jacobi_boost(e.phase(t)), Evaluation::boost, S0_));
}

}  // namespace bookspin::physics
