#pragma once
// The phone-toss lab's clip (`bookspin fit --render`, docs/phone-lab.md, "The clip"): each
// fitted toss as a two-tile comparison, the body turning as the phone turned (its measured ω
// replayed, physics::OmegaReplay) beside the fitted exact motion (physics::ExactInFrame), with
// the panel. Part of the fit product (products/fit.hpp), which names its paths and writes it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "clip/clip_request.hpp"
#include "common/json_writer.hpp"
#include "fit/fit.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {

/// What `--render` asks of the fit.
struct FitRender {
  /// --scene: a scene TOML whose body (body.shape, body.mesh, [book] …) is drawn and whose
  /// render.* keys (size, fps, formats, camera, codec …) the clips take; nullopt: the phone
  /// preset at the render defaults.
  std::optional<std::filesystem::path> scene_file;
  /// The clip plays the flight this many times slower than it happened (--slow-motion).
  double slow_motion = 4.0;
};

/// The clips `--render` makes, as the command reads them (fit_clips).
struct FitClips {
  scene::Scene scene;        ///< fit_clip_scene
  double slow_motion = 4.0;  ///< the clips play the flight this many times slower
  /// The fit manifest's "render" member: the slow-motion factor and the resolved scene
  /// (scene::canonical_scene); and the files the scene reads (textures, a mesh), whose SHA-256
  /// join the head: a changed texture remakes the clips.
  JsonObject head;
  std::vector<std::filesystem::path> inputs;
};

/// The slow-motion factors --slow-motion accepts.
inline constexpr double kMinSlowMotion = 1.0, kMaxSlowMotion = 20.0;

/// The scene every toss's clip is made from: `render.scene_file` read (scene::parse_scene) or
/// the built-in `body.shape = "phone"`, with render.panel on and the sphere, Poinsot inset and
/// twist line off (the fit's chart has the sphere of the fitted body). Its model, initial and
/// time keys and any [[compare]] are not used: the recording gives the motion. Throws
/// InputError (a bad scene file; a slow-motion factor outside [kMinSlowMotion, kMaxSlowMotion],
/// naming --slow-motion).
scene::Scene fit_clip_scene(const FitRender& render);

/// `render` read: its scene (fit_clip_scene), what the manifest's head says of it, and the
/// files it reads. Throws InputError as fit_clip_scene.
FitClips fit_clips(const FitRender& render);

/// The clip of toss `toss` (from 0) of `fit`, as a comparison scene made from `base`
/// (fit_clip_scene): named `<recording>-toss<N>`, two tiles "measured" and "exact fit",
/// time in seconds from the flight's start, dt = 1/(fps · slow_motion) (one step a frame) and
/// floor(duration · fps · slow_motion) + 1 frames, so the clip lasts slow_motion times the
/// flight. No I/O.
scene::Scene toss_clip_scene(const scene::Scene& base, const std::string& recording,
                             const fit::FitResult& fit, int toss, double slow_motion);

/// The tiles' simulators of a toss of `fit` (chart.toss), in the tiles' order: the measured ω
/// (bias removed) of the flight's samples replayed (fit::TossChart's t and measured), and the
/// fitted exact motion (the fit's axes, moment ratios and the toss's ω0), both told in the phone
/// frame from R = I at the flight's start (the world is the phone's frame then) and drawing `body`
/// placed in the phone frame by its built axes (Body::principal_axes: the phone preset is the
/// phone; a book or a mesh in its own axes as the phone's), with the fitted inertia for L and the
/// energy; the panel's ω is about the fitted principal axes (axis i as the drawn body's axis of the
/// i-th smallest moment, so that the panel's flip axis shows ω about the fitted intermediate axis).
/// docs/physics.md §20.
std::vector<clip::TileModel> toss_tile_models(const fit::FitResult& fit,
                                              const fit::TossChart& chart,
                                              const physics::Body& body);

}  // namespace bookspin::products
