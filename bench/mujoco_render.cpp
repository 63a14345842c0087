#include "bench/mujoco_render.hpp"

#include <stdexcept>
#include <string>

#include "bench/mujoco.hpp"

#ifdef BOOKSPIN_HAVE_MUJOCO
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>
#endif

namespace bookspin::bench {

#ifndef BOOKSPIN_HAVE_MUJOCO

struct MujocoRenderer::Impl {};
MujocoRenderer::MujocoRenderer(const MujocoRenderSetup&) {
  throw std::runtime_error("MuJoCo was not found when bookspin was built");
}
MujocoRenderer::~MujocoRenderer() = default;
void MujocoRenderer::draw(const Eigen::Matrix3d&, const Eigen::Vector3d&) {}
RgbaImage MujocoRenderer::read_back() { return {}; }

#else

namespace {

/// bookspin's world (+y up) → MuJoCo's (+z up): (x, y, z) → (x, −z, y), a proper rotation.
Eigen::Matrix3d to_mujoco() {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  return m;
}

std::string model_xml(const MujocoRenderSetup& s) {
  const Eigen::Vector3d half = 0.5 * s.book_size;
  char xml[2048];
  std::snprintf(xml, sizeof xml,
                "<mujoco model=\"book\">\n"
                "  <option gravity=\"0 0 0\"><flag contact=\"disable\"/></option>\n"
                "  <visual>\n"
                "    <global offwidth=\"%d\" offheight=\"%d\" fovy=\"%.9g\"/>\n"
                "    <quality offsamples=\"%d\" shadowsize=\"0\"/>\n"
                "    <headlight ambient=\"0.3 0.3 0.3\" diffuse=\"0.7 0.7 0.7\"/>\n"
                "    <rgba haze=\"0.15 0.17 0.2 1\"/>\n"
                "  </visual>\n"
                "  <asset>\n"
                "    <texture name=\"cover\" type=\"cube\" builtin=\"checker\" width=\"512\"\n"
                "             height=\"512\" rgb1=\"0.55 0.12 0.1\" rgb2=\"0.9 0.85 0.75\"/>\n"
                "    <material name=\"cover\" texture=\"cover\"/>\n"
                "  </asset>\n"
                "  <worldbody>\n"
                "    <body name=\"book\">\n"
                "      <freejoint/>\n"
                "      <geom type=\"box\" size=\"%.9g %.9g %.9g\" material=\"cover\"/>\n"
                "    </body>\n"
                "  </worldbody>\n"
                "</mujoco>\n",
                s.width, s.height, s.fov_y_deg, s.msaa, half.x(), half.y(), half.z());
  return xml;
}

std::string egl_error(const char* what) {
  char text[96];
  std::snprintf(text, sizeof text, "%s failed (EGL error 0x%04x)", what, eglGetError());
  return text;
}

}  // namespace

struct MujocoRenderer::Impl {
  MujocoRenderSetup setup;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  mjModel* model = nullptr;
  mjData* data = nullptr;
  mjvScene scene;
  mjvCamera camera;
  mjvOption option;
  mjrContext gl;
  bool scene_made = false, gl_made = false;
  std::vector<unsigned char> rgb;

  ~Impl() {
    if (gl_made) mjr_freeContext(&gl);
    if (scene_made) mjv_freeScene(&scene);
    if (data) mj_deleteData(data);
    if (model) mj_deleteModel(model);
    if (context != EGL_NO_CONTEXT) {
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display, context);
    }
    // No eglTerminate: the display is shared with bookspin's renderers in this process.
  }

  void make_context() {
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_platform_display)
      display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
      throw std::runtime_error(egl_error("MuJoCo renderer: eglInitialize"));
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(egl_error("eglBindAPI"));
    // No surface is ever drawn to (MuJoCo draws into its own framebuffer object), so no
    // config where EGL_KHR_no_config_context allows it, as bookspin's renderer does.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!extensions || !std::strstr(extensions, "EGL_KHR_no_config_context")) {
      const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint count = 0;
      if (!eglChooseConfig(display, attributes, &config, 1, &count) || count < 1)
        throw std::runtime_error(egl_error("MuJoCo renderer: eglChooseConfig"));
    }
    context = eglCreateContext(display, config, EGL_NO_CONTEXT, nullptr);  // compatibility
    if (context == EGL_NO_CONTEXT)
      throw std::runtime_error(egl_error("MuJoCo renderer: eglCreateContext"));
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
      throw std::runtime_error(egl_error("MuJoCo renderer: eglMakeCurrent"));
  }
};

MujocoRenderer::MujocoRenderer(const MujocoRenderSetup& setup) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.setup = setup;
  m.make_context();
  m.model = load_mjcf(model_xml(setup), "book-render.xml", "the render model");
  m.data = mj_makeData(m.model);
  if (m.data == nullptr) throw std::runtime_error("MuJoCo: cannot allocate mjData");
  mjv_defaultScene(&m.scene);
  mjv_makeScene(m.model, &m.scene, 100);
  m.scene_made = true;
  mjv_defaultOption(&m.option);
  mjr_defaultContext(&m.gl);
  mjr_makeContext(m.model, &m.gl, mjFONTSCALE_100);
  m.gl_made = true;
  mjr_setBuffer(mjFB_OFFSCREEN, &m.gl);
  if (m.gl.currentBuffer != mjFB_OFFSCREEN || m.gl.offWidth < setup.width ||
      m.gl.offHeight < setup.height)
    throw std::runtime_error("MuJoCo renderer: no off-screen buffer of the frame's size");
  // The free camera at bookspin's eye and target: MuJoCo puts it at lookat − distance ·
  // (cos e cos a, cos e sin a, sin e) for azimuth a and elevation e.
  const Eigen::Vector3d lookat = to_mujoco() * setup.target;
  const Eigen::Vector3d back = to_mujoco() * (setup.eye - setup.target);
  const Eigen::Vector3d forward = -back.normalized();
  mjv_defaultCamera(&m.camera);
  m.camera.type = mjCAMERA_FREE;
  for (int i = 0; i < 3; ++i) m.camera.lookat[i] = lookat[i];
  m.camera.distance = back.norm();
  m.camera.azimuth = std::atan2(forward.y(), forward.x()) * 180.0 / M_PI;
  m.camera.elevation = std::asin(forward.z()) * 180.0 / M_PI;
  m.rgb.resize(3 * static_cast<std::size_t>(setup.width) * setup.height);
}

MujocoRenderer::~MujocoRenderer() = default;

void MujocoRenderer::draw(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& centre) {
  Impl& m = *impl_;
  // A free joint's qpos: position, then the body → world quaternion (w, x, y, z).
  const Eigen::Vector3d position = to_mujoco() * centre;
  const Eigen::Quaterniond q(to_mujoco() * rotation);
  for (int i = 0; i < 3; ++i) m.data->qpos[i] = position[i];
  m.data->qpos[3] = q.w();
  m.data->qpos[4] = q.x();
  m.data->qpos[5] = q.y();
  m.data->qpos[6] = q.z();
  mj_kinematics(m.model, m.data);
  mjv_updateScene(m.model, m.data, &m.option, nullptr, &m.camera, mjCAT_ALL, &m.scene);
  mjr_render(mjrRect{0, 0, m.setup.width, m.setup.height}, &m.scene, &m.gl);
}

RgbaImage MujocoRenderer::read_back() {
  Impl& m = *impl_;
  const int w = m.setup.width, h = m.setup.height;
  mjr_readPixels(m.rgb.data(), nullptr, mjrRect{0, 0, w, h}, &m.gl);
  RgbaImage image(w, h);
  for (int y = 0; y < h; ++y) {
    const unsigned char* source = m.rgb.data() + 3 * static_cast<std::size_t>(h - 1 - y) * w;
    std::uint8_t* out = image.row(y);
    for (int x = 0; x < w; ++x, source += 3, out += 4) {
      out[0] = source[0];
      out[1] = source[1];
      out[2] = source[2];
      out[3] = 255;
    }
  }
  return image;
}

#endif

}  // namespace bookspin::bench
