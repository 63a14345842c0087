#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/subcommand.hpp"
#include "render/renderer.hpp"
#include "video/video.hpp"

namespace bookspin::cli {

namespace {

/// Prints the EGL/GL and FFmpeg set-up.
int info_command() {
  for (const auto& line : video::ffmpeg_info()) std::cout << line << '\n';
  std::cout.flush();
  const render::GlInfo gl = render::gl_info();
  for (const auto& line : gl.lines()) std::cout << line << '\n';
  const float anisotropy = render::effective_anisotropy(render::kAutoAnisotropy, gl.gl_renderer);
  std::cout << "texture filtering (render.anisotropy = 0): "
            << (anisotropy > 1.0f ? std::to_string(static_cast<int>(anisotropy)) + "x anisotropic"
                                  : std::string("trilinear (software rasterizer)"))
            << '\n';
  return kExitOk;
}

}  // namespace

Subcommand add_info(CLI::App& cli) {
  return {
      cli.add_subcommand(
          "info", "Print the EGL vendor, GL renderer and version, FFmpeg versions and encoders"),
      [] { return info_command(); }};
}

}  // namespace bookspin::cli
