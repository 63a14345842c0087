#include "render/egl_display.hpp"

#include <epoxy/gl.h>

#include <map>
#include <mutex>
#include <sstream>

#include "render/egl_context.hpp"

namespace bookspin::render {

bool has_extension(const char* list, std::string_view name) {
  if (list == nullptr) return false;
  std::string_view rest(list);
  while (!rest.empty()) {
    const auto space = rest.find(' ');
    if (rest.substr(0, space) == name) return true;
    if (space == std::string_view::npos) break;
    rest.remove_prefix(space + 1);
  }
  return false;
}

std::string last_egl_error() { return egl_error_name(eglGetError()); }

namespace {

// Never destroyed, so a Renderer that outlives static destruction (a static one) still
// finds the registry.
struct DisplayUsers {
  std::mutex mutex;
  std::map<EGLDisplay, int> count;
};

DisplayUsers& display_users() {
  static auto* users = new DisplayUsers;
  return *users;
}

}  // namespace

void retain_display(EGLDisplay display) {
  DisplayUsers& users = display_users();
  const std::lock_guard lock(users.mutex);
  ++users.count[display];
}

void release_display(EGLDisplay display) {
  DisplayUsers& users = display_users();
  const std::lock_guard lock(users.mutex);
  auto it = users.count.find(display);
  if (it == users.count.end() || --it->second > 0) return;
  users.count.erase(it);
  eglTerminate(display);
}

namespace {

EGLConfig choose_config(EGLDisplay display, std::string& failure) {
  if (has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context"))
    return EGL_NO_CONFIG_KHR;
  // We never draw to an EGL surface, so any surface type will do.
  const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_DONT_CARE,
                               EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, attributes, &config, 1, &count))
    failure = "eglChooseConfig failed: " + last_egl_error();
  else if (count < 1)
    failure = "no EGL config supports OpenGL";
  return config;
}

EGLContext create_core_context(EGLDisplay display, std::string& failure) {
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!has_extension(extensions, "EGL_KHR_surfaceless_context")) {
    failure = "no EGL_KHR_surfaceless_context";
    return EGL_NO_CONTEXT;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    failure = "eglBindAPI(EGL_OPENGL_API) failed: " + last_egl_error();
    return EGL_NO_CONTEXT;
  }
  const EGLConfig config = choose_config(display, failure);
  if (!failure.empty()) return EGL_NO_CONTEXT;
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               3,
                               EGL_CONTEXT_MINOR_VERSION,
                               3,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_NONE};
  const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT)
    failure = "eglCreateContext(OpenGL 3.3 core) failed: " + last_egl_error();
  return context;
}

// Makes the context current without a surface and checks the GL version really is 3.3+.
void make_current_and_check(Attempt& attempt) {
  if (!eglMakeCurrent(attempt.display, EGL_NO_SURFACE, EGL_NO_SURFACE, attempt.context)) {
    attempt.failure = "eglMakeCurrent(EGL_NO_SURFACE) failed: " + last_egl_error();
    return;
  }
  const int version = epoxy_gl_version();
  if (version < 33 || epoxy_is_desktop_gl() == 0)
    attempt.failure =
        "context is not desktop OpenGL 3.3+ (version " + std::to_string(version) + ")";
}

void abandon(Attempt& attempt) {
  if (attempt.context != EGL_NO_CONTEXT) {
    eglMakeCurrent(attempt.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(attempt.display, attempt.context);
    attempt.context = EGL_NO_CONTEXT;
  }
  release_display(attempt.display);
}

}  // namespace

Attempt try_display(EGLDisplay display) {
  Attempt attempt;
  attempt.display = display;
  if (display == EGL_NO_DISPLAY) {
    attempt.failure = "no display: " + last_egl_error();
    return attempt;
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    attempt.failure = "eglInitialize failed: " + last_egl_error();
    return attempt;
  }
  retain_display(display);
  attempt.context = create_core_context(display, attempt.failure);
  if (attempt.failure.empty()) make_current_and_check(attempt);
  if (!attempt.failure.empty()) abandon(attempt);
  return attempt;
}

std::string egl_error_name(int code) {
  switch (code) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
      return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
      return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
      return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
      return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT:
      return "EGL_BAD_DEVICE_EXT";
    default: {
      std::ostringstream out;
      out << "EGL error 0x" << std::hex << code;
      return out.str();
    }
  }
}

}  // namespace bookspin::render
