#pragma once
// The scenes the picture tests render, at the goldens' size, and renderers shared between
// them (creating one costs ~0.4 s on llvmpipe; one renderer draws any number of frames).
#include <string>
#include <vector>

#include "clip/render_settings.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace bookspin::picture {

/// Goldens are 256×256: big enough to show faces, text bands and overlays, small in git.
inline constexpr int kGoldenSize = 256;

/// The texture filtering every golden was made with, pinned in each scene the picture tests
/// render (figure_scene, rendered_frame), before the test's own overrides: trilinear, no
/// anisotropic filtering. The automatic value (render.anisotropy = 0) is trilinear on llvmpipe,
/// where the goldens were made, but 4× anisotropic on a GPU, which drew five goldens' grazing
/// covers sharper than the tolerance allows (docs/performance-render.md, "A GPU").
inline constexpr const char* kGoldenFiltering = "render.anisotropy=1";

/// The stems of scenes/fig*.toml, sorted (every figure gets goldens automatically).
std::vector<std::string> figure_scene_names();

/// scenes/<name>.toml at kGoldenSize² with kGoldenFiltering, with further `overrides`
/// ("key=value", TOML). Without
/// the momentum sphere (render.sphere=false) unless `overrides` set render.sphere: the
/// figures' goldens predate it and stay as they are; the sphere has goldens of its own.
scene::Scene figure_scene(const std::string& name, std::vector<std::string> overrides = {});

/// fig09's rigid book at rest (frame 0 = the identity pose), captioned "Face mapping:
/// <label>", seen from `direction` (TOML, e.g. "[0.0, 0.0, 1.0]"), plus `overrides`.
scene::Scene book_at_rest(const std::string& label, const std::string& direction,
                          std::vector<std::string> overrides = {});

/// A renderer for clip::render_settings_for(scene), shared by every scene with the same
/// settings in this process.
render::Renderer& renderer_for(const scene::Scene& scene);

/// The frames pinned for a scene of `frames` frames: the first, the middle and the last
/// (for a diverging figure the last frame holds the last pose before the blow-up and the banner).
std::vector<int> pinned_frames(int frames);

/// "fig05-particle-unstable-x-f0375": the golden's name for frame `index` of `scene`.
std::string golden_name(const std::string& scene, int index);

/// Expects each of pinned_frames(scene.frames), drawn by clip::render_still with
/// renderer_for(scene), to match the golden `prefix` + golden_name(scene.name, index).
void expect_pinned_frames_match(const scene::Scene& scene, const std::string& prefix = "");

/// `name` with every character GoogleTest does not allow in a test name replaced by '_'.
std::string test_name(std::string name);

/// Frame `index` of `bookspin render scenes/<scene>.toml --frames index+1` at `width`×`height`
/// pixels with kGoldenFiltering and the fastest MP4 preset (the MP4 is not looked at) and the
/// further overrides `sets` ("key=value", TOML; the CLI's own path: a comparison runs one simulator
/// per tile), rendered into a fresh folder named `folder` and read back from its PNG; the folder is
/// removed once read. A failed render is a test failure and gives an empty (0×0) image.
RgbaImage rendered_frame(const std::string& scene, int index, int width, int height,
                         const std::vector<std::string>& sets, const std::string& folder);

}  // namespace bookspin::picture
