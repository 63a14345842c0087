#include "app/bench_mujoco.hpp"

#include <stdexcept>

#ifdef BOOKSPIN_HAVE_MUJOCO
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>

#include "analysis/accuracy.hpp"
#include "app/bench_clock.hpp"
#endif

namespace bookspin::app {

#ifndef BOOKSPIN_HAVE_MUJOCO

std::string mujoco_missing() {
  return "MuJoCo was not found when bookspin was built (install libmujoco-dev and re-run CMake)";
}

MujocoResult run_mujoco(const MujocoSetup&, const physics::ExactRotation&, long, long, int) {
  throw std::runtime_error(mujoco_missing());
}

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

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

ModelPtr load_model(const std::string& xml) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  const char* name = "book.xml";
  if (mj_makeEmptyFileVFS(&vfs, name, static_cast<int>(xml.size())) != 0)
    throw std::runtime_error("MuJoCo: cannot create a virtual file");
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, name)], xml.data(), xml.size());
  char error[1000] = "";
  ModelPtr model(mj_loadXML(name, &vfs, error, sizeof error));
  mj_deleteVFS(&vfs);
  if (!model) throw std::runtime_error(std::string("MuJoCo rejected the book model: ") + error);
  return model;
}

// A free joint's qpos is position then the body's quaternion (w, x, y, z), body → world;
// its qvel is the linear velocity then the angular velocity in the body frame, which at
// t = 0 (identity orientation) is also the world frame.
void reset(const mjModel* model, mjData* data, const Eigen::Vector3d& omega0) {
  mj_resetData(model, data);
  for (int i = 0; i < 3; ++i) data->qvel[3 + i] = omega0[i];
}

Eigen::Matrix3d orientation(const mjData* data) {
  const mjtNum* q = data->qpos + 3;
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
}

}  // namespace

std::string mujoco_missing() { return {}; }

MujocoResult run_mujoco(const MujocoSetup& setup, const physics::ExactRotation& exact,
                        long error_steps, long timing_steps, int repetitions) {
  const ModelPtr model = load_model(model_xml(setup));
  const DataPtr data(mj_makeData(model.get()));
  MujocoResult result;
  for (int i = 0; i < 3; ++i) result.moments[i] = model->body_inertia[3 + i];  // body 1
  std::sort(result.moments.data(), result.moments.data() + 3);
  reset(model.get(), data.get(), setup.omega0_body);
  for (long i = 0; i < error_steps; ++i) mj_step(model.get(), data.get());
  result.orientation_error = analysis::rotation_angle_between(
      exact.orientation(static_cast<double>(error_steps) * setup.dt), orientation(data.get()));
  result.ns_per_step = best_ns_per_step(
      timing_steps, repetitions, [&] { reset(model.get(), data.get(), setup.omega0_body); },
      [&](long steps) {
        for (long i = 0; i < steps; ++i) mj_step(model.get(), data.get());
      });
  return result;
}

#endif

}  // namespace bookspin::app
