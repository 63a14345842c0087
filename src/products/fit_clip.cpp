#include "products/fit_clip.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

#include "common/errors.hpp"
#include "physics/replay_model.hpp"
#include "scene/canonical.hpp"

namespace bookspin::products {

namespace {

std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

/// The scene used without --scene: the phone preset at the render defaults.
constexpr std::string_view kPhoneScene = "body.shape = \"phone\"\n";

}  // namespace

scene::Scene fit_clip_scene(const FitRender& render) {
  if (!(render.slow_motion >= kMinSlowMotion && render.slow_motion <= kMaxSlowMotion))
    throw InputError("--slow-motion: " + fixed(render.slow_motion, 3) + " is outside [" +
                     fixed(kMinSlowMotion, 0) + ", " + fixed(kMaxSlowMotion, 0) + "]");
  scene::Scene scene = render.scene_file ? scene::parse_scene(*render.scene_file)
                                         : scene::parse_scene_text(kPhoneScene, "phone.toml");
  scene.render.panel = true;
  scene.render.sphere = false;  // the sphere of the drawn body, not the fitted one
  scene.render.poinsot = false;
  scene.render.caption_twist = false;
  scene.compare.clear();
  scene.model = physics::ModelConfig{};
  scene.model.kind = physics::ModelKind::exact;  // names only: the tiles' models are given
  scene.initial = physics::InitialState{};
  // The keys each toss's clip sets (toss_clip_scene) at their defaults, so that the manifest
  // holds only what the clips take from the file.
  const scene::Scene defaults;
  scene.name = "phone-toss";
  scene.title = scene.description = "";
  scene.dt = defaults.dt;
  scene.steps_per_frame = defaults.steps_per_frame;
  scene.frames = defaults.frames;
  scene.time_unit = "s";  // the recording's time
  return scene;
}

FitClips fit_clips(const FitRender& render) {
  FitClips clips{fit_clip_scene(render), render.slow_motion, {}, {}};
  clips.head = {{"slow_motion", {JsonNumber{render.slow_motion}}},
                {"scene", {scene::canonical_scene(clips.scene), true}}};
  const scene::RenderOptions& r = clips.scene.render;
  for (const std::string& file :
       {r.texture_front, r.texture_back, r.texture_spine, r.texture_pages, clips.scene.body_mesh})
    if (!file.empty()) clips.inputs.emplace_back(file);
  return clips;
}

scene::Scene toss_clip_scene(const scene::Scene& base, const std::string& recording,
                             const fit::FitResult& fit, int toss, double slow_motion) {
  const fit::Flight& flight = fit.tosses.at(static_cast<std::size_t>(toss)).flight;
  scene::Scene scene = base;
  const std::string n = std::to_string(toss + 1);
  scene.name = recording + "-toss" + n;
  char factor[32];
  std::snprintf(factor, sizeof factor, "%g", slow_motion);  // "4", "2.5"
  scene.title = recording + ", toss " + n + " (" + fixed(flight.t_start, 2) + "–" +
                fixed(flight.t_end, 2) + " s), " + factor + "× slower";
  scene.description = "The phone's measured ω replayed beside the fitted exact motion";
  const double rate = scene.render.fps * slow_motion;  // frames per second of the recording
  scene.dt = 1.0 / rate;
  scene.steps_per_frame = 1;
  const double duration = flight.t_end - flight.t_start;
  scene.frames = static_cast<int>(std::floor(duration * rate + 1e-9)) + 1;
  scene.compare = {{"measured", "measured", scene.model}, {"exact fit", "exact-fit", scene.model}};
  return scene;
}

std::vector<clip::TileModel> toss_tile_models(const fit::FitResult& fit,
                                              const fit::TossChart& chart,
                                              const physics::Body& body) {
  const fit::TossFit& fitted = fit.tosses.at(static_cast<std::size_t>(chart.toss));
  const fit::BodyEstimate& estimate = fit.body;
  const Eigen::Matrix3d inertia =
      estimate.axes * estimate.ratios.asDiagonal() * estimate.axes.transpose();
  // The drawn body's principal frame → the phone frame: its built axes are the phone's.
  const Eigen::Matrix3d placement = body.principal_axes.transpose();
  const std::vector<double>& t = chart.t;
  const double rate = (static_cast<double>(t.size()) - 1) / (t.back() - t.front());
  auto measured = std::make_shared<const physics::OmegaReplay>(t, chart.measured);
  auto exact = std::make_shared<const physics::ExactInFrame>(
      estimate.axes, estimate.ratios, fitted.omega0, physics::Drag{fit.drag, fitted.drag_rate});
  // The panel's ω: about the fitted principal axes 1, 2, 3, told as the drawn body's axes of
  // the same moment order, so that its flip axis (the drawn body's intermediate) shows ω about
  // the fitted intermediate axis: the flips, as the fit's chart shows them.
  const std::array<int, 3> order = physics::principal_order(body.moments);
  Eigen::Matrix3d omega_axes;
  for (int i = 0; i < 3; ++i) omega_axes.row(order[i]) = estimate.axes.col(i).transpose();
  const auto model = [&body, placement, inertia,
                      omega_axes](std::shared_ptr<const physics::PrescribedMotion> motion) {
    return [body, placement, inertia, omega_axes, motion]() -> std::unique_ptr<physics::Simulator> {
      return std::make_unique<physics::ReplayModel>(body, placement, inertia, motion, omega_axes);
    };
  };
  const Eigen::Vector3d& r = estimate.ratios;
  return {
      {model(measured), "gyroscope ω integrated, " + fixed(rate, 0) + " samples/s"},
      {model(exact), "exact, I₁ : I₂ : I₃ = " + fixed(r[0], 3) + " : " + fixed(r[1], 3) + " : 1"}};
}

}  // namespace bookspin::products
