#pragma once
// The one table of the numeric limits a scene is validated against: every number and integer
// key, its range and its default. The readers in scene.cpp and model_reader.cpp take their
// bounds from here (through limit()), and scenes/README.md ("Limits") documents the same
// table, checked by tests/scene/limits_doc_test.cpp.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

namespace bookspin::scene {

struct Limit {
  std::string_view key;  ///< dotted scene key ("time.dt"); for a vector key, each component
  double min;            ///< smallest value (or component) allowed
  double max;            ///< largest value (or component) allowed
  bool min_open;         ///< min itself excluded (> min rather than >= min)
  /// The value a missing key takes; nullopt where it is not one number (a vector, a default
  /// that depends on another key, a key that is required where it is allowed).
  std::optional<double> fallback;
  bool integer = false;  ///< an integer key (min, max and fallback are whole numbers)
  /// A non-zero value must be at least this large in magnitude (for a vector: its length);
  /// 0 where any value in [min, max] is fine. Keeps a spin or a jiggle from being so small
  /// that |L|² or the energy underflow to 0 while L itself is not 0.
  double smallest_nonzero = 0.0;
};

/// Largest value of an integer limit that is std::int64_t's maximum (2⁶³ − 1 is not a double).
inline constexpr double kInt64Max = 9223372036854775807.0;

/// The smallest body, in length units: the longest side of the box that holds it in its
/// principal frame (the book's largest `book.size` component) must be at least this, the
/// smallest `book.size` and a unit-size mesh at the smallest `body.scale`. The automatic
/// camera stands 1.1 to 126 times the body's radius away and refuses an eye within 1e-12 of
/// its target (render/camera.cpp), 10⁶ times below; a camera placed by
/// `render.camera_distance` must be as far from the centre. scenes/README.md, "Limits".
inline constexpr double kMinBodySize = 1e-6;

/// Every numeric scene key (scenes/README.md, "Keys" and "Limits"). Masses, lengths and spins
/// are bounded on both sides so that moments (mass × length², 1e-24 … 1e24), angular momenta
/// and energies stay well inside the double range for every model.
inline constexpr std::array kLimits{
    Limit{"model.spring_constant", 0.0, 1e12, true, 10.0},
    Limit{"model.lattice_cells", 0, 64, false, 0.0, true},
    Limit{"model.normalize_every", 1, 1000000, false, 1.0, true},
    Limit{"model.drag_rate", -1e3, 1e3, false, 0.0},
    Limit{"body.mass", 1e-12, 1e12, false, 1.0},
    Limit{"body.scale", 1e-6, 1e6, false, 1.0},
    Limit{"book.size", 1e-6, 1e6, false, std::nullopt},
    Limit{"book.mass", 1e-12, 1e12, false, 8.0},
    Limit{"initial.angular_velocity", -1e6, 1e6, false, std::nullopt, false, 1e-9},
    Limit{"initial.spin_rate", -1e6, 1e6, false, std::nullopt, false, 1e-9},
    Limit{"initial.jiggle", 0.0, 1e6, false, 0.0, false, 1e-9},
    Limit{"initial.seed", 0, kInt64Max, false, 1.0, true},
    Limit{"time.dt", 0.0, 1e3, true, 1.0 / 60.0},
    Limit{"time.steps_per_frame", 1, 1000000, false, 6.0, true},
    Limit{"time.frames", 1, 100000, false, 300.0, true},
    Limit{"time.duration", 0.0, 1e6, true, std::nullopt},
    Limit{"render.width", 16, 7680, false, 1280.0, true},
    Limit{"render.height", 16, 7680, false, 720.0, true},
    Limit{"render.fps", 1, 240, false, 30.0, true},
    Limit{"render.fov_y", 1.0, 170.0, false, 30.0},
    Limit{"render.camera_distance", 0.0, 1e4, false, 0.0, false, kMinBodySize},
    Limit{"render.camera_direction", -1e12, 1e12, false, std::nullopt},
    Limit{"render.crf", 0, 51, false, 16.0, true},
    Limit{"render.png_compression", 0, 9, false, 1.0, true},
    Limit{"render.anisotropy", 0, 16, false, 0.0, true},
    Limit{"render.msaa", 1, 8, false, 4.0, true},
    Limit{"render.gif_width", 16, 7680, false, std::nullopt, true},
    Limit{"render.gif_fps", 1, 50, false, std::nullopt, true},
    Limit{"render.webm_crf", 0, 63, false, 32.0, true},
};

/// The limit of `key`; a key missing from kLimits does not compile.
consteval const Limit& limit(std::string_view key) {
  for (const Limit& l : kLimits)
    if (l.key == key) return l;
  throw "no such key in kLimits";  // not a constant expression: a compile error
}

/// The frames that cover `duration` (time units) at `dt` × `steps_per_frame` a frame: the
/// first at t = 0, the last at or just past `duration` (1e-9 of a frame's time forgiven for
/// round-off); time.duration's rule (scenes/README.md, "Keys"). A double: the caller checks it
/// against time.frames' maximum.
inline double frames_covering(double duration, double dt, int steps_per_frame) {
  return 1.0 + std::ceil(duration / (dt * steps_per_frame) - 1e-9);
}

}  // namespace bookspin::scene
