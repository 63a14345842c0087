#include "render/face_images.hpp"

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>

#include "render/cairo_draw.hpp"
#include "render/cover_art.hpp"
#include "render/render_error.hpp"

namespace bookspin::render {

namespace {

RgbaImage draw_face_image(FaceImage which) {
  switch (which) {
    case FaceImage::front:
      return art::front_cover();
    case FaceImage::back:
      return art::back_cover();
    case FaceImage::spine:
      return art::spine();
    case FaceImage::pages:
      return art::pages();
  }
  throw RenderError("unknown face image");
}

std::string describe(cairo_status_t status, const std::string& path) {
  if (!std::filesystem::exists(path)) return "file not found";
  // cairo reports a file it cannot decode as a PNG as "out of memory" (its libpng error
  // path): say what it is, with cairo's words for what went wrong.
  return std::string("not a readable PNG (cairo: ") + cairo_status_to_string(status) + ")";
}

}  // namespace

RgbaImage generate_face_image(FaceImage which) {
  // The art never changes within a process: draw each image once, hand out copies
  // (a second Renderer, e.g. a preview next to a video, then starts faster).
  static std::mutex mutex;
  static std::array<std::optional<RgbaImage>, 4> cache;
  const std::lock_guard lock(mutex);
  auto& slot = cache[static_cast<std::size_t>(which)];
  if (!slot) slot = draw_face_image(which);
  return *slot;
}

RgbaImage load_face_image(const std::string& path, const char* face) {
  draw::SurfacePtr png(cairo_image_surface_create_from_png(path.c_str()), &cairo_surface_destroy);
  const cairo_status_t status = cairo_surface_status(png.get());
  if (status != CAIRO_STATUS_SUCCESS)
    throw RenderError(std::string("cannot read the ") + face + " texture '" + path +
                      "': " + describe(status, path));
  const int width = cairo_image_surface_get_width(png.get());
  const int height = cairo_image_surface_get_height(png.get());
  if (width < 1 || height < 1)
    throw RenderError(std::string("the ") + face + " texture '" + path + "' is empty");
  // The book is opaque: flatten any transparency onto white paper.
  auto flat = draw::make_surface(width, height);
  auto ctx = draw::make_context(flat.get());
  cairo_set_source_rgb(ctx.get(), 1, 1, 1);
  cairo_paint(ctx.get());
  cairo_set_source_surface(ctx.get(), png.get(), 0, 0);
  cairo_paint(ctx.get());
  return draw::to_rgba(flat.get());
}

FaceImages face_images(const std::string& front, const std::string& back, const std::string& spine,
                       const std::string& pages) {
  const auto one = [](const std::string& path, FaceImage which, const char* face) {
    return path.empty() ? generate_face_image(which) : load_face_image(path, face);
  };
  return {one(front, FaceImage::front, "front"), one(back, FaceImage::back, "back"),
          one(spine, FaceImage::spine, "spine"), one(pages, FaceImage::pages, "pages")};
}

}  // namespace bookspin::render
