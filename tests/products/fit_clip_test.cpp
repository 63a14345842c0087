// The phone-toss lab's clip (`bookspin fit --render`): its scene and time, its two tiles'
// motions against each other and the phone frame, the videos decoded by FFmpeg's own command-line
// tools (frame count and size; the two tiles' pixels alike where the motions agree), and the
// fit product with and without it (manifest, up to date, all or nothing, bad input).
#include "products/fit_clip.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "clip/compare_layout.hpp"
#include "common/errors.hpp"
#include "common/text_file.hpp"
#include "fit/synthetic_recording.hpp"
#include "physics/presets.hpp"
#include "products/fit.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

/// A phone alone (principal axes 1, 2, 3 along the phone's y, x, −z: the frame change matters),
/// two tosses about the intermediate axis at 17–18 rad/s: 1.3 s and 1.2 s of torque-free
/// flight, two flips each (the first after about 0.35 s).
fit::test::SyntheticRecording two_tosses() {
  return fit::test::make_recording(fit::test::phone_alone(),
                                   {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}}, 6);
}

/// The recording written as a phyphox export folder `dir`/toss, and the fit's scene file: the
/// phone preset at 320×180, 20 frames/s (small: the renderer is Mesa's software rasterizer).
fs::path write_inputs(const fs::path& dir, const fit::test::SyntheticRecording& rec) {
  fit::test::write_export(dir / "toss", rec, fit::test::Dialect::comma);
  std::ofstream(dir / "small.toml") << "body.shape = \"phone\"\n"
                                       "render.width = 320\nrender.height = 180\n"
                                       "render.fps = 20\nrender.msaa = 1\n";
  return dir / "toss";
}

FitJob render_job(const fs::path& dir) {
  FitJob job;
  job.recording = fit::pool_recordings({fit::read_recording(dir / "toss")});
  job.out_dir = dir / "out";
  job.width = 320;
  job.height = 160;
  FitRender render;
  render.scene_file = dir / "small.toml";
  render.slow_motion = 2.0;
  job.clips = fit_clips(render);
  return job;
}

/// Runs `command`, returning its standard output (binary) and setting `status`.
std::string run(const std::string& command, int& status) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) {
    status = -1;
    return out;
  }
  char buffer[65536];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
  status = pclose(pipe);
  return out;
}

/// Every frame of `video` as packed RGB (width × height × 3 bytes each), decoded by the ffmpeg
/// program: a reader independent of bookspin's encoder.
std::vector<std::string> decode_rgb(const fs::path& video, int width, int height) {
  int status = 0;
  const std::string bytes =
      run("ffmpeg -v error -i '" + video.string() + "' -f rawvideo -pix_fmt rgb24 -", status);
  EXPECT_EQ(status, 0);
  const std::size_t size = static_cast<std::size_t>(width) * height * 3;
  std::vector<std::string> frames;
  for (std::size_t at = 0; at + size <= bytes.size(); at += size)
    frames.push_back(bytes.substr(at, size));
  return frames;
}

/// Mean |a − b| over the RGB bytes of rectangle `r` of two frames (or of two rectangles of the
/// same size, `r` in frame a and `r` shifted by `dx` in frame b).
double mean_difference(const std::string& a, const std::string& b, int width, const PixelRegion& r,
                       int dx = 0) {
  double sum = 0.0;
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const auto pa =
            static_cast<unsigned char>(a[(static_cast<std::size_t>(y) * width + x) * 3 + c]);
        const auto pb =
            static_cast<unsigned char>(b[(static_cast<std::size_t>(y) * width + x + dx) * 3 + c]);
        sum += std::abs(pa - pb);
      }
  return sum / (3.0 * r.width * r.height);
}

TEST(FitClip, SceneTimeRunsInSecondsOfTheFlightSlowedDown) {
  fit::FitResult fit;
  fit::TossFit toss;
  toss.flight = {10, 140, 2.5, 3.8};  // 1.3 s
  fit.tosses = {toss, toss};
  FitRender render;
  render.slow_motion = 4.0;
  const scene::Scene base = fit_clip_scene(render);
  EXPECT_EQ(base.body.shape, physics::BodyShape::phone);
  EXPECT_TRUE(base.render.panel);
  EXPECT_FALSE(base.render.sphere);
  const scene::Scene s = toss_clip_scene(base, "rec", fit, 1, 4.0);
  EXPECT_EQ(s.name, "rec-toss2");
  // 1.3 s × 4 × 30 frames/s = 156 frame intervals: 157 frames, one step of 1/120 s each.
  EXPECT_EQ(s.frames, 157);
  EXPECT_DOUBLE_EQ(s.dt, 1.0 / 120.0);
  EXPECT_EQ(s.steps_per_frame, 1);
  ASSERT_EQ(s.compare.size(), 2u);
  EXPECT_EQ(s.compare[0].label, "measured");
  EXPECT_EQ(s.compare[1].label, "exact fit");
  EXPECT_NE(s.title.find("4× slower"), std::string::npos) << s.title;
  render.slow_motion = 0.5;
  EXPECT_THROW(fit_clip_scene(render), InputError);
  render.slow_motion = 4.0;
  render.scene_file = "/nonexistent/scene.toml";
  try {
    fit_clip_scene(render);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.toml"), std::string::npos) << e.what();
  }
}

/// Both tiles start at R = I in the phone frame, the body drawn in the phone's axes (the
/// phone preset's long side along the phone's y, its screen facing +z); the measured ω
/// replayed and the fitted exact motion turn the body alike through the flips, the true
/// orientation being what both approximate (docs/physics.md §20).
void expect_tiles_turn_alike(const fit::test::SyntheticRecording& rec, const std::string& name) {
  SCOPED_TRACE(name);
  const fs::path dir = bookspin::test::fresh_dir("products/fit_clip_tiles/" + name);
  fit::test::write_export(dir / "toss", rec, fit::test::Dialect::comma);
  const fit::GyroRecording recording = fit::pool_recordings({fit::read_recording(dir / "toss")});
  const fit::FitResult fit = fit::fit_recording(recording, fit::find_flights(recording));
  ASSERT_EQ(fit.tosses.size(), 2u);
  const physics::Body body = physics::preset_body(physics::BodyShape::phone);
  for (int toss = 0; toss < 2; ++toss) {
    std::vector<clip::TileModel> models =
        toss_tile_models(fit, fit::toss_chart(recording, fit, toss), body);
    ASSERT_EQ(models.size(), 2u);
    auto measured = models[0].make();
    auto exact = models[1].make();
    measured->reset({});
    exact->reset({});
    const Eigen::Matrix3d start = measured->orientation();
    const Eigen::Matrix3Xd surface = start * body.vertices;  // the drawn surface at the start
    const Eigen::Vector3d extent = surface.rowwise().maxCoeff() - surface.rowwise().minCoeff();
    EXPECT_NEAR(extent.y(), 2.94, 1e-6);  // the phone's long side along the phone's y
    EXPECT_NEAR(extent.x(), 1.42, 1e-6);
    EXPECT_LT((exact->orientation() - start).cwiseAbs().maxCoeff(), 1e-12);
    // The panel's ω: about the fitted axes, the intermediate one as the phone preset's y.
    std::vector<double> t;
    std::vector<Eigen::Vector3d> omega;
    fit::measured_omega(recording, fit, toss, t, omega);
    EXPECT_NEAR(measured->diagnostics().omega_body.y(), fit.body.axes.col(1).dot(omega.front()),
                1e-12);
    const double duration = fit.tosses[toss].flight.t_end - fit.tosses[toss].flight.t_start;
    ASSERT_TRUE(fit.tosses[toss].half_period_fitted);
    EXPECT_LT(*fit.tosses[toss].half_period_fitted, duration);  // a flip in the flight
    // Through the flight: the two orientations within 0.05 rad (the replay's sampling error is
    // ~0.01 rad, the fit's ω0 and moments add theirs), while the body itself turns by several
    // radians; and the exact fit's world L is fixed.
    const int steps = 100;
    double worst = 0.0, turned = 0.0;
    for (int i = 1; i <= steps; ++i) {
      measured->step(duration / steps);
      exact->step(duration / steps);
      const Eigen::Matrix3d a = measured->orientation(), b = exact->orientation();
      worst = std::max(worst, Eigen::AngleAxisd(a * b.transpose()).angle());
      turned = std::max(turned, Eigen::AngleAxisd(a * body.principal_axes).angle());
    }
    EXPECT_LT(worst, 0.05) << "toss " << toss;
    EXPECT_GT(turned, 2.5) << "toss " << toss;
  }
}

TEST(FitClip, TilesStartAsThePhoneAndTurnAlike) {
  expect_tiles_turn_alike(two_tosses(), "phone-alone");
  // A phone askew on a book: principal axes turned 20° in the phone (no symmetry of the frame
  // change to hide a transpose).
  expect_tiles_turn_alike(
      fit::test::make_recording(fit::test::phone_on_book(),
                                {{{3.0, 14.0, 2.5}, 1.3}, {{-2.5, 13.0, 3.0}, 1.3}}, 8),
      "phone-on-book");
}

TEST(FitClip, RendersEachTossBesideTheFitAndIsUpToDate) {
  const fs::path dir = bookspin::test::fresh_dir("products/fit_clip");
  const auto rec = two_tosses();
  write_inputs(dir, rec);
  // The fit alone first: its manifest head is the fit's without --render.
  FitJob plain = render_job(dir);
  plain.clips.reset();
  ASSERT_EQ(make_fit(plain), cache::Outcome::made);
  const fs::path manifest = dir / "out" / "toss" / "fit-manifest.json";
  const std::string plain_manifest = read_text_file(manifest, "manifest");
  const std::string plain_head = plain_manifest.substr(0, plain_manifest.find("\"outputs\""));

  FitJob job = render_job(dir);
  std::vector<std::string> summary;
  ASSERT_EQ(make_fit(job, &summary), cache::Outcome::made);
  const FitLayout layout = fit_layout(job.out_dir, "toss", 2, true, {"mp4"});
  ASSERT_EQ(layout.videos.size(), 2u);
  EXPECT_EQ(layout.videos[0], dir / "out" / "toss-toss1.mp4");
  const std::string listed = read_text_file(manifest, "manifest");
  for (const fs::path& video : layout.videos) {
    EXPECT_TRUE(fs::exists(video)) << video;
    EXPECT_NE(listed.find("\"" + video.filename().string() + "\""), std::string::npos) << listed;
  }
  const auto wrote = std::find_if(summary.begin(), summary.end(), [](const std::string& line) {
    return line.rfind("wrote ", 0) == 0;
  });
  ASSERT_NE(wrote, summary.end());
  EXPECT_NE(wrote->find("2 video(s)"), std::string::npos) << *wrote;
  // No scratch left behind: OUT/toss holds the manifest alone.
  std::vector<std::string> in_folder;
  for (const auto& entry : fs::directory_iterator(dir / "out" / "toss"))
    in_folder.push_back(entry.path().filename().string());
  EXPECT_EQ(in_folder, std::vector<std::string>{"fit-manifest.json"});

  const fit::GyroRecording recording = fit::pool_recordings({fit::read_recording(dir / "toss")});
  const fit::FitResult fit = fit::fit_recording(recording, fit::find_flights(recording));
  for (int toss = 0; toss < 2; ++toss) {
    const fit::Flight& flight = fit.tosses[toss].flight;
    // floor(duration × slow motion × fps) + 1 frames, 320×180, decoded by ffprobe.
    const int frames = static_cast<int>(std::floor((flight.t_end - flight.t_start) * 2 * 20)) + 1;
    int status = 0;
    const std::string probe =
        run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
            "stream=codec_name,width,height,nb_read_frames -of csv=p=0 '" +
                layout.videos[toss].string() + "'",
            status);
    ASSERT_EQ(status, 0);
    EXPECT_EQ(probe, "h264,320,180," + std::to_string(frames) + "\n");

    // The pictures: the two tiles hold the same body in the same pose at the start, and still
    // nearly so after the flips (the motions agree: TilesStartAsThePhoneAndTurnAlike), while
    // each tile's own picture changes a lot. Compared below the captions (whose words differ).
    const std::vector<std::string> rgb = decode_rgb(layout.videos[toss], 320, 180);
    ASSERT_EQ(static_cast<int>(rgb.size()), frames);
    const clip::CompareLayout tiles = clip::compare_layout(2, 320, 180, true);
    const PixelRect& left = tiles.tiles[0];
    const PixelRect& right = tiles.tiles[1];
    const int dx = static_cast<int>(right.x - left.x);
    const PixelRegion below{static_cast<int>(left.x), static_cast<int>(left.y + 0.35 * left.height),
                            static_cast<int>(left.width), static_cast<int>(0.65 * left.height) - 1};
    const std::string& first = rgb.front();
    const double start_apart = mean_difference(first, first, 320, below, dx);
    double moved = 0.0, apart = 0.0;
    for (std::size_t f = rgb.size() / 4; f < rgb.size(); f += rgb.size() / 4) {
      moved = std::max(moved, mean_difference(first, rgb[f], 320, below));
      apart = std::max(apart, mean_difference(rgb[f], rgb[f], 320, below, dx));
    }
    EXPECT_LT(start_apart, 1.0) << "toss " << toss;
    EXPECT_GT(moved, 5.0) << "toss " << toss;
    EXPECT_LT(apart, 0.25 * moved) << "toss " << toss << ": moved " << moved;
  }

  // Up to date the second time; the fit without --render again: the plain fit's outputs and
  // manifest head, the videos gone.
  EXPECT_EQ(make_fit(job), cache::Outcome::up_to_date);
  ASSERT_EQ(make_fit(plain), cache::Outcome::made);
  const std::string again = read_text_file(manifest, "manifest");
  EXPECT_EQ(again.substr(0, again.find("\"outputs\"")), plain_head);
  for (const fs::path& video : layout.videos) EXPECT_FALSE(fs::exists(video)) << video;
}

TEST(FitClip, BadInputWritesNothingAndAFailedWriteKeepsTheEarlierFit) {
  const fs::path dir = bookspin::test::fresh_dir("products/fit_clip_bad");
  write_inputs(dir, two_tosses());
  FitJob job = render_job(dir);
  // A scene file that is not a scene: one line naming it, refused before the fit is asked.
  std::ofstream(dir / "bad.toml") << "body.shape = \"brick\"\n";
  FitRender bad;
  bad.scene_file = dir / "bad.toml";
  try {
    fit_clip_scene(bad);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.toml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("body.shape"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "out"));

  // Every toss stable (spun about the largest axis): no moments, no motion to show.
  const fs::path stable_dir = bookspin::test::fresh_dir("products/fit_clip_stable");
  write_inputs(stable_dir,
               fit::test::make_recording(fit::test::phone_on_book(),
                                         {{{0.4, 0.3, 8.0}, 1.2}, {{-0.3, 0.4, 8.0}, 1.2}}, 5));
  FitJob stable = render_job(stable_dir);
  try {
    make_fit(stable);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--render"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--moments"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(stable_dir / "out" / "toss-fit.csv"));
  EXPECT_FALSE(fs::exists(stable_dir / "out" / "toss" / "fit-manifest.json"));

  // A fit, then a render whose second video cannot be put in place (a folder holds its name):
  // OutputError, and the earlier fit's files and manifest stay byte for byte.
  FitJob plain = job;
  plain.clips.reset();
  plain.width = 300;  // charts unlike the render's: a chart put in place alone would show
  ASSERT_EQ(make_fit(plain), cache::Outcome::made);
  fs::create_directories(dir / "out" / "toss-toss2.mp4" / "in-the-way");
  const auto before = bookspin::test::tree_of(dir / "out");
  EXPECT_THROW(make_fit(job), OutputError);
  EXPECT_EQ(bookspin::test::tree_of(dir / "out"), before);
}

}  // namespace
}  // namespace bookspin::products
