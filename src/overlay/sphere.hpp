#pragma once
// The momentum sphere inset: curves on a unit sphere drawn in orthographic projection from
// a fixed oblique view, labelled axes, trails with a dot at their end. Pure drawing: the
// pipeline says what the curves are (docs/physics.md §15).
#include <cairo.h>

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "common/colour.hpp"
#include "common/pixel_rect.hpp"
#include "common/rgba_image.hpp"

namespace bookspin::overlay {

/// A polyline on the unit sphere (unit 3-vectors in the sphere's own frame).
struct SphereCurve {
  std::vector<Eigen::Vector3d> points;
  Rgb colour;
  double width = 1.0;  ///< line width as a share of 1/150 of the inset's side
};

/// An axis of the sphere's frame, drawn from −direction to +direction through the centre,
/// labelled at its + end.
struct SphereAxis {
  Eigen::Vector3d direction;  ///< unit
  std::string label;
  Rgb colour;
};

/// A run's path on the sphere; its last point is drawn as a dot (radius 2 + 0.8 × width).
struct SphereTrail {
  std::vector<Eigen::Vector3d> points;
  Rgb colour;
  double width = 1.6;  ///< line width as a share of 1/150 of the inset's side
};

struct SphereSpec {
  std::string title;
  std::vector<SphereAxis> axes;
  std::vector<SphereCurve> curves;      ///< drawn first (polhodes, separatrices)
  std::vector<SphereTrail> trails;      ///< drawn over the curves
  Eigen::Vector3d view{1.0, 0.5, 0.6};  ///< towards the viewer (need not be unit)
  Eigen::Vector3d up{0.0, 0.0, 1.0};    ///< points up on screen (made orthogonal to view)
};

/// Screen position of unit vector p for an inset of centre (cx, cy) and radius r (pixels,
/// y down); `depth` gets p's component towards the viewer (> 0: the near hemisphere).
Eigen::Vector2d project_to_inset(const SphereSpec& spec, const Eigen::Vector3d& p, double cx,
                                 double cy, double r, double* depth = nullptr);

/// The sphere's disc inside the square inset `rect`: centre and radius, pixels.
struct SphereDisc {
  double cx, cy, r;
};
SphereDisc sphere_disc(const PixelRect& rect);

/// Draws `spec` into the square `rect` of `image` on a translucent dark background: the
/// sphere's outline, the axes and their labels, the curves (near side solid, far side faint
/// and dashed), the trails and their end dots, and the title on top.
void draw_sphere(RgbaImage& image, const PixelRect& rect, const SphereSpec& spec);

class CairoCanvas;

/// draw_sphere for an inset drawn on every frame of a clip: what does not change (the
/// background, title, outline, axes and curves) is drawn once, and each frame adds only the
/// trails and the axis labels over a copy of it. The pixels are exactly draw_sphere's.
class SphereInset {
 public:
  /// An inset `rect` on image_width×image_height images showing `spec` (its trails are
  /// ignored: draw() gives them).
  SphereInset(int image_width, int image_height, const PixelRect& rect, SphereSpec spec);
  ~SphereInset();
  SphereInset(const SphereInset&) = delete;
  SphereInset& operator=(const SphereInset&) = delete;

  /// As draw_sphere(image, rect, spec with `trails`). Throws std::invalid_argument for an
  /// image of another size than the constructor's.
  void draw(RgbaImage& image, std::vector<SphereTrail> trails);
  /// Whether `image` has the size this inset was made for.
  bool fits(const RgbaImage& image) const {
    return image.width == width_ && image.height == height_;
  }

 private:
  int width_, height_;
  PixelRect rect_;
  SphereSpec spec_;
  std::unique_ptr<CairoCanvas> canvas_;  ///< null where the inset is too small to draw
  std::vector<unsigned char> base_;      ///< the canvas with the unchanging layer drawn
};

}  // namespace bookspin::overlay
