#pragma once
// The four face images as mipmapped GL textures, made once per Renderer.
#include <array>

#include "render/book_faces.hpp"
#include "render/face_images.hpp"
#include "render/gl_util.hpp"

namespace bookspin::render {

class BookTextures {
 public:
  /// Uploads the images (indexed by FaceImage) with mipmaps, trilinear + anisotropic
  /// filtering up to `max_anisotropy` (1 = trilinear only). Requires a current context;
  /// throws RenderError (image larger than GL_MAX_TEXTURE_SIZE, GL error).
  BookTextures(const FaceImages& images, float max_anisotropy);

  GLuint texture(FaceImage which) const { return textures_[static_cast<std::size_t>(which)].get(); }

 private:
  std::array<TextureHandle, 4> textures_;
};

}  // namespace bookspin::render
