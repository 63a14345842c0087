#pragma once
// The 2D decoration of a frame: caption, plot panel, divergence banner (overlays drawn on
// the rendered image; the renderer knows nothing of them).
#include <memory>
#include <optional>
#include <vector>

#include "analysis/measures.hpp"
#include "charts/diagnostics_history.hpp"
#include "common/rgba_image.hpp"
#include "overlay/caption.hpp"
#include "overlay/sphere.hpp"
#include "physics/simulator.hpp"
#include "scene/scene.hpp"

namespace bookspin::charts {

/// "diverged at t = 31.35".
std::string divergence_text(double t);

/// The caption of a frame: title, model and toggles, the `twist` line when given (it stays the
/// same through a clip), time; plus the divergence warning.
std::vector<overlay::CaptionLine> caption_for(const scene::Scene& scene, double t,
                                              std::optional<double> diverged_at,
                                              const std::optional<std::string>& twist = {});

/// The caption line of render.caption_twist, angles in rad to 3 decimals with a minus sign
/// (U+2212): "twist per period: measured −1.234 rad, closed form −1.234 rad"; a missing
/// number reads "none" (docs/physics.md §19: no full period measured, or no period).
std::string twist_line(const analysis::TwistMeasure& twist);

/// Decorates a rendered frame of `scene` at time `t`: with render.panel the live plots of
/// `history` (every frame so far) on the right, with render.sphere the momentum sphere inset
/// at the left edge (sphere_view.hpp) with `history`'s trail, then the caption (kept within the
/// book's part), then after a divergence the "diverged at" banner.
void decorate_frame(RgbaImage& image, const scene::Scene& scene, double t,
                    std::optional<double> diverged_at, const DiagnosticsHistory& history);

/// CPU seconds spent in each overlay (accumulated over the frames decorated).
struct OverlayTimes {
  double panel = 0.0, sphere = 0.0, caption = 0.0;  ///< caption: with the banner, if any
};

/// decorate_frame for the frames of one clip: the same pixels, with what does not change
/// from frame to frame kept between them (the clip's render loop holds one).
class FrameDecorator {
 public:
  /// `scene` must outlive the decorator. With render.caption_twist, measures the twist here
  /// (analysis::measure_twist), once for the clip.
  explicit FrameDecorator(const scene::Scene& scene);
  ~FrameDecorator();
  FrameDecorator(const FrameDecorator&) = delete;
  FrameDecorator& operator=(const FrameDecorator&) = delete;

  /// The twist line of the caption (twist_line()); empty without render.caption_twist.
  const std::optional<std::string>& twist_caption() const { return twist_line_; }

  /// As decorate_frame(image, scene, t, diverged_at, history); with `times`, adds the CPU
  /// time of each overlay to it.
  void decorate(RgbaImage& image, double t, std::optional<double> diverged_at,
                const DiagnosticsHistory& history, OverlayTimes* times = nullptr);

 private:
  const scene::Scene& scene_;
  overlay::CaptionPainter caption_;
  std::optional<std::string> twist_line_;         ///< with render.caption_twist, measured once
  std::unique_ptr<overlay::SphereInset> sphere_;  ///< made for the first frame's size
};

}  // namespace bookspin::charts
