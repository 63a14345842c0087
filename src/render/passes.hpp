#pragma once
// Internal: the three things drawn each frame, each owning its program and buffers.
// All require the renderer's context to be current.
#include <Eigen/Dense>
#include <vector>

#include "render/book_mesh.hpp"
#include "render/book_textures.hpp"
#include "render/gl_util.hpp"
#include "render/marker_mesh.hpp"

namespace bookspin::render {

/// World → view and view → clip, single precision for GL.
struct ViewProjection {
  Eigen::Matrix4f view;
  Eigen::Matrix4f projection;
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
  ProgramHandle program_;
  VertexArrayHandle vao_;
  BufferHandle vbo_;
  BookTextures textures_;
  GLint view_location_, projection_location_, specular_location_, shininess_location_;
};

/// Arrows and axes: one streamed vertex buffer, one draw.
class MarkerPass {
 public:
  MarkerPass();
  void draw(const std::vector<MarkerVertex>& vertices, const ViewProjection& camera);

 private:
  ProgramHandle program_;
  VertexArrayHandle vao_;
  BufferHandle vbo_;
  GLint view_location_, projection_location_;
};

}  // namespace bookspin::render
