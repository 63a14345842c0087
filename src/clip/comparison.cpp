#include "clip/comparison.hpp"

#include <cerrno>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <tuple>

#include "charts/decoration.hpp"
#include "charts/sphere_view.hpp"
#include "clip/compare_layout.hpp"
#include "clip/frame.hpp"
#include "clip/render_settings.hpp"
#include "common/errors.hpp"
#include "output/diagnostics_csv.hpp"
#include "output/output_dir.hpp"
#include "overlay/cairo_canvas.hpp"

namespace bookspin::clip {

namespace {

/// One tile's run. Not movable: the FrameSource keeps a reference to `scene`.
struct TileState {
  explicit TileState(scene::Scene s) : scene(std::move(s)), source(scene), drawing(scene.body) {}
  scene::Scene scene;  ///< the comparison scene with this tile's model
  analysis::FrameSource source;
  BodyDrawing drawing;
  ShownFrame frame;
};
using Tiles = std::vector<std::unique_ptr<TileState>>;

/// A diagnostics CSV written under a temporary name, added by finish() to the run's outputs.
class TileCsv {
 public:
  explicit TileCsv(const std::filesystem::path& path) : file_(path) {
    std::error_code ec;
    output::make_directories(path.parent_path(), ec);
    out_.open(file_.temp_path(), std::ios::binary);
    if (!out_) throw_output_error("cannot create", path, errno);
    out_ << output::diagnostics_csv_header() << '\n';
  }
  void add(int index, const physics::Diagnostics& row) {
    out_ << output::diagnostics_csv_row(index, row) << '\n';
  }
  void finish(output::OutputSet& set) {
    out_.close();
    if (!out_) throw_output_error("cannot write", file_.final_path(), errno);
    set.add(file_);
  }

 private:
  output::AtomicFile file_;
  std::ofstream out_;
};

void draw_header(cairo_t* cr, const PixelRect& strip, const std::string& title, double t) {
  const double font = 0.5 * strip.height;
  overlay::select_overlay_font(cr, true, font);
  cairo_set_source_rgb(cr, 0.95, 0.95, 0.92);
  const double baseline = strip.y + 0.5 * strip.height + 0.36 * font;
  cairo_move_to(cr, 0.6 * font, baseline);
  cairo_show_text(cr, title.c_str());
  char time[32];
  std::snprintf(time, sizeof time, "t = %.1f", t);
  cairo_text_extents_t e;
  cairo_text_extents(cr, time, &e);
  cairo_move_to(cr, strip.width - e.x_advance - 0.6 * font, baseline);
  cairo_show_text(cr, time);
}

/// The caption of one tile: the tile's label (its scene's title), its model line, t and
/// any divergence.
std::vector<overlay::CaptionLine> tile_caption(const TileState& p) {
  return charts::caption_for(p.scene, p.frame.t, p.frame.diverged_at);
}

void decorate(RgbaImage& frame, const scene::Scene& scene, const CompareLayout& layout,
              const Tiles& tiles) {
  const double t = tiles.front()->frame.t;
  std::optional<PixelRect> plots = layout.plots;
  if (scene.render.sphere) {
    // One trail per tile, in the tile's colour in the plots (palette order).
    std::vector<charts::SphereRun> trails;
    for (std::size_t i = 0; i < tiles.size(); ++i)
      trails.push_back({&tiles[i]->frame.history, palette_colour(i)});
    PixelRect rect = charts::sphere_rect(frame.width, frame.height, frame.width);
    if (plots) std::tie(rect, *plots) = charts::split_for_sphere(*plots);
    overlay::draw_sphere(frame, rect, charts::sphere_spec(charts::sphere_moments(scene), trails));
  }
  if (plots) {
    std::vector<charts::PanelRun> runs;
    for (const auto& p : tiles) runs.emplace_back(p->scene, p->frame.history, p->scene.title);
    charts::draw_panel(frame, *plots, charts::panel_plots(runs, charts::clip_end_time(scene), t));
  }
  {
    const PixelRect& strip = layout.header;
    overlay::CairoCanvas canvas(frame.width, frame.height,
                                overlay::region_around(strip.x, strip.y, strip.width, strip.height,
                                                       0.0, frame.width, frame.height));
    draw_header(canvas.cr(), strip, scene.title, t);
    canvas.composite_onto(frame);
  }
  // One font size for every tile (the largest at which every caption fits its tile), so
  // the labels read as a set.
  double font = std::min(0.026 * frame.height, 0.045 * layout.tile_height);
  const double margin = 0.4 * font, max_width = layout.tile_width - 2 * margin;
  for (const auto& p : tiles) font = overlay::caption_font_size(tile_caption(*p), font, max_width);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const PixelRect& tile = layout.tiles[i];
    overlay::CaptionLayout caption{tile.x + margin, tile.y + margin, font, max_width};
    overlay::draw_caption(frame, tile_caption(*tiles[i]), caption);
  }
}

RgbaImage compose(const scene::Scene& scene, const CompareLayout& layout,
                  render::Renderer& renderer, const Tiles& tiles) {
  RgbaImage frame = blank_frame(scene.render.width, scene.render.height);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const PixelRect& tile = layout.tiles[i];
    blit(frame, renderer.render(tiles[i]->drawing.input_for(tiles[i]->frame.pose)),
         static_cast<int>(tile.x), static_cast<int>(tile.y));
  }
  decorate(frame, scene, layout, tiles);
  return frame;
}

/// The row of a frame: the shown pose's diagnostics at the frame's time (held after a
/// divergence, as in a single clip).
physics::Diagnostics row_of(const ShownFrame& frame) {
  physics::Diagnostics row = frame.pose.diagnostics;
  row.t = frame.t;
  return row;
}

/// Steps every tile, renders and queues each frame; returns the signal that stopped it, or 0.
int render_loop(const ClipRequest& request, const CompareLayout& layout, render::Renderer& renderer,
                Tiles& tiles, output::ClipSinks& sinks,
                std::vector<std::unique_ptr<TileCsv>>& csvs) {
  const scene::Scene& scene = request.scene;
  for (int index = 0; index < scene.frames; ++index) {
    if (const int signal = stop_signal(request.stop_signal, "render frames")) return signal;
    for (auto& p : tiles) advance(p->source, index, p->scene, p->frame);
    sinks.add(index, compose(scene, layout, renderer, tiles), row_of(tiles.front()->frame));
    for (std::size_t i = 1; i < tiles.size(); ++i) csvs[i - 1]->add(index, row_of(tiles[i]->frame));
    if (request.on_progress) request.on_progress(index + 1);
  }
  return 0;
}

}  // namespace

ClipResult render_comparison(const ClipRequest& request) {
  const scene::Scene& scene = request.scene;
  const CompareLayout layout =
      compare_layout(static_cast<int>(scene.compare.size()), scene.render.width,
                     scene.render.height, scene.render.panel);
  Tiles tiles;
  for (const auto& tile : scene.compare)
    tiles.push_back(std::make_unique<TileState>(tile_scene(scene, tile)));
  render::Renderer renderer(
      render_settings_for(tiles.front()->scene, layout.tile_width, layout.tile_height, 1.0));
  BOOKSPIN_ASSERT(request.tile_csvs.size() + 1 == scene.compare.size());
  output::ClipSinks sinks(request.paths, sink_options(request));
  if (request.on_note && !sinks.encoder_message().empty()) request.on_note(sinks.encoder_message());
  std::vector<std::unique_ptr<TileCsv>> csvs;
  for (const auto& path : request.tile_csvs) csvs.push_back(std::make_unique<TileCsv>(path));
  ClipResult result;
  // On a stop, the sinks' and CSVs' destructors remove every temporary.
  if ((result.signal = render_loop(request, layout, renderer, tiles, sinks, csvs)) != 0)
    return result;
  output::OutputSet outputs;
  sinks.finish(outputs);
  for (auto& csv : csvs) csv->finish(outputs);
  if ((result.signal = commit_unless_stopped(request, outputs)) != 0) return result;
  result.frames = scene.frames;
  for (const auto& p : tiles) {
    if (p->frame.diverged_at)
      result.diverged_tiles.push_back({p->scene.title, *p->frame.diverged_at});
  }
  return result;
}

}  // namespace bookspin::clip
