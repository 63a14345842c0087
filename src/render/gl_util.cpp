#include "render/gl_util.hpp"

#include <sstream>
#include <vector>

#include "render/render_error.hpp"

namespace bookspin::render {

namespace {

std::string hex_name(const char* prefix, GLenum code) {
  std::ostringstream out;
  out << prefix << " 0x" << std::hex << code;
  return out.str();
}

/// The info log of a shader or program object, read with the matching pair of GL calls.
template <typename GetIv, typename GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint length = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
  get_log(object, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.data();
}

/// Whether a shader compiled or a program linked (`status`: GL_COMPILE/LINK_STATUS).
template <typename GetIv>
bool succeeded(GLuint object, GetIv get_iv, GLenum status) {
  GLint ok = GL_FALSE;
  get_iv(object, status, &ok);
  return ok == GL_TRUE;
}

std::string shader_log(GLuint shader) {
  return info_log(shader, glGetShaderiv, glGetShaderInfoLog);
}

std::string program_log(GLuint program) {
  return info_log(program, glGetProgramiv, glGetProgramInfoLog);
}

GLuint compile(std::string_view name, GLenum type, std::string_view source) {
  const GLuint shader = glCreateShader(type);
  if (shader == 0) throw RenderError("glCreateShader failed for " + std::string(name));
  const GLchar* text = source.data();
  const GLint length = static_cast<GLint>(source.size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  if (!succeeded(shader, glGetShaderiv, GL_COMPILE_STATUS)) {
    const std::string log = shader_log(shader);
    glDeleteShader(shader);
    const char* kind = type == GL_VERTEX_SHADER ? "vertex" : "fragment";
    throw RenderError("cannot compile " + std::string(kind) + " shader of '" + std::string(name) +
                      "': " + log);
  }
  return shader;
}

}  // namespace

namespace {

struct NamedCode {
  GLenum code;
  const char* name;
};

/// The GL constant's name from `table`, or `prefix 0x…` for a code not in it.
template <std::size_t N>
std::string name_of(GLenum code, const NamedCode (&table)[N], const char* prefix) {
  for (const NamedCode& entry : table)
    if (entry.code == code) return entry.name;
  return hex_name(prefix, code);
}

#define BOOKSPIN_GL_NAME(code) \
  { code, #code }

constexpr NamedCode kErrors[] = {BOOKSPIN_GL_NAME(GL_NO_ERROR),
                                 BOOKSPIN_GL_NAME(GL_INVALID_ENUM),
                                 BOOKSPIN_GL_NAME(GL_INVALID_VALUE),
                                 BOOKSPIN_GL_NAME(GL_INVALID_OPERATION),
                                 BOOKSPIN_GL_NAME(GL_INVALID_FRAMEBUFFER_OPERATION),
                                 BOOKSPIN_GL_NAME(GL_OUT_OF_MEMORY)};

constexpr NamedCode kFramebufferStatuses[] = {
    BOOKSPIN_GL_NAME(GL_FRAMEBUFFER_COMPLETE),
    BOOKSPIN_GL_NAME(GL_FRAMEBUFFER_UNDEFINED),
    BOOKSPIN_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT),
    BOOKSPIN_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT),
    BOOKSPIN_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER),
    BOOKSPIN_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER),
    BOOKSPIN_GL_NAME(GL_FRAMEBUFFER_UNSUPPORTED),
    BOOKSPIN_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE),
    BOOKSPIN_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS)};

#undef BOOKSPIN_GL_NAME

}  // namespace

std::string gl_error_name(GLenum code) { return name_of(code, kErrors, "GL error"); }

std::string framebuffer_status_name(GLenum status) {
  return name_of(status, kFramebufferStatuses, "framebuffer status");
}

bool is_software_rasterizer(std::string_view gl_renderer) {
  for (const char* software : {"llvmpipe", "softpipe", "SWR"}) {
    if (gl_renderer.find(software) != std::string_view::npos) return true;
  }
  return false;
}

void check_gl(std::string_view what) {
  const GLenum first = glGetError();
  if (first == GL_NO_ERROR) return;
  // Drain the queue so a later check does not report this failure again.
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
  }
  throw RenderError("OpenGL error " + gl_error_name(first) + " during " + std::string(what));
}

GLuint build_program(std::string_view name, std::string_view vertex_source,
                     std::string_view fragment_source) {
  const GLuint vertex = compile(name, GL_VERTEX_SHADER, vertex_source);
  GLuint fragment = 0;
  try {
    fragment = compile(name, GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);  // flagged; freed with the program
  glDeleteShader(fragment);
  if (!succeeded(program, glGetProgramiv, GL_LINK_STATUS)) {
    const std::string log = program_log(program);
    glDeleteProgram(program);
    throw RenderError("cannot link shader program '" + std::string(name) + "': " + log);
  }
  check_gl("building shader program " + std::string(name));
  return program;
}

GLint uniform_location(GLuint program, const char* uniform) {
  const GLint location = glGetUniformLocation(program, uniform);
  if (location < 0)
    throw RenderError(std::string("shader has no active uniform '") + uniform + "'");
  return location;
}

void delete_program(GLuint name) { glDeleteProgram(name); }
void delete_buffer(GLuint name) { glDeleteBuffers(1, &name); }
void delete_vertex_array(GLuint name) { glDeleteVertexArrays(1, &name); }
void delete_texture(GLuint name) { glDeleteTextures(1, &name); }
void delete_framebuffer(GLuint name) { glDeleteFramebuffers(1, &name); }
void delete_renderbuffer(GLuint name) { glDeleteRenderbuffers(1, &name); }

}  // namespace bookspin::render
