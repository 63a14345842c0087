// `bookspin inertia`: a mesh file's volume, mass, centre of mass and inertia tensor
// (docs/physics.md §11), as text or as one JSON object.
#include <cstdio>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "jobs/mesh_inertia.hpp"
#include "output/finite_number.hpp"

namespace bookspin::cli {

namespace {

/// The shortest text that reads back as exactly `x` (std::to_chars), valid JSON: finite, or
/// an internal error naming the field (output/finite_number.hpp).
std::string exact(double x, std::string_view field) {
  return output::finite_text(x, "inertia JSON field " + std::string(field));
}

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

// Built with append: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
std::string json_vector(const Eigen::RowVector3d& v, std::string_view field) {
  const auto number = [field](double x) { return exact(x, field); };
  std::string out;
  return out.append("[").append(row(v, number, ", ")).append("]");
}

std::string json_matrix(const Eigen::Matrix3d& m, std::string_view field) {
  std::string out;
  return out.append("[")
      .append(json_vector(m.row(0), field))
      .append(", ")
      .append(json_vector(m.row(1), field))
      .append(", ")
      .append(json_vector(m.row(2), field))
      .append("]");
}

void print_json(const physics::MassProperties& p) {
  std::cout << "{\"volume\": " << exact(p.volume, "volume")
            << ", \"mass\": " << exact(p.mass, "mass") << ", \"center_of_mass\": "
            << json_vector(p.center_of_mass.transpose(), "center_of_mass")
            << ", \"inertia\": " << json_matrix(p.I_body, "inertia") << ", \"principal_moments\": "
            << json_vector(p.principal_moments.transpose(), "principal_moments")
            << ", \"principal_axes\": " << json_matrix(p.principal_axes, "principal_axes") << "}\n";
}

void print_text(const std::string& file, const physics::MassProperties& p) {
  const auto line = [](const Eigen::RowVector3d& v) { return "  " + row(v, readable, "  "); };
  std::cout << "mesh               " << file << " (" << p.shells
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
}

}  // namespace

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
    print_json(p);
  } else {
    print_text(options.mesh_path, p);
  }
  return kExitOk;
}

}  // namespace bookspin::cli
