// bookspin-explorer-data: what the explorer page (web/) needs of each scene, written by
// bookspin's own code: the scene's settings as validated by the scene reader (ω0 resolved
// from spin_axis, the body's mass and scale), and the book's four face images from the
// renderer's texture code. The page builds the body itself from these through the physics
// compiled to WebAssembly, so it reads no mesh files.
//
// Usage: bookspin-explorer-data OUT_DIR SCENE...
// Writes OUT_DIR/explorer-data.json and OUT_DIR/face-{front,back,spine,pages}.png.
// Errors as bookspin's: bad scene → one line, exit 2; failed write → exit 1; bug → 70.
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "output/png_writer.hpp"
#include "physics/presets.hpp"
#include "render/face_images.hpp"
#include "scene/scene.hpp"

namespace {

using namespace bookspin;

std::string quoted(const std::string& s) {
  std::ostringstream out;
  out << '"';
  for (const char c : s) {
    if (c == '"' || c == '\\') out << '\\' << c;
    else if (static_cast<unsigned char>(c) < 0x20) out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
    else out << c;
  }
  out << '"';
  return out.str();
}

std::string vec(const Eigen::Vector3d& v) {
  std::ostringstream out;
  out << std::setprecision(17) << '[' << v.x() << ',' << v.y() << ',' << v.z() << ']';
  return out.str();
}

std::string method(const physics::ModelConfig& m, const char* suffix) {
  std::ostringstream out;
  out << "\"model" << suffix << "\":" << quoted(std::string(physics::to_string(m.kind)))
      << ",\"integrator" << suffix << "\":" << quoted(std::string(physics::to_string(m.integrator)))
      << ",\"normalize" << suffix << "\":" << (m.normalize ? "true" : "false");
  return out.str();
}

/// One scene as the page's state (web/src/state.js) plus what builds its body.
std::string scene_json(const scene::Scene& s) {
  if (s.body.shape == physics::BodyShape::mesh)
    return {};  // the page builds presets and the book only
  std::ostringstream out;
  out << std::setprecision(17);
  const physics::ModelConfig& first = s.compare.empty() ? s.model : s.compare[0].model;
  out << "{\"name\":" << quoted(s.name) << ",\"title\":" << quoted(s.title)
      << ",\"description\":" << quoted(s.description) << ",\"state\":{"
      << "\"body\":" << quoted(std::string(physics::to_string(s.body.shape))) << ','
      << method(first, "") << ",\"damping\":" << (first.damping ? "true" : "false")
      << ",\"k\":" << first.spring_constant << ",\"dt\":" << s.dt << ",\"axis\":\"custom\""
      << ",\"w\":" << vec(s.initial.omega0_body) << ",\"jiggle\":" << s.initial.jiggle
      << ",\"seed\":" << s.initial.seed << ",\"speed\":" << s.dt * s.steps_per_frame * s.render.fps
      << ",\"showL\":" << (s.render.show_angular_momentum ? "true" : "false")
      << ",\"showAxes\":" << (s.render.show_body_axes ? "true" : "false");
  if (s.compare.size() >= 2) {
    // The page compares two methods: the first tile against the last (e.g. Euler and exact).
    out << ",\"compare\":true," << method(s.compare.back().model, "2");
  }
  out << "},\"book\":{\"size\":" << vec(s.body.cage.size) << ",\"mass\":" << s.body.cage.mass << '}';
  if (s.body.shape != physics::BodyShape::book) {
    // preset_body(shape, mass, scale): the scale from the cage of the unit preset.
    const physics::Body unit = physics::preset_body(s.body.shape, 1.0, 1.0);
    out << ",\"mass\":" << s.body.cage.mass << ",\"scale\":" << s.body.cage.size.x() / unit.cage.size.x();
  }
  out << '}';
  return out.str();
}

int run(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: bookspin-explorer-data OUT_DIR SCENE...\n";
    return 2;
  }
  const std::filesystem::path out_dir = argv[1];
  std::vector<std::string> entries;
  for (int i = 2; i < argc; ++i) {
    const scene::Scene s = scene::parse_scene(argv[i]);
    if (std::string json = scene_json(s); !json.empty()) entries.push_back(std::move(json));
    else std::cerr << "bookspin-explorer-data: note: " << argv[i] << ": mesh body, not in the explorer\n";
  }
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  const char* names[] = {"front", "back", "spine", "pages"};
  for (int f = 0; f < 4; ++f) {
    output::write_png(out_dir / ("face-" + std::string(names[f]) + ".png"),
                      render::generate_face_image(static_cast<render::FaceImage>(f)), 6);
  }
  const std::filesystem::path json = out_dir / "explorer-data.json";
  std::ofstream file(json);
  file << "[\n";
  for (std::size_t i = 0; i < entries.size(); ++i) file << entries[i] << (i + 1 < entries.size() ? ",\n" : "\n");
  file << "]\n";
  file.close();
  if (!file) throw_output_error("write", json, "write failed");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const InputError& e) {
    std::cerr << "bookspin-explorer-data: error: " << e.what() << '\n';
    return 2;
  } catch (const OutputError& e) {
    std::cerr << "bookspin-explorer-data: error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "bookspin-explorer-data: internal error: " << e.what() << '\n';
    return 70;
  }
}
