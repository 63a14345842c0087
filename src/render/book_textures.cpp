#include "render/book_textures.hpp"

#include <algorithm>

#include "render/render_error.hpp"

namespace bookspin::render {

namespace {

bool has_anisotropy() {
  return epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") ||
         epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic");
}

void check_texture_size(const RgbaImage& image) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (image.width > max_size || image.height > max_size)
    throw RenderError("texture image " + std::to_string(image.width) + "x" +
                      std::to_string(image.height) + " exceeds GL_MAX_TEXTURE_SIZE " +
                      std::to_string(max_size));
}

TextureHandle upload(const RgbaImage& image, float max_anisotropy) {
  check_texture_size(image);
  GLuint name = 0;
  glGenTextures(1, &name);
  TextureHandle handle(name);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Row 0 of the image (its top) becomes t = 0, matching face_corner_uv's v = 0 at the top.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.pixels.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  // Capped by RenderSettings::max_anisotropy (4× by default; why there).
  if (max_anisotropy > 1.0f && has_anisotropy()) {
    GLfloat limit = 1.0f;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &limit);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, std::min(max_anisotropy, limit));
  }
  check_gl("uploading a face texture");
  return handle;
}

}  // namespace

BookTextures::BookTextures(const FaceImages& images, float max_anisotropy) {
  for (std::size_t i = 0; i < images.size(); ++i) textures_[i] = upload(images[i], max_anisotropy);
}

}  // namespace bookspin::render
