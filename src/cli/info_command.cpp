#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/subcommand.hpp"
#include "common/errors.hpp"
#include "render/renderer.hpp"
#include "typeface/typeface.hpp"
#include "video/video.hpp"

namespace bookspin::cli {

namespace {

/// Prints the FFmpeg set-up and the faces and options every text is drawn with (no GL needed:
/// printed, and flushed, before the EGL/GL set-up is asked, which fails without an EGL driver),
/// then the EGL/GL set-up.
int info_command() {
  for (const auto& line : video::ffmpeg_info()) std::cout << line << '\n';
  for (const auto& line : typeface::info_lines()) std::cout << line << '\n';
  flush_standard_output();
  const render::GlInfo gl = render::gl_info();
  for (const auto& line : gl.lines()) std::cout << line << '\n';
  const float anisotropy = render::effective_anisotropy(render::kAutoAnisotropy, gl.gl_renderer);
  std::cout << "texture filtering (render.anisotropy = 0): "
            << (anisotropy > 1.0f ? std::to_string(static_cast<int>(anisotropy)) + "x anisotropic"
                                  : std::string("trilinear (software rasterizer)"))
            << '\n';
  flush_standard_output();
  return kExitOk;
}

}  // namespace

Subcommand add_info(CLI::App& cli) {
  return {
      cli.add_subcommand(
          "info",
          "Print the EGL vendor, GL renderer and version, FFmpeg versions and encoders, the text's "
          "faces and options"),
      [] { return info_command(); }};
}

}  // namespace bookspin::cli
