#pragma once
// Mass-spring book: 8 corner particles and 28 springs (paper §3, docs/physics.md §2).
#include <array>

#include "physics/simulator.hpp"

namespace bookspin::physics {

inline constexpr int kSprings = 28;  ///< one per corner pair

/// Corner positions or velocities stored one row per axis, so that the spring loops read
/// each axis' 8 values contiguously.
using CornerRows = Eigen::Matrix<double, 3, 8, Eigen::RowMajor>;

/// Particles of mass m = M/8 at the corners, a spring of constant k between every pair
/// with the rest length of the book at rest. Positions and velocities are 3×8, world frame.
/// Integrators: `euler` (the paper's order: forces from the positions at step start, then
/// x += dt·v, then v += dt·a), `symplectic-euler` (v first, then x), `velocity-verlet`
/// (Swope et al. 1982; with damping the velocity-dependent force uses the half-step
/// velocity). Optional critical damping and energy normalization (paper §3.2–3.3).
/// The paper's energy normalization (§3.2, docs/physics.md §2), shared by the particle book
/// and the lattice: the factor that scales every velocity so that the kinetic energy
/// `kinetic` becomes E0 − U (`energy0` minus the spring energy at the step's start), never
/// below 0.1·E0; 1 for a body at rest. Energies in mass·length²/time².
double energy_normalization_scale(double kinetic, double energy0, double spring_energy_at_start);

class ParticleModel final : public Simulator {
 public:
  ParticleModel(const Book& book, const ModelConfig& config);
  void reset(const InitialState& initial) override;
  void step(double dt) override;
  Corners corners() const override { return x_; }
  /// Best-fit rotation of the corners (about their mean) onto the corners at rest.
  Eigen::Matrix3d orientation() const override;
  /// The corners' mean (equal masses), world.
  Eigen::Vector3d center_of_mass() const override { return x_.rowwise().mean(); }
  Diagnostics diagnostics() const override;
  /// R.col(axis)·L/|L| of the best-fit rotation R and the corners' L, as diagnostics() has it.
  double cos_axis_L(int axis) const override;
  bool finite() const override;

  Corners velocities() const { return v_; }

 private:
  /// Spring (and optional damping) forces on each particle (3×8) for positions x and
  /// velocities v; writes the spring energy Σ ½ k r² into `energy`.
  CornerRows forces(const CornerRows& x, const CornerRows& v, double& energy) const;
  double spring_energy(const CornerRows& x) const;
  double kinetic_energy() const;
  /// The corners about their mean (3×8, world), the best-fit rotation R of them onto the rest
  /// shape (Kabsch, body → world) and their angular momentum L about the mean (world): the
  /// body frame and momentum diagnostics() and cos_axis_L() read.
  struct Spin {
    Corners rel;
    Eigen::Matrix3d R;
    Eigen::Vector3d L;
  };
  Spin spin() const;
  void normalize(double spring_energy_at_start);

  Book book_;
  ModelConfig config_;
  NormalizeSchedule schedule_;  ///< which steps normalize (model.normalize_every)
  double particle_mass_;
  double damping_;                              ///< 2√(km) with damping, else 0
  Corners rest_;                                ///< body corners at rest (3×8)
  std::array<double, kSprings> rest_length_{};  ///< per corner pair
  CornerRows x_, v_;
  double energy0_ = 0.0;  ///< total energy fixed at reset (all kinetic)
  double t_ = 0.0;
};

}  // namespace bookspin::physics
