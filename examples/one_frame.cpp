// The whole data flow in one screen: scene file → Scene → simulator → pose → renderer →
// PNG. No caption or panel (that is pipeline/), no MP4 (that is output/clip_sinks).
//
//   build/examples/one_frame scenes/fig05-particle-unstable-x.toml 120 frame.png
#include <cstdlib>
#include <iostream>
#include <string>

#include "output/png_writer.hpp"
#include "physics/simulator.hpp"
#include "render/renderer.hpp"
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
    auto simulator = physics::make_simulator(scene.book, scene.model);
    simulator->reset(scene.initial);
    for (long step = 0; step < static_cast<long>(frame) * scene.steps_per_frame; ++step)
      simulator->step(scene.dt);
    const physics::BookPose pose = simulator->pose();

    // 3. Render the book's 8 world corners (the renderer knows nothing of physics).
    render::RenderSettings settings;
    settings.width = scene.render.width;
    settings.height = scene.render.height;
    settings.camera =
        render::default_camera(0.5 * scene.book.size.norm(), settings.width, settings.height);
    render::Renderer renderer(settings);
    render::FrameInput input;
    input.corners = pose.corners;
    const RgbaImage image = renderer.render(input);

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
