#include "physics/damped_exact.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace bookspin::physics {

DampedExactRotation::DampedExactRotation(const Eigen::Vector3d& moments,
                                         const Eigen::Vector3d& omega0_body, Drag drag,
                                         ExactParts parts)
    : free_(moments, omega0_body, parts), drag_(drag) {
  if (!std::isfinite(drag.rate))
    throw std::invalid_argument("DampedExactRotation: the drag rate is not finite");
}

double DampedExactRotation::stretched(double t) const {
  if (!drag_defined_until(drag_, t))
    throw std::invalid_argument("DampedExactRotation: the quadratic law's gain has blown up by t");
  return stretched_time(drag_, t);
}

Eigen::Vector3d DampedExactRotation::omega_body(double t) const {
  if (!drag_.active()) return free_.omega_body(t);
  return decay(t) * free_.omega_body(stretched(t));
}

Eigen::Vector3d DampedExactRotation::angular_momentum_body(double t) const {
  if (!drag_.active()) return free_.angular_momentum_body(t);
  return decay(t) * free_.angular_momentum_body(stretched(t));
}

Eigen::Vector3d DampedExactRotation::angular_momentum_world(double t) const {
  if (!drag_.active()) return free_.angular_momentum_world();
  return decay(t) * free_.angular_momentum_world();
}

Eigen::Matrix3d DampedExactRotation::orientation(double t) const {
  if (!drag_.active()) return free_.orientation(t);
  return free_.orientation(stretched(t));
}

double DampedExactRotation::energy(double t) const {
  if (!drag_.active()) return free_.energy();
  const double g = decay(t);
  return g * g * free_.energy();
}

double DampedExactRotation::flip_period_at(double t) const {
  const double half = free_.flip_period();
  if (!std::isfinite(half) || !drag_.active()) return half;
  return time_of_stretched(drag_, stretched(t) + half) - t;
}

double time_of_stretched(const Drag& drag, double s) {
  if (!drag.active()) return s;
  const double r = drag.rate;
  if (drag.law == DragLaw::linear) {
    // s = (1 − e^{−rt})/r  ⇒  t = −ln(1 − r s)/r.
    if (r * s >= 1.0) return std::numeric_limits<double>::infinity();
    return -std::log1p(-r * s) / r;
  }
  // s = ln(1 + r t)/r  ⇒  t = (e^{r s} − 1)/r.
  return std::expm1(r * s) / r;
}

}  // namespace bookspin::physics
