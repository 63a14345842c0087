#include "bench/mujoco.hpp"

#include <algorithm>
#include <stdexcept>

#ifdef BOOKSPIN_HAVE_MUJOCO
#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <cstring>
#endif

namespace bookspin::bench {

#ifndef BOOKSPIN_HAVE_MUJOCO

std::string mujoco_missing() {
  return "MuJoCo was not found when bookspin was built (install libmujoco-dev and re-run CMake)";
}

struct MujocoBook::Impl {};
MujocoBook::MujocoBook(const MujocoSetup&) { throw std::runtime_error(mujoco_missing()); }
MujocoBook::~MujocoBook() = default;
void MujocoBook::reset() {}
void MujocoBook::step(long) {}
Eigen::Matrix3d MujocoBook::orientation() const { return Eigen::Matrix3d::Identity(); }
Eigen::Vector3d MujocoBook::sorted_moments() const { return Eigen::Vector3d::Zero(); }

#else

namespace {

// Gravity off and contacts off: a torque-free rigid body, like bookspin's models.
std::string model_xml(const MujocoSetup& s) {
  char xml[1024];
  const Eigen::Vector3d half = 0.5 * s.book.size;
  std::snprintf(xml, sizeof xml,
                "<mujoco model=\"book\">\n"
                "  <option timestep=\"%.17g\" gravity=\"0 0 0\" integrator=\"%s\">\n"
                "    <flag contact=\"disable\"/>\n"
                "  </option>\n"
                "  <worldbody>\n"
                "    <body name=\"book\">\n"
                "      <freejoint/>\n"
                "      <geom type=\"box\" size=\"%.17g %.17g %.17g\" mass=\"%.17g\"/>\n"
                "    </body>\n"
                "  </worldbody>\n"
                "</mujoco>\n",
                s.dt, s.rk4 ? "RK4" : "Euler", half.x(), half.y(), half.z(), s.book.mass);
  return xml;
}

}  // namespace

std::string mujoco_missing() { return {}; }

struct MujocoBook::Impl {
  mjModel* model = nullptr;
  mjData* data = nullptr;
  Eigen::Vector3d omega0;
  ~Impl() {
    if (data) mj_deleteData(data);
    if (model) mj_deleteModel(model);
  }
};

MujocoBook::MujocoBook(const MujocoSetup& setup) : impl_(std::make_unique<Impl>()) {
  impl_->model = load_mjcf(model_xml(setup), "book.xml", "the book model");
  impl_->data = mj_makeData(impl_->model);
  if (impl_->data == nullptr) throw std::runtime_error("MuJoCo: cannot allocate mjData");
  impl_->omega0 = setup.omega0_body;
  reset();
}

MujocoBook::~MujocoBook() = default;

// A free joint's qpos is the position, then the body's quaternion (w, x, y, z), body →
// world; its qvel is the linear velocity, then the angular velocity in the body frame,
// which at t = 0 (identity orientation) is also the world frame.
void MujocoBook::reset() {
  mj_resetData(impl_->model, impl_->data);
  for (int i = 0; i < 3; ++i) impl_->data->qvel[3 + i] = impl_->omega0[i];
}

void MujocoBook::step(long steps) {
  for (long i = 0; i < steps; ++i) mj_step(impl_->model, impl_->data);
}

Eigen::Matrix3d MujocoBook::orientation() const {
  const mjtNum* q = impl_->data->qpos + 3;
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
}

Eigen::Vector3d MujocoBook::sorted_moments() const {
  Eigen::Vector3d moments(impl_->model->body_inertia + 3);  // body 1; body 0 is the world
  std::sort(moments.data(), moments.data() + 3);
  return moments;
}

#endif

}  // namespace bookspin::bench
