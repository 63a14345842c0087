#pragma once
// Poinsot's construction view (render.poinsot; docs/physics.md §16): the charts' side of
// it, turning principal moments and a run's history (L and the orientation per frame) into an
// overlay::PoinsotSpec, and placing the inset in the frame.
#include <Eigen/Dense>

#include "charts/diagnostics_history.hpp"
#include "common/pixel_rect.hpp"
#include "overlay/poinsot.hpp"

namespace bookspin::charts {

/// The construction at the last sample of `history` (which must hold orientations: add()
/// with corners) for principal moments `moments` (body, mass·length², > 0): the inertia
/// ellipsoid xᵀIx = 1 as placed now, the invariable plane at √(2E)/|L| along L, the polhode
/// through the first sample's L/|L| carried by the body, the herpolhode of every sample so far,
/// the plane's disc 1.25 times the herpolhode's closed-form outer bound (at least half the
/// largest semi-axis). Throws std::invalid_argument for an empty history, one without
/// orientations, or L = 0.
overlay::PoinsotSpec poinsot_spec(const Eigen::Vector3d& moments,
                                  const DiagnosticsHistory& history);

/// The inset's square in a width×height frame: with the plot panel (`panel_column`, the
/// panel's rectangle) on top of the column, the plots below (split_for_sphere); without it at
/// the right edge, level with the momentum sphere and as large (side min(0.45·height,
/// 0.42·width)).
PixelRect poinsot_rect(int width, int height, const PixelRect* panel_column);

}  // namespace bookspin::charts
