#include "picture_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include "charts/decoration.hpp"
#include "clip/frame.hpp"
#include "clip/render_settings.hpp"
#include "golden_store.hpp"
#include "output/png_writer.hpp"
#include "support/scratch.hpp"

namespace bookspin::picture {

namespace {

std::filesystem::path scenes_dir() { return std::filesystem::path(BOOKSPIN_SOURCE_DIR) / "scenes"; }

/// Everything in RenderSettings that changes the picture, as text (the cache key).
std::string settings_key(const render::RenderSettings& s) {
  std::ostringstream key;
  key.precision(17);
  const auto& c = s.camera;
  key << s.width << 'x' << s.height << ' ' << c.fov_y_deg << ' ' << c.eye.transpose() << ' '
      << c.target.transpose() << ' ' << c.up.transpose() << ' ' << s.textures.front << '|'
      << s.textures.back << '|' << s.textures.spine << '|' << s.textures.pages << ' '
      << s.show_angular_momentum << s.show_body_axes << ' ' << s.msaa_samples;
  return key.str();
}

}  // namespace

std::vector<std::string> figure_scene_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(scenes_dir())) {
    const auto& path = entry.path();
    if (path.extension() == ".toml" && path.stem().string().rfind("fig", 0) == 0) {
      names.push_back(path.stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

scene::Scene figure_scene(const std::string& name, std::vector<std::string> overrides) {
  const std::string size = std::to_string(kGoldenSize);
  const bool sphere_chosen = std::any_of(overrides.begin(), overrides.end(), [](const auto& o) {
    return o.rfind("render.sphere=", 0) == 0;
  });
  if (!sphere_chosen) overrides.insert(overrides.begin(), "render.sphere=false");
  // The filtering the goldens were made with, first so that a test's own choice overrides it
  // (kGoldenFiltering).
  overrides.insert(overrides.begin(), {"render.width=" + size, "render.height=" + size,
                                       std::string(kGoldenFiltering)});
  return scene::parse_scene(scenes_dir() / (name + ".toml"), overrides);
}

// No plot panel: it moves the camera sideways, which would show slivers of the neighbouring
// faces in the on-axis views.
scene::Scene book_at_rest(const std::string& label, const std::string& direction,
                          std::vector<std::string> overrides) {
  overrides.insert(overrides.begin(), {"initial.angular_velocity=[0.0, 0.0, 0.0]",
                                       "initial.jiggle=0.0", "time.frames=1", "render.panel=false",
                                       "scene.title=\"Face mapping: " + label + "\"",
                                       "render.camera_direction=" + direction});
  return figure_scene("fig09-matrix-unstable-x", std::move(overrides));
}

render::Renderer& renderer_for(const scene::Scene& scene) {
  // Never destroyed, on purpose: a static's destructor runs at exit(), after the GL driver's own
  // exit handlers may have unloaded it. On NVIDIA, ~Renderer there deleted its textures through
  // libepoxy into the unmapped libnvidia-eglcore and the suite died of SIGSEGV after passing
  // (docs/performance-render.md, "A GPU"). The renderers live as long as the process; the system
  // takes their memory and the driver its contexts. (The display registry,
  // src/render/egl_display.cpp, is never destroyed for the same reason.)
  static auto* renderers = new std::map<std::string, std::unique_ptr<render::Renderer>>;
  const render::RenderSettings settings = clip::render_settings_for(scene);
  auto& slot = (*renderers)[settings_key(settings)];
  if (!slot) slot = std::make_unique<render::Renderer>(settings);
  return *slot;
}

std::vector<int> pinned_frames(int frames) {
  std::vector<int> pinned{0, frames / 2, frames - 1};
  pinned.erase(std::unique(pinned.begin(), pinned.end()), pinned.end());  // short clips
  return pinned;
}

std::string golden_name(const std::string& scene, int index) {
  char suffix[16];
  std::snprintf(suffix, sizeof suffix, "-f%04d", index);
  return scene + suffix;
}

std::string test_name(std::string name) {
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

void expect_pinned_frames_match(const scene::Scene& scene, const std::string& prefix) {
  render::Renderer& renderer = renderer_for(scene);
  for (const int index : pinned_frames(scene.frames)) {
    const std::string name = prefix + golden_name(scene.name, index);
    EXPECT_TRUE(matches_golden(name, clip::render_still(scene, renderer, index))) << name;
  }
}

RgbaImage rendered_frame(const std::string& scene, int index, int width, int height,
                         const std::vector<std::string>& sets, const std::string& folder) {
  std::string args =
      std::string("--set ") + kGoldenFiltering + " --set render.width=" + std::to_string(width) +
      " --set render.height=" + std::to_string(height) + " --set render.preset='\"ultrafast\"'";
  for (const std::string& set : sets) args += " --set " + set;
  const auto dir = test::fresh_dir("picture/" + folder);
  const std::string command = std::string(BOOKSPIN_EXE) + " render " + BOOKSPIN_SOURCE_DIR +
                              "/scenes/" + scene + ".toml -o " + dir.string() + " --frames " +
                              std::to_string(index + 1) + " " + args + " > /dev/null 2>&1";
  if (std::system(command.c_str()) != 0) {
    ADD_FAILURE() << "failed: " << command;
    return RgbaImage{};
  }
  char frame[32];
  std::snprintf(frame, sizeof frame, "frame_%05d.png", index);
  const RgbaImage image = output::read_png(dir / scene / "frames" / frame);
  std::filesystem::remove_all(dir);
  return image;
}

}  // namespace bookspin::picture
