#pragma once
// Each fitted toss as a scene (docs/phone-lab.md, "A toss in the explorer"): the box with the
// fitted moments spinning from the fitted ω0 under the exact motion, time in seconds, and the
// toss's measured ω in that scene's body frame; as values, which the explorer's Phone-toss lab
// plays (web/fit_bindings.cpp), and as the scene file's text and its measured ω's CSV, which
// the fit product writes (products/fit.hpp). No file written here.
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "common/csv_writer.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "physics/book.hpp"
#include "physics/drag.hpp"
#include "physics/polhode.hpp"

namespace bookspin::fit {

/// The frames a second of a toss's scene: the scene's render.fps default (scene/limits.hpp;
/// products/fit.cpp holds the two equal at compile time), so that its two substeps of
/// 1/240 s a frame play a quarter of real time.
inline constexpr double kTossSceneFramesPerSecond = 30.0;
/// The smallest side of a toss's book: the scene's smallest `book.size` (scene/limits.hpp, held
/// equal likewise).
inline constexpr double kMinTossBookSide = 1e-6;

/// The scene's body frame in the phone frame (3×3, columns: body x, y, z): the fitted principal
/// axes 2, −1, 3. The book's intermediate, smallest and largest axes are x, y, z
/// (scenes/README.md); axis 1 is negated so that the frame stays right-handed (the fit's axes
/// are, BodyEstimate), since Euler's equations in a mirrored frame run backwards.
Eigen::Matrix3d toss_scene_frame(const BodyEstimate& body);

/// The book of mass 1 whose moments about x, y, z are the fitted ratios (I2/I3, I1/I3, 1)
/// (physics::book_with_moments; mass 1 and I3 = 1 fix the units, the motion sees the ratios
/// alone); nullopt where the ratios break the triangle inequality or a side would be
/// below kMinTossBookSide (a body too flat for a scene).
std::optional<physics::Book> toss_book(const BodyEstimate& body);

/// The scene name of toss `toss` (1-based) of recording `recording` (file-safe,
/// GyroRecording::name): "<recording>-toss<N>", with every '.' made '_' (a scene name
/// holds no "..") and "recording-" before it unless it starts with a letter or a digit
/// of any script (common/file_name.hpp).
std::string toss_scene_name(const std::string& recording, int toss);

/// The file name of toss `toss`'s (0-based) measured ω beside its scene file, for a recording
/// named `recording`: "<recording>-toss<N>-measured.csv" (the fit product's layout names the
/// same file).
std::string toss_measured_file(const std::string& recording, int toss);

/// One toss as a scene: what its scene file says and what the explorer's lab plays.
struct TossScene {
  std::string name;         ///< toss_scene_name
  std::string title;        ///< naming the recording and the toss
  std::string description;  ///< the flight, the fitted moments and drag, in words
  physics::Book book;       ///< toss_book (mass 1, moments I2/I3, I1/I3, 1 about x, y, z)
  Eigen::Vector3d omega0 = Eigen::Vector3d::Zero();  ///< rad/s, the scene's body frame
  double dt = 0.0;                                   ///< s, the substep (1/240 s)
  int steps_per_frame = 1;  ///< substeps a frame at kTossSceneFramesPerSecond (2)
  double duration = 0.0;    ///< s: the flight or four fitted half periods (at most 30 s)
  physics::Drag drag;       ///< the fitted law and this toss's rate (1/s)
  /// The toss's measured ω: t (N, s since the flight's start) and ω (3×N, rad/s, the scene's
  /// body frame: toss_scene_frame()ᵀ · the measured ω with the bias removed, measured_omega),
  /// one sample of the flight a column; and its L/|L| with the book's moments
  /// (physics::momentum_directions), which the explorer draws on the sphere.
  std::vector<double> measured_t;
  Eigen::Matrix3Xd measured_omega;
  physics::MomentumDirections measured_L;
  std::string measured_file;  ///< toss_measured_file: the scene names it as measured.omega
};

/// Toss `toss` (0-based) of `fit` of `recording` as a scene, named after recording.name;
/// nullopt where toss_book has no book for the fit (no rigid body has the fitted moments).
std::optional<TossScene> toss_scene(const GyroRecording& recording, const FitResult& fit, int toss);

/// The scene file (TOML text) of toss `toss` (0-based) of a recording named `recording`, whose
/// values are `scene`: scene.name, title and description, model exact with the fitted drag,
/// `book` the toss's book, initial.angular_velocity ω0 in the scene's body frame (rad/s: the
/// time unit is the second, t = 0 the flight's start), time.dt and steps_per_frame (at 30
/// frames/s, a quarter of real time), time.duration, the panel, sphere and L on, and
/// measured.omega the file scene.measured_file (toss_measured_csv).
std::string toss_scene_text(const TossScene& scene, int toss, const std::string& recording);

/// The measured ω of a toss's scene as a CSV: columns t (s since the flight's start), wx, wy, wz
/// (rad/s, the scene's body frame: TossScene::measured_omega), one row a sample.
CsvTable toss_measured_csv(const TossScene& scene);

}  // namespace bookspin::fit
