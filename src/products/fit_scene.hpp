#pragma once
// The fit product's scenes (docs/phone-lab.md, "A toss in the explorer"): each fitted toss as
// a bookspin scene, the box with the fitted moments spinning from the fitted ω0 under the exact
// motion, time in seconds, so that `bookspin explore` (or `render`) plays the fit; and the
// toss's measured ω in that scene's body frame, the CSV the scene names for the explorer.
#include <Eigen/Dense>
#include <optional>
#include <string>

#include "common/csv_writer.hpp"
#include "fit/fit.hpp"
#include "physics/book.hpp"
#include "scene/limits.hpp"

namespace bookspin::products {

/// The scene's body frame in the phone frame (3×3, columns: body x, y, z): the fitted principal
/// axes 2, −1, 3. The book's intermediate, smallest and largest axes are x, y, z
/// (scenes/README.md); axis 1 is negated so that the frame stays right-handed (the fit's axes
/// are, fit::BodyEstimate), since Euler's equations in a mirrored frame run backwards.
Eigen::Matrix3d toss_scene_frame(const fit::BodyEstimate& body);

/// The book of mass 1 whose moments about x, y, z are the fitted ratios (I2/I3, I1/I3, 1)
/// (physics::book_with_moments; mass 1 and I3 = 1 fix the units, the motion sees the ratios
/// alone); nullopt where the ratios break the triangle inequality or a side would be
/// below the scene's smallest `book.size` (a body too flat for a scene).
std::optional<physics::Book> toss_book(const fit::BodyEstimate& body);

/// The scene name of toss `toss` (1-based) of recording `recording` (file-safe,
/// fit::GyroRecording::name): "<recording>-toss<N>", with every '.' made '_' (a scene name
/// holds no "..") and "recording-" before it unless it starts with a letter or a digit.
std::string toss_scene_name(const std::string& recording, int toss);

/// The frames a second of a toss's scene: render.fps, which its file leaves at the default
/// (scene/limits.hpp), so that its two substeps of 1/240 s a frame play a quarter of real time.
constexpr double kTossSceneFramesPerSecond = *scene::limit("render.fps").fallback;

/// Toss `toss` (0-based) of `fit` as a scene, for a recording named `recording`: what its scene
/// file says (toss_scene_text) and what the explorer's Phone-toss lab plays (web/fit_bindings.cpp).
struct TossScene {
  std::string name;         ///< toss_scene_name
  std::string title;        ///< naming the recording and the toss
  std::string description;  ///< the flight, the fitted moments and drag, in words
  physics::Book book;       ///< toss_book (mass 1, moments I2/I3, I1/I3, 1 about x, y, z)
  Eigen::Vector3d omega0 = Eigen::Vector3d::Zero();  ///< rad/s, the scene's body frame
  double dt = 0.0;                                   ///< s, the substep
  int steps_per_frame = 1;                           ///< substeps a frame at 30 frames/s
  double duration = 0.0;  ///< s: the flight or four fitted half periods (at most 30 s)
  physics::Drag drag;     ///< the fitted law and this toss's rate (1/s)
};

/// The values toss_scene_text writes (see there). Throws InternalError where toss_book has no
/// book for the fit.
TossScene toss_scene(const fit::FitResult& fit, int toss, const std::string& recording);

/// The scene file (TOML text) of toss `toss` (0-based) of `fit`, for a recording named
/// `recording`: scene.name `toss_scene_name`, a title naming the recording and the toss,
/// model exact, `book` toss_book (which must exist: a bug otherwise), initial.angular_velocity
/// the toss's ω0 in the scene's body frame (toss_scene_frame()ᵀ·ω0, rad/s: the time unit is the
/// second, t = 0 the flight's start), time.dt 1/240 s and 2 steps a frame (at 30 frames/s, a
/// quarter of real time), time.duration the flight or four fitted half periods (at most 30 s),
/// whichever is longer, the panel, sphere and L on; `measured_csv`, when not empty, the file
/// name (beside the scene) of its measured ω as `measured.omega` (toss_measured_csv).
std::string toss_scene_text(const fit::FitResult& fit, int toss, const std::string& recording,
                            const std::string& measured_csv);

/// The measured ω of toss `toss` (0-based) of `fit` in its scene's body frame: columns t (s since
/// the flight's start), wx, wy, wz (rad/s, toss_scene_frame()ᵀ · the measured ω with the bias
/// removed, fit::measured_omega), one row a sample of the flight.
CsvTable toss_measured_csv(const fit::GyroRecording& recording, const fit::FitResult& fit,
                           int toss);

}  // namespace bookspin::products
