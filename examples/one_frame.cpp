// The whole data flow in one screen: scene file → Scene → simulator → pose → renderer →
// PNG, for any body (the book, a preset, a mesh). No caption or panel (that is charts/), no
// MP4 (that is clip/clip_sinks).
//
//   build/examples/one_frame scenes/fig05-particle-unstable-x.toml 120 frame.png
//   build/examples/one_frame scenes/t-handle-dzhanibekov.toml 60 t-handle.png
#include <cstdlib>
#include <iostream>
#include <string>

#include "clip/render_settings.hpp"
#include "engines/models.hpp"
#include "output/png_writer.hpp"
#include "physics/simulator.hpp"
#include "scene/scene.hpp"

using namespace bookspin;

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: one_frame SCENE.toml FRAME OUT.png\n";
    return 2;
  }
  try {
    // 1. Read and validate the scene.
    const scene::Scene scene = scene::parse_scene(argv[1]);
    const int frame = std::stoi(argv[2]);

    // 2. Step the simulator from the initial state to the frame's time.
    auto simulator = engines::make_model(scene.body, scene.model);
    simulator->reset(scene.initial);
    for (long step = 0; step < static_cast<long>(frame) * scene.steps_per_frame; ++step)
      simulator->step(scene.dt);
    const physics::Pose pose = simulator->pose();

    // 3. Render the pose (the renderer knows nothing of physics: the clip stage translates
    //    the scene's render keys and the body's pose into its settings and input).
    render::Renderer renderer(clip::render_settings_for(scene));
    const clip::BodyDrawing body(scene.body);
    const RgbaImage image = renderer.render(body.input_for(pose));

    // 4. Write one PNG.
    output::write_png(argv[3], image, 6);
    std::cout << "t = " << frame * scene.steps_per_frame * scene.dt
              << ", E = " << pose.diagnostics.energy_kinetic << ", wrote " << argv[3] << '\n';
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "one_frame: " << e.what() << '\n';
    return 1;
  }
}
