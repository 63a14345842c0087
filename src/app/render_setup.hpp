#pragma once
// Set-up shared by `bookspin render` for single and comparison scenes.
#include <filesystem>

#include "app/clip_sinks.hpp"
#include "app/commands.hpp"
#include "scene/scene.hpp"

namespace bookspin::app {

/// The encoder settings of a render of `scene` (render.width, height, fps, codec, crf,
/// preset) with `jobs` threads (0: the encoder's own choice for all cores).
video::EncoderSettings encoder_settings(const scene::Scene& scene, int jobs);

/// Sink settings from the scene's render.* keys and the command line (--no-png, --jobs,
/// --png-compression).
SinkOptions sink_options(const scene::Scene& scene, const RenderOptions& options);

/// Checks early that the output directory exists or can be made and is writable, so a bad
/// -o fails before any work. Throws video::OutputError naming the directory.
void prepare_output_dir(const std::filesystem::path& dir);

}  // namespace bookspin::app
