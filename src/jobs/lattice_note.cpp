#include "jobs/lattice_note.hpp"

#include <cstdio>
#include <vector>

#include "physics/lattice.hpp"

namespace bookspin::jobs {

namespace {

std::string note_for(const physics::Body& body, const physics::ModelConfig& model) {
  const int n = model.lattice_cells > 0 ? model.lattice_cells : physics::kDefaultLatticeCells;
  const physics::Lattice lattice =
      physics::build_lattice(body.vertices, body.triangles, body.cage.mass, n);
  // The body's moments are about its principal axes x, y, z, ascending (§12), as the
  // lattice's principal moments are.
  const Eigen::Vector3d& want = body.moments;
  const Eigen::Vector3d& got = lattice.principal_moments;
  char line[400];
  std::snprintf(line, sizeof line,
                "lattice: %d cells along the longest side, %d particles, %d springs; principal "
                "moments %.4g, %.4g, %.4g against the body's %.4g, %.4g, %.4g (%+.1f%%, %+.1f%%, "
                "%+.1f%%)",
                n, lattice.particles(), lattice.spring_count(), got[0], got[1], got[2], want[0],
                want[1], want[2], 100.0 * (got[0] / want[0] - 1.0),
                100.0 * (got[1] / want[1] - 1.0), 100.0 * (got[2] / want[2] - 1.0));
  return line;
}

}  // namespace

std::string lattice_note(const scene::Scene& scene) {
  if (scene.body.shape == physics::BodyShape::book) return {};
  std::vector<physics::ModelConfig> models;
  if (scene.compare.empty()) {
    models.push_back(scene.model);
  } else {
    for (const auto& tile : scene.compare) models.push_back(tile.model);
  }
  std::string note;
  for (const auto& model : models) {
    if (model.kind != physics::ModelKind::particle) continue;
    if (!note.empty()) note += '\n';
    note += note_for(scene.body, model);
  }
  return note;
}

}  // namespace bookspin::jobs
