#include "physics/replay_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "physics/shape.hpp"

namespace bookspin::physics {

namespace {

/// exp([θ]×): the rotation by |θ| about θ (Rodrigues).
Eigen::Matrix3d rotation_exp(const Eigen::Vector3d& theta) {
  const double angle = theta.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, theta / angle).toRotationMatrix();
}

void require_rotation(const Eigen::Matrix3d& m, const char* what) {
  if (!m.allFinite() || (m.transpose() * m - Eigen::Matrix3d::Identity()).norm() > 1e-9 ||
      std::abs(m.determinant() - 1.0) > 1e-9)
    throw std::invalid_argument(std::string(what) + " is not a rotation");
}

}  // namespace

OmegaReplay::OmegaReplay(std::vector<double> t, std::vector<Eigen::Vector3d> omega)
    : t_(std::move(t)), omega_(std::move(omega)) {
  if (t_.size() < 2 || t_.size() != omega_.size())
    throw std::invalid_argument("OmegaReplay: needs at least 2 samples, one ω per time");
  const double t0 = t_.front();
  for (std::size_t i = 0; i < t_.size(); ++i) {
    if (!std::isfinite(t_[i]) || !omega_[i].allFinite())
      throw std::invalid_argument("OmegaReplay: a time or ω is not finite");
    if (i > 0 && !(t_[i] > t_[i - 1]))
      throw std::invalid_argument("OmegaReplay: times are not strictly increasing");
  }
  for (double& ti : t_) ti -= t0;
  R_.reserve(t_.size());
  R_.push_back(Eigen::Matrix3d::Identity());
  for (std::size_t i = 0; i + 1 < t_.size(); ++i)
    R_.push_back(R_[i] * rotation_exp(step_rotation(omega_[i], omega_[i + 1], t_[i + 1] - t_[i])));
}

// The fourth-order Magnus expansion (docs/physics.md §20) of dR/dt = R [ω]× for ω linear over
// the step: the first term is the integral of ω, the second the commutator term
// (h²/12)[[ω0]×, [ω1]×] = (h²/12)[ω0 × ω1]×.
Eigen::Vector3d OmegaReplay::step_rotation(const Eigen::Vector3d& w0, const Eigen::Vector3d& w1,
                                           double h) {
  return 0.5 * h * (w0 + w1) + (h * h / 12.0) * w0.cross(w1);
}

std::size_t OmegaReplay::interval(double tau) const {
  const auto it = std::upper_bound(t_.begin(), t_.end(), tau);
  const std::size_t after = static_cast<std::size_t>(it - t_.begin());
  return std::clamp<std::size_t>(after == 0 ? 0 : after - 1, 0, t_.size() - 2);
}

Eigen::Vector3d OmegaReplay::omega(double t) const {
  if (t <= t_.front()) return omega_.front();
  if (t >= t_.back()) return omega_.back();
  const std::size_t i = interval(t);
  const double s = (t - t_[i]) / (t_[i + 1] - t_[i]);
  return (1.0 - s) * omega_[i] + s * omega_[i + 1];
}

Eigen::Matrix3d OmegaReplay::orientation(double t) const {
  // Before the first sample and after the last, ω is held: a constant ω's step is exact.
  if (t <= t_.front()) return rotation_exp(t * omega_.front());
  if (t >= t_.back()) return R_.back() * rotation_exp((t - t_.back()) * omega_.back());
  const std::size_t i = interval(t);
  return R_[i] * rotation_exp(step_rotation(omega_[i], omega(t), t - t_[i]));
}

ExactInFrame::ExactInFrame(const Eigen::Matrix3d& axes, const Eigen::Vector3d& moments,
                           const Eigen::Vector3d& omega0, Drag drag)
    : axes_(axes), exact_(moments, axes.transpose() * omega0, drag) {
  require_rotation(axes, "ExactInFrame: axes");
}

Eigen::Vector3d ExactInFrame::omega(double t) const { return axes_ * exact_.omega_body(t); }

Eigen::Matrix3d ExactInFrame::orientation(double t) const {
  return axes_ * exact_.orientation(t) * axes_.transpose();
}

ReplayModel::ReplayModel(const Body& body, const Eigen::Matrix3d& placement,
                         const Eigen::Matrix3d& inertia,
                         std::shared_ptr<const PrescribedMotion> motion,
                         const std::optional<Eigen::Matrix3d>& omega_axes)
    : body_(body),
      cage_corners_(body.cage.body_corners()),
      placement_(placement),
      inertia_(inertia),
      omega_axes_(omega_axes.value_or(placement.transpose())),
      motion_(std::move(motion)) {
  require_rotation(placement, "ReplayModel: placement");
  if (!inertia.allFinite() || !omega_axes_.allFinite())
    throw std::invalid_argument("ReplayModel: inertia or omega_axes is not finite");
  if (!motion_) throw std::invalid_argument("ReplayModel: no motion");
  update();
}

void ReplayModel::reset(const InitialState& /*initial*/) {
  t_ = t_base_ = dt_ = 0.0;
  steps_ = 0;
  update();
}

// t = t_base + n·dt from the step count, as ExactModel::advance (docs/physics.md §10.6).
void ReplayModel::step(double dt) {
  if (dt != dt_) {
    t_base_ = t_;
    dt_ = dt;
    steps_ = 0;
  }
  ++steps_;
  t_ = t_base_ + static_cast<double>(steps_) * dt_;
  update();
}

void ReplayModel::update() {
  R_ = motion_->orientation(t_);
  omega_ = motion_->omega(t_);
}

Corners ReplayModel::corners() const { return orientation() * cage_corners_; }

Diagnostics ReplayModel::diagnostics() const {
  const Eigen::Vector3d L = R_ * (inertia_ * omega_);
  // The axis cosines, strain and orthogonality of the drawn body's pose; ω and the energy are
  // the motion's own, with the motion frame's inertia.
  return prescribed_diagnostics(body_, orientation(), L, t_, omega_axes_ * omega_,
                                0.5 * omega_.dot(inertia_ * omega_));
}

bool ReplayModel::finite() const { return std::isfinite(t_) && is_sane(R_) && is_sane(omega_); }

}  // namespace bookspin::physics
