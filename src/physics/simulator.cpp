#include "physics/simulator.hpp"

#include <array>
#include <random>
#include <stdexcept>

#include "physics/exact_model.hpp"
#include "physics/lattice_model.hpp"
#include "physics/names.hpp"
#include "physics/particle_model.hpp"
#include "physics/rigid_matrix_model.hpp"
#include "physics/rigid_quaternion_model.hpp"

namespace bookspin::physics {

namespace {

constexpr std::array<std::pair<ModelKind, std::string_view>, 7> kModelNames{{
    {ModelKind::particle, "particle"},
    {ModelKind::rigid_matrix, "rigid-matrix"},
    {ModelKind::rigid_quaternion, "rigid-quaternion"},
    {ModelKind::exact, "exact"},
    {ModelKind::mujoco, "mujoco"},
    {ModelKind::bullet, "bullet"},
    {ModelKind::ode, "ode"},
}};

constexpr std::array<std::pair<Integrator, std::string_view>, 14> kIntegratorNames{{
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
}};

/// The values of `table`, in its order.
template <typename Enum, std::size_t N>
constexpr std::array<Enum, N> values_of(
    const std::array<std::pair<Enum, std::string_view>, N>& table) {
  std::array<Enum, N> values{};
  for (std::size_t i = 0; i < N; ++i) values[i] = table[i].first;
  return values;
}

constexpr std::array kModelKinds = values_of(kModelNames);
constexpr std::array kIntegrators = values_of(kIntegratorNames);

template <typename Enum, std::size_t N>
std::string_view name_of(const std::array<std::pair<Enum, std::string_view>, N>& table, Enum e) {
  for (const auto& [value, name] : table)
    if (value == e) return name;
  return "?";
}

template <typename Enum, std::size_t N>
bool value_of(const std::array<std::pair<Enum, std::string_view>, N>& table, std::string_view text,
              Enum& out) {
  for (const auto& [value, name] : table) {
    if (name == text) {
      out = value;
      return true;
    }
  }
  return false;
}

bool is_particle_integrator(Integrator i) {
  return i == Integrator::euler || i == Integrator::symplectic_euler ||
         i == Integrator::velocity_verlet;
}

bool is_rigid_integrator(Integrator i) {
  return i == Integrator::euler || i == Integrator::rk4 || i == Integrator::implicit_midpoint ||
         i == Integrator::splitting || i == Integrator::splitting4;
}

}  // namespace

std::span<const ModelKind> model_kinds() { return kModelKinds; }
std::span<const Integrator> integrators() { return kIntegrators; }
std::string_view to_string(ModelKind kind) { return name_of(kModelNames, kind); }
std::string_view to_string(Integrator integrator) { return name_of(kIntegratorNames, integrator); }
bool parse_model_kind(std::string_view text, ModelKind& out) {
  return value_of(kModelNames, text, out);
}
bool parse_integrator(std::string_view text, Integrator& out) {
  return value_of(kIntegratorNames, text, out);
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

bool supports(ModelKind kind, Integrator integrator) {
  switch (kind) {
    case ModelKind::particle:
      return is_particle_integrator(integrator);
    case ModelKind::exact:
      return integrator == Integrator::euler;  // the integrator key is ignored by "exact"
    case ModelKind::mujoco:
      return integrator == Integrator::euler || integrator == Integrator::rk4 ||
             integrator == Integrator::implicit;
    case ModelKind::bullet:
      return integrator == Integrator::implicit_body || integrator == Integrator::implicit_world ||
             integrator == Integrator::explicit_gyro || integrator == Integrator::none;
    case ModelKind::ode:
      return integrator == Integrator::step || integrator == Integrator::quickstep ||
             integrator == Integrator::none;
    default:
      return is_rigid_integrator(integrator);
  }
}

bool is_engine(ModelKind kind) {
  return kind == ModelKind::mujoco || kind == ModelKind::bullet || kind == ModelKind::ode;
}

Integrator default_integrator(ModelKind kind) {
  switch (kind) {
    case ModelKind::bullet:
      return Integrator::implicit_body;
    case ModelKind::ode:
      return Integrator::step;
    default:
      return Integrator::euler;
  }
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
  switch (config.kind) {
    case ModelKind::particle:
      if (body.shape == BodyShape::book) return std::make_unique<ParticleModel>(body.cage, config);
      return make_body_lattice_model(body, config);
    case ModelKind::rigid_matrix:
      return std::make_unique<RigidMatrixModel>(body, config);
    case ModelKind::rigid_quaternion:
      return std::make_unique<RigidQuaternionModel>(body, config);
    case ModelKind::exact:
      break;
    case ModelKind::mujoco:
    case ModelKind::bullet:
    case ModelKind::ode:
      throw std::invalid_argument("model '" + std::string(to_string(config.kind)) +
                                  "' is another engine's: engines::make_model builds it");
  }
  return make_exact_simulator(body);
}

}  // namespace bookspin::physics
