#pragma once
// Colours shared by every picture: one RGB type and one palette for telling runs apart.
#include <array>
#include <cstddef>

namespace bookspin {

/// A colour, each channel in [0, 1] (sRGB, as cairo takes it).
struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;
};

/// Runs, methods and tiles told apart by colour: the Okabe–Ito colours (colour-blind safe;
/// Okabe & Ito 2008), with a near-black fifth so that the palette's look-alike vermillion and
/// orange sit far apart.
inline constexpr std::array<Rgb, 9> kPalette{{{0.00, 0.45, 0.70},
                                              {0.84, 0.37, 0.00},
                                              {0.00, 0.62, 0.45},
                                              {0.80, 0.47, 0.65},
                                              {0.20, 0.20, 0.20},
                                              {0.34, 0.71, 0.91},
                                              {0.90, 0.62, 0.00},
                                              {0.60, 0.60, 0.20},
                                              {0.55, 0.35, 0.15}}};

/// One colour per component, x red, y green, z blue, as the rendered body axes: ω_x, ω_y and
/// ω_z in every picture (the clips' panel, the fitted tosses' charts), in the explorer page
/// (web/src/colours.js, OMEGA_COLOURS: these channels × 255, rounded, as hex) and in the
/// notebook (examples/intermediate-axis.ipynb); tests/common/colour_test.cpp holds the three to
/// the same colours.
inline constexpr std::array<Rgb, 3> kComponentColours{
    {{0.85, 0.15, 0.10}, {0.10, 0.60, 0.20}, {0.15, 0.35, 0.90}}};

/// kPalette, cycled by `index` (≥ 0).
inline constexpr Rgb palette_colour(std::size_t index) { return kPalette[index % kPalette.size()]; }

}  // namespace bookspin
