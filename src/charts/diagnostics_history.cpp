#include "charts/diagnostics_history.hpp"

#include <cmath>

#include "analysis/motion.hpp"
#include "physics/poinsot.hpp"
#include "physics/polhode.hpp"

namespace bookspin::charts {

void DiagnosticsHistory::add(const physics::Diagnostics& d, const physics::Corners* corners) {
  if (t.empty()) energy0 = d.energy_total;
  t.push_back(d.t);
  omega_x.push_back(d.omega_body.x());
  omega_y.push_back(d.omega_body.y());
  omega_z.push_back(d.omega_body.z());
  // A book at rest has E0 = 0: the relative drift is undefined, so the curve is left out
  // (non-finite points break a plotted line).
  energy_drift.push_back(energy0 != 0.0 ? d.energy_total / energy0 - 1.0 : std::nan(""));
  strain_max.push_back(d.strain_max);
  quaternion_deviation.push_back(d.quaternion_norm - 1.0);
  orthogonality_error.push_back(d.orthogonality_error);
  momentum_direction.push_back(physics::momentum_direction_body(d));
  angular_momentum.push_back(d.L);
  if (corners) orientation.push_back(physics::rotation_from_corners(*corners));
}

PanelRun::PanelRun(const scene::Scene& scene, const DiagnosticsHistory& history, std::string label)
    : label(std::move(label)),
      kind(scene.model.kind),
      history(&history),
      flip_axis(analysis::intermediate_axis(scene.body.moments)),
      time_unit(scene.time_unit),
      measured(scene.measured.file.empty() ? nullptr : &scene.measured) {}

}  // namespace bookspin::charts
