#include "physics/lattice_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "physics/particle_model.hpp"
#include "physics/shape.hpp"

namespace bookspin::physics {

LatticeModel::LatticeModel(Lattice lattice, const Eigen::Vector3d& moments,
                           const Corners& cage_rest, const ModelConfig& config)
    : lattice_(std::move(lattice)),
      moments_(moments),
      cage_rest_(cage_rest),
      config_(config),
      schedule_(config) {
  const int P = lattice_.particles(), S = lattice_.spring_count();
  if (P == 0) throw std::invalid_argument("lattice model: no particles");
  if (!moments.allFinite() || moments.minCoeff() <= 0.0)
    throw std::invalid_argument("lattice model: principal moments must be finite and positive");
  if (!supports(ModelKind::particle, config.integrator))
    throw std::invalid_argument("lattice model: integrator " +
                                std::string(to_string(config.integrator)) +
                                " is not a particle integrator");
  const double k = config.spring_constant;
  first_.resize(S);
  second_.resize(S);
  rest_length_.resize(S);
  k_.resize(S);
  damping_.resize(S);
  stiffness_.resize(S);
  for (int s = 0; s < S; ++s) {
    const int i = lattice_.springs(0, s), j = lattice_.springs(1, s);
    first_[s] = i;
    second_[s] = j;
    rest_length_[s] = lattice_.rest_length[s];
    stiffness_[s] = lattice_.stiffness[s];
    k_[s] = k * stiffness_[s];
    const double m = spring_mass(lattice_.mass[i], lattice_.mass[j]);  // docs/physics.md §13
    damping_[s] = config.damping ? 2.0 * std::sqrt(k_[s] * m) : 0.0;
  }
  inverse_mass_.resize(P);
  mass_fraction_.resize(P);
  for (int p = 0; p < P; ++p) {
    inverse_mass_[p] = 1.0 / lattice_.mass[p];
    mass_fraction_[p] = lattice_.mass[p] / lattice_.total_mass;
  }
  inertia_inverse_ = lattice_.inertia.inverse();
  // The cage follows particles when each of its corners is one (the one-cell book).
  for (int c = 0; c < 8; ++c) {
    for (int p = 0; p < P; ++p)
      if (lattice_.rest.col(p) == cage_rest_.col(c)) {
        cage_particle_.push_back(p);
        break;
      }
    if (static_cast<int>(cage_particle_.size()) != c + 1) {
      cage_particle_.clear();
      break;
    }
  }
  x_ = lattice_.rest;
  v_ = Rows::Zero(3, P);
  f_ = Rows::Zero(3, P);
}

void LatticeModel::reset(const InitialState& initial) {
  // As the particle model (docs/physics.md §5): ω0' = I⁻¹ (I ω0 + δL), I = diag(moments).
  const Eigen::Matrix3d inertia = moments_.asDiagonal();
  const Eigen::Vector3d omega0 = inertia.inverse() * (inertia * initial.omega0_body +
                                                      jiggle_delta_L(initial.seed, initial.jiggle));
  x_ = lattice_.rest;
  const Eigen::Vector3d c0 = lattice_.center_of_mass;
  for (int p = 0; p < x_.cols(); ++p) {
    const Eigen::Vector3d r = Eigen::Vector3d(x_.col(p)) - c0;
    v_.col(p) = omega0.cross(r);
  }
  energy0_ = kinetic_energy();
  t_ = 0.0;
  schedule_.reset();
}

// The particle model's spring force (docs/physics.md §2, paper §3.3) per spring s = (i, j):
//   c = (b_s (x_ij · v_ij)/|x_ij| + k_s (|x_ij| − L_s)) / |x_ij|,   F_i −= c x_ij,  F_j += c x_ij,
// in one pass over the springs (structure of arrays, no allocation), summing into F in
// spring order as ParticleModel does.
double LatticeModel::forces(const Rows& x, const Rows& v) {
  const int P = static_cast<int>(x.cols()), S = static_cast<int>(first_.size());
  const double* x0 = x.data();
  const double* x1 = x0 + P;
  const double* x2 = x1 + P;
  const double* v0 = v.data();
  const double* v1 = v0 + P;
  const double* v2 = v1 + P;
  f_.setZero();
  double* f0 = f_.data();
  double* f1 = f0 + P;
  double* f2 = f1 + P;
  const int* first = first_.data();
  const int* second = second_.data();
  const double* rest = rest_length_.data();
  const double* k = k_.data();
  const double* b = damping_.data();
  const double* stiffness = stiffness_.data();
  double energy = 0.0;
  for (int s = 0; s < S; ++s) {
    const int i = first[s], j = second[s];
    const double dx = x0[i] - x0[j], dy = x1[i] - x1[j], dz = x2[i] - x2[j];
    const double dvx = v0[i] - v0[j], dvy = v1[i] - v1[j], dvz = v2[i] - v2[j];
    const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double inverse_len = 1.0 / len;
    const double stretch = len - rest[s];
    const double c =
        (b[s] * (dx * dvx + dy * dvy + dz * dvz) * inverse_len + k[s] * stretch) * inverse_len;
    energy += stiffness[s] * (stretch * stretch);
    const double fx = c * dx, fy = c * dy, fz = c * dz;
    f0[i] -= fx;
    f1[i] -= fy;
    f2[i] -= fz;
    f0[j] += fx;
    f1[j] += fy;
    f2[j] += fz;
  }
  return 0.5 * config_.spring_constant * energy;
}

double LatticeModel::spring_energy() const {
  double energy = 0.0;
  for (std::size_t s = 0; s < first_.size(); ++s) {
    const double stretch = (x_.col(first_[s]) - x_.col(second_[s])).norm() - rest_length_[s];
    energy += stiffness_[s] * (stretch * stretch);
  }
  return 0.5 * config_.spring_constant * energy;
}

double LatticeModel::kinetic_energy() const {
  double twice = 0.0;
  for (int p = 0; p < v_.cols(); ++p) twice += lattice_.mass[p] * v_.col(p).squaredNorm();
  return 0.5 * twice;
}

void LatticeModel::step(double dt) {
  const int P = static_cast<int>(x_.cols());
  const double energy_at_start = forces(x_, v_);
  // Per particle: v += (dt/m) F, x += dt v in the order of each integrator (docs/physics.md
  // §2, §10), written as ParticleModel writes them so that the book's bits agree.
  auto kick = [&](double h) {
    for (int axis = 0; axis < 3; ++axis)
      for (int p = 0; p < P; ++p) v_(axis, p) += (h * inverse_mass_[p]) * f_(axis, p);
  };
  auto drift = [&](double h) { x_ += h * v_; };
  switch (config_.integrator) {
    case Integrator::symplectic_euler:
      kick(dt);
      drift(dt);
      break;
    case Integrator::velocity_verlet:
      kick(0.5 * dt);
      drift(dt);
      forces(x_, v_);
      kick(0.5 * dt);
      break;
    default:  // euler, in the paper's order: x from the old v, then v
      drift(dt);
      kick(dt);
  }
  if (schedule_.due()) normalize(energy_at_start);
  t_ += dt;
}

// Paper §3.2 as in the particle model (docs/physics.md §2): scale the velocities so that
// the kinetic energy is max(E0 − U_start, 0.1·E0), remove the centre-of-mass drift (mass
// weighted) and put the centre of mass back where it was at rest.
void LatticeModel::normalize(double spring_energy_at_start) {
  const double scale =
      energy_normalization_scale(kinetic_energy(), energy0_, spring_energy_at_start);
  Eigen::Vector3d v_mean = Eigen::Vector3d::Zero();
  for (int p = 0; p < v_.cols(); ++p) v_mean += mass_fraction_[p] * v_.col(p);
  v_ = scale * (v_.colwise() - v_mean);
  x_.colwise() -= center_of_mass() - lattice_.center_of_mass;
}

Eigen::Vector3d LatticeModel::center_of_mass() const {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int p = 0; p < x_.cols(); ++p) c += mass_fraction_[p] * x_.col(p);
  return c;
}

Eigen::Matrix3d LatticeModel::orientation() const {
  return best_fit_rotation(Eigen::Matrix3Xd(x_), lattice_.rest, lattice_.mass);
}

Corners LatticeModel::corners() const {
  Corners out;
  if (!cage_particle_.empty()) {
    for (int c = 0; c < 8; ++c) out.col(c) = x_.col(cage_particle_[c]);
    return out;
  }
  const Eigen::Matrix3d R = orientation();
  const Eigen::Vector3d c = center_of_mass();
  for (int corner = 0; corner < 8; ++corner)
    out.col(corner) = R * (cage_rest_.col(corner) - lattice_.center_of_mass) + c;
  return out;
}

Eigen::Vector3d LatticeModel::angular_momentum() const {
  const Eigen::Vector3d c = center_of_mass();
  Eigen::Vector3d v_mean = Eigen::Vector3d::Zero();
  for (int p = 0; p < v_.cols(); ++p) v_mean += mass_fraction_[p] * v_.col(p);
  Eigen::Vector3d L = Eigen::Vector3d::Zero();
  for (int p = 0; p < x_.cols(); ++p) {
    const Eigen::Vector3d r = Eigen::Vector3d(x_.col(p)) - c;
    const Eigen::Vector3d u = Eigen::Vector3d(v_.col(p)) - v_mean;
    L += lattice_.mass[p] * r.cross(u);
  }
  return L;
}

Diagnostics LatticeModel::diagnostics() const {
  Diagnostics d;
  d.t = t_;
  d.L = angular_momentum();
  const Eigen::Matrix3d R = orientation();
  // docs/physics.md §13: the rest inertia of the lattice, not the strained one.
  d.omega_body = inertia_inverse_ * (R.transpose() * d.L);
  d.energy_kinetic = kinetic_energy();
  d.energy_potential = spring_energy();
  d.energy_total = d.energy_kinetic + d.energy_potential;
  const double L_norm = d.L.norm();
  for (int axis = 0; axis < 3; ++axis) d.cos_axis_L[axis] = R.col(axis).dot(d.L) / L_norm;
  d.cos_principal_L = cos_principal_L();
  double worst = 0.0;
  for (std::size_t s = 0; s < first_.size(); ++s) {
    const double len = (x_.col(first_[s]) - x_.col(second_[s])).norm();
    worst = std::max(worst, std::abs(len / rest_length_[s] - 1.0));
  }
  d.strain_max = worst;
  d.orthogonality_error = 0.0;
  d.quaternion_norm = 1.0;
  return d;
}

Eigen::Vector3d LatticeModel::cos_principal_L() const {
  const std::array<int, 3> order = principal_order(moments_);
  const Eigen::Vector3d L = angular_momentum();
  const Eigen::Matrix3d R = orientation();
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) out[i] = R.col(order[i]).dot(L) / L.norm();
  return out;
}

Eigen::Matrix3Xd LatticeModel::deformed_surface() const {
  return lattice_.embed_surface(Eigen::Matrix3Xd(x_));
}

bool LatticeModel::finite() const { return is_sane(x_) && is_sane(v_); }

std::unique_ptr<Simulator> make_body_lattice_model(const Body& body, const ModelConfig& config) {
  const int cells = config.lattice_cells > 0 ? config.lattice_cells : kDefaultLatticeCells;
  return std::make_unique<LatticeModel>(
      build_lattice(body.vertices, body.triangles, body.cage.mass, cells), body.moments,
      body.cage.body_corners(), config);
}

}  // namespace bookspin::physics
