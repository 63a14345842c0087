#include "render/offscreen_target.hpp"

#include <algorithm>

#include "render/render_error.hpp"

namespace bookspin::render {

namespace {

RenderbufferHandle make_renderbuffer(GLenum format, int samples, int width, int height) {
  GLuint name = 0;
  glGenRenderbuffers(1, &name);
  RenderbufferHandle handle(name);
  glBindRenderbuffer(GL_RENDERBUFFER, name);
  if (samples > 1)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  check_gl("allocating a " + std::to_string(width) + "x" + std::to_string(height) +
           " renderbuffer");
  return handle;
}

FramebufferHandle make_framebuffer(GLuint color, GLuint depth, const char* what) {
  GLuint name = 0;
  glGenFramebuffers(1, &name);
  FramebufferHandle handle(name);
  glBindFramebuffer(GL_FRAMEBUFFER, name);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  if (depth != 0)
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw RenderError(std::string("cannot complete the ") + what +
                      " framebuffer: " + framebuffer_status_name(status));
  check_gl(std::string("creating the ") + what + " framebuffer");
  return handle;
}

int clamp_samples(int requested) {
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  return std::clamp(requested, 1, std::max(1, static_cast<int>(max_samples)));
}

void check_size(int width, int height) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width > max_size || height > max_size)
    throw RenderError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                      " exceeds GL_MAX_RENDERBUFFER_SIZE " + std::to_string(max_size));
}

}  // namespace

OffscreenTarget::OffscreenTarget(int width, int height, int samples)
    : width_(width), height_(height), samples_(clamp_samples(samples)) {
  check_size(width, height);
  const int depth_samples = samples_ > 1 ? samples_ : 1;
  depth_ = make_renderbuffer(GL_DEPTH_COMPONENT24, depth_samples, width, height);
  resolve_color_ = make_renderbuffer(GL_RGBA8, 1, width, height);
  if (samples_ > 1) {
    msaa_color_ = make_renderbuffer(GL_RGBA8, samples_, width, height);
    msaa_fbo_ = make_framebuffer(msaa_color_.get(), depth_.get(), "multisampled");
    resolve_fbo_ = make_framebuffer(resolve_color_.get(), 0, "resolve");
  } else {
    resolve_fbo_ = make_framebuffer(resolve_color_.get(), depth_.get(), "single-sample");
  }
}

void OffscreenTarget::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, drawing_framebuffer());
  glViewport(0, 0, width_, height_);
}

void OffscreenTarget::resolve() const { resolve(whole_frame(width_, height_)); }

// Resolving a sub-rectangle is exact: each resolved pixel averages its own samples only.
void OffscreenTarget::resolve(const PixelRegion& box) const {
  if (samples_ > 1 && !box.empty()) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_.get());
    glBlitFramebuffer(box.x, box.y, box.right(), box.bottom(), box.x, box.y, box.right(),
                      box.bottom(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_.get());
  check_gl("resolving the multisampled frame");
}

GLuint OffscreenTarget::drawing_framebuffer() const {
  return samples_ > 1 ? msaa_fbo_.get() : resolve_fbo_.get();
}

void OffscreenTarget::save_background() {
  if (!background_fbo_.get()) {
    background_color_ = make_renderbuffer(GL_RGBA8, samples_, width_, height_);
    background_fbo_ = make_framebuffer(background_color_.get(), 0, "background");
  }
  copy_color(drawing_framebuffer(), background_fbo_.get(), whole_frame(width_, height_));
}

void OffscreenTarget::restore_background(const PixelRegion& box) const {
  if (!box.empty()) copy_color(background_fbo_.get(), drawing_framebuffer(), box);
}

// A blit between framebuffers of equal sample count and format is a plain copy (GL 3.3
// §4.3.2 requires identical rectangles then). The scissor test applies to blits, so it is
// off here; a copy without it is also what lets the driver use memcpy.
void OffscreenTarget::copy_color(GLuint from, GLuint to, const PixelRegion& box) const {
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
  glBlitFramebuffer(box.x, box.y, box.right(), box.bottom(), box.x, box.y, box.right(),
                    box.bottom(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
  check_gl("copying the background");
}

}  // namespace bookspin::render
