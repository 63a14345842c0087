#pragma once
// A validated scene: everything one clip needs (keys: scenes/README.md). The door of
// src/scene: parse_scene() turns a TOML file plus `--set key=value` overrides into a Scene
// or throws InputError with one line naming the file, line and key.
#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "physics/lattice.hpp"
#include "physics/simulator.hpp"
#include "scene/limits.hpp"
#include "scene/measured_file.hpp"

namespace bookspin::scene {

struct RenderOptions {
  int width = 1280;                                 ///< pixels, even
  int height = 720;                                 ///< pixels, even
  int fps = 30;                                     ///< frames per second of the clip
  double fov_y_deg = 30.0;                          ///< vertical field of view, degrees
  double camera_distance = 0.0;                     ///< 0: framed automatically
  Eigen::Vector3d camera_direction{0.9, 0.6, 3.2};  ///< from the origin towards the eye
  bool show_angular_momentum = false;
  bool show_body_axes = false;
  /// Face textures (PNG paths, resolved against the scene's folder); empty: generated.
  std::string texture_front, texture_back, texture_spine, texture_pages;
  std::string codec = "libx264";
  /// faster at CRF 16: medium at 18's picture for less encoding (docs/performance.md).
  int crf = 16;
  std::string preset = "faster";
  int png_compression =
      1;  ///< deflate level 0–9 for frame PNGs (output::write_png maps it onto libdeflate's)
  /// Anisotropic texture filtering cap, 1 … 16 (1 = trilinear only); 0 = automatic: 4× on a
  /// GPU, trilinear on a software rasterizer (see render::RenderSettings::max_anisotropy).
  int anisotropy = 0;
  /// Multisample anti-aliasing samples per pixel: 1 (off), 2, 4 or 8 (capped by the GL).
  int msaa = 4;
  /// Live plots beside the book (ω, energy drift, shape): the book is framed in the left
  /// 60% of the frame and the plots fill the right 40%.
  bool panel = false;
  /// The momentum sphere inset (docs/physics.md §15): polhodes, separatrices and the run's
  /// body-frame L/|L| with its trail, drawn at the left edge of the book's part of the frame
  /// (a comparison: one trail per tile, atop the plot column).
  bool sphere = false;
  /// Video files of one render (render.formats, `render --format`): any of "mp4" (H.264),
  /// "webm" (VP9) and "gif" (global palette), each at most once, at least one; all fed by
  /// the same frames (docs/outputs.md).
  std::vector<std::string> formats{"mp4"};
  int gif_width = 640;  ///< GIF width in pixels (height keeps the aspect, even); ≤ width
  int gif_fps = 15;     ///< GIF frame rate target: every round(fps / gif_fps)-th frame is kept
  int webm_crf = 32;    ///< VP9 constant quality 0 (best) … 63
  /// Poinsot's construction inset (docs/physics.md §16): the inertia ellipsoid rolling on the
  /// invariable plane in the world frame, with the polhode and the herpolhode so far; at the
  /// top of the plot column with render.panel, else at the right edge. Single runs only.
  bool poinsot = false;
  /// A caption line with the twist about L per body-frame period, measured from the run and
  /// in Montgomery's closed form (docs/physics.md §19), computed once before the first frame.
  /// Single runs whose body-frame motion is periodic only.
  bool caption_twist = false;
};

/// The video formats `render` can write, in the order they are listed in messages.
inline constexpr std::array<std::string_view, 3> kVideoFormats{"mp4", "webm", "gif"};

/// Why `formats` is not a valid list of video formats (empty, unknown or repeated name), or
/// "" when it is. The reason names the offending entry and the formats expected.
std::string video_formats_problem(const std::vector<std::string>& formats);

/// One tile of a comparison scene (`[[compare]]`): the scene's book, initial state, time
/// and render keys with its own model settings.
struct CompareTile {
  std::string label;  ///< shown on the tile, e.g. "rigid-matrix, SVD"
  std::string name;   ///< file-name form of the label (diagnostics-<name>.csv), unique
  physics::ModelConfig model;
};

struct Scene {
  std::string name;         ///< output name: file stem unless scene.name is set
  std::string title;        ///< human title (caption, gallery)
  std::string description;  ///< what the clip shows
  /// The simulated body ([body] table, docs/physics.md §12); the book by default.
  physics::Body body;
  /// body.mesh resolved against the scene file's folder; empty unless body.shape = "mesh".
  std::string body_mesh;
  /// Warnings met while reading the scene (e.g. a mesh shell wound inward, turned around),
  /// one line each, for the command to print.
  std::vector<std::string> warnings;
  physics::ModelConfig model;
  physics::InitialState initial;
  double dt = 1.0 / 60.0;   ///< time step, time units
  int steps_per_frame = 6;  ///< substeps per video frame
  int frames = 300;         ///< video frames (CSV rows), frame 0 = initial state
  /// time.unit: "s" where the time unit is the second (a fitted toss), "" for the abstract
  /// time unit of the paper's scenes; the panel's labels say it (docs/physics.md §1).
  std::string time_unit;
  RenderOptions render;
  std::filesystem::path source;  ///< the scene file
  /// Non-empty for a comparison scene: each tile runs its own simulator from the same
  /// initial state, and the clip shows them side by side (kMaxCompareTiles at most).
  std::vector<CompareTile> compare;
  /// measured.omega: a measured ω shown beside the run (measured_file.hpp); the explorer draws
  /// it, the other products leave it. Empty file: none.
  MeasuredOmega measured;
};

/// The single-model scene a comparison tile stands for: `scene` with the tile's model.
Scene tile_scene(const Scene& scene, const CompareTile& tile);

/// Limits enforced by validation (documented in scenes/README.md); the numeric keys' ranges
/// are in the one table kLimits (scene/limits.hpp).
inline constexpr int kMaxDimension = static_cast<int>(limit("render.width").max);
inline constexpr int kMaxFrames = static_cast<int>(limit("time.frames").max);
inline constexpr int kMaxStepsPerFrame = static_cast<int>(limit("time.steps_per_frame").max);
inline constexpr std::uintmax_t kMaxSceneFileBytes = 1 << 20;
inline constexpr int kMaxCompareTiles = 9;
using physics::kMaxLatticeCells;  ///< model.lattice_cells (physics/lattice.hpp)
static_assert(limit("model.lattice_cells").max == kMaxLatticeCells);

/// A scene its model's engine cannot run (scenes/README.md, "Engine limits": ODE's subnormal
/// dt, MuJoCo's mjMINVAL): bad input like every other InputError (what() names the file, line
/// or --set, and the key), and the one refusal a sweep records as its point's reason instead
/// of refusing the whole sweep (jobs/sweep.hpp).
class EngineRefusal : public InputError {
 public:
  EngineRefusal(const InputError& error, std::string key, std::string reason)
      : InputError(error), refused_key_(std::move(key)), reason_(std::move(reason)) {}
  /// The key refused ("time.dt", "book.mass", …) and why, without the file or line.
  const std::string& refused_key() const { return refused_key_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string refused_key_, reason_;
};

/// Reads and validates `path`, applying `overrides` ("key=value", value in TOML syntax) on
/// top of the file. Throws InputError on any bad input: unreadable or oversized file, TOML
/// syntax, unknown key, wrong type, out-of-range value, missing texture file, a mesh file
/// that is missing or not a closed mesh; EngineRefusal (an InputError) for a value the
/// model's engine cannot run.
Scene parse_scene(const std::filesystem::path& path,
                  const std::vector<std::string>& overrides = {});

/// Same from TOML text; `origin` names it in messages and resolves relative texture paths.
Scene parse_scene_text(std::string_view text, const std::filesystem::path& origin,
                       const std::vector<std::string>& overrides = {});

}  // namespace bookspin::scene
