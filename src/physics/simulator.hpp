#pragma once
// The one interface every simulator of a body implements (docs/physics.md §5, §9 and §10).
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "physics/body.hpp"
#include "physics/book.hpp"
#include "physics/drag.hpp"

namespace bookspin::physics {

/// The models. mujoco, bullet and ode are other engines' rigid bodies (docs/engines.md): the
/// physics room only names them; src/engines builds them (engines::make_model).
enum class ModelKind { particle, rigid_matrix, rigid_quaternion, exact, mujoco, bullet, ode };

/// Time integrators. Which ones a model accepts is checked by make_simulator().
enum class Integrator {
  euler,              ///< explicit Euler in the paper's order (default for every model)
  symplectic_euler,   ///< particle: velocity first, then position
  velocity_verlet,    ///< particle
  rk4,                ///< rigid: classical Runge–Kutta 4
  implicit_midpoint,  ///< rigid
  splitting,          ///< rigid: symplectic splitting of the free rotor (DLM 1997 / NO_SQUISH)
  splitting4,         ///< rigid: fourth-order composition of `splitting` (docs/physics.md §10)
  // The engines' own modes (docs/engines.md), each accepted by its engine only:
  implicit,        ///< mujoco: integrator="implicit" (implicit in velocity)
  implicit_body,   ///< bullet: BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY (Bullet's default)
  implicit_world,  ///< bullet: BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD
  explicit_gyro,   ///< bullet: BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT ("explicit")
  none,            ///< bullet: no gyroscopic flag; ode: dWorldStep, gyroscopic mode off
  step,            ///< ode: dWorldStep, gyroscopic mode on (ODE's default)
  quickstep,       ///< ode: dWorldQuickStep, gyroscopic mode on
  /// rigid: Jolt's and Rapier's gyroscopic step, explicit Euler on the body-frame L rescaled to
  /// keep |L|, then the orientation turned by the new ω (docs/physics.md §10.7)
  rescaled_euler,
};

struct ModelConfig {
  ModelKind kind = ModelKind::particle;
  Integrator integrator = Integrator::euler;
  bool normalize = false;  ///< energy (particle), SVD (matrix), |q| (quaternion)
  /// With normalize: normalize after every N-th step only (steps N, 2N, 3N, … of a run;
  /// docs/physics.md §18). 1 = every step, the paper's method.
  int normalize_every = 1;
  bool damping = true;            ///< critical spring damping (particle only)
  double spring_constant = 10.0;  ///< k, force per length (particle only)
  /// Particle lattice of a non-book body: cells along the body's longest side; 0 = default
  /// (docs/physics.md §13). Not used by the book or the rigid and exact models.
  int lattice_cells = 0;
  /// Air drag on the body's rotation (docs/physics.md §21): the exact model's closed form
  /// (the free motion in stretched time), the rigid models' exact sub-flow of the torque
  /// around each step (Strang splitting). Not accepted by the particle model or the engines.
  Drag drag = {};
};

/// Initial condition: identity orientation, body-frame ω0, and a seeded jiggle.
struct InitialState {
  Eigen::Vector3d omega0_body{0.114819, 0.0, 0.0};  ///< rad per time unit, body frame
  double jiggle = 0.0;  ///< amplitude of the uniform perturbation added to each component of L
  std::uint64_t seed = 1;
};

/// Per-frame diagnostics (docs/physics.md §9). Units: time units, rad/time, energy units.
struct Diagnostics {
  double t = 0.0;
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();  ///< body frame
  Eigen::Vector3d L = Eigen::Vector3d::Zero();           ///< world frame
  double energy_kinetic = 0.0;
  double energy_potential = 0.0;  ///< spring energy (0 for rigid models)
  double energy_total = 0.0;
  Eigen::Vector3d cos_axis_L = Eigen::Vector3d::Zero();  ///< cos(body axis d in world, L)
  /// max |len/rest − 1| over the springs of a particle model (the book: its 28 corner pairs;
  /// the lattice: every spring); 0 for the rigid and exact models
  double strain_max = 0.0;
  double orthogonality_error = 0.0;  ///< ‖RᵀR − I‖_F of the matrix placing the corners
  double quaternion_norm = 1.0;      ///< |q|, 1 where there is no quaternion
  /// cos(principal axis in world, L) for the principal axes sorted by moment: smallest,
  /// intermediate, largest (docs/physics.md §12). For the book: body y, x, z.
  Eigen::Vector3d cos_principal_L = Eigen::Vector3d::Zero();
  /// The pose as Simulator::orientation() and center_of_mass() give it (R body→world, 3×3;
  /// centre of mass, world): filled by Simulator::pose(), identity and zero from diagnostics().
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
};

/// Which steps of a run normalize (docs/physics.md §18): with config.normalize, steps
/// N, 2N, 3N, … (N = config.normalize_every, counted from reset()); none without it.
class NormalizeSchedule {
 public:
  explicit NormalizeSchedule(const ModelConfig& config)
      : every_(config.normalize ? config.normalize_every : 0) {}
  /// Starts counting again from step 1 (Simulator::reset()).
  void reset() { since_ = 0; }
  /// Counts one step; true when this step is to normalize.
  bool due() {
    if (every_ <= 0) return false;
    if (++since_ < every_) return false;
    since_ = 0;
    return true;
  }

 private:
  int every_ = 0;  ///< N, or 0: never
  int since_ = 0;  ///< steps since the last normalization
};

/// What the simulator hands to the rest of the pipeline each frame.
struct Pose {
  Corners corners;  ///< 3×8 world-space corners (the book's, or the body's cage: §12)
  Diagnostics diagnostics;
  /// 3×V world-space surface of a body that deforms by itself (the lattice, §13), vertex i
  /// the body's rest vertex i; empty (0 columns) for every other model, whose surface follows
  /// the corners.
  Eigen::Matrix3Xd surface;
};

/// A simulator of one body (book, preset or mesh): pure physics, deterministic, no I/O.
class Simulator {
 public:
  virtual ~Simulator() = default;
  /// Resets to identity orientation at t = 0 from `initial` (jiggle applied, see jiggle_delta_L).
  virtual void reset(const InitialState& initial) = 0;
  /// Advances the state by one step of `dt` time units.
  virtual void step(double dt) = 0;
  /// World-space corners (3×8).
  virtual Corners corners() const = 0;
  /// The body's orientation R (3×3, body→world, a rotation to round-off): the nearest
  /// rotation to the rigid matrix model's R (docs/physics.md §3), the normalized quaternion's
  /// matrix, the exact R(t), and for the models that deform (particle, lattice) the best-fit
  /// rotation of their particles onto the body at rest (Kabsch; docs/physics.md §13).
  virtual Eigen::Matrix3d orientation() const = 0;
  /// The centre of mass (world, length units): the origin for the rigid and exact models, the
  /// particles' mass-weighted mean for the particle and lattice models.
  virtual Eigen::Vector3d center_of_mass() const { return Eigen::Vector3d::Zero(); }
  /// Diagnostics of the current state.
  virtual Diagnostics diagnostics() const = 0;
  /// diagnostics().cos_axis_L[axis] (axis 0, 1, 2: body x, y, z), the same bits, without the
  /// rest of the diagnostics: the flip detector's signal, read after every step
  /// (analysis::flip_signal, docs/physics.md §14). The rigid and particle models compute the
  /// cosine alone; the others take it from diagnostics().
  virtual double cos_axis_L(int axis) const { return diagnostics().cos_axis_L[axis]; }
  /// True while every state variable is finite and not absurdly large, and the last step
  /// succeeded (an implicit step that did not converge ends the run: docs/physics.md §10).
  virtual bool finite() const = 0;
  /// Why the run stopped when finite() is false for a reason other than overflow (e.g.
  /// "implicit midpoint: fixed-point iteration did not converge at t = …"); empty otherwise.
  virtual std::string divergence_reason() const { return {}; }
  /// The body's surface as this model deforms it (3×V, world), for models whose surface does
  /// not follow the 8 corners (the lattice, docs/physics.md §13); empty (3×0) otherwise.
  virtual Eigen::Matrix3Xd deformed_surface() const { return Eigen::Matrix3Xd(3, 0); }

  Pose pose() const {
    Pose pose{corners(), diagnostics(), deformed_surface()};
    pose.diagnostics.orientation = orientation();
    pose.diagnostics.center_of_mass = center_of_mass();
    return pose;
  }
};

/// The seeded, deterministic jiggle (docs/physics.md §5): a vector uniform in
/// [−amplitude, amplitude]³ from a 64-bit Mersenne Twister (std::mt19937_64, whose
/// output sequence the C++ standard fixes, mapped to doubles by hand so that every
/// standard library gives the same bits). Added to the world angular momentum L at reset.
Eigen::Vector3d jiggle_delta_L(std::uint64_t seed, double amplitude);

/// Whether a model accepts an integrator (particle: euler, symplectic-euler, velocity-verlet;
/// rigid: euler, rk4, implicit-midpoint, splitting, splitting4, rescaled-euler; exact: euler, i.e.
/// the key is unused; mujoco: euler, rk4, implicit; bullet: implicit-body, implicit-world,
/// explicit, none; ode: step, quickstep, none).
bool supports(ModelKind kind, Integrator integrator);

/// Whether a model takes air drag (ModelConfig::drag): the rigid and exact models.
bool supports_drag(ModelKind kind);

/// True for the other engines' models (mujoco, bullet, ode), which make_simulator() cannot
/// build: engines::make_model() does.
bool is_engine(ModelKind kind);

/// The integrator a model runs when the scene names none: an engine's own default (mujoco:
/// euler, bullet: implicit-body, ode: step), euler for bookspin's models.
Integrator default_integrator(ModelKind kind);

/// Creates the simulator of `body` for `config`. The rigid and exact models use
/// body.moments and move body.cage's corners (docs/physics.md §12). Throws
/// std::invalid_argument when the model does not support the integrator, for drag on a
/// model other than the rigid and exact ones (supports_drag()), for the
/// particle model of a non-book body (which needs the lattice, docs/physics.md §13), and
/// for an engine's model (is_engine(): engines::make_model() builds those).
std::unique_ptr<Simulator> make_simulator(const Body& body, const ModelConfig& config);
/// make_simulator(book_body(book), config).
std::unique_ptr<Simulator> make_simulator(const Book& book, const ModelConfig& config);

std::string_view to_string(ModelKind kind);
std::string_view to_string(Integrator integrator);
/// Parses "particle" | "rigid-matrix" | "rigid-quaternion" | "exact" | "mujoco" | "bullet" |
/// "ode"; false if unknown.
bool parse_model_kind(std::string_view text, ModelKind& out);
/// Parses "euler" | "symplectic-euler" | "velocity-verlet" | "rk4" | "implicit-midpoint" |
/// "splitting" | "splitting4" | "implicit" | "implicit-body" | "implicit-world" | "explicit" |
/// "none" | "step" | "quickstep"; false if unknown.
bool parse_integrator(std::string_view text, Integrator& out);

}  // namespace bookspin::physics
