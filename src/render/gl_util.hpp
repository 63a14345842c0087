#pragma once
// Internal GL helpers: error checks that throw RenderError, shader programs, owning handles.
#include <epoxy/gl.h>

#include <string>
#include <string_view>
#include <utility>

namespace bookspin::render {

/// "GL_INVALID_OPERATION", ... (hex for unknown codes).
std::string gl_error_name(GLenum code);
/// "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT", ... for a glCheckFramebufferStatus result.
std::string framebuffer_status_name(GLenum status);

/// Whether a GL_RENDERER string names a software rasterizer (llvmpipe, softpipe, SWR).
bool is_software_rasterizer(std::string_view gl_renderer);

/// Throws RenderError "OpenGL error GL_... during <what>" if glGetError reports anything
/// (drains all pending errors and names the first).
void check_gl(std::string_view what);

/// Compiles and links a vertex + fragment shader; throws RenderError with the info log
/// (on one line) naming `name` on failure. Returns the program object.
GLuint build_program(std::string_view name, std::string_view vertex_source,
                     std::string_view fragment_source);

/// Uniform location; throws RenderError if the program has no such active uniform, so a
/// renamed uniform fails loudly instead of silently doing nothing.
GLint uniform_location(GLuint program, const char* uniform);

/// Owns one GL object name; `Deleter` is called with the name when replaced or destroyed.
/// Requires the owning context to be current at destruction (Renderer guarantees it).
template <void (*Deleter)(GLuint)>
class GlHandle {
 public:
  GlHandle() = default;
  explicit GlHandle(GLuint name) : name_(name) {}
  ~GlHandle() { reset(); }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  GlHandle(GlHandle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  GLuint get() const { return name_; }
  void reset() {
    if (name_ != 0) Deleter(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
};

void delete_program(GLuint name);
void delete_buffer(GLuint name);
void delete_vertex_array(GLuint name);
void delete_texture(GLuint name);
void delete_framebuffer(GLuint name);
void delete_renderbuffer(GLuint name);

using ProgramHandle = GlHandle<delete_program>;
using BufferHandle = GlHandle<delete_buffer>;
using VertexArrayHandle = GlHandle<delete_vertex_array>;
using TextureHandle = GlHandle<delete_texture>;
using FramebufferHandle = GlHandle<delete_framebuffer>;
using RenderbufferHandle = GlHandle<delete_renderbuffer>;

}  // namespace bookspin::render
