#include "render/renderer.hpp"

#include <optional>

#include "render/book_mesh.hpp"
#include "render/face_images.hpp"
#include "render/marker_mesh.hpp"
#include "render/offscreen_target.hpp"
#include "render/passes.hpp"
#include "render/pixel_box.hpp"
#include "render/pixel_reader.hpp"

namespace bookspin::render {

namespace {

// Two pixel buffers: frame N's read-back runs while the caller finishes frame N − 1. More
// only adds latency and memory; llvmpipe and GPU drivers alike finish a frame well within
// one frame of the caller's work.
constexpr int kPipelineDepth = 2;

// Sizes must be even: the output stage encodes 4:2:0 chroma, which halves both dimensions.
void validate_settings(const RenderSettings& settings) {
  const auto size = std::to_string(settings.width) + "x" + std::to_string(settings.height);
  if (settings.width <= 0 || settings.height <= 0)
    throw RenderError("image size must be positive, got " + size);
  if (settings.width % 2 != 0 || settings.height % 2 != 0)
    throw RenderError("image width and height must be even, got " + size);
  if (settings.max_anisotropy < 0.0f || settings.max_anisotropy > 16.0f)
    throw RenderError("max_anisotropy must be 0 (automatic) or 1 … 16, got " +
                      std::to_string(settings.max_anisotropy));
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

float effective_anisotropy(float requested, const std::string& gl_renderer) {
  if (requested != kAutoAnisotropy) return requested;
  return is_software_rasterizer(gl_renderer) ? 1.0f : 4.0f;
}

struct Renderer::Impl {
  RenderSettings settings;
  // Declared first so it is destroyed last: every GL object below needs it.
  std::unique_ptr<EglContext> context;
  std::optional<OffscreenTarget> target;
  std::optional<BackgroundPass> background;
  std::optional<BookPass> book;
  std::optional<MarkerPass> markers;
  std::optional<SurfacePass> surface;  ///< made for the first frame that has a surface
  std::optional<PixelReader> reader;
  ViewProjection camera;
  bool background_saved = false;
  RgbaImage spare;           ///< a buffer from recycle() for the next read-back
  PixelRegion previous_box;  ///< where the last frame drew; the whole frame before the first

  explicit Impl(const RenderSettings& s) : settings(s) {
    validate_settings(settings);
    camera = view_projection(settings);
    // Files first: a bad texture path fails fast, before any GL work.
    const FaceTextures& paths = settings.textures;
    const FaceImages images = face_images(paths.front, paths.back, paths.spine, paths.pages);
    context = std::make_unique<EglContext>();
    target.emplace(settings.width, settings.height, settings.msaa_samples);
    background.emplace();
    book.emplace(images,
                 effective_anisotropy(settings.max_anisotropy, context->info().gl_renderer));
    markers.emplace();
    reader.emplace(kPipelineDepth, PixelReader::read_directly_here(context->info().gl_renderer));
    previous_box = whole_frame(settings.width, settings.height);
  }

  ~Impl() {
    // GL objects are deleted in the member destructors; they need our context current.
    try {
      if (context) context->make_current();
    } catch (...) {  // nothing sensible to do in a destructor; the driver frees on exit
    }
    surface.reset();
    markers.reset();
    book.reset();
    background.reset();
    target.reset();
  }

  /// Where this frame's book (or surface: `surface_positions`, 3×V world, may be empty) and
  /// markers can put pixels.
  PixelRegion drawn_box(const std::vector<BookVertex>& book_mesh,
                        const Eigen::Matrix3Xd& surface_positions,
                        const std::vector<MarkerVertex>& marker_mesh) const {
    ScreenBounds bounds(camera.projection * camera.view, settings.width, settings.height);
    add_vertices(bounds, book_mesh);
    for (Eigen::Index v = 0; v < surface_positions.cols(); ++v) {
      const Eigen::Vector3f p = surface_positions.col(v).cast<float>();
      bounds.add({p.x(), p.y(), p.z()});
    }
    add_vertices(bounds, marker_mesh);
    return bounds.box();
  }

  /// The background never changes, so it is drawn once and saved; each frame restores it,
  /// clears depth, draws and resolves only in the box where the last frame or this one
  /// drew. Everything outside that box already holds the resolved background, so the
  /// image is the same as redrawing the whole frame, for a fraction of the work.
  void draw(const FrameInput& frame) {
    context->make_current();
    const bool has_surface = frame.surface.topology != nullptr;
    if (has_surface) {  // a malformed surface throws before anything is drawn
      if (!surface) surface.emplace();
      surface->prepare(frame.surface);
    }
    const bool draw_surface = has_surface && positions_drawable(frame.surface.positions);
    const std::vector<BookVertex> book_mesh =
        has_surface ? std::vector<BookVertex>{} : build_book_mesh(frame.corners);
    static const Eigen::Matrix3Xd no_positions(3, 0);
    const Eigen::Matrix3Xd& surface_positions =
        draw_surface ? frame.surface.positions : no_positions;
    std::vector<MarkerVertex> marker_mesh;
    if (settings.show_angular_momentum || settings.show_body_axes) {
      marker_mesh = build_markers(frame.corners, frame.angular_momentum_direction,
                                  settings.show_angular_momentum, settings.show_body_axes);
    }
    const PixelRegion box = drawn_box(book_mesh, surface_positions, marker_mesh);
    const PixelRegion dirty = united(box, previous_box);
    if (!background_saved) {
      target->bind_for_drawing();
      background->draw();
      target->save_background();
      background_saved = true;
    } else {
      target->restore_background(dirty);
    }
    target->bind_for_drawing();
    glEnable(GL_SCISSOR_TEST);
    glScissor(dirty.x, dirty.y, dirty.width, dirty.height);
    glClear(GL_DEPTH_BUFFER_BIT);  // no colour clear: the background covers every pixel
    book->draw(book_mesh, camera);
    if (draw_surface) surface->draw(frame.surface, camera);
    if (!marker_mesh.empty()) markers->draw(marker_mesh, camera);
    glDisable(GL_SCISSOR_TEST);
    check_gl("drawing a frame");
    target->resolve(dirty);
    previous_box = box;
  }

  RgbaImage render(const FrameInput& frame) {
    draw(frame);
    RgbaImage image;
    reader->read(*target, image);
    return image;
  }

  void submit(const FrameInput& frame) {
    if (reader->pending() >= reader->ring_size())
      throw std::logic_error("Renderer::submit with the pipeline full: collect() first");
    draw(frame);
    reader->start(*target);
  }

  std::optional<RgbaImage> take_oldest() {
    if (reader->pending() == 0) return std::nullopt;
    context->make_current();
    return reader->finish(std::move(spare));
  }
};

Renderer::Renderer(const RenderSettings& settings) : impl_(std::make_unique<Impl>(settings)) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

RgbaImage Renderer::render(const FrameInput& frame) { return impl_->render(frame); }
void Renderer::draw(const FrameInput& frame) {
  impl_->draw(frame);
  glFinish();
  check_gl("finishing a frame");
}
RgbaImage Renderer::read_back() {
  impl_->context->make_current();
  RgbaImage image;
  impl_->reader->read(*impl_->target, image);
  return image;
}
void Renderer::submit(const FrameInput& frame) { impl_->submit(frame); }
std::optional<RgbaImage> Renderer::collect() {
  if (impl_->reader->pending() < impl_->reader->ring_size()) return std::nullopt;
  return impl_->take_oldest();
}
std::optional<RgbaImage> Renderer::flush() { return impl_->take_oldest(); }
void Renderer::recycle(RgbaImage image) { impl_->spare = std::move(image); }
int Renderer::pipeline_depth() const { return impl_->reader->ring_size(); }
const RenderSettings& Renderer::settings() const { return impl_->settings; }
const GlInfo& Renderer::info() const { return impl_->context->info(); }

GlInfo gl_info() {
  const EglContext context;
  return context.info();
}

}  // namespace bookspin::render
