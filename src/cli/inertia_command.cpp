// `bookspin inertia`: a mesh file's volume, mass, centre of mass and inertia tensor
// (docs/physics.md §11), as text or as one JSON object.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "cli/subcommand.hpp"
#include "common/errors.hpp"
#include "jobs/mesh_inertia.hpp"

namespace bookspin::cli {
namespace {

struct InertiaOptions {
  std::string mesh_path;
  double mass = 0.0;     ///< total mass; 0 = not given (use density)
  double density = 1.0;  ///< mass per length³, after scaling
  double scale = 1.0;    ///< multiplies the file's coordinates
  bool json = false;     ///< one JSON object instead of the table
};

/// A finite number > 0 (CLI::PositiveNumber lets NaN and infinity through).
const CLI::Validator kFinitePositive(
    [](std::string& text) -> std::string {
      double value = 0.0;
      if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !(value > 0.0))
        return "Value " + text + " is not a finite positive number";
      return {};
    },
    "POSITIVE");

/// Prints a mesh file's volume, mass, centre of mass, inertia about the centre of mass and
/// principal frame (docs/physics.md §11); warnings on stderr.
int inertia_command(const InertiaOptions& options) {
  jobs::InertiaRequest request;
  request.mesh_path = options.mesh_path;
  request.scale = options.scale;
  if (options.mass > 0.0) request.mass = options.mass;
  request.density = options.density;
  // The options a number beyond the double range comes from, named in the error.
  char given[160];
  if (options.mass > 0.0)
    std::snprintf(given, sizeof given, " (from --mass %g and --scale %g)", options.mass,
                  options.scale);
  else
    std::snprintf(given, sizeof given, " (from --density %g and --scale %g)", options.density,
                  options.scale);
  physics::MassProperties p;
  try {
    p = jobs::mesh_inertia(request);
  } catch (const InputError& e) {
    const std::string message = e.what();
    const bool range = message.find(physics::kOverflow) != std::string::npos ||
                       message.find(physics::kUnderflow) != std::string::npos ||
                       message.find("mesh size out of range") != std::string::npos;
    if (range) throw InputError(message + given);
    throw;
  }
  // Never print NaN, infinity, or a mass or moment that underflowed to 0.
  if (const std::string range = physics::range_error(p); !range.empty())
    throw InputError(options.mesh_path + ": " + range + given);
  for (const auto& warning : p.warnings)
    std::cerr << "bookspin: warning: " << options.mesh_path << ": " << warning << '\n';
  if (options.json) {
    std::cout << jobs::inertia_json(p);
  } else {
    std::cout << jobs::inertia_table(options.mesh_path, p);
  }
  return kExitOk;
}

}  // namespace

Subcommand add_inertia(CLI::App& cli) {
  const auto stored = std::make_shared<InertiaOptions>();
  InertiaOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "inertia",
      "Print the volume, mass, centre of mass and inertia tensor of a closed mesh (OBJ, STL, "
      "glTF 2.0) of uniform density");
  cmd->add_option("MESH", options.mesh_path, "Mesh file: .obj, .stl, .gltf or .glb")->required();
  CLI::Option* mass = cmd->add_option("--mass", options.mass, "Total mass (instead of --density)")
                          ->check(kFinitePositive);
  CLI::Option* density =
      cmd->add_option("--density", options.density, "Mass per unit volume, after --scale")
          ->check(kFinitePositive)
          ->capture_default_str();
  mass->excludes(density);
  cmd->add_option("--scale", options.scale, "Multiply every coordinate of the file by S")
      ->check(kFinitePositive)
      ->capture_default_str();
  cmd->add_flag("--json", options.json, "Print one JSON object (full precision) instead");
  return {cmd, [stored] { return inertia_command(*stored); }};
}

}  // namespace bookspin::cli
