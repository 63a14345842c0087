#include <iostream>

#include "app/commands.hpp"
#include "render/renderer.hpp"
#include "video/ffmpeg_info.hpp"

namespace bookspin::app {

int info_command() {
  for (const auto& line : video::ffmpeg_info()) std::cout << line << '\n';
  std::cout.flush();
  for (const auto& line : render::gl_info().lines()) std::cout << line << '\n';
  return kExitOk;
}

}  // namespace bookspin::app
