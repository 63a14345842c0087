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
  check_gl("allocating a " + std::to_string(width) + "x" + std::to_string(height) + " renderbuffer");
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
    throw RenderError(std::string("cannot complete the ") + what + " framebuffer: " +
                      framebuffer_status_name(status));
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
  const GLuint fbo = samples_ > 1 ? msaa_fbo_.get() : resolve_fbo_.get();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, width_, height_);
}

void OffscreenTarget::resolve() const {
  if (samples_ > 1) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_.get());
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_.get());
  check_gl("resolving the multisampled frame");
}

}  // namespace bookspin::render
