#include "render/renderer.hpp"

#include <optional>

#include "render/book_mesh.hpp"
#include "render/face_images.hpp"
#include "render/offscreen_target.hpp"
#include "render/overlay_mesh.hpp"
#include "render/passes.hpp"
#include "render/pixel_reader.hpp"

namespace bookspin::render {

namespace {

// Sizes must be even: the video stage encodes 4:2:0 chroma, which halves both dimensions.
void validate_settings(const RenderSettings& settings) {
  const auto size = std::to_string(settings.width) + "x" + std::to_string(settings.height);
  if (settings.width <= 0 || settings.height <= 0)
    throw RenderError("image size must be positive, got " + size);
  if (settings.width % 2 != 0 || settings.height % 2 != 0)
    throw RenderError("image width and height must be even, got " + size);
  if (settings.msaa_samples < 1)
    throw RenderError("msaa_samples must be >= 1 (1 = off), got " +
                      std::to_string(settings.msaa_samples));
  validate_camera(settings.camera);
}

ViewProjection view_projection(const RenderSettings& settings) {
  const double aspect = static_cast<double>(settings.width) / settings.height;
  return {view_matrix(settings.camera).cast<float>(),
          projection_matrix(settings.camera, aspect).cast<float>()};
}

}  // namespace

struct Renderer::Impl {
  RenderSettings settings;
  // Declared first so it is destroyed last: every GL object below needs it.
  std::unique_ptr<EglContext> context;
  std::optional<OffscreenTarget> target;
  std::optional<BackgroundPass> background;
  std::optional<BookPass> book;
  std::optional<OverlayPass> overlays;
  PixelReader reader;
  ViewProjection camera;

  explicit Impl(const RenderSettings& s) : settings(s) {
    validate_settings(settings);
    camera = view_projection(settings);
    // Files first: a bad texture path fails fast, before any GL work.
    const FaceTextures& paths = settings.textures;
    const FaceImages images = face_images(paths.front, paths.back, paths.spine, paths.pages);
    context = std::make_unique<EglContext>();
    target.emplace(settings.width, settings.height, settings.msaa_samples);
    background.emplace();
    book.emplace(images);
    overlays.emplace();
  }

  ~Impl() {
    // GL objects are deleted in the member destructors; they need our context current.
    try {
      if (context) context->make_current();
    } catch (...) {  // nothing sensible to do in a destructor; the driver frees on exit
    }
    overlays.reset();
    book.reset();
    background.reset();
    target.reset();
  }

  RgbaImage render(const FrameInput& frame) {
    context->make_current();
    target->bind_for_drawing();
    glClear(GL_DEPTH_BUFFER_BIT);  // no colour clear: the background covers every pixel
    background->draw();
    book->draw(build_book_mesh(frame.corners), camera);
    if (settings.show_angular_momentum || settings.show_body_axes) {
      overlays->draw(build_overlays(frame.corners, frame.angular_momentum_direction,
                                    settings.show_angular_momentum, settings.show_body_axes),
                     camera);
    }
    check_gl("drawing a frame");
    target->resolve();
    RgbaImage image;
    reader.read(*target, image);
    return image;
  }
};

Renderer::Renderer(const RenderSettings& settings) : impl_(std::make_unique<Impl>(settings)) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

RgbaImage Renderer::render(const FrameInput& frame) { return impl_->render(frame); }
const RenderSettings& Renderer::settings() const { return impl_->settings; }
const GlInfo& Renderer::info() const { return impl_->context->info(); }

GlInfo gl_info() {
  const EglContext context;
  return context.info();
}

}  // namespace bookspin::render
