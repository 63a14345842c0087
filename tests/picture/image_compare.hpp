#pragma once
// Tolerant image comparison for the golden-image tests: a pixel "differs" when any channel
// differs by more than a threshold, and two images match while few enough pixels differ.
#include <string>

#include "common/rgba_image.hpp"

namespace bookspin::picture {

/// Why these numbers. The goldens are rendered by Mesa llvmpipe (CPU), the reference; the
/// same tests must pass on NVIDIA's EGL and on later Mesa releases. Between conformant GL
/// implementations, at 256×256:
///  - Faces differ by interpolation, lighting and texture-filtering rounding: a few levels
///    per channel. A channel difference of up to 24/255 (~9%) is therefore ignored
///    everywhere; a wrong face (dark blue front, burgundy back, cream pages), a missing
///    overlay or a moved edge changes pixels by far more.
///  - Edges (silhouette, creases, arrows, cover text) differ where sub-sample coverage
///    rounds differently: one-pixel-wide lines, a small share of the image. Emulating that
///    harder than reality — the whole picture a quarter pixel off (tolerance_test.cpp) —
///    marks at most 0.38% of the pixels (PSNR ≥ 42 dB); turning MSAA off entirely, 0.10%.
///    Conformant implementations share the pixel-centre convention and the standard 4×
///    sample pattern, so they differ by less.
///  - Real bugs at 256×256 (teeth_test.cpp): the book turned by 3° marks 1.9% of the pixels,
///    the next frame 2.4%, mirrored cover art 3.0%, swapped covers 12%, a mirror image 16%.
/// So `max_differing_fraction` = 0.5% sits above every legitimate difference we can produce
/// and at least 3× below the subtlest bug. (The 1–2% common elsewhere would let a 3° turn
/// and a mirrored cover through: at this size they change few pixels.) Captions, banners
/// and plots are drawn by cairo on the CPU in the typeface stage's built-in DejaVu, with its
/// options set in code: identical wherever the same cairo and FreeType run, whatever the
/// machine's font set-up (src/typeface/typeface.hpp).
struct Tolerance {
  int channel_threshold = 24;             ///< a channel difference above this marks the pixel
  double max_differing_fraction = 0.005;  ///< largest allowed share of marked pixels
};

struct Comparison {
  bool same_size = false;
  long differing_pixels = 0;       ///< pixels with a channel difference > threshold
  double differing_fraction = 0;   ///< of all pixels (1 when the sizes differ)
  int max_channel_difference = 0;  ///< largest channel difference, 0…255
  double psnr_db = 0;              ///< over R, G, B; +inf for identical images
  bool passed = false;             ///< same size and differing_fraction ≤ the tolerance

  /// "PSNR 31.2 dB, 0.41% of pixels differ by > 24/255 (allowed 0.50%), max 87/255".
  std::string summary(const Tolerance& tolerance) const;
};

Comparison compare_images(const RgbaImage& actual, const RgbaImage& expected,
                          const Tolerance& tolerance = {});

/// A picture of where `actual` and `expected` differ: the expected image as a faint grey
/// ghost; pixels differing by more than the threshold in red (brighter = larger
/// difference), pixels differing by 1…threshold (tolerated noise) in blue. Sizes must
/// agree (std::invalid_argument otherwise).
RgbaImage diff_image(const RgbaImage& actual, const RgbaImage& expected,
                     const Tolerance& tolerance = {});

/// `image` flipped left to right.
RgbaImage mirrored(const RgbaImage& image);

}  // namespace bookspin::picture
