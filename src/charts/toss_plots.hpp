#pragma once
// The phone-toss lab's chart (docs/phone-lab.md, "Reading the result"): one toss's measured ω
// as dots beside the fitted exact motion as lines, its flips marked, and beside them the
// measured L on the momentum sphere (docs/physics.md §15) with the fitted exact orbit.
#include "common/colour.hpp"
#include "common/rgba_image.hpp"
#include "fit/report.hpp"
#include "overlay/sphere.hpp"

namespace bookspin::charts {

/// The measured L/|L| (orange trail, its end dotted) and the fitted exact orbit (blue).
inline constexpr Rgb kMeasuredLColour{0.95, 0.45, 0.05};
inline constexpr Rgb kFittedOrbitColour{0.10, 0.25, 0.75};

/// A toss on the momentum sphere (docs/physics.md §15), in the fitted body's principal frame
/// (axes 1, 2, 3 by ascending moment, each labelled with the phone axis it lies nearest, signed:
/// fit::TossChart): the measured L/|L| (one point a sample) as a trail in kMeasuredLColour, the
/// fitted exact motion's L/|L| over one period of ω (its polhode; over the flight when the
/// motion has no period) as a curve in kFittedOrbitColour, over the polhode family and the
/// separatrices of the fitted moments (fit::TossChart::polhodes, as charts::sphere_spec draws
/// them).
overlay::SphereSpec toss_sphere_spec(const fit::TossChart& chart);

/// A toss (fit::toss_chart's values) on a white width×height image: on the left the measured ω's
/// three phone-frame components (rad/s, bias removed) as dots against the recording's time
/// (s), the fitted exact ω as lines in the same colours, and each flip of the fitted motion (a
/// sign change of ω about the intermediate axis; none for a stable toss, whose wobble changes
/// that sign without flipping) as a grey dashed vertical line; on the right,
/// in a square of side min(height, 0.4·width), toss_sphere_spec's sphere.
RgbaImage toss_image(const fit::TossChart& chart, int width, int height);

}  // namespace bookspin::charts
