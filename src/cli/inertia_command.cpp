// `bookspin inertia`: a mesh file's volume, mass, centre of mass and inertia tensor
// (docs/physics.md §11), as text or as one JSON object.
#include <cstdio>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "jobs/mesh_inertia.hpp"

namespace bookspin::cli {

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

}  // namespace bookspin::cli
