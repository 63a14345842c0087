#pragma once
// The render stage's door: draws a book given as 8 world-space corners, or any triangle
// surface given by its world positions, off-screen, headless (EGL, OpenGL 3.3 core), into an
// RGBA image. Knows nothing of physics.
#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/rgba_image.hpp"
#include "render/camera.hpp"
#include "render/egl_context.hpp"
#include "render/render_error.hpp"
#include "render/surface.hpp"

namespace bookspin::render {

/// Half the largest diagonal of the default 1.878 × 2.9085 × 0.5 book, rounded up (world
/// units): the bounding radius the default camera is placed for.
inline constexpr double default_bounding_radius = 1.75;

/// Optional PNG per face image; an empty path means the generated default.
/// `pages` covers the fore-edge, top and bottom (see book_faces.hpp for orientations).
struct FaceTextures {
  std::string front, back, spine, pages;
};

/// RenderSettings::max_anisotropy's "choose for the GL in use" value.
inline constexpr float kAutoAnisotropy = 0.0f;

/// The anisotropy `requested` resolves to on a GL whose GL_RENDERER string is `gl_renderer`:
/// itself unless automatic, then 1 on a software rasterizer (llvmpipe, softpipe, SWR) and 4
/// elsewhere.
float effective_anisotropy(float requested, const std::string& gl_renderer);

struct RenderSettings {
  int width = 1280;  ///< pixels, even, > 0
  int height = 720;  ///< pixels, even, > 0
  /// Defaults to default_camera(default_bounding_radius, 1280, 720); call default_camera
  /// again for another image shape or book size.
  Camera camera = default_camera(default_bounding_radius, 1280, 720);
  FaceTextures textures;
  bool show_angular_momentum = false;  ///< yellow arrow from the origin along L
  bool show_body_axes = false;         ///< red x, green y, blue z from the centre of the 8 corners
  int msaa_samples = 4;                ///< 1 = off; clamped to GL_MAX_SAMPLES
  /// Anisotropic texture filtering cap; 1 = trilinear only; 0 = automatic (kAutoAnisotropy):
  /// 4× on a GPU, enough for covers seen nearly edge-on, and trilinear on a software
  /// rasterizer: on Mesa llvmpipe (22.3) with MSAA, 4× anisotropy is most of the book's cost,
  /// and close, magnified faces (a stretched book filling the view) take seconds per frame.
  float max_anisotropy = kAutoAnisotropy;
};

/// One frame's input.
struct FrameInput {
  /// 3×8, world, column p = corner p (docs/physics.md §1: bit 0 = x, bit 1 = y, bit 2 = z).
  /// Drawn exactly as given (stretched or exploded books too); any non-finite corner →
  /// no book is drawn, only the background (and the L arrow if enabled). With a surface,
  /// the book is not drawn and the corners (the body's box) only place the body axes.
  Eigen::Matrix<double, 3, 8> corners = Eigen::Matrix<double, 3, 8>::Zero();
  /// World direction of the angular momentum (any length; zero = no arrow).
  Eigen::Vector3d angular_momentum_direction = Eigen::Vector3d::Zero();
  /// When surface.topology is set, this surface is drawn instead of the book, lit with the
  /// book's lights (surface.hpp); a non-finite position → no surface, only the background
  /// and markers.
  SurfaceFrame surface{};
};

/// Owns a headless GL context (EglContext), the face textures and the shaders.
/// Not copyable; movable. Use from the thread that created it (the context is made current
/// on each render call, so several Renderers may share a thread).
class Renderer {
 public:
  /// Creates the context, builds shaders, generates/loads textures (once). Throws
  /// RenderError: width/height not even and > 0, msaa_samples < 1, a degenerate camera,
  /// a texture file missing or unreadable (message names face and file), a missing font,
  /// or any EGL/GL failure.
  explicit Renderer(const RenderSettings& settings);
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Renders one frame: width×height RGBA, top row first, opaque. Throws RenderError on a
  /// GL failure, std::invalid_argument for a malformed surface (validate_topology, or fewer
  /// positions than its triangles use). Synchronous (tests, stills); frames in flight from
  /// submit() are unaffected.
  RgbaImage render(const FrameInput& frame);

  /// render() in two halves, so that each can be timed (bookspin-bench): draw() draws
  /// `frame` (MSAA resolve included) and waits until the GL has finished it; read_back()
  /// then returns its pixels, exactly what render() would have returned. Same errors as
  /// render(); read_back() without a draw() first returns the last frame drawn.
  void draw(const FrameInput& frame);
  RgbaImage read_back();

  /// Pipelined rendering (the render command's path): draws `frame` and starts its
  /// read-back through a ring of pixel-buffer objects without waiting for it. At most
  /// pipeline_depth() frames may be in flight (std::logic_error otherwise), so call
  /// collect() after each submit(). Throws RenderError on a GL failure.
  void submit(const FrameInput& frame);
  /// The oldest frame in flight once pipeline_depth() frames are, so that the newest
  /// frame's drawing overlaps the caller's work on this one; std::nullopt before that.
  /// The image is exactly what render() would have returned for that frame.
  std::optional<RgbaImage> collect();
  /// The oldest frame in flight however many there are (end of a clip); std::nullopt when
  /// none is left.
  std::optional<RgbaImage> flush();
  /// Hands back an image the caller is done with; the next collect() or flush() of the
  /// same size returns its pixels in that buffer instead of allocating a new one.
  void recycle(RgbaImage image);
  /// Frames in flight before collect() returns one (pixel buffers in the ring, ≥ 2).
  int pipeline_depth() const;

  const RenderSettings& settings() const;
  /// Platform, vendor, renderer and version strings of this renderer's context.
  const GlInfo& info() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Creates a temporary headless context and reports what it runs on (for `bookspin info`).
/// Throws RenderError if no context can be created.
GlInfo gl_info();

}  // namespace bookspin::render
