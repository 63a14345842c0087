#pragma once
// `bookspin render` for a comparison scene ([[compare]] panels side by side in one clip).
#include "app/commands.hpp"
#include "scene/scene.hpp"

namespace bookspin::app {

/// Renders a comparison scene: every panel's simulator starts from the scene's initial state
/// and steps in lockstep; one renderer at tile size draws each panel's book into its tile,
/// each tile is labelled (label, model line, t), and the composited frame goes to
/// OUT/<scene>.mp4 and OUT/<scene>/frames/. Each panel's diagnostics go to
/// OUT/<scene>/diagnostics-<panel name>.csv (the diagnostics CSV's columns). Returns the
/// exit status (128 + signal when interrupted; nothing unfinished is left behind).
int render_comparison(const scene::Scene& scene, const RenderOptions& options);

}  // namespace bookspin::app
