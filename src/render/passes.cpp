#include "render/passes.hpp"

#include <cstddef>
#include <initializer_list>

#include "render/book_faces.hpp"
#include "render/embedded_shaders.hpp"  // generated from shaders/ at build time (build dir)

namespace bookspin::render {

namespace {

GLuint new_vertex_array() {
  GLuint name = 0;
  glGenVertexArrays(1, &name);
  return name;
}

GLuint new_buffer() {
  GLuint name = 0;
  glGenBuffers(1, &name);
  return name;
}

/// One float vector of a vertex: its attribute index, its size and where it sits.
struct FloatAttribute {
  GLuint index;
  int components;
  std::size_t offset;
};

/// Binds `vao` and `vbo` and describes the layout of `Vertex` in the buffer.
template <typename Vertex>
void set_vertex_layout(GLuint vao, GLuint vbo, std::initializer_list<FloatAttribute> attributes) {
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  for (const FloatAttribute& a : attributes) {
    glEnableVertexAttribArray(a.index);
    glVertexAttribPointer(a.index, a.components, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(a.offset));
  }
}

void set_camera(GLint view_location, GLint projection_location, const ViewProjection& camera) {
  glUniformMatrix4fv(view_location, 1, GL_FALSE, camera.view.data());  // Eigen: column-major
  glUniformMatrix4fv(projection_location, 1, GL_FALSE, camera.projection.data());
}

// Re-specifying the whole buffer each frame lets the driver orphan the old storage.
template <typename Vertex>
void stream(GLuint vbo, const std::vector<Vertex>& vertices) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STREAM_DRAW);
}

/// What every depth-tested solid draw starts with: its program and camera, its vertex array
/// and this frame's vertices streamed into its buffer.
template <typename Vertex>
void begin_solid_draw(const SolidProgram& solid, const ViewProjection& camera,
                      const std::vector<Vertex>& vertices) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(solid.program.get());
  set_camera(solid.view_location, solid.projection_location, camera);
  glBindVertexArray(solid.vao.get());
  stream(solid.vbo.get(), vertices);
}

}  // namespace

SolidProgram::SolidProgram(std::string_view name, std::string_view vertex_source,
                           std::string_view fragment_source)
    : program(build_program(name, vertex_source, fragment_source)),
      vao(new_vertex_array()),
      vbo(new_buffer()),
      view_location(uniform_location(program.get(), "u_view")),
      projection_location(uniform_location(program.get(), "u_projection")) {}

// ---- background -------------------------------------------------------------------------

BackgroundPass::BackgroundPass()
    : program_(build_program("background", shaders::background_vert, shaders::background_frag)),
      vao_(new_vertex_array()) {
  glUseProgram(program_.get());
  glUniform3f(uniform_location(program_.get(), "u_top"), 0.34f, 0.40f, 0.49f);
  glUniform3f(uniform_location(program_.get(), "u_bottom"), 0.075f, 0.085f, 0.11f);
  check_gl("setting up the background");
}

void BackgroundPass::draw() const {
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glUseProgram(program_.get());
  glBindVertexArray(vao_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
}

// ---- book -------------------------------------------------------------------------------

BookPass::BookPass(const FaceImages& images, float max_anisotropy)
    : solid_("book", shaders::book_vert, shaders::book_frag),
      textures_(images, max_anisotropy),
      specular_location_(uniform_location(solid_.program.get(), "u_specular")),
      shininess_location_(uniform_location(solid_.program.get(), "u_shininess")) {
  set_vertex_layout<BookVertex>(solid_.vao.get(), solid_.vbo.get(),
                                {{0, 3, offsetof(BookVertex, position)},
                                 {1, 3, offsetof(BookVertex, normal)},
                                 {2, 2, offsetof(BookVertex, uv)}});
  glUseProgram(solid_.program.get());
  glUniform1i(uniform_location(solid_.program.get(), "u_texture"), 0);
  check_gl("setting up the book");
}

void BookPass::draw(const std::vector<BookVertex>& vertices, const ViewProjection& camera) {
  if (vertices.empty()) return;
  begin_solid_draw(solid_, camera, vertices);
  glActiveTexture(GL_TEXTURE0);
  for (std::size_t f = 0; f < book_faces.size(); ++f) {
    const bool cover = book_faces[f].image != FaceImage::pages;
    // Cloth covers get a soft sheen; paper edges stay matte.
    glUniform1f(specular_location_, cover ? 0.22f : 0.04f);
    glUniform1f(shininess_location_, cover ? 28.0f : 8.0f);
    glBindTexture(GL_TEXTURE_2D, textures_.texture(book_faces[f].image));
    glDrawArrays(GL_TRIANGLES, static_cast<GLint>(f * vertices_per_face), vertices_per_face);
  }
}

// ---- markers ----------------------------------------------------------------------------

MarkerPass::MarkerPass() : solid_("marker", shaders::marker_vert, shaders::marker_frag) {
  set_vertex_layout<MarkerVertex>(solid_.vao.get(), solid_.vbo.get(),
                                  {{0, 3, offsetof(MarkerVertex, position)},
                                   {1, 3, offsetof(MarkerVertex, normal)},
                                   {2, 3, offsetof(MarkerVertex, color)}});
  check_gl("setting up the markers");
}

void MarkerPass::draw(const std::vector<MarkerVertex>& vertices, const ViewProjection& camera) {
  if (vertices.empty()) return;
  begin_solid_draw(solid_, camera, vertices);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
}

}  // namespace bookspin::render
