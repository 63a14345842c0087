#pragma once
// A headless OpenGL 3.3+ core context on EGL: no window, no pbuffer (surfaceless).
#include <memory>
#include <string>
#include <vector>

#include "common/non_copyable.hpp"

namespace bookspin::render {

/// What the context runs on; the strings behind `bookspin info`.
struct GlInfo {
  std::string egl_platform;  ///< e.g. "device 0 (software)", "surfaceless", "default display"
  std::string egl_vendor;
  std::string egl_version;
  std::string gl_vendor;
  std::string gl_renderer;
  std::string gl_version;
  /// "EGL platform: ...", "EGL vendor: ...", ... one line each.
  std::vector<std::string> lines() const;
};

/// Owns an EGL display reference and an OpenGL core context, current on the creating thread.
/// Tried in order, each falling through to the next if it cannot initialize or cannot give a
/// GL 3.3 core context: (a) the EGL device platform (env BOOKSPIN_EGL_DEVICE=<index> picks
/// the device, otherwise hardware devices before software ones); (b) Mesa's surfaceless
/// platform; (c) the default display. BOOKSPIN_EGL_PLATFORM=device|surfaceless|default
/// restricts creation to that one step (diagnostics, tests). Throws RenderError (one line listing
/// why each step failed) if none works, or if libEGL.so.1 cannot be loaded at all.
class EglContext : NonCopyable {
 public:
  EglContext();
  ~EglContext();

  /// Makes this context current on the calling thread (cheap if it already is).
  void make_current();
  /// Platform, vendor and version strings of this context.
  const GlInfo& info() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Name of an EGL error code ("EGL_BAD_ALLOC", ...), or its hex value if unknown.
std::string egl_error_name(int code);

}  // namespace bookspin::render
