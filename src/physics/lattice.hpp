#pragma once
// The particle model of any closed body: a regular lattice of cells filling the body
// (docs/physics.md §13). Pure math: surface in, particles and springs out.
#include <Eigen/Core>

namespace bookspin::physics {

/// Most cells along the longest side a lattice may have (64³ cells, ~3.6 M springs).
inline constexpr int kMaxLatticeCells = 64;
/// Cells along the longest side when the scene does not say (docs/physics.md §13: the
/// T-handle's lattice inertia is within 2% of its mesh's at this resolution).
inline constexpr int kDefaultLatticeCells = 24;

/// Particles and springs filling a closed body, plus the embedding of its surface.
/// All positions are in the frame of the surface given to build_lattice() (the body's
/// principal frame, centre of mass at the origin), length units of that surface.
struct Lattice {
  Eigen::Matrix3Xd rest;        ///< 3×P particle positions at rest
  Eigen::VectorXd mass;         ///< P particle masses, Σ = the body's mass
  Eigen::Matrix2Xi springs;     ///< 2×S particle indices (i < j), sorted by (i, j)
  Eigen::VectorXd rest_length;  ///< S rest lengths |rest_i − rest_j|
  /// S stiffness factors: the spring constant of spring s is k · stiffness(s), with k the
  /// model's spring constant (docs/physics.md §13: Σ over the cells sharing the spring of
  /// the cell's filled fraction / cells_along_longest; exactly 1 for the one-cell book).
  Eigen::VectorXd stiffness;
  /// 8×V: the particles at the corners of the cell each surface vertex is embedded in,
  /// local corner c at cell offset (bit 0, bit 1, bit 2 of c) along (x, y, z).
  Eigen::Matrix<int, 8, Eigen::Dynamic> vertex_cell;
  /// 3×V trilinear coordinates of each surface vertex in its cell (in [0, 1] when the
  /// vertex lies in that cell; outside when the nearest kept cell had to be used).
  Eigen::Matrix3Xd vertex_coords;

  Eigen::Vector3d origin = Eigen::Vector3d::Zero();     ///< lower corner of the grid
  Eigen::Vector3d cell_size = Eigen::Vector3d::Zero();  ///< cell edges (x, y, z)
  Eigen::Vector3i cells = Eigen::Vector3i::Zero();      ///< cells along x, y, z
  int cells_along_longest = 0;                          ///< n, as asked
  int cells_kept = 0;                                   ///< cells with any part of the body in them
  double volume = 0.0;                                  ///< sampled volume of the body (length³)

  double total_mass = 0.0;                                   ///< Σ mass
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();  ///< Σ m x / M at rest
  /// 3×3 inertia of the particles at rest about their centre of mass, lattice frame:
  /// Σ m (|r|² 1 − r rᵀ).
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();   ///< ascending
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();  ///< rows, right-handed

  int particles() const { return static_cast<int>(rest.cols()); }
  int spring_count() const { return static_cast<int>(springs.cols()); }

  /// The surface (3×V) carried by the particles at `particle_positions` (3×P, any frame):
  /// each vertex is Σ_c N_c(u) x_c over its cell's 8 corners, N_c the trilinear weights.
  /// At rest it returns the surface given to build_lattice() to round-off.
  /// Throws std::invalid_argument if `particle_positions` has not P columns.
  Eigen::Matrix3Xd embed_surface(const Eigen::Matrix3Xd& particle_positions) const;
};

/// Fills the closed surface `triangles` (3×N vertex indices into `vertices`, 3×V, the
/// body's principal frame) with a lattice of `cells_along_longest` cells along the longest
/// side of its bounding box and carrying `mass` (docs/physics.md §13):
///   - the grid spans the bounding box exactly, with n_d = max(1, round(n·extent_d/extent_max))
///     cells along axis d (nearly cubic cells; a box is one cell at n = 1);
///   - each cell is cut by s×s vertical columns (s the smallest power of 2 with s·n ≥ 1024),
///     along which the winding number is integrated exactly in z (each closed shell counted
///     with its outward orientation, so shells add up as in mass_properties()); f is the
///     cell's filled fraction and a cell is kept when f > 0 (inside or touching);
///   - a particle at every corner of a kept cell; each cell's f goes half in equal parts to
///     its 8 corners and half by the trilinear weights of its filled part; the masses are
///     these shares scaled to `mass`;
///   - within each kept cell a spring joins every pair of its 8 corners; springs of
///     neighbouring cells joining the same two particles are merged, their stiffness factors
///     f/n adding up (parallel springs).
/// Throws std::invalid_argument for n outside [1, kMaxLatticeCells], a mass that is not
/// finite and positive, no triangles, an index out of range, a non-finite coordinate, a
/// flat bounding box or a surface that encloses nothing.
Lattice build_lattice(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles,
                      double mass, int cells_along_longest);

/// An upper bound on the lattice's highest angular frequency at spring constant k (rad per
/// time unit): ω_max² ≤ max_p 2 Σ_{springs at p} k_s / m_p (Gershgorin's bound on M⁻¹K, the
/// stiffness of a spring being at most k_s along any direction). The undamped explicit
/// integrators are stable for ω_max·dt < 2 (docs/physics.md §10, §13).
double max_angular_frequency(const Lattice& lattice, double k);

/// The mass in a spring's critical damping b_s = 2√(k_s m_s) (docs/physics.md §13):
/// m_s = 2 m_i m_j / (m_i + m_j), twice the pair's reduced mass, exactly m_i when m_i = m_j
/// (the paper's 2√(km), paper §3.3).
inline double spring_mass(double m_i, double m_j) {
  return m_i == m_j ? m_i : 2.0 * m_i * m_j / (m_i + m_j);
}

/// An upper bound on the damping rate of the lattice's fastest mode with critical damping at
/// spring constant k (1 per time unit): γ_max ≤ max_p 2 Σ_{springs at p} b_s / m_p
/// (Gershgorin's bound on M⁻¹B). With damping the explicit integrators are stable for
/// γ_max·dt < 2 as well (tested; the bound is 2–3 times conservative). Per-spring critical
/// damping makes γ_max ≈ 10 ω_max for a lattice (docs/physics.md §13).
double max_damping_rate(const Lattice& lattice, double k);

/// The rotation R (3×3, det +1) minimising Σ w_p |R (rest_p − c0) − (current_p − c)|² with
/// c, c0 the w-weighted centroids (Kabsch 1976 via the SVD of the weighted covariance).
/// `current` and `rest` are 3×N, `weights` N (≥ 0, not all 0).
Eigen::Matrix3d best_fit_rotation(const Eigen::Matrix3Xd& current, const Eigen::Matrix3Xd& rest,
                                  const Eigen::VectorXd& weights);

}  // namespace bookspin::physics
