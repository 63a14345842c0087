#pragma once
// Where frames are drawn: a multisampled FBO, resolved into a single-sample FBO, plus a
// copy of the background so that later frames restore it instead of redrawing it.
#include "render/gl_util.hpp"
#include "render/pixel_box.hpp"

namespace bookspin::render {

/// Renderbuffer-backed framebuffers of width×height pixels: RGBA8 + 24-bit depth with
/// `samples` MSAA samples (clamped to GL_MAX_SAMPLES; 1 = no MSAA, drawing goes straight
/// to the resolve target). Requires a current GL context; throws RenderError naming the
/// GL_FRAMEBUFFER_INCOMPLETE_... status if a framebuffer cannot be completed.
class OffscreenTarget {
 public:
  OffscreenTarget(int width, int height, int samples);

  /// Binds the framebuffer to draw into and sets the viewport.
  void bind_for_drawing() const;
  /// Resolves the multisampled image into the single-sample framebuffer (glBlitFramebuffer)
  /// and leaves that one bound for reading.
  void resolve() const;
  /// Same for the pixels of `box` only; the rest of the single-sample image is kept.
  void resolve(const PixelRegion& box) const;
  /// Keeps a copy of the whole drawn image (every sample) as the background.
  void save_background();
  /// Copies the saved background back over `box` of the drawing framebuffer: exactly the
  /// samples drawing the background there would give. Requires save_background().
  void restore_background(const PixelRegion& box) const;
  /// The single-sample framebuffer holding the finished frame (bottom row first, GL style).
  GLuint resolved_framebuffer() const { return resolve_fbo_.get(); }

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }  ///< samples actually used

 private:
  GLuint drawing_framebuffer() const;
  void copy_color(GLuint from, GLuint to, const PixelRegion& box) const;

  int width_;
  int height_;
  int samples_;
  FramebufferHandle msaa_fbo_;
  RenderbufferHandle msaa_color_;
  FramebufferHandle resolve_fbo_;
  RenderbufferHandle resolve_color_;
  RenderbufferHandle depth_;
  FramebufferHandle background_fbo_;  ///< same sample count as the drawing framebuffer
  RenderbufferHandle background_color_;
};

}  // namespace bookspin::render
