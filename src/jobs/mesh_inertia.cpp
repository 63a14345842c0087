#include "jobs/mesh_inertia.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "common/errors.hpp"
#include "common/json_writer.hpp"
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

namespace {

/// Ten significant digits, for people.
std::string readable(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", x);
  return buffer;
}

template <typename Format>
std::string row(const Eigen::RowVector3d& v, Format format, const char* sep) {
  return format(v(0)) + sep + format(v(1)) + sep + format(v(2));
}

/// A row as a JSON array of three numbers.
JsonValue json_vector(const Eigen::RowVector3d& v) { return {JsonArray{{v(0)}, {v(1)}, {v(2)}}}; }

/// A matrix as a JSON array of its rows.
JsonValue json_matrix(const Eigen::Matrix3d& m) {
  return {JsonArray{json_vector(m.row(0)), json_vector(m.row(1)), json_vector(m.row(2))}};
}

}  // namespace

std::string inertia_json(const physics::MassProperties& p) {
  const JsonObject members{{"volume", {p.volume}},
                           {"mass", {p.mass}},
                           {"center_of_mass", json_vector(p.center_of_mass.transpose())},
                           {"inertia", json_matrix(p.I_body)},
                           {"principal_moments", json_vector(p.principal_moments.transpose())},
                           {"principal_axes", json_matrix(p.principal_axes)}};
  return json_text({members}, "inertia JSON field", JsonLayout::indented) + "\n";
}

std::string inertia_table(const std::string& file, const physics::MassProperties& p) {
  const auto line = [](const Eigen::RowVector3d& v) { return "  " + row(v, readable, "  "); };
  std::ostringstream out;
  out << "mesh               " << file << " (" << p.shells
      << (p.shells == 1 ? " shell)" : " shells)") << '\n'
      << "volume             " << readable(p.volume) << '\n'
      << "mass               " << readable(p.mass) << '\n'
      << "centre of mass     " << row(p.center_of_mass.transpose(), readable, "  ") << '\n'
      << "inertia about the centre of mass, mesh axes:\n"
      << line(p.I_body.row(0)) << '\n'
      << line(p.I_body.row(1)) << '\n'
      << line(p.I_body.row(2)) << '\n'
      << "principal moments  " << row(p.principal_moments.transpose(), readable, "  ")
      << "  (ascending)\n"
      << "principal axes, one row per moment (right-handed):\n"
      << line(p.principal_axes.row(0)) << '\n'
      << line(p.principal_axes.row(1)) << '\n'
      << line(p.principal_axes.row(2)) << '\n';
  return out.str();
}

}  // namespace bookspin::jobs
