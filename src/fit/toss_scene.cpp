#include "fit/toss_scene.hpp"

#include <algorithm>
#include <cctype>

#include "common/file_name.hpp"
#include "common/json_string.hpp"
#include "common/number_text.hpp"
#include "fit/fit_tables.hpp"
#include "fit/pool.hpp"

namespace bookspin::fit {
namespace {

std::string number(double value, const char* what) {
  return finite_text(value, what, NumberStyle::shortest);
}

std::string vector3(const Eigen::Vector3d& v, const char* what) {
  std::string text(1, '[');
  for (int c = 0; c < 3; ++c) text.append(c ? ", " : "").append(number(v[c], what));
  return text.append("]");
}

/// The scene's substep (s) and substeps a frame: at 30 frames/s a quarter of real time.
constexpr double kDt = 1.0 / 240.0;
constexpr int kStepsPerFrame = 2;
/// The longest scene (s): four half periods near the separatrix may be long.
constexpr double kMaxDuration = 30.0;

}  // namespace

Eigen::Matrix3d toss_scene_frame(const BodyEstimate& body) {
  Eigen::Matrix3d frame;
  frame << body.axes.col(1), -body.axes.col(0), body.axes.col(2);
  return frame;
}

std::optional<physics::Book> toss_book(const BodyEstimate& body) {
  const Eigen::Vector3d& r = body.ratios;
  std::optional<physics::Book> book = physics::book_with_moments({r[1], r[0], r[2]}, 1.0);
  if (book && book->size.minCoeff() < kMinTossBookSide) return std::nullopt;
  return book;
}

std::string toss_scene_name(const std::string& recording, int toss) {
  std::string name = recording + "-toss" + std::to_string(toss);
  std::replace(name.begin(), name.end(), '.', '_');
  if (!starts_with_letter_or_digit(name)) name = "recording-" + name;
  return name;
}

std::string toss_measured_file(const std::string& recording, int toss) {
  return recording + "-toss" + std::to_string(toss + 1) + "-measured.csv";
}

std::optional<TossScene> toss_scene(const GyroRecording& recording, const FitResult& fit,
                                    int toss) {
  const std::optional<physics::Book> book = toss_book(fit.body);
  if (!book) return std::nullopt;
  const TossFit& t = fit.tosses.at(static_cast<std::size_t>(toss));
  const std::string& name = recording.name;
  TossScene scene;
  scene.book = *book;
  const Eigen::Matrix3d to_body = toss_scene_frame(fit.body).transpose();
  scene.omega0 = toss_scene_frame(fit.body).transpose() * t.omega0;
  scene.dt = kDt;
  scene.steps_per_frame = kStepsPerFrame;
  const double flight = t.flight.t_end - t.flight.t_start;
  scene.duration =
      std::max(flight, std::min(kMaxDuration, 4.0 * t.half_period_fitted.value_or(0.0)));
  // The fitted drag (docs/physics.md §21); a negative quadratic rate (a gain within its error
  // of zero) blows up at −1/r: the run stops well before (scenes/README.md, model.drag_rate).
  scene.drag = physics::Drag{fit.drag, t.drag_rate};
  if (scene.drag.law == physics::DragLaw::quadratic && scene.drag.rate < 0)
    scene.duration = std::min(scene.duration, -0.45 / scene.drag.rate);
  const std::string n = std::to_string(toss + 1);
  const Eigen::Vector3d& r = fit.body.ratios;
  const std::string moments = fixed(r[0], 4) + " : " + fixed(r[1], 4) + " : 1";
  scene.name = toss_scene_name(name, toss + 1);
  scene.measured_file = toss_measured_file(name, toss);
  // The toss named by its own recording and its own times (of several pooled, the one it was
  // thrown in, on that recording's clock), and the pooled fit it belongs to.
  const RecordingPart& part = part_at(fit.parts, t.flight.t_start);
  const bool pooled = fit.parts.size() >= 2;
  scene.title =
      part.name + ", toss " + n + (pooled ? " of " + name : "") + ": the fitted exact motion";
  scene.description =
      "Toss " + n + (pooled ? " of " + name + ", thrown in the recording " : " of the recording ") +
      part.name + " (" + fixed(t.flight.t_start - part.t_offset, 3) + "–" +
      fixed(t.flight.t_end - part.t_offset, 3) +
      " s), fitted by bookspin fit: a box with the fitted moments " + moments +
      " spinning from the fitted ω0 under the exact motion" +
      (t.drag_rate != 0.0 && fit.drag != physics::DragLaw::none
           ? " slowed by the fitted " + std::string(physics::to_string(fit.drag)) + " drag (" +
                 fixed(t.drag_rate, 3) + " /s)"
           : std::string()) +
      ", t = 0 the flight's start" +
      (t.stable ? "; a stable toss: it wobbles, it does not flip" : "") +
      (fit.body.moments_determined ? "" : "; the moments are poorly determined") + ".";
  // The measured ω in the scene's body frame, time from the flight's start.
  std::vector<double> times;
  std::vector<Eigen::Vector3d> omega;
  measured_omega(recording, fit, toss, times, omega);
  scene.measured_omega.resize(3, static_cast<Eigen::Index>(omega.size()));
  for (std::size_t i = 0; i < times.size(); ++i) {
    scene.measured_t.push_back(times[i] - t.flight.t_start);
    scene.measured_omega.col(static_cast<Eigen::Index>(i)) = to_body * omega[i];
  }
  scene.measured_L =
      physics::momentum_directions(scene.book.principal_moments(), scene.measured_omega);
  return scene;
}

std::string toss_scene_text(const TossScene& scene, int toss, const std::string& recording) {
  std::string model = "\n\n[model]\nkind = \"exact\"\n";
  if (scene.drag.law != physics::DragLaw::none)
    model += "drag = " + json_string(std::string(physics::to_string(scene.drag.law))) +
             "  # the air's drag as fitted (docs/physics.md §21)\ndrag_rate = " +
             number(scene.drag.rate, "toss scene model.drag_rate") + "  # 1/s\n";
  model += "\n";
  const std::string n = std::to_string(toss + 1);
  std::string text =
      "# Toss " + n + " of " + recording +
      " as bookspin fit fitted it (docs/phone-lab.md):\n"
      "# the exact motion of a box with the fitted moment ratios from the fitted ω0, in the\n"
      "# body frame x, y, z = the fitted principal axes 2, -1, 3 (their phone-frame components\n"
      "# in the fit's -fit-body.csv). Time unit: the second; ω in rad/s; t = 0 the flight's\n"
      "# start.\n"
      "[scene]\n"
      "name = " +
      json_string(scene.name) + "\ntitle = " + json_string(scene.title) +
      "\ndescription = " + json_string(scene.description) + model +
      "[book]  # moments about x, y, z: I2/I3, I1/I3, 1 (mass 1)\n"
      "size = " +
      vector3(scene.book.size, "toss scene book.size") +
      "\nmass = 1.0\n\n[initial]\nangular_velocity = " +
      vector3(scene.omega0, "toss scene initial.angular_velocity") + "  # rad/s, body frame\n\n" +
      "[time]\nunit = \"s\"\ndt = " + number(scene.dt, "toss scene time.dt") +
      "  # s\nsteps_per_frame = " + std::to_string(scene.steps_per_frame) +
      "  # 30 frames/s: a quarter of real time\nduration = " +
      number(scene.duration, "toss scene time.duration") +
      "  # s: the flight, or four fitted half periods\n\n"
      "[render]\npanel = true\nsphere = true\nshow_angular_momentum = true\n";
  return text + "\n[measured]\nomega = " + json_string(scene.measured_file) +
         "  # the toss's measured ω, body frame: the explorer shows it beside the fit\n";
}

CsvTable toss_measured_csv(const TossScene& scene) {
  CsvTable table{{"t", "wx", "wy", "wz"}, {}};
  for (std::size_t i = 0; i < scene.measured_t.size(); ++i) {
    const Eigen::Vector3d w = scene.measured_omega.col(static_cast<Eigen::Index>(i));
    table.rows.push_back({shortest_cell(scene.measured_t[i]), shortest_cell(w[0]),
                          shortest_cell(w[1]), shortest_cell(w[2])});
  }
  return table;
}

}  // namespace bookspin::fit
