#pragma once
// The momentum sphere view (render.sphere; docs/physics.md §15): the pipeline's side of it,
// turning principal moments and a run's history into an overlay::SphereSpec and placing the
// inset in the frame.
#include <Eigen/Dense>
#include <array>
#include <utility>
#include <vector>

#include "charts/diagnostics_history.hpp"
#include "common/colour.hpp"
#include "common/pixel_rect.hpp"
#include "common/rgba_image.hpp"
#include "overlay/sphere.hpp"
#include "physics/polhode.hpp"
#include "scene/scene.hpp"

namespace bookspin::charts {

/// The principal moments the sphere is drawn for (body frame, mass·length²): the scene's
/// body (docs/physics.md §12).
Eigen::Vector3d sphere_moments(const scene::Scene& scene);

/// One trail on the sphere: a run's body-frame L/|L| so far, in `colour`.
struct SphereRun {
  const DiagnosticsHistory* history = nullptr;
  Rgb colour;
};

/// The sphere for principal moments `moments` (mass·length², > 0): axes labelled by body
/// axis and rank ("x · intermediate"), the polhode family (4 energies per family,
/// physics::polhode_family) in grey, the separatrices in magenta, one trail per run (each
/// narrower than the one before, so coinciding trails show every colour).
overlay::SphereSpec sphere_spec(const Eigen::Vector3d& moments, const std::vector<SphereRun>& runs);

/// The same sphere drawn from values made beforehand: `order`, the body axes by ascending
/// moment (physics::principal_order), and `polhodes`, the polhode family with its separatrices
/// (physics::polhode_family), so that a chart that carries them is drawn from the chart alone.
overlay::SphereSpec sphere_spec(const std::array<int, 3>& order,
                                std::vector<physics::Polhode> polhodes,
                                const std::vector<SphereRun>& runs);

/// The trails of sphere_spec(moments, runs) alone (what changes from frame to frame).
std::vector<overlay::SphereTrail> sphere_trails(const std::vector<SphereRun>& runs);

/// The inset's square in a width×height frame whose book part is `book_width` pixels wide
/// (the whole width, or the part left of the panel): at the left edge, below the caption,
/// above the divergence banner; side min(0.45·height, 0.42·book_width). Its top is 0.19·height,
/// below a caption of three lines; each of `caption_lines` beyond three moves it down by the
/// caption's line height (1.35 font sizes, the font overlay::default_caption_font), and at least
/// to the bottom of their box.
PixelRect sphere_rect(int width, int height, double book_width, int caption_lines = 3);

/// A comparison's plot column shared with the sphere: the sphere's square on top (side
/// min(column width, 0.42 × column height), centred), the rest of the column below for the
/// plots. Returns {sphere, plots}.
std::pair<PixelRect, PixelRect> split_for_sphere(const PixelRect& column);

/// Colour of the separatrices (the polhodes are grey).
inline constexpr Rgb kSeparatrixColour{0.80, 0.05, 0.60};

}  // namespace bookspin::charts
