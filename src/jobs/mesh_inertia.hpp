#pragma once
// A mesh file's mass properties: load (src/mesh), integrate (src/physics, docs/physics.md
// §11), and turn the physics' error reasons into input errors naming the file.
#include <filesystem>
#include <optional>
#include <string>

#include "physics/mass_properties.hpp"

namespace bookspin::jobs {

struct InertiaRequest {
  std::filesystem::path mesh_path;
  double scale = 1.0;          ///< multiplies every coordinate of the file, > 0
  std::optional<double> mass;  ///< total mass, > 0; overrides density when set
  double density = 1.0;        ///< mass per length³ (length after scaling), > 0
};

/// The mesh's volume, mass, centre of mass, inertia about the centre of mass and principal
/// frame, in the file's axes and scaled units; warnings (a shell turned around) in
/// `warnings`. Throws InputError "FILE: reason" for a file that cannot be read (see
/// mesh::load_mesh) or a mesh that bounds no solid: "open mesh: N boundary edges",
/// "non-manifold mesh: …", "inconsistent winding: …", "zero volume: …".
physics::MassProperties mesh_inertia(const InertiaRequest& request);

/// `p` as one line of JSON: volume, mass, center_of_mass, inertia (3×3 rows), principal_moments,
/// principal_axes (3×3, one row per moment), each number the shortest text that reads back
/// exactly. A non-finite number is an internal error naming the field (common/number_text.hpp).
std::string inertia_json(const physics::MassProperties& p);

/// `p` as the table `bookspin inertia` prints for people (ten significant digits), headed by
/// the mesh file's name and its shell count.
std::string inertia_table(const std::string& file, const physics::MassProperties& p);

}  // namespace bookspin::jobs
