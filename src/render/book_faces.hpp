#pragma once
// THE face mapping of the book (docs/physics.md §1), kept in this one place.
//
// Corner p has body coordinate −size/2 + size·bit(p, d), bit 0 = x, bit 1 = y, bit 2 = z.
// Faces: front cover +z, back cover −z, spine +x, fore-edge (page edges) −x, top +y,
// bottom −y.
//
// Each face lists its corners in texture order: top-left, top-right, bottom-right,
// bottom-left of the texture image, as seen from outside the book. Seen from outside, the
// image is never mirrored: (TR − TL) × (BL − TL) points into the book (tests check this).
//  - front (+z), seen from +z with +y up: title upright, reads left to right.
//  - back (−z), seen from −z with +y up: upright.
//  - spine (+x): the image's long side runs along y, its top edge lies on the front-cover
//    side (+z). Seen from +x with +y up the title reads bottom to top (rotated 90°
//    counter-clockwise); with the book lying front cover up it reads left to right.
//  - fore-edge, top, bottom: the "pages" image, its rows (page lines) run along y (fore-
//    edge) or x (top, bottom); its top edge lies on the back-cover side (−z) and its bottom
//    edge on the front-cover side (+z), so cover-board bands line up on all three faces.
#include <array>

namespace bookspin::render {

/// Which of the four face images a face shows.
enum class FaceImage { front, back, spine, pages };

/// One face of the book.
struct FaceSpec {
  const char* name;
  int axis;                    ///< outward normal's axis in the body frame (0 x, 1 y, 2 z)
  int sign;                    ///< +1 or −1: outward normal = sign · e_axis
  std::array<int, 4> corners;  ///< texture top-left, top-right, bottom-right, bottom-left
  FaceImage image;
};

inline constexpr std::array<FaceSpec, 6> book_faces{{
    {"front", 2, +1, {6, 7, 5, 4}, FaceImage::front},
    {"back", 2, -1, {3, 2, 0, 1}, FaceImage::back},
    {"spine", 0, +1, {5, 7, 3, 1}, FaceImage::spine},
    {"fore-edge", 0, -1, {0, 2, 6, 4}, FaceImage::pages},
    {"top", 1, +1, {2, 3, 7, 6}, FaceImage::pages},
    {"bottom", 1, -1, {1, 0, 4, 5}, FaceImage::pages},
}};

/// Texture coordinates (u right, v down; v = 0 is the image's top row) of the four corners
/// in FaceSpec::corners order.
inline constexpr std::array<std::array<float, 2>, 4> face_corner_uv{
    {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}}};

}  // namespace bookspin::render
