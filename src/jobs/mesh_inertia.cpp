#include "jobs/mesh_inertia.hpp"

#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "mesh/mesh.hpp"

namespace bookspin::jobs {

physics::MassProperties mesh_inertia(const InertiaRequest& request) {
  const std::string file = request.mesh_path.string();
  const bool by_mass = request.mass.has_value();
  const double amount = by_mass ? *request.mass : request.density;
  if (!(std::isfinite(amount) && amount > 0.0))
    throw InputError(file + ": " + (by_mass ? "mass" : "density") + " must be a positive number");
  const mesh::TriangleMesh mesh = mesh::load_mesh(request.mesh_path, request.scale);
  const physics::MassPropertiesResult result =
      physics::mass_properties(mesh.vertices, mesh.triangles, by_mass ? 1.0 : request.density);
  if (!result.ok()) throw InputError(file + ": " + result.error);
  return by_mass ? physics::with_mass(result.properties, *request.mass) : result.properties;
}

}  // namespace bookspin::jobs
