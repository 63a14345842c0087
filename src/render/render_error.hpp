#pragma once
// The one exception type of the render stage.
#include <stdexcept>
#include <string>

namespace bookspin::render {

/// Thrown for every EGL/GL/texture/settings failure of the renderer. what() is one line that
/// names the failing step and, where there is one, the error's name (EGL_BAD_ALLOC,
/// GL_INVALID_OPERATION, GL_FRAMEBUFFER_INCOMPLETE_..., ...).
class RenderError : public std::runtime_error {
 public:
  explicit RenderError(const std::string& message);
};

}  // namespace bookspin::render
