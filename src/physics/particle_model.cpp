#include "physics/particle_model.hpp"

#include <cmath>
#include <utility>

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

/// Springs (i, i+1) … (i, 7) are consecutive, so block i of each axis is one value minus a
/// contiguous slice of the same row: a few SIMD operations instead of scalar gathers.
template <int I>
void spring_block(const CornerRows& p, SpringVectors& d) {
  constexpr int count = 7 - I;
  constexpr int first = 7 * I - I * (I - 1) / 2;  // springs in the blocks before
  d.x.segment<count>(first) = p(0, I) - p.row(0).segment<count>(I + 1).transpose().array();
  d.y.segment<count>(first) = p(1, I) - p.row(1).segment<count>(I + 1).transpose().array();
  d.z.segment<count>(first) = p(2, I) - p.row(2).segment<count>(I + 1).transpose().array();
}

template <int... I>
SpringVectors spring_vectors(const CornerRows& p, std::integer_sequence<int, I...>) {
  SpringVectors d;
  (spring_block<I>(p, d), ...);
  return d;
}

/// Differences x_i − x_j of the spring ends, in pair order.
SpringVectors spring_vectors(const CornerRows& p) {
  return spring_vectors(p, std::make_integer_sequence<int, 7>{});
}

/// The net force on each corner from each spring's force on its second corner (the first
/// gets the opposite), summed in pair order. Fully unrolled, every index is a constant and
/// the 24 sums stay in registers; this beats SIMD slices plus horizontal sums.
CornerRows corner_forces(const SpringVectors& on_second) {
  CornerRows f = CornerRows::Zero();
#pragma GCC unroll 28
  for (int s = 0; s < kSprings; ++s) {
    const int i = kEnds.first[s], j = kEnds.second[s];
    f(0, i) -= on_second.x[s];
    f(1, i) -= on_second.y[s];
    f(2, i) -= on_second.z[s];
    f(0, j) += on_second.x[s];
    f(1, j) += on_second.y[s];
    f(2, j) += on_second.z[s];
  }
  return f;
}

}  // namespace

ParticleModel::ParticleModel(const Book& book, const ModelConfig& config)
    : book_(book),
      config_(config),
      schedule_(config),
      particle_mass_(book.mass / 8.0),
      damping_(config.damping ? 2.0 * std::sqrt(config.spring_constant * particle_mass_) : 0.0),
      rest_(book.body_corners()) {
  const SpringVectors d = spring_vectors(CornerRows(rest_));
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
  schedule_.reset();
}

// Each spring pulls its ends together with −c·(x_i − x_j) on i and +c·(x_i − x_j) on j,
//   c = (2√(km) (x_ij · v_ij)/|x_ij| + k(|x_ij| − L_ij)) / |x_ij|,
// which is the paper's F_ij = −(2√(km) x̂·(v_i − v_j) + k(|x_ij| − L_ij)) x̂ (§3.3) with
// the unit vector x̂ = x_ij/|x_ij| folded in: one square root and one division per spring
// instead of a square root and three divisions, which bound the step. The 28 springs are
// computed side by side in SIMD lanes, in blocks that share a first corner.
CornerRows ParticleModel::forces(const CornerRows& x, const CornerRows& v, double& energy) const {
  const double k = config_.spring_constant;
  const SpringVectors d = spring_vectors(x);
  const SpringVectors dv = spring_vectors(v);
  const SpringArray len = (d.x * d.x + d.y * d.y + d.z * d.z).sqrt();
  const SpringArray inverse_len = len.inverse();
  const SpringArray stretch = len - Eigen::Map<const SpringArray>(rest_length_.data());
  const SpringArray c =
      (damping_ * (d.x * dv.x + d.y * dv.y + d.z * dv.z) * inverse_len + k * stretch) * inverse_len;
  energy = 0.5 * k * stretch.square().sum();
  return corner_forces({c * d.x, c * d.y, c * d.z});
}

double ParticleModel::spring_energy(const CornerRows& x) const {
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
  const CornerRows f = forces(x_, v_, energy_at_start);
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
  if (schedule_.due()) normalize(energy_at_start);
  t_ += dt;
}

double energy_normalization_scale(double kinetic, double energy0, double spring_energy_at_start) {
  const double target = std::max(energy0 - spring_energy_at_start, 0.1 * energy0);
  return kinetic > 0.0 ? std::sqrt(target / kinetic) : 1.0;
}

// Paper §3.2: scale all velocities by one factor so that kinetic energy = E − U, never
// below 0.1·E (docs/physics.md §2), then remove the centre-of-mass drift.
void ParticleModel::normalize(double spring_energy_at_start) {
  const double scale =
      energy_normalization_scale(kinetic_energy(), energy0_, spring_energy_at_start);
  // s·v − mean(s·v) as s·(v − mean v): the mean need not wait for the square root.
  const Eigen::Vector3d v_mean = v_.rowwise().mean();
  v_ = scale * (v_.colwise() - v_mean);
  x_.colwise() -= x_.rowwise().mean();
}

Eigen::Matrix3d ParticleModel::orientation() const {
  const Corners x = x_;
  return best_fit_rotation(x.colwise() - x.rowwise().mean(), rest_);
}

namespace {

/// cos(R's column `axis`, L), R a rotation (its columns of unit length).
double spin_cosine(const Eigen::Matrix3d& R, const Eigen::Vector3d& L, int axis) {
  return R.col(axis).dot(L) / L.norm();
}

}  // namespace

ParticleModel::Spin ParticleModel::spin() const {
  Spin s;
  const Eigen::Vector3d centre = x_.rowwise().mean();
  s.rel = x_.colwise() - centre;
  const Corners vel = v_.colwise() - v_.rowwise().mean();
  // Body frame: best-fit rotation of the current corners onto the rest shape (Kabsch).
  s.R = best_fit_rotation(s.rel, rest_);
  s.L.setZero();
  for (int p = 0; p < 8; ++p) s.L += particle_mass_ * s.rel.col(p).cross(vel.col(p));
  return s;
}

double ParticleModel::cos_axis_L(int axis) const {
  const Spin s = spin();
  return spin_cosine(s.R, s.L, axis);
}

Diagnostics ParticleModel::diagnostics() const {
  Diagnostics d;
  d.t = t_;
  const Spin s = spin();
  const Eigen::Matrix3d& R = s.R;
  d.L = s.L;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (int p = 0; p < 8; ++p) {
    const Eigen::Vector3d r = s.rel.col(p);
    inertia += particle_mass_ * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  d.omega_body = R.transpose() * inertia.ldlt().solve(d.L);
  d.energy_kinetic = kinetic_energy();
  d.energy_potential = spring_energy(x_);
  d.energy_total = d.energy_kinetic + d.energy_potential;
  for (int axis = 0; axis < 3; ++axis) d.cos_axis_L[axis] = spin_cosine(R, d.L, axis);
  d.cos_principal_L = principal_cosines(d.cos_axis_L, book_.principal_moments());
  d.strain_max = strain_max(Corners(x_), rest_);
  d.orthogonality_error = orthogonality_error(R);
  return d;
}

bool ParticleModel::finite() const { return is_sane(x_) && is_sane(v_); }

}  // namespace bookspin::physics
