// The peer section: bookspin's renderer against MuJoCo's (mjr_render), both drawing and
// reading back the same poses of the pipeline scene at 1280×720, then both again with every
// frame sent through the same encoder as the render command's.
#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "analysis/frame_source.hpp"
#include "bench/clock.hpp"
#include "bench/mujoco.hpp"
#include "bench/mujoco_render.hpp"
#include "bench/sections.hpp"
#include "clip/clip_request.hpp"
#include "clip/frame.hpp"
#include "clip/render_settings.hpp"
#include "output/png_writer.hpp"
#include "scene/scene.hpp"
#include "video/video.hpp"

namespace bookspin::bench {

namespace {

/// Wall and process CPU seconds; keep_best keeps the run with the shorter wall time.
struct PeerTiming {
  double wall = 1e300, cpu = 0.0;
  void keep_best(double w, double c) {
    if (w < wall) wall = w, cpu = c;
  }
};

/// The rotation (body → world) and centre that carry `rest` (3×8, body frame) best onto
/// `world` (3×8) in the least-squares sense (Kabsch: the SVD of the cross-covariance).
void rigid_fit(const Eigen::Matrix<double, 3, 8>& rest, const Eigen::Matrix<double, 3, 8>& world,
               Eigen::Matrix3d* rotation, Eigen::Vector3d* centre) {
  const Eigen::Vector3d rest_centre = rest.rowwise().mean();
  *centre = world.rowwise().mean();
  const Eigen::Matrix3d h =
      (rest.colwise() - rest_centre) * (world.colwise() - *centre).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  *rotation = svd.matrixV() * d * svd.matrixU().transpose();
}

/// Draws and reads back every pose with `draw_and_read` (pose index → frame); with `encode`,
/// sends each frame through the render command's encoder into `file` (removed afterwards).
/// Keeps frame `keep_index` in `*kept` when `kept` is given.
template <typename DrawAndRead>
void timed_frames(int frames, DrawAndRead&& draw_and_read, const scene::Scene& scene, int jobs,
                  const std::filesystem::path* file, PeerTiming* timing, RgbaImage* kept) {
  const auto wall_start = std::chrono::steady_clock::now();
  const double cpu_start = process_cpu_seconds();
  std::unique_ptr<video::Mp4Encoder> encoder;
  if (file)
    encoder = std::make_unique<video::Mp4Encoder>(*file, clip::encoder_settings(scene, jobs));
  for (int i = 0; i < frames; ++i) {
    RgbaImage image = draw_and_read(i);
    if (encoder) encoder->add_frame(image);
    if (kept && i == frames / 2) *kept = std::move(image);
  }
  if (encoder) encoder->finish();
  timing->keep_best(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count(),
      process_cpu_seconds() - cpu_start);
  if (file) std::filesystem::remove(*file);
}

}  // namespace

void bench_peer(const BenchContext& c) {
  if (const std::string why = mujoco_missing(); !why.empty()) {
    c.report->remark("peer: skipped, " + why);
    return;
  }
  const int w = 1280, h = 720, frames = c.options.frames;
  scene::Scene scene = scene::parse_scene(
      c.options.scene_path,
      {"render.width=" + std::to_string(w), "render.height=" + std::to_string(h)});
  scene.frames = frames;
  // The book alone, framed in the whole image: what both renderers draw.
  const render::RenderSettings settings = clip::render_settings_for(scene, w, h, 1.0, 0.0);
  std::vector<physics::Pose> poses;
  {
    analysis::FrameSource source(scene);
    clip::ShownFrame frame;
    for (int index = 0; index < frames; ++index) {
      clip::advance(source, index, scene, frame);
      poses.push_back(frame.pose);
    }
  }
  const clip::BodyDrawing drawing(scene.body);
  const Eigen::Matrix<double, 3, 8> rest = scene.body.cage.body_corners();
  std::vector<Eigen::Matrix3d> rotations(poses.size());
  std::vector<Eigen::Vector3d> centres(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i)
    rigid_fit(rest, poses[i].corners, &rotations[i], &centres[i]);
  MujocoRenderSetup setup;
  setup.book_size = scene.body.cage.size;
  setup.width = w;
  setup.height = h;
  setup.msaa = scene.render.msaa;
  setup.fov_y_deg = settings.camera.fov_y_deg;
  setup.eye = settings.camera.eye;
  setup.target = settings.camera.target;

  PeerTiming own, own_encoded, mujoco, mujoco_encoded;
  RgbaImage own_frame, mujoco_frame;
  const std::filesystem::path file = c.scratch / "peer.mp4";
  const int rounds = std::max(1, c.options.rounds), jobs = c.options.jobs;
  // Each renderer holds its GL context current while it lives, so they take turns.
  for (int round = 0; round < rounds; ++round) {
    {
      render::Renderer renderer(settings);
      const auto draw_and_read = [&](int i) {
        renderer.draw(drawing.input_for(poses[static_cast<std::size_t>(i)]));
        return renderer.read_back();
      };
      timed_frames(frames, draw_and_read, scene, jobs, nullptr, &own, &own_frame);
      timed_frames(frames, draw_and_read, scene, jobs, &file, &own_encoded, nullptr);
    }
    {
      MujocoRenderer renderer(setup);
      const auto draw_and_read = [&](int i) {
        renderer.draw(rotations[static_cast<std::size_t>(i)], centres[static_cast<std::size_t>(i)]);
        return renderer.read_back();
      };
      timed_frames(frames, draw_and_read, scene, jobs, nullptr, &mujoco, &mujoco_frame);
      timed_frames(frames, draw_and_read, scene, jobs, &file, &mujoco_encoded, nullptr);
    }
  }
  if (!c.options.out_dir.empty()) {  // to look at: the middle frame from each
    output::write_png(std::filesystem::path(c.options.out_dir) / "peer-bookspin.png", own_frame);
    output::write_png(std::filesystem::path(c.options.out_dir) / "peer-mujoco.png", mujoco_frame);
  }
  const std::string what = std::to_string(frames) + " poses " + std::to_string(w) + "x" +
                           std::to_string(h) + ", best of " + std::to_string(rounds) +
                           " alternated runs";
  const auto row = [&](const std::string& metric, const PeerTiming& t, const std::string& note) {
    char cpu[64];
    std::snprintf(cpu, sizeof cpu, "; CPU %.2f s (all threads)", t.cpu);
    c.report->add({"peer", metric, t.wall, "s", note + ", " + what + cpu});
  };
  const std::string encoder = scene.render.codec + " crf " + std::to_string(scene.render.crf) +
                              " preset " + scene.render.preset;
  row("bookspin draw + read-back", own, "render::Renderer draw() and read_back(), 4x MSAA");
  row("MuJoCo mjr_render + mjr_readPixels", mujoco,
      "free textured box of the book's size, off-screen EGL buffer, " + std::to_string(setup.msaa) +
          "x MSAA, flipped to RGBA top-first");
  row("bookspin draw + read-back + encoder", own_encoded, encoder);
  row("MuJoCo mjr_render + mjr_readPixels + encoder", mujoco_encoded, encoder);
  c.report->add({"peer", "MuJoCo / bookspin, draw + read-back", mujoco.wall / own.wall, "x",
                 "wall time; above 1: bookspin is faster"});
  c.report->add({"peer", "MuJoCo / bookspin, draw + read-back, CPU time", mujoco.cpu / own.cpu, "x",
                 "process CPU time, every thread (llvmpipe's too)"});
  c.report->add({"peer", "MuJoCo / bookspin, with the encoder",
                 mujoco_encoded.wall / own_encoded.wall, "x",
                 "wall time, the same encoder for both"});
}

}  // namespace bookspin::bench
