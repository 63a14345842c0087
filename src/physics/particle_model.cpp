#include "physics/particle_model.hpp"

#include <cmath>

#include "physics/shape.hpp"

namespace bookspin::physics {

namespace {

/// The 28 springs' corner pairs (i < j) in corner_pairs() order, as two index arrays fixed
/// at compile time, so the force loop needs no lookup through a function-local static.
struct SpringEnds {
  std::array<int, kSprings> first{}, second{};
};

constexpr SpringEnds kEnds = [] {
  SpringEnds ends;
  int s = 0;
  for (int i = 0; i < 8; ++i) {
    for (int j = i + 1; j < 8; ++j, ++s) {
      ends.first[s] = i;
      ends.second[s] = j;
    }
  }
  return ends;
}();

/// Per-spring values, one lane per spring: Eigen evaluates these expressions with SIMD
/// packets (28 is even), which is where the step's sqrt and divisions go.
using SpringArray = Eigen::Array<double, kSprings, 1>;

/// Differences x_i − x_j of the spring ends, one array per axis.
struct SpringVectors {
  SpringArray x, y, z;
};

SpringVectors spring_vectors(const Corners& points) {
  SpringVectors d;
  for (int s = 0; s < kSprings; ++s) {
    const int i = kEnds.first[s], j = kEnds.second[s];
    d.x[s] = points(0, i) - points(0, j);
    d.y[s] = points(1, i) - points(1, j);
    d.z[s] = points(2, i) - points(2, j);
  }
  return d;
}

}  // namespace

ParticleModel::ParticleModel(const Book& book, const ModelConfig& config)
    : book_(book),
      config_(config),
      particle_mass_(book.mass / 8.0),
      damping_(config.damping ? 2.0 * std::sqrt(config.spring_constant * particle_mass_) : 0.0),
      rest_(book.body_corners()) {
  const SpringVectors d = spring_vectors(rest_);
  for (int s = 0; s < kSprings; ++s)
    rest_length_[s] = Eigen::Vector3d(d.x[s], d.y[s], d.z[s]).norm();
}

void ParticleModel::reset(const InitialState& initial) {
  // Same perturbed angular velocity as the rigid models: ω0' = I_body⁻¹ (I_body ω0 + δL).
  const Eigen::Vector3d omega0 =
      book_.inertia_body().inverse() * initial_angular_momentum(book_, initial);
  x_ = rest_;
  for (int p = 0; p < 8; ++p) v_.col(p) = omega0.cross(x_.col(p));
  energy0_ = kinetic_energy();
  t_ = 0.0;
}

// Two passes with the same arithmetic, in the same order, as the textbook loop over pairs
// (so the results are bit-identical to it): first every spring's length, unit vector and
// force magnitude side by side in SIMD lanes, then the forces gathered onto the corners
// and the energy summed, spring by spring in pair order.
Corners ParticleModel::forces(const Corners& x, const Corners& v, double& energy) const {
  const double k = config_.spring_constant;
  const SpringVectors d = spring_vectors(x);
  const SpringVectors dv = spring_vectors(v);
  const SpringArray len = (d.x * d.x + d.y * d.y + d.z * d.z).sqrt();
  const SpringArray ux = d.x / len, uy = d.y / len, uz = d.z / len;
  const SpringArray stretch = len - Eigen::Map<const SpringArray>(rest_length_.data());
  // F_ij = −(2√(km) x̂·(v_i − v_j) + k(|x_ij| − L_ij)) x̂ (paper §3.3); F_ji = −F_ij.
  const SpringArray magnitude = damping_ * (ux * dv.x + uy * dv.y + uz * dv.z) + k * stretch;
  Corners f = Corners::Zero();
  energy = 0.0;
  for (int s = 0; s < kSprings; ++s) {
    energy += 0.5 * k * stretch[s] * stretch[s];
    const int i = kEnds.first[s], j = kEnds.second[s];
    const double fx = magnitude[s] * ux[s], fy = magnitude[s] * uy[s], fz = magnitude[s] * uz[s];
    f(0, i) -= fx;
    f(1, i) -= fy;
    f(2, i) -= fz;
    f(0, j) += fx;
    f(1, j) += fy;
    f(2, j) += fz;
  }
  return f;
}

double ParticleModel::spring_energy(const Corners& x) const {
  const SpringVectors d = spring_vectors(x);
  double energy = 0.0;
  for (int s = 0; s < kSprings; ++s) {
    const double stretch = Eigen::Vector3d(d.x[s], d.y[s], d.z[s]).norm() - rest_length_[s];
    energy += 0.5 * config_.spring_constant * stretch * stretch;
  }
  return energy;
}

double ParticleModel::kinetic_energy() const { return 0.5 * particle_mass_ * v_.squaredNorm(); }

void ParticleModel::step(double dt) {
  double energy_at_start = 0.0;
  const double inv_m = 1.0 / particle_mass_;
  const Corners f = forces(x_, v_, energy_at_start);
  switch (config_.integrator) {
    case Integrator::symplectic_euler:
      v_ += (dt * inv_m) * f;
      x_ += dt * v_;
      break;
    case Integrator::velocity_verlet: {
      v_ += (0.5 * dt * inv_m) * f;
      x_ += dt * v_;
      double unused = 0.0;
      v_ += (0.5 * dt * inv_m) * forces(x_, v_, unused);
      break;
    }
    default:  // euler, in the paper's order
      x_ += dt * v_;
      v_ += (dt * inv_m) * f;
  }
  if (config_.normalize) normalize(energy_at_start);
  t_ += dt;
}

// Paper §3.2: scale all velocities by one factor so that kinetic energy = E − U, never
// below 0.1·E (physics.md §2), then remove the centre-of-mass drift.
void ParticleModel::normalize(double spring_energy_at_start) {
  const double kinetic = kinetic_energy();
  const double target = std::max(energy0_ - spring_energy_at_start, 0.1 * energy0_);
  if (kinetic > 0.0) v_ *= std::sqrt(target / kinetic);
  x_.colwise() -= x_.rowwise().mean();
  v_.colwise() -= v_.rowwise().mean();
}

Diagnostics ParticleModel::diagnostics() const {
  Diagnostics d;
  d.t = t_;
  const Eigen::Vector3d centre = x_.rowwise().mean();
  const Corners rel = x_.colwise() - centre;
  const Corners vel = v_.colwise() - v_.rowwise().mean();
  // Body frame: best-fit rotation of the current corners onto the rest shape (Kabsch).
  const Eigen::Matrix3d R = best_fit_rotation(rel, rest_);
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (int p = 0; p < 8; ++p) {
    const Eigen::Vector3d r = rel.col(p);
    d.L += particle_mass_ * r.cross(vel.col(p));
    inertia += particle_mass_ * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  d.omega_body = R.transpose() * inertia.ldlt().solve(d.L);
  d.energy_kinetic = kinetic_energy();
  d.energy_potential = spring_energy(x_);
  d.energy_total = d.energy_kinetic + d.energy_potential;
  for (int axis = 0; axis < 3; ++axis) d.cos_axis_L[axis] = R.col(axis).dot(d.L) / d.L.norm();
  d.strain_max = strain_max(x_, rest_);
  d.orthogonality_error = orthogonality_error(R);
  return d;
}

bool ParticleModel::finite() const { return is_sane(x_) && is_sane(v_); }

}  // namespace bookspin::physics
