#pragma once
// The curves a plot panel shows, accumulated frame by frame (a few doubles per frame).
#include <string>
#include <vector>

#include "physics/simulator.hpp"
#include "scene/scene.hpp"

namespace bookspin::charts {

/// Per-frame samples of one run, in frame order.
struct DiagnosticsHistory {
  std::vector<double> t;                          ///< time units
  std::vector<double> omega_x, omega_y, omega_z;  ///< body frame, rad per time unit
  std::vector<double> energy_drift;               ///< E/E0 − 1, dimensionless
  std::vector<double> strain_max;                 ///< max |len/rest − 1|
  std::vector<double> quaternion_deviation;       ///< |q| − 1
  std::vector<double> orthogonality_error;        ///< ‖RᵀR − I‖_F
  /// u = RᵀL/|L|, body frame, unit (physics::momentum_direction_body; docs/physics.md §15)
  std::vector<Eigen::Vector3d> momentum_direction;
  /// L, world frame (the invariable plane's normal, docs/physics.md §16)
  std::vector<Eigen::Vector3d> angular_momentum;
  /// R, body → world, from the corners (physics::rotation_from_corners); one per sample when
  /// add() was given the corners, else empty
  std::vector<Eigen::Matrix3d> orientation;
  double energy0 = 0.0;  ///< E of the first sample

  /// Appends one frame's sample; the first sample fixes E0. With `corners` (3×8, world)
  /// also the orientation.
  void add(const physics::Diagnostics& d, const physics::Corners* corners = nullptr);
  std::size_t size() const { return t.size(); }
};

/// One run drawn in a panel: its history and how it is named in legends. Made from the
/// run's scene, so that the model and the axis that flips come from it.
struct PanelRun {
  /// `history` must outlive the run; `label` is the legend text in comparison plots (empty
  /// for a single run).
  PanelRun(const scene::Scene& scene, const DiagnosticsHistory& history, std::string label = {});

  std::string label;
  physics::ModelKind kind;  ///< picks the shape measures
  const DiagnosticsHistory* history;
  /// Body axis (0 = x, 1 = y, 2 = z) of the intermediate principal moment, whose ω the plots
  /// of the flips show: it changes sign at every flip (x for the book, y for the presets;
  /// analysis::intermediate_axis, docs/physics.md §12).
  int flip_axis;
  /// "s" or "" (the scene's time.unit): the plots' time and rate labels.
  std::string time_unit;
  /// The scene's measured ω (measured.omega), drawn beside the run, or null; the scene's, so it
  /// lives as long as the scene.
  const scene::MeasuredOmega* measured = nullptr;
};

}  // namespace bookspin::charts
