#include "fit/toss_model.hpp"

#include <algorithm>
#include <cmath>

namespace bookspin::fit {

namespace {

constexpr double kStep = 1e-6;  // relative difference step of the setups (|θ_p| ≥ 1) or absolute
constexpr int kDragParameter = 8;  // θ's index of the drag rate

std::array<double, TossModel::kParameters> parameters(const double* aa, const double* log_ratios,
                                                      const double* omega0_rate) {
  return {aa[0],          aa[1],          aa[2],          log_ratios[0], log_ratios[1],
          omega0_rate[0], omega0_rate[1], omega0_rate[2], omega0_rate[3]};
}

}  // namespace

Eigen::Matrix3d rotation_from_angle_axis(const double* aa) {
  const Eigen::Vector3d v(aa[0], aa[1], aa[2]);
  const double angle = v.norm();
  if (angle < 1e-300) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, v / angle).toRotationMatrix();
}

TossModel::Motion::Motion(const Eigen::Matrix3d& R0, const std::array<double, kParameters>& theta,
                          physics::DragLaw law)
    : axes(R0 * rotation_from_angle_axis(theta.data())),
      exact(Eigen::Vector3d(std::exp(theta[3]), std::exp(theta[4]), 1.0),
            axes.transpose() * Eigen::Vector3d(theta[5], theta[6], theta[7]),
            physics::ExactParts::omega_only),
      drag{law, law == physics::DragLaw::none ? 0.0 : theta[8]} {
  if (!std::isfinite(drag.rate)) throw std::invalid_argument("TossModel: drag rate not finite");
}

std::optional<TossModel::Form> TossModel::form_of(const Motion& motion) {
  const physics::ExactCase c = motion.exact.motion_case();
  if (c == physics::ExactCase::steady || c == physics::ExactCase::separatrix) return std::nullopt;
  const physics::ExactOmegaForm f = motion.exact.omega_form();
  if (!(f.k < 1.0 && f.kc2 > 0.0)) return std::nullopt;
  return Form{motion.axes * f.A, f.lambda, f.u0, f.k, f.kc2, f.K};
}

TossModel::TossModel(const Eigen::Matrix3d& R0, const double* aa, const double* log_ratios,
                     const double* omega0_rate, physics::DragLaw law, bool derivatives)
    : centre_(R0, parameters(aa, log_ratios, omega0_rate), law) {
  form_ = form_of(centre_);
  if (form_) agm_.emplace(form_->k, form_->kc2);
  if (!derivatives) return;
  const std::array<double, kParameters> theta = parameters(aa, log_ratios, omega0_rate);
  closed_ = form_.has_value();
  plus_.reserve(kParameters);
  minus_.reserve(kParameters);
  for (int p = 0; p < kParameters; ++p) {
    step_[p] = kStep * std::max(1.0, std::abs(theta[p]));
    std::array<double, kParameters> up = theta, down = theta;
    up[p] += step_[p];
    down[p] -= step_[p];
    plus_.emplace_back(R0, up, law);
    minus_.emplace_back(R0, down, law);
    if (!closed_ || p == kDragParameter) continue;  // the rate's column is analytic (§21)
    const std::optional<Form> a = form_of(plus_.back()), b = form_of(minus_.back());
    // The same branch of the closed form on both sides: the same case, amplitudes and modulus
    // near the centre's (a case or sign change would jump by their size).
    const double size = form_->C.cwiseAbs().maxCoeff();
    const auto near = [&](const std::optional<Form>& f, const Motion& m) {
      return f && m.exact.motion_case() == centre_.exact.motion_case() &&
             (f->C - form_->C).cwiseAbs().maxCoeff() < 0.1 * size &&
             std::abs(f->k - form_->k) < 0.1;
    };
    if (!near(a, plus_.back()) || !near(b, minus_.back())) {
      closed_ = false;
      continue;
    }
    const double twice = 2.0 * step_[p];
    dC_[p] = (a->C - b->C) / twice;
    dlambda_[p] = (a->lambda - b->lambda) / twice;
    dk_[p] = (a->k - b->k) / twice;
    // u0 lies in (−2K, 2K]: a step across its ends jumps by the period 4K.
    const double period = 4.0 * form_->K;
    double du = a->u0 - b->u0;
    du -= period * std::round(du / period);
    du0_[p] = du / twice;
  }
  if (closed_) {
    plus_.clear();
    minus_.clear();
  }
}

Eigen::Vector3d TossModel::omega(double tau, Jacobian* jacobian) const {
  if (!form_) {
    if (jacobian)
      for (int p = 0; p < kParameters; ++p)
        jacobian->col(p) = (plus_[p].omega(tau) - minus_[p].omega(tau)) / (2.0 * step_[p]);
    return centre_.omega(tau);
  }
  const Form& f = *form_;
  // Under drag the free motion at the stretched time s, scaled by g (docs/physics.md §21).
  const physics::Drag& drag = centre_.drag;
  const double s = physics::stretched_time(drag, tau), g = physics::drag_decay(drag, tau);
  const double u = f.lambda * s + f.u0;
  const JacobiAgm::Values v = (*agm_)(u);
  const Eigen::Vector3d J(v.cn, v.sn, v.dn);
  const Eigen::Vector3d w_free = f.C * J;
  const Eigen::Vector3d w = g * w_free;
  if (!jacobian) return w;
  if (!closed_) {
    for (int p = 0; p < kParameters; ++p)
      jacobian->col(p) = (plus_[p].omega(tau) - minus_[p].omega(tau)) / (2.0 * step_[p]);
    return w;
  }
  // ∂/∂u: d sn = cn dn, d cn = −sn dn, d dn = −k² sn cn. ∂/∂k at fixed u through the amplitude
  // φ = am u: ∂φ/∂k = −dn (ℰ(u)/(k k'²) − u/k − k sn cn/(k'² dn)), ℰ(u) = Z(u) + (E/K) u
  // (docs/physics.md §8, "The fit's derivatives").
  const double k = f.k, kc2 = f.kc2;
  const Eigen::Vector3d J_u(-v.sn * v.dn, v.cn * v.dn, -k * k * v.sn * v.cn);
  Eigen::Vector3d J_k = Eigen::Vector3d::Zero();
  if (k > 0.0) {
    const double P = v.zeta / (k * kc2) + u * agm_->e_over_k_minus_kc2() / (k * kc2) -
                     k * v.sn * v.cn / (kc2 * v.dn);
    const double phi_k = -v.dn * P;
    J_k = Eigen::Vector3d(-v.sn * phi_k, v.cn * phi_k,
                          -(k * v.sn * v.sn + k * k * v.sn * v.cn * phi_k) / v.dn);
  }
  const Eigen::Vector3d a = f.C * J_u, b = f.C * J_k;
  for (int p = 0; p < kDragParameter; ++p)
    jacobian->col(p) = g * (dC_[p] * J + (s * dlambda_[p] + du0_[p]) * a + dk_[p] * b);
  // ∂ω/∂r = (∂g/∂r) ω_free(s) + g λ (∂s/∂r) C ∂J/∂u (§21); zero without a drag law.
  jacobian->col(kDragParameter) =
      physics::drag_decay_rate_derivative(drag, tau) * w_free +
      (g * f.lambda * physics::stretched_time_rate_derivative(drag, tau)) * a;
  return w;
}

}  // namespace bookspin::fit
