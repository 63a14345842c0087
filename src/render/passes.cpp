#include "render/passes.hpp"

#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>

#include "render/book_faces.hpp"
#include "render/embedded_shaders.hpp"  // generated from shaders/ at build time (build dir)
#include "render/render_error.hpp"

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

GLuint new_texture() {
  GLuint name = 0;
  glGenTextures(1, &name);
  return name;
}

/// 3×N floats → 4×N (RGBA32F texels: a GL 3.3 texture buffer has no three-component float
/// format).
Eigen::Matrix4Xf padded(const Eigen::Matrix3Xf& columns) {
  Eigen::Matrix4Xf out = Eigen::Matrix4Xf::Zero(4, columns.cols());
  out.topRows<3>() = columns;
  return out;
}

void buffer_data(GLenum target, GLuint buffer, std::size_t bytes, const void* data, GLenum usage) {
  glBindBuffer(target, buffer);
  glBufferData(target, static_cast<GLsizeiptr>(bytes), data, usage);
}

// Texture units of the surface's per-triangle tables (unit 0 stays the book's).
constexpr GLint kColourUnit = 1;
constexpr GLint kFaceNormalUnit = 2;

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

// ---- surface ----------------------------------------------------------------------------

SurfacePass::SurfacePass()
    : solid_("surface", shaders::surface_vert, shaders::surface_frag),
      normal_vbo_(new_buffer()),
      index_buffer_(new_buffer()),
      colour_buffer_(new_buffer()),
      face_normal_buffer_(new_buffer()),
      colour_texture_(new_texture()),
      face_normal_texture_(new_texture()),
      smooth_location_(uniform_location(solid_.program.get(), "u_smooth")) {
  const GLuint program = solid_.program.get();
  glBindVertexArray(solid_.vao.get());
  glBindBuffer(GL_ARRAY_BUFFER, solid_.vbo.get());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, normal_vbo_.get());
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_.get());  // recorded in the vertex array
  glUseProgram(program);
  glUniform1i(uniform_location(program, "u_face_colours"), kColourUnit);
  glUniform1i(uniform_location(program, "u_face_normals"), kFaceNormalUnit);
  // The book covers' sheen: bodies read as the same material family as the book.
  glUniform1f(uniform_location(program, "u_specular"), 0.22f);
  glUniform1f(uniform_location(program, "u_shininess"), 28.0f);
  const std::pair<GLuint, GLuint> tables[] = {
      {colour_texture_.get(), colour_buffer_.get()},
      {face_normal_texture_.get(), face_normal_buffer_.get()}};
  for (const auto& [texture, buffer] : tables) {
    glBindBuffer(GL_TEXTURE_BUFFER, buffer);
    glBufferData(GL_TEXTURE_BUFFER, 16, nullptr, GL_STATIC_DRAW);  // storage before attaching
    glBindTexture(GL_TEXTURE_BUFFER, texture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, buffer);
  }
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  check_gl("setting up the surface");
}

void SurfacePass::prepare(const SurfaceFrame& surface) {
  if (surface.topology != uploaded_) upload(surface.topology);
  if (surface.positions.cols() < vertex_count_)
    throw std::invalid_argument("surface: " + std::to_string(surface.positions.cols()) +
                                " positions, but its triangles use " +
                                std::to_string(vertex_count_) + " vertices");
}

void SurfacePass::upload(const std::shared_ptr<const SurfaceTopology>& topology) {
  const int vertex_count = validate_topology(*topology);
  const Eigen::Index n = topology->triangles.cols();
  GLint max_texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
  if (n > max_texels)
    throw RenderError("a surface of " + std::to_string(n) + " triangles exceeds this GL's " +
                      std::to_string(max_texels) + " texels per texture buffer");
  const Eigen::Matrix<GLuint, 3, Eigen::Dynamic> indices = topology->triangles.cast<GLuint>();
  glBindVertexArray(solid_.vao.get());
  buffer_data(GL_ELEMENT_ARRAY_BUFFER, index_buffer_.get(), indices.size() * sizeof(GLuint),
              indices.data(), GL_STATIC_DRAW);
  const Eigen::Matrix4Xf colours = padded(topology->face_colours);
  buffer_data(GL_TEXTURE_BUFFER, colour_buffer_.get(), colours.size() * sizeof(float),
              colours.data(), GL_STATIC_DRAW);
  glUseProgram(solid_.program.get());
  glUniform1i(smooth_location_, topology->smooth ? 1 : 0);
  if (topology->smooth) {
    glEnableVertexAttribArray(1);
  } else {
    glDisableVertexAttribArray(1);
    glVertexAttrib3f(1, 0.0f, 0.0f, 0.0f);
  }
  check_gl("uploading a surface");
  uploaded_ = topology;
  vertex_count_ = vertex_count;
}

void SurfacePass::draw(const SurfaceFrame& surface, const ViewProjection& camera) {
  const SurfaceTopology& topology = *uploaded_;
  const Eigen::Matrix3Xf positions = surface.positions.cast<float>();
  const Eigen::Matrix4Xf face_normal_texels =
      padded(face_normals(surface.positions, topology.triangles));
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(solid_.program.get());
  set_camera(solid_.view_location, solid_.projection_location, camera);
  glBindVertexArray(solid_.vao.get());
  buffer_data(GL_ARRAY_BUFFER, solid_.vbo.get(), positions.size() * sizeof(float), positions.data(),
              GL_STREAM_DRAW);
  if (topology.smooth) {
    const Eigen::Matrix3Xf normals = vertex_normals(surface.positions, topology.triangles);
    buffer_data(GL_ARRAY_BUFFER, normal_vbo_.get(), normals.size() * sizeof(float), normals.data(),
                GL_STREAM_DRAW);
  }
  buffer_data(GL_TEXTURE_BUFFER, face_normal_buffer_.get(),
              face_normal_texels.size() * sizeof(float), face_normal_texels.data(), GL_STREAM_DRAW);
  glActiveTexture(GL_TEXTURE0 + kColourUnit);
  glBindTexture(GL_TEXTURE_BUFFER, colour_texture_.get());
  glActiveTexture(GL_TEXTURE0 + kFaceNormalUnit);
  glBindTexture(GL_TEXTURE_BUFFER, face_normal_texture_.get());
  glActiveTexture(GL_TEXTURE0);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(3 * topology.triangles.cols()), GL_UNSIGNED_INT,
                 nullptr);
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
