// The fit's toss scenes (docs/phone-lab.md, "A toss in the explorer"), made by make_fit from a
// synthetic recording of a phone askew on a book (tests/fit/synthetic_recording.hpp: Euler's
// equations integrated by RK4, not the exact solution): each loads through the scene reader;
// its body, integrated as a mesh (physics::mass_properties, not the book's formula), has the
// fitted moment ratios of the body CSV; its ω0 is the CSV's ω0 (phone frame) taken to the
// scene's body frame (the fitted axes 2, −1, 3: a right-handed frame); its exact motion, taken
// back to the phone frame, runs through the recorded samples; it flips with the CSV's fitted
// half period, first where the measured ω about the intermediate axis changes sign; and the
// measured ω it names is the recording's, bias removed, in that frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "analysis/motion.hpp"
#include "common/text_file.hpp"
#include "fit/synthetic_recording.hpp"
#include "physics/damped_exact.hpp"
#include "physics/exact_solution.hpp"
#include "physics/mass_properties.hpp"
#include "products/fit.hpp"
#include "scene/scene.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

/// The index of column `name` in a CSV file's header (the fit's columns, by name: a column
/// added elsewhere moves none of these).
std::size_t column_of(const fs::path& path, const std::string& name) {
  std::istringstream text(read_text_file(path, "test CSV"));
  std::string header;
  std::getline(text, header);
  std::istringstream cells(header);
  std::size_t i = 0;
  for (std::string cell; std::getline(cells, cell, ','); ++i)
    if (cell == name) return i;
  ADD_FAILURE() << "no column " << name << " in " << path;
  return 0;
}

/// The rows of a CSV file after its header, each split at commas (no quoting in the fit's).
std::vector<std::vector<std::string>> csv_rows(const fs::path& path) {
  std::istringstream text(read_text_file(path, "test CSV"));
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(text, line);
  while (std::getline(text, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

/// The principal moments of the box of `size`, ascending, integrated as a closed mesh.
Eigen::Vector3d box_moments(const Eigen::Vector3d& size, double mass) {
  Eigen::Matrix3Xd vertices(3, 8);
  for (int p = 0; p < 8; ++p)
    for (int d = 0; d < 3; ++d) vertices(d, p) = ((p >> d) & 1) ? size[d] : 0.0;
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  Eigen::Matrix3Xi triangles(3, 12);
  for (int f = 0; f < 6; ++f) {
    triangles.col(2 * f) << quads[f][0], quads[f][1], quads[f][2];
    triangles.col(2 * f + 1) << quads[f][0], quads[f][2], quads[f][3];
  }
  const physics::MassPropertiesResult mass_properties =
      physics::mass_properties(vertices, triangles);
  EXPECT_TRUE(mass_properties.ok()) << mass_properties.error;
  return mass / mass_properties.properties.volume * mass_properties.properties.principal_moments;
}

TEST(FitScene, EachTossIsASceneOfTheFittedMotion) {
  const fs::path dir = bookspin::test::fresh_dir("products/fit_scene");
  const auto synthetic = fit::test::make_recording(
      fit::test::phone_on_book(), {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.3}}, 3);
  fit::test::write_export(dir / "toss", synthetic, fit::test::Dialect::comma);
  FitJob job;
  job.recording = fit::pool_recordings({fit::read_recording(dir / "toss")});
  job.out_dir = dir / "out";
  job.width = 480;
  job.height = 240;
  std::vector<std::string> summary;
  ASSERT_EQ(make_fit(job, &summary), cache::Outcome::made);
  const FitLayout layout = fit_layout(job.out_dir, "toss", 2);
  ASSERT_EQ(layout.scenes.size(), 2u);

  const auto body = csv_rows(layout.body_csv).at(0);
  const double r1 = std::stod(body[0]), r2 = std::stod(body[1]);
  Eigen::Matrix3d axes;  // columns: the fitted principal axes 1, 2, 3, phone frame
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) axes(c, a) = std::stod(body[5 + 3 * a + c]);
  const auto tosses = csv_rows(layout.csv);
  ASSERT_EQ(tosses.size(), 2u);

  for (int k = 0; k < 2; ++k) {
    SCOPED_TRACE("toss " + std::to_string(k + 1));
    const scene::Scene s = scene::parse_scene(layout.scenes[k]);
    EXPECT_EQ(s.name, "toss-toss" + std::to_string(k + 1));
    EXPECT_NE(s.title.find("toss " + std::to_string(k + 1)), std::string::npos) << s.title;
    EXPECT_EQ(s.model.kind, physics::ModelKind::exact);
    EXPECT_EQ(s.body.shape, physics::BodyShape::book);

    // The body: the fitted ratios, about y, x, z (the book's smallest, intermediate, largest).
    const Eigen::Vector3d m = box_moments(s.body.cage.size, s.body.cage.mass);
    EXPECT_NEAR(m[0] / m[2], r1, 1e-9);
    EXPECT_NEAR(m[1] / m[2], r2, 1e-9);
    EXPECT_LT(s.body.moments.y(), s.body.moments.x());
    EXPECT_LT(s.body.moments.x(), s.body.moments.z());

    // ω0: the CSV's, phone frame, in the body frame x, y, z = axes 2, −1, 3 (right-handed).
    Eigen::Matrix3d frame;
    frame << axes.col(1), -axes.col(0), axes.col(2);
    EXPECT_NEAR(frame.determinant(), 1.0, 1e-6);
    const auto& row = tosses[k];
    const double t_start = std::stod(row[1]), t_end = std::stod(row[2]);
    const Eigen::Vector3d omega0_phone(std::stod(row[3]), std::stod(row[4]), std::stod(row[5]));
    EXPECT_LT((s.initial.omega0_body - frame.transpose() * omega0_phone).norm(),
              1e-9 * omega0_phone.norm());

    // The scene's exact motion, back in the phone frame, runs through the recorded samples
    // (bias removed) at the gyroscope's noise (0.01 rad/s); a mirrored frame runs backwards.
    // The fitted drag (the CSV's rate, the default linear law) rides along in the scene.
    EXPECT_EQ(s.model.drag.law, physics::DragLaw::linear);
    EXPECT_NEAR(s.model.drag.rate, std::stod(row[column_of(layout.csv, "drag_rate")]), 1e-12);
    const physics::DampedExactRotation exact(s.body.moments, s.initial.omega0_body, s.model.drag,
                                             physics::ExactParts::omega_only);
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < synthetic.t.size(); ++i) {
      if (synthetic.t[i] < t_start || synthetic.t[i] > t_end) continue;
      const Eigen::Vector3d measured = synthetic.omega[i] - synthetic.bias;
      sum += (frame * exact.omega_body(synthetic.t[i] - t_start) - measured).squaredNorm();
      ++n;
    }
    ASSERT_GT(n, 50);
    EXPECT_LT(std::sqrt(sum / n), 0.03);

    // Its flips: every fitted half period (the CSV's, and the RK4 truth's within 1 %), the
    // first where the measured ω about the intermediate axis (body x) first changes sign.
    const double half_period = std::stod(row[column_of(layout.csv, "half_period_fitted")]);
    EXPECT_NEAR(exact.flip_period_at(0.0), half_period, 0.01 * half_period);
    EXPECT_NEAR(exact.flip_period_at(0.0), synthetic.tosses[k].half_period,
                0.01 * synthetic.tosses[k].half_period);
    ASSERT_FALSE(s.measured.file.empty());
    const scene::MeasuredOmega& w = s.measured;
    std::optional<double> crossing;
    for (Eigen::Index i = 1; i < w.omega.cols() && !crossing; ++i) {
      const double a = w.omega(0, i - 1), b = w.omega(0, i);
      if ((a > 0) != (b > 0)) crossing = w.t[i - 1] + (w.t[i] - w.t[i - 1]) * a / (a - b);
    }
    ASSERT_TRUE(crossing.has_value());
    // The free motion's first flip, in the damped motion's time (docs/physics.md §21).
    const std::optional<double> first_free = analysis::exact_first_flip(exact.free(), 0);
    ASSERT_TRUE(first_free.has_value());
    EXPECT_NEAR(physics::time_of_stretched(s.model.drag, *first_free), *crossing, 0.01);
    // The scene plays the flight and at least three flips.
    const double duration = (s.frames - 1) * s.dt * s.steps_per_frame;
    EXPECT_GE(duration, t_end - t_start - 1e-9);
    EXPECT_GE(duration, 3 * half_period);

    // The measured ω it names: the recording's samples of the flight less one bias (the
    // finder's estimate of the true one, within 0.02 rad/s).
    ASSERT_GT(w.omega.cols(), 50);
    std::optional<Eigen::Vector3d> bias;
    for (Eigen::Index i = 0; i < w.omega.cols(); ++i) {
      const double t = t_start + w.t[static_cast<std::size_t>(i)];
      const auto at = std::lower_bound(synthetic.t.begin(), synthetic.t.end(), t - 1e-9);
      ASSERT_NE(at, synthetic.t.end());
      const Eigen::Vector3d offset =
          synthetic.omega[at - synthetic.t.begin()] - frame * w.omega.col(i);
      if (!bias) bias = offset;
      EXPECT_LT((offset - *bias).norm(), 1e-6) << "sample " << i;
    }
    EXPECT_LT((*bias - synthetic.bias).norm(), 0.02);
  }
  // The summary says how to open them.
  bool says = false;
  for (const std::string& line : summary)
    says |= line.find("bookspin explore ") != std::string::npos &&
            line.find((job.out_dir / "toss-toss").string() + "*.toml") != std::string::npos;
  EXPECT_TRUE(says);
}

// Moments that break the triangle inequality (given by --moments) make no body: no scene and
// no measured CSV, the rest written, and the summary says why.
TEST(FitScene, NoSceneForMomentsNoBodyHas) {
  const fs::path dir = bookspin::test::fresh_dir("products/fit_scene_none");
  const auto synthetic =
      fit::test::make_recording(fit::test::phone_on_book(), {{{0.5, 12.0, 0.4}, 1.2}}, 3);
  fit::test::write_export(dir / "toss", synthetic, fit::test::Dialect::comma);
  FitJob job;
  job.recording = fit::pool_recordings({fit::read_recording(dir / "toss")});
  job.out_dir = dir / "out";
  job.width = 480;
  job.height = 240;
  job.request.settings.moments = Eigen::Vector3d(1.0, 2.0, 5.0);  // 1 + 2 < 5
  std::vector<std::string> summary;
  ASSERT_EQ(make_fit(job, &summary), cache::Outcome::made);
  const FitLayout with = fit_layout(job.out_dir, "toss", 1);
  EXPECT_FALSE(fs::exists(with.scenes[0]));
  EXPECT_FALSE(fs::exists(with.measured[0]));
  for (const fs::path& path : fit_layout(job.out_dir, "toss", 1, false).outputs())
    EXPECT_TRUE(fs::exists(path)) << path;
  bool says = false;
  for (const std::string& line : summary)
    says |= line.find("triangle inequality") != std::string::npos;
  EXPECT_TRUE(says);
}

// The scene's name is one the scene reader takes, whatever the recording's file-safe name.
TEST(FitScene, NamesAreSceneNames) {
  EXPECT_EQ(fit::toss_scene_name("Gyroscope-rotation-rate-2025-02-14-09-35-02", 2),
            "Gyroscope-rotation-rate-2025-02-14-09-35-02-toss2");
  EXPECT_EQ(fit::toss_scene_name("a..b", 1), "a__b-toss1");
  EXPECT_EQ(fit::toss_scene_name("-x", 1), "recording--x-toss1");
  for (const std::string name : {"a..b", "-x", "_y", ".z"}) {
    const std::string text = "[scene]\nname = \"" + fit::toss_scene_name(name, 1) + "\"\n";
    EXPECT_NO_THROW(scene::parse_scene_text(text, "toss.toml")) << name;
  }
}

}  // namespace
}  // namespace bookspin::products
