#pragma once
// Internal: the three things drawn each frame, each owning its program and buffers.
// All require the renderer's context to be current.
#include <Eigen/Dense>
#include <string_view>
#include <vector>

#include "render/book_mesh.hpp"
#include "render/book_textures.hpp"
#include "render/gl_util.hpp"
#include "render/marker_mesh.hpp"
#include "render/surface.hpp"

namespace bookspin::render {

/// World → view and view → clip, single precision for GL.
struct ViewProjection {
  Eigen::Matrix4f view;
  Eigen::Matrix4f projection;
};

/// What a depth-tested solid drawn from one streamed vertex buffer owns: its program,
/// vertex array and buffer, and where its camera matrices go.
struct SolidProgram {
  SolidProgram(std::string_view name, std::string_view vertex_source,
               std::string_view fragment_source);
  ProgramHandle program;
  VertexArrayHandle vao;
  BufferHandle vbo;
  GLint view_location, projection_location;
};

/// Full-screen vertical gradient; drawn first, without depth.
class BackgroundPass {
 public:
  BackgroundPass();
  void draw() const;

 private:
  ProgramHandle program_;
  VertexArrayHandle vao_;  // core profile needs one bound even with no attributes
};

/// The textured, lit book: one streamed vertex buffer, one draw per face (own texture).
class BookPass {
 public:
  BookPass(const FaceImages& images, float max_anisotropy);
  /// vertices: build_book_mesh output (6 faces × vertices_per_face, book_faces order).
  void draw(const std::vector<BookVertex>& vertices, const ViewProjection& camera);

 private:
  SolidProgram solid_;
  BookTextures textures_;
  GLint specular_location_, shininess_location_;
};

/// A lit triangle surface (any body, a deformed lattice) with the book's lights: indices and
/// face colours uploaded once per topology, positions and normals streamed every frame.
class SurfacePass {
 public:
  SurfacePass();
  /// Makes `surface.topology` (non-null) the uploaded one if it is not already, and checks
  /// that the positions cover its indices. Throws std::invalid_argument for a bad topology
  /// (validate_topology) or fewer positions than its indices need, RenderError if the GL
  /// cannot hold it (more triangles than GL_MAX_TEXTURE_BUFFER_SIZE).
  void prepare(const SurfaceFrame& surface);
  /// Draws `surface` (prepared; positions drawable: positions_drawable).
  void draw(const SurfaceFrame& surface, const ViewProjection& camera);

 private:
  void upload(const std::shared_ptr<const SurfaceTopology>& topology);

  SolidProgram solid_;  // its vbo holds the positions
  BufferHandle normal_vbo_, index_buffer_, colour_buffer_, face_normal_buffer_;
  TextureHandle colour_texture_, face_normal_texture_;
  GLint smooth_location_;
  /// Held, not only compared, so that its address cannot be reused by another topology.
  std::shared_ptr<const SurfaceTopology> uploaded_;
  int vertex_count_ = 0;  ///< vertices the uploaded triangles use
};

/// Arrows and axes: one streamed vertex buffer, one draw.
class MarkerPass {
 public:
  MarkerPass();
  void draw(const std::vector<MarkerVertex>& vertices, const ViewProjection& camera);

 private:
  SolidProgram solid_;
};

}  // namespace bookspin::render
