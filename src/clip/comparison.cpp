// The comparison composer: a comparison scene's tiles side by side in one frame.
#include <optional>
#include <tuple>

#include "charts/decoration.hpp"
#include "charts/sphere_view.hpp"
#include "clip/compare_layout.hpp"
#include "clip/composer.hpp"
#include "overlay/caption.hpp"

namespace bookspin::clip {

namespace {

/// The caption of one tile: the tile's label (its scene's title), its model line and any
/// divergence (the time is the header's, the tiles' in lockstep). A model line too wide for
/// the tile (`max_width` pixels) at `font` is broken after its commas into two lines, or where
/// two do not fit it at `least`, at that size.
std::vector<overlay::CaptionLine> tile_caption(const TileRun& tile, double font, double least,
                                               double max_width) {
  const std::vector<overlay::CaptionLine> full =
      charts::caption_for(tile.scene, tile.shown.t, tile.shown.diverged_at);
  overlay::CaptionLine model = full[1];
  if (!tile.model_line.empty()) model.text = tile.model_line;  // the model's line
  auto wrapped = overlay::wrap_at_commas(model, font, max_width, 2);
  if (overlay::caption_font_size(wrapped, font, max_width) < least)
    wrapped = overlay::wrap_at_commas(model, least, max_width, 2);
  std::vector<overlay::CaptionLine> lines{full[0]};
  lines.insert(lines.end(), wrapped.begin(), wrapped.end());
  for (std::size_t i = 3; i < full.size(); ++i) lines.push_back(full[i]);  // the divergence
  return lines;
}

class ComparisonComposer final : public Composer {
 public:
  explicit ComparisonComposer(const scene::Scene& scene)
      : scene_(scene),
        layout_(compare_layout(static_cast<int>(scene.compare.size()), scene.render.width,
                               scene.render.height, scene.render.panel)) {}

  /// Each tile's body framed below the tile's caption (three lines, its title and a model line
  /// on two, at the largest font decorate() gives them, from the top margin).
  render::RenderSettings picture_settings(const scene::Scene& first_tile) const override {
    const double font = largest_tile_font(scene_.render.height);
    const double caption_bottom = 0.4 * font + overlay::caption_height(3, font, keyed());
    return render_settings_for(first_tile, layout_.tile_width, layout_.tile_height, 1.0, 0.0,
                               std::min(0.5, caption_bottom / layout_.tile_height));
  }

  RgbaImage compose(std::vector<RgbaImage>& pictures, const Tiles& tiles) override {
    RgbaImage frame = blank_frame(scene_.render.width, scene_.render.height);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      const PixelRect& tile = layout_.tiles[i];
      blit(frame, pictures[i], static_cast<int>(tile.x), static_cast<int>(tile.y));
    }
    decorate(frame, tiles);
    return frame;
  }

 private:
  void decorate(RgbaImage& frame, const Tiles& tiles) const {
    const double t = tiles.front()->shown.t;
    std::optional<PixelRect> plots = layout_.plots;
    if (scene_.render.sphere) {
      // One trail per tile, in the tile's colour in the plots (palette order).
      std::vector<charts::SphereRun> trails;
      for (std::size_t i = 0; i < tiles.size(); ++i)
        trails.push_back({&tiles[i]->shown.history, palette_colour(i)});
      PixelRect rect = charts::sphere_rect(frame.width, frame.height, frame.width);
      if (plots) std::tie(rect, *plots) = charts::split_for_sphere(*plots);
      overlay::draw_sphere(frame, rect,
                           charts::sphere_spec(charts::sphere_moments(scene_), trails));
    }
    if (plots) {
      std::vector<charts::PanelRun> runs;
      for (const auto& p : tiles) runs.emplace_back(p->scene, p->shown.history, p->scene.title);
      // The tiles' captions carry each run's colour and dash: the panel needs no legend.
      auto specs = charts::panel_plots(runs, charts::clip_end_time(scene_), t);
      for (overlay::PlotSpec& spec : specs) spec.legend = false;
      charts::draw_panel(frame, *plots, specs);
    }
    overlay::draw_title_strip(frame, layout_.header, scene_.title, t);
    // One font size for every tile (the largest at which every caption fits its tile, at
    // least 12 px where the tiles are large enough, a long model line then on two lines), so
    // the labels read as a set.
    const double largest = largest_tile_font(frame.height);
    const double least = std::min(largest, overlay::kMinFont);
    const double margin = 0.4 * largest, max_width = layout_.tile_width - 2 * margin;
    std::vector<std::vector<overlay::CaptionLine>> captions;
    double font = largest;
    for (const auto& p : tiles) {
      captions.push_back(tile_caption(*p, largest, least, max_width));
      font = overlay::caption_font_size(captions.back(), font, max_width);
    }
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      const PixelRect& tile = layout_.tiles[i];
      overlay::CaptionLayout caption{tile.x + margin, tile.y + margin, font, max_width, {}};
      if (keyed()) {
        const charts::RunStyle style = charts::run_style(i);  // as the panel draws the run
        caption.key = overlay::CaptionKey{style.colour, style.dashed};
      }
      overlay::draw_caption(frame, captions[i], caption);
    }
  }

  /// Whether the tiles' captions are keyed to their runs' colours: where the runs are drawn in
  /// colours (the panel's curves, the sphere's trails).
  bool keyed() const { return scene_.render.panel || scene_.render.sphere; }

  /// The tiles' caption font before it shrinks to fit their widths (pixels).
  double largest_tile_font(int frame_height) const {
    return std::min(0.026 * frame_height, 0.045 * layout_.tile_height);
  }

  const scene::Scene& scene_;
  const CompareLayout layout_;
};

}  // namespace

std::unique_ptr<Composer> comparison_composer(const scene::Scene& scene) {
  return std::make_unique<ComparisonComposer>(scene);
}

}  // namespace bookspin::clip
