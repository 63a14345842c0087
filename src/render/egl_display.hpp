#pragma once
// Internal: one EGL display → an OpenGL 3.3 core context made current without a surface.
#include <epoxy/egl.h>

#include <string>
#include <string_view>

namespace bookspin::render {

/// True if the space-separated extension list (may be null) contains `name`.
bool has_extension(const char* list, std::string_view name);

/// Name of the current eglGetError() code (clears it).
std::string last_egl_error();

/// An initialized display with a current GL context, or the reason there is none.
struct Attempt {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  std::string failure;  ///< empty on success
};

/// Initializes `display` (EGL_NO_DISPLAY is reported as a failure), creates an OpenGL 3.3
/// core context (EGL_KHR_surfaceless_context required; no config if EGL_KHR_no_config_context)
/// and makes it current with EGL_NO_SURFACE. On failure everything is undone and
/// `failure` says why (with the EGL error name). Never throws.
Attempt try_display(EGLDisplay display);

/// Counted use of an initialized display: EGL displays are per process and not reference
/// counted, so eglTerminate would pull the display from under every other context on it
/// (two Renderers, or `info` beside a Renderer). The last release terminates it.
void retain_display(EGLDisplay display);
void release_display(EGLDisplay display);

}  // namespace bookspin::render
