#pragma once
// The particle model of any body: the mass-spring lattice of lattice.hpp moved with the
// particle model's integrators (paper §3, docs/physics.md §2 and §13).
#include <memory>
#include <vector>

#include "physics/body.hpp"
#include "physics/lattice.hpp"
#include "physics/simulator.hpp"

namespace bookspin::physics {

/// Mass-spring lattice: particles of Lattice::mass at Lattice::rest, spring s with constant
/// k·stiffness(s) (k = config.spring_constant) and Lattice::rest_length(s). The physics is
/// the particle model's (docs/physics.md §2): integrators `euler` (paper order),
/// `symplectic-euler`, `velocity-verlet`; optional critical damping b_s = 2√(k_s m_s) per
/// spring with m_s = 2 m_i m_j/(m_i + m_j) (twice the pair's reduced mass: the particle
/// mass itself when both ends weigh the same, as in the paper); optional energy
/// normalization with the 0.1·E0 floor and the spring energy at step start. For the
/// one-cell lattice of a book (8 corners, M/8 each, 28 springs of stiffness 1) this is
/// ParticleModel to round-off (docs/physics.md §13). Positions and velocities 3×P, world.
class LatticeModel final : public Simulator {
 public:
  /// `lattice` from build_lattice() in the body's principal frame; `moments` the body's
  /// principal moments about x, y, z of that frame (mass·length², used for the jiggle,
  /// docs/physics.md §5, and to sort the axes in cos_principal_L()); `cage_rest` (3×8) the
  /// corners of the box corners() reports, in the same frame. Throws std::invalid_argument
  /// for an empty lattice, a moment that is not finite and positive, or an integrator the
  /// particle model does not accept.
  LatticeModel(Lattice lattice, const Eigen::Vector3d& moments, const Corners& cage_rest,
               const ModelConfig& config);

  /// Identity orientation, springs at rest, v_p = ω0' × (x_p − c0) with ω0' = I⁻¹(I ω0 + δL),
  /// I = diag(moments), δL the jiggle (docs/physics.md §5), c0 the lattice's centre of mass.
  void reset(const InitialState& initial) override;
  void step(double dt) override;
  /// 3×8 world: the cage's corners. When every cage corner is a particle at rest (the
  /// one-cell book), those particles; otherwise the cage moved rigidly with the lattice:
  /// R (cage − c0) + c, R the mass-weighted best-fit rotation (Kabsch), c the centre of mass.
  Corners corners() const override;
  /// R: the mass-weighted best-fit rotation of the particles onto the lattice at rest.
  Eigen::Matrix3d orientation() const override;
  /// c = Σ m x / M, world.
  Eigen::Vector3d center_of_mass() const override;
  /// t; L = Σ m (x − c) × (v − v̄) (world); ω_body = I_lattice⁻¹ Rᵀ L with I_lattice the
  /// lattice's rest inertia (body frame) and R the best-fit rotation; energies; cos_axis_L
  /// of R's columns; strain_max over every spring; orthogonality_error 0; |q| = 1.
  Diagnostics diagnostics() const override;
  bool finite() const override;

  /// cos(principal axis, L) for the axes of the smallest, intermediate and largest of
  /// `moments` (ties in the order x, y, z), each axis moved by the best-fit rotation R.
  Eigen::Vector3d cos_principal_L() const;
  /// The body's surface (3×V, world) carried by the particles (Lattice::embed_surface).
  Eigen::Matrix3Xd deformed_surface() const override;

  const Lattice& lattice() const { return lattice_; }
  Eigen::Matrix3Xd positions() const { return x_; }   ///< 3×P, world
  Eigen::Matrix3Xd velocities() const { return v_; }  ///< 3×P, world

 private:
  using Rows = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>;
  /// Spring and damping forces into f_ (3×P) for positions x and velocities v; returns the
  /// spring energy Σ ½ k_s (|x_ij| − L_ij)².
  double forces(const Rows& x, const Rows& v);
  double spring_energy() const;
  double kinetic_energy() const;
  void normalize(double spring_energy_at_start);
  /// Σ m (x − c) × (v − v̄), world.
  Eigen::Vector3d angular_momentum() const;

  Lattice lattice_;
  Eigen::Vector3d moments_;
  Corners cage_rest_;
  ModelConfig config_;
  NormalizeSchedule schedule_;      ///< which steps normalize (model.normalize_every)
  std::vector<int> cage_particle_;  ///< 8 particle indices, or empty: rigid cage
  // Springs, structure of arrays.
  std::vector<int> first_, second_;
  std::vector<double> rest_length_, k_, damping_, stiffness_;
  std::vector<double> inverse_mass_, mass_fraction_;
  Eigen::Matrix3d inertia_inverse_;  ///< I_lattice⁻¹, body frame
  Rows x_, v_, f_;
  double energy0_ = 0.0;
  double t_ = 0.0;
};

/// The particle model of a non-book `body` (docs/physics.md §13): its surface filled by
/// build_lattice() with config.lattice_cells cells along the longest side (0: the default,
/// kDefaultLatticeCells) at the body's mass (body.cage.mass), moving the body's cage. Throws
/// std::invalid_argument as build_lattice() and LatticeModel do.
std::unique_ptr<Simulator> make_body_lattice_model(const Body& body, const ModelConfig& config);

}  // namespace bookspin::physics
