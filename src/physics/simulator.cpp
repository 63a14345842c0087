#include "physics/simulator.hpp"

#include <array>
#include <random>
#include <stdexcept>

#include "physics/exact_model.hpp"
#include "physics/lattice_model.hpp"
#include "physics/model_modes.hpp"
#include "physics/particle_model.hpp"
#include "physics/rigid_matrix_model.hpp"
#include "physics/rigid_quaternion_model.hpp"

namespace bookspin::physics {

namespace {

template <typename Enum>
struct Named {
  Enum value;
  std::string_view name;
  bool engine = false;  ///< a model of another engine's (docs/engines.md): src/engines builds it
};

/// Every model: its name, and whether it is another engine's.
constexpr std::array<Named<ModelKind>, 7> kModelNames{{
    {ModelKind::particle, "particle"},
    {ModelKind::rigid_matrix, "rigid-matrix"},
    {ModelKind::rigid_quaternion, "rigid-quaternion"},
    {ModelKind::exact, "exact"},
    {ModelKind::mujoco, "mujoco", true},
    {ModelKind::bullet, "bullet", true},
    {ModelKind::ode, "ode", true},
}};

/// Every model's modes, each model's default first (model_modes()).
constexpr ModelMode kModes[] = {
    {ModelKind::particle, Integrator::euler},
    {ModelKind::particle, Integrator::symplectic_euler},
    {ModelKind::particle, Integrator::velocity_verlet},
    {ModelKind::rigid_matrix, Integrator::euler},
    {ModelKind::rigid_matrix, Integrator::rk4},
    {ModelKind::rigid_matrix, Integrator::implicit_midpoint},
    {ModelKind::rigid_matrix, Integrator::splitting},
    {ModelKind::rigid_matrix, Integrator::splitting4},
    {ModelKind::rigid_matrix, Integrator::rescaled_euler},
    {ModelKind::rigid_quaternion, Integrator::euler},
    {ModelKind::rigid_quaternion, Integrator::rk4},
    {ModelKind::rigid_quaternion, Integrator::implicit_midpoint},
    {ModelKind::rigid_quaternion, Integrator::splitting},
    {ModelKind::rigid_quaternion, Integrator::splitting4},
    {ModelKind::rigid_quaternion, Integrator::rescaled_euler},
    {ModelKind::exact, Integrator::euler},  // the integrator key is unused by "exact"
    {ModelKind::mujoco, Integrator::euler},
    {ModelKind::mujoco, Integrator::rk4},
    {ModelKind::mujoco, Integrator::implicit},
    {ModelKind::bullet, Integrator::implicit_body},
    {ModelKind::bullet, Integrator::implicit_world},
    {ModelKind::bullet, Integrator::explicit_gyro},
    {ModelKind::bullet, Integrator::none},
    {ModelKind::ode, Integrator::step},
    {ModelKind::ode, Integrator::quickstep},
    {ModelKind::ode, Integrator::none},
};

constexpr std::array<Named<Integrator>, 15> kIntegratorNames{{
    {Integrator::euler, "euler"},
    {Integrator::symplectic_euler, "symplectic-euler"},
    {Integrator::velocity_verlet, "velocity-verlet"},
    {Integrator::rk4, "rk4"},
    {Integrator::implicit_midpoint, "implicit-midpoint"},
    {Integrator::splitting, "splitting"},
    {Integrator::splitting4, "splitting4"},
    {Integrator::implicit, "implicit"},
    {Integrator::implicit_body, "implicit-body"},
    {Integrator::implicit_world, "implicit-world"},
    {Integrator::explicit_gyro, "explicit"},
    {Integrator::none, "none"},
    {Integrator::step, "step"},
    {Integrator::quickstep, "quickstep"},
    {Integrator::rescaled_euler, "rescaled-euler"},
}};

template <typename Enum, std::size_t N>
std::string_view name_of(const std::array<Named<Enum>, N>& table, Enum e) {
  for (const Named<Enum>& entry : table)
    if (entry.value == e) return entry.name;
  return "?";
}

template <typename Enum, std::size_t N>
bool value_of(const std::array<Named<Enum>, N>& table, std::string_view text, Enum& out) {
  for (const Named<Enum>& entry : table) {
    if (entry.name == text) {
      out = entry.value;
      return true;
    }
  }
  return false;
}

}  // namespace

std::string_view to_string(ModelKind kind) { return name_of(kModelNames, kind); }
std::string_view to_string(Integrator integrator) { return name_of(kIntegratorNames, integrator); }
bool parse_model_kind(std::string_view text, ModelKind& out) {
  return value_of(kModelNames, text, out);
}
bool parse_integrator(std::string_view text, Integrator& out) {
  return value_of(kIntegratorNames, text, out);
}
std::vector<ModelKind> model_kinds() {
  std::vector<ModelKind> kinds;
  for (const Named<ModelKind>& entry : kModelNames) kinds.push_back(entry.value);
  return kinds;
}
std::vector<Integrator> integrators() {
  std::vector<Integrator> all;
  for (const Named<Integrator>& entry : kIntegratorNames) all.push_back(entry.value);
  return all;
}

Eigen::Vector3d jiggle_delta_L(std::uint64_t seed, double amplitude) {
  std::mt19937_64 engine(seed);
  Eigen::Vector3d delta;
  for (int d = 0; d < 3; ++d) {
    const double unit = static_cast<double>(engine() >> 11) * 0x1.0p-53;  // [0, 1)
    delta[d] = amplitude * (2.0 * unit - 1.0);
  }
  return delta;
}

std::span<const ModelMode> model_modes() { return kModes; }

bool supports(ModelKind kind, Integrator integrator) {
  for (const ModelMode& mode : kModes)
    if (mode.kind == kind && mode.integrator == integrator) return true;
  return false;
}

bool is_engine(ModelKind kind) {
  for (const Named<ModelKind>& entry : kModelNames)
    if (entry.value == kind) return entry.engine;
  return false;
}

Integrator default_integrator(ModelKind kind) {
  for (const ModelMode& mode : kModes)
    if (mode.kind == kind) return mode.integrator;
  throw std::logic_error("physics::default_integrator: model kind " +
                         std::to_string(static_cast<int>(kind)) + " has no modes");
}

bool supports_drag(ModelKind kind) {
  return kind == ModelKind::rigid_matrix || kind == ModelKind::rigid_quaternion ||
         kind == ModelKind::exact;
}

std::unique_ptr<Simulator> make_simulator(const Book& book, const ModelConfig& config) {
  return make_simulator(book_body(book), config);
}

std::unique_ptr<Simulator> make_simulator(const Body& body, const ModelConfig& config) {
  if (!supports(config.kind, config.integrator)) {
    throw std::invalid_argument("model '" + std::string(to_string(config.kind)) +
                                "' does not support integrator '" +
                                std::string(to_string(config.integrator)) + "'");
  }
  if (config.drag.active() && !supports_drag(config.kind)) {
    throw std::invalid_argument("model '" + std::string(to_string(config.kind)) +
                                "' takes no drag (only rigid-matrix, rigid-quaternion, exact)");
  }
  if (is_engine(config.kind)) {
    throw std::invalid_argument("model '" + std::string(to_string(config.kind)) +
                                "' is another engine's: engines::make_model builds it");
  }
  switch (config.kind) {
    case ModelKind::particle:
      if (body.shape == BodyShape::book) return std::make_unique<ParticleModel>(body.cage, config);
      return make_body_lattice_model(body, config);
    case ModelKind::rigid_matrix:
      return std::make_unique<RigidMatrixModel>(body, config);
    case ModelKind::rigid_quaternion:
      return std::make_unique<RigidQuaternionModel>(body, config);
    case ModelKind::exact:
      return make_exact_simulator(body, config.drag);
    default:
      break;
  }
  // A model with modes in kModes but no case here: a bug, never another model in its place.
  throw std::logic_error("physics::make_simulator: no simulator for model '" +
                         std::string(to_string(config.kind)) + "'");
}

}  // namespace bookspin::physics
