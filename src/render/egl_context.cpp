#include "render/egl_context.hpp"

#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <optional>

#include "render/egl_display.hpp"
#include "render/render_error.hpp"

namespace bookspin::render {

namespace {

// epoxy aborts the process if it cannot load libEGL; probe first so that is an exception.
void require_libegl() {
  void* handle = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw RenderError(std::string("cannot load libEGL.so.1 (") + (why ? why : "unknown") +
                      "): install an EGL implementation (e.g. libegl1 and Mesa's libegl-mesa0)");
  }
  // Deliberately kept loaded: epoxy is about to load it too.
}

std::string safe_string(const char* text) { return text ? text : "(unknown)"; }

// ---- the three steps ----------------------------------------------------------------

struct Step {
  Attempt attempt;
  std::string platform;  ///< what GlInfo::egl_platform will say
};

std::optional<int> requested_device() {
  const char* text = std::getenv("BOOKSPIN_EGL_DEVICE");
  if (text == nullptr || *text == '\0') return std::nullopt;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || value < 0 || value > 1000)
    throw RenderError(std::string("BOOKSPIN_EGL_DEVICE must be a device index >= 0, got '") + text +
                      "'");
  return static_cast<int>(value);
}

bool is_software(EGLDeviceEXT device) {
  return has_extension(eglQueryDeviceStringEXT(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
}

std::vector<EGLDeviceEXT> query_devices() {
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return {};
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (!eglQueryDevicesEXT(count, devices.data(), &count)) return {};
  devices.resize(static_cast<std::size_t>(count));
  return devices;
}

// Indices to try: the requested one, else hardware devices first, then software ones.
std::vector<int> device_order(const std::vector<EGLDeviceEXT>& devices) {
  if (const auto wanted = requested_device()) {
    if (*wanted >= static_cast<int>(devices.size()))
      throw RenderError("BOOKSPIN_EGL_DEVICE=" + std::to_string(*wanted) + " but EGL lists " +
                        std::to_string(devices.size()) + " device(s)");
    return {*wanted};
  }
  std::vector<int> order;
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < static_cast<int>(devices.size()); ++i) {
      if (is_software(devices[static_cast<std::size_t>(i)]) == (pass == 1)) order.push_back(i);
    }
  }
  return order;
}

std::string describe_device(EGLDeviceEXT device, int index) {
  std::string text =
      "device " + std::to_string(index) + (is_software(device) ? " (software" : " (hardware");
  if (has_extension(eglQueryDeviceStringEXT(device, EGL_EXTENSIONS), "EGL_EXT_device_drm")) {
    if (const char* file = eglQueryDeviceStringEXT(device, EGL_DRM_DEVICE_FILE_EXT))
      text += ", " + std::string(file);
  }
  return text + ")";
}

Step try_device_platform(const char* client_extensions) {
  Step step;
  step.platform = "device platform";
  const bool enumerable = has_extension(client_extensions, "EGL_EXT_device_enumeration") ||
                          has_extension(client_extensions, "EGL_EXT_device_base");
  if (!enumerable || !has_extension(client_extensions, "EGL_EXT_platform_device")) {
    if (requested_device())
      throw RenderError(
          "BOOKSPIN_EGL_DEVICE is set but EGL has no device platform "
          "(EGL_EXT_device_enumeration + EGL_EXT_platform_device)");
    step.attempt.failure = "no EGL_EXT_device_enumeration/EGL_EXT_platform_device";
    return step;
  }
  const std::vector<EGLDeviceEXT> devices = query_devices();
  std::string failures;
  for (const int index : device_order(devices)) {
    const EGLDeviceEXT device = devices[static_cast<std::size_t>(index)];
    step.attempt = try_display(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr));
    step.platform = "EGL device platform, " + describe_device(device, index);
    if (step.attempt.failure.empty()) return step;
    failures += (failures.empty() ? "" : ", ") + describe_device(device, index) + ": " +
                step.attempt.failure;
  }
  step.platform = "device platform";
  step.attempt.failure = devices.empty() ? "no EGL devices" : failures;
  return step;
}

Step try_surfaceless_platform(const char* client_extensions) {
  Step step;
  step.platform = "Mesa surfaceless platform";
  if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
    step.attempt.failure = "no EGL_MESA_platform_surfaceless";
    return step;
  }
  step.attempt = try_display(
      eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
  return step;
}

Step try_default_display() {
  Step step;
  step.platform = "default display";
  step.attempt = try_display(eglGetDisplay(EGL_DEFAULT_DISPLAY));
  return step;
}

// BOOKSPIN_EGL_PLATFORM=device|surfaceless|default restricts creation to that one step
// (for diagnosing a machine, and for testing each step); unset = all, in order.
std::string forced_platform() {
  const char* text = std::getenv("BOOKSPIN_EGL_PLATFORM");
  const std::string value = text ? text : "";
  if (!value.empty() && value != "device" && value != "surfaceless" && value != "default")
    throw RenderError("BOOKSPIN_EGL_PLATFORM must be device, surfaceless or default, got '" +
                      value + "'");
  return value;
}

// Runs the steps in order; the first that yields a context wins.
Step create_context() {
  require_libegl();
  const std::string forced = forced_platform();
  const auto wanted = [&forced](const char* name) { return forced.empty() || forced == name; };
  // Null (with EGL_BAD_DISPLAY) when the implementation has no client extensions.
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (client == nullptr) eglGetError();
  const bool platform_base = has_extension(client, "EGL_EXT_platform_base");
  std::string failures;
  const std::pair<const char*, Step (*)(const char*)> platform_steps[] = {
      {"device", &try_device_platform}, {"surfaceless", &try_surfaceless_platform}};
  for (const auto& [name, step_fn] : platform_steps) {
    if (!wanted(name)) continue;
    if (!platform_base) {
      failures += std::string(name) + " platform: no EGL_EXT_platform_base; ";
      continue;
    }
    Step step = step_fn(client);
    if (step.attempt.failure.empty()) return step;
    failures += step.platform + ": " + step.attempt.failure + "; ";
  }
  if (wanted("default")) {
    Step step = try_default_display();
    if (step.attempt.failure.empty()) return step;
    failures += step.platform + ": " + step.attempt.failure;
  }
  throw RenderError("no headless OpenGL 3.3 core context on EGL: " + failures);
}

std::string gl_string(GLenum name) {
  return safe_string(reinterpret_cast<const char*>(glGetString(name)));
}

GlInfo query_info(EGLDisplay display, const std::string& platform) {
  GlInfo info;
  info.egl_platform = platform;
  info.egl_vendor = safe_string(eglQueryString(display, EGL_VENDOR));
  info.egl_version = safe_string(eglQueryString(display, EGL_VERSION));
  info.gl_vendor = gl_string(GL_VENDOR);
  info.gl_renderer = gl_string(GL_RENDERER);
  info.gl_version = gl_string(GL_VERSION);
  return info;
}

}  // namespace

struct EglContext::State {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  GlInfo info;
};

EglContext::EglContext() : state_(std::make_unique<State>()) {
  const Step step = create_context();
  state_->display = step.attempt.display;
  state_->context = step.attempt.context;
  state_->info = query_info(state_->display, step.platform);
}

EglContext::~EglContext() {
  if (eglGetCurrentContext() == state_->context)
    eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(state_->display, state_->context);
  release_display(state_->display);
}

void EglContext::make_current() {
  if (eglGetCurrentContext() == state_->context) return;
  if (!eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, state_->context))
    throw RenderError("eglMakeCurrent failed: " + last_egl_error());
}

const GlInfo& EglContext::info() const { return state_->info; }

std::vector<std::string> GlInfo::lines() const {
  return {"EGL platform: " + egl_platform, "EGL vendor: " + egl_vendor,
          "EGL version: " + egl_version,   "GL vendor: " + gl_vendor,
          "GL renderer: " + gl_renderer,   "GL version: " + gl_version};
}

}  // namespace bookspin::render
