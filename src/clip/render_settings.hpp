#pragma once
// The scene → renderer adapter: what the renderer needs from a scene and a pose (kept here so
// that the renderer knows nothing of physics and the physics nothing of pictures).
#include <memory>

#include "physics/body.hpp"
#include "physics/simulator.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace bookspin::clip {

/// Renderer settings from the scene's render.* keys; the camera is framed on the book's
/// bounding sphere unless render.camera_distance is set. With render.panel the book is
/// framed in the left kBookShare of the frame, leaving the right for the plots; always below
/// the caption, so that no caption covers the body.
render::RenderSettings render_settings_for(const scene::Scene& scene);

/// Same for a width×height image (pixels, even) whose columns [book_left, book_share) (fractions
/// of the width, 0 ≤ book_left < book_share ≤ 1) frame the book: the camera moves sideways (eye
/// and target together), so the projection stays symmetric and the renderer needs no notion
/// of a viewport. With render.sphere, render_settings_for(scene) frames the body right of the
/// sphere's inset.
/// The rows [book_top, 1) (a fraction of the height, from the top) frame it likewise: the
/// camera stands back until the bounding sphere fits them and moves up (eye and target) to
/// centre it there.
render::RenderSettings render_settings_for(const scene::Scene& scene, int width, int height,
                                           double book_share, double book_left = 0.0,
                                           double book_top = 0.0);

/// The renderer's input for one pose of the book: its 8 corners and L.
render::FrameInput frame_input_for(const physics::Pose& pose);

/// The renderer's input for one pose of any body (docs/physics.md §12). The book is drawn from
/// its corners; any other body as its surface (triangles and face colours shared by every frame,
/// so the renderer uploads them once): the lattice's own deformed surface where the pose has
/// one (§13), else the rest surface carried by the moved cage corners (trilinear_deform, exact
/// for the rigid models' possibly non-orthogonal matrices).
class BodyDrawing {
 public:
  explicit BodyDrawing(const physics::Body& body);
  render::FrameInput input_for(const physics::Pose& pose) const;

 private:
  physics::Corners rest_corners_;                            ///< 3×8, body frame: the cage at rest
  Eigen::Matrix3Xd rest_vertices_;                           ///< 3×V, body frame
  std::shared_ptr<const render::SurfaceTopology> topology_;  ///< null for the book
};

}  // namespace bookspin::clip
