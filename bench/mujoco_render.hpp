#pragma once
// MuJoCo's own renderer (mjr_render on an off-screen EGL context) drawing a free textured box
// of the book's size: the peer row of the bench. Built only with MuJoCo (BOOKSPIN_HAVE_MUJOCO).
#include <Eigen/Dense>
#include <memory>

#include "common/rgba_image.hpp"

namespace bookspin::bench {

struct MujocoRenderSetup {
  Eigen::Vector3d book_size{1, 1, 1};             ///< full edge lengths, body frame
  int width = 1280, height = 720;                 ///< pixels
  int msaa = 4;                                   ///< samples of the off-screen buffer
  double fov_y_deg = 30.0;                        ///< vertical field of view, degrees
  Eigen::Vector3d eye{0, 0, 8}, target{0, 0, 0};  ///< bookspin's camera, world frame (+y up)
};

/// One EGL context of its own (OpenGL compatibility profile, which mjr_* needs), made current
/// on the calling thread for the object's life, with one mjModel: a free body holding a box
/// geom of the book's size with a checker texture on every face, MuJoCo's head light, no
/// shadows. bookspin's world has +y up, MuJoCo's +z: poses and camera are turned by
/// (x, y, z) → (x, −z, y) on the way in. Not copyable.
class MujocoRenderer {
 public:
  /// Throws std::runtime_error if MuJoCo is missing, EGL gives no context, or MuJoCo rejects
  /// the model.
  explicit MujocoRenderer(const MujocoRenderSetup& setup);
  ~MujocoRenderer();
  MujocoRenderer(const MujocoRenderer&) = delete;
  MujocoRenderer& operator=(const MujocoRenderer&) = delete;

  /// Draws the box with body → world rotation `rotation` (3×3, bookspin's world) and centre
  /// `centre` (world): mj_kinematics, mjv_updateScene, mjr_render into the off-screen buffer.
  void draw(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& centre);
  /// mjr_readPixels of the last draw (RGB, bottom row first) as 8-bit RGBA, top row first,
  /// alpha 255: the frame an encoder takes.
  RgbaImage read_back();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bookspin::bench
