#include "engines/mujoco_model.hpp"

#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>

#include "common/errors.hpp"

namespace bookspin::engines {

namespace {

// MuJoCo prints a warning and resets mjData when the state turns bad (NaN or huge qpos, qvel,
// qacc); bookspin ends the run there instead (finite() false, divergence_reason()), so the
// warning is kept quiet and read from mjData's warning counters.
void quiet_warning(const char*) {}

std::mutex& mujoco_loader_mutex() {
  static std::mutex mutex;
  return mutex;
}

std::string model_xml(const physics::Body& body, physics::Integrator integrator) {
  char xml[1024];
  const Eigen::Vector3d& I = body.moments;
  std::snprintf(xml, sizeof xml,
                "<mujoco model=\"bookspin\">\n"
                "  <option gravity=\"0 0 0\" integrator=\"%s\">\n"
                "    <flag contact=\"disable\"/>\n"
                "  </option>\n"
                "  <worldbody>\n"
                "    <body name=\"body\">\n"
                "      <freejoint/>\n"
                "      <inertial pos=\"0 0 0\" mass=\"%.17g\" diaginertia=\"%.17g %.17g %.17g\"/>\n"
                "    </body>\n"
                "  </worldbody>\n"
                "</mujoco>\n",
                mujoco_integrator_name(integrator), body.cage.mass, I.x(), I.y(), I.z());
  return xml;
}

}  // namespace

const char* mujoco_integrator_name(physics::Integrator integrator) {
  switch (integrator) {
    case physics::Integrator::rk4:
      return "RK4";
    case physics::Integrator::implicit:
      return "implicit";
    default:
      return "Euler";
  }
}

mjModel* load_mjcf(const std::string& xml, const char* file_name, const char* what) {
  const std::lock_guard<std::mutex> lock(mujoco_loader_mutex());
  mju_user_warning = quiet_warning;
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  if (mj_makeEmptyFileVFS(&vfs, file_name, static_cast<int>(xml.size())) != 0)
    throw std::runtime_error("MuJoCo: cannot create a virtual file");
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, file_name)], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* model = mj_loadXML(file_name, &vfs, error, sizeof error);
  mj_deleteVFS(&vfs);
  if (model == nullptr) {
    // MuJoCo's message spans lines (the error, then the element and line of the XML): one
    // line, its parts joined by "; ".
    std::string message;
    for (const char* c = error; *c != '\0'; ++c) {
      if (*c != '\n') {
        message += *c;
      } else if (!message.empty() && c[1] != '\0') {
        message += "; ";
      }
    }
    throw std::runtime_error(std::string("MuJoCo rejected ") + what + ": " + message);
  }
  return model;
}

MujocoModel::MujocoModel(const physics::Body& body, physics::Integrator integrator)
    : EngineBody(body) {
  // A body MuJoCo's compiler refuses (a mass or moment at most its mjMINVAL, 1e-15; moments
  // that break A + B >= C) is bad input, not a bug: the scene reader refuses the known limits
  // first (scenes/README.md, "Engine limits"), and anything else MuJoCo says is passed on as
  // one line naming the body, never as an internal error.
  try {
    model_ = load_mjcf(model_xml(body, integrator), "bookspin.xml", "the body's model");
  } catch (const std::runtime_error& e) {
    char numbers[160];
    std::snprintf(numbers, sizeof numbers,
                  "mass %.6g, principal moments %.6g, %.6g, %.6g; MuJoCo needs each above its "
                  "mjMINVAL, 1e-15",
                  body.cage.mass, body.moments.x(), body.moments.y(), body.moments.z());
    throw InputError(std::string(e.what()) + " (this body: " + numbers + ")");
  }
  data_ = mj_makeData(model_);
  if (data_ == nullptr) {
    mj_deleteModel(model_);
    throw std::runtime_error("MuJoCo: cannot allocate mjData");
  }
  reset(physics::InitialState{});
}

MujocoModel::~MujocoModel() {
  mj_deleteData(data_);
  mj_deleteModel(model_);
}

void MujocoModel::reset(const physics::InitialState& initial) {
  mj_resetData(model_, data_);
  const Eigen::Vector3d omega = initial_omega(initial);
  for (int i = 0; i < 3; ++i) data_->qvel[3 + i] = omega[i];
  t_ = 0.0;
  failure_.clear();
}

void MujocoModel::step(double dt) {
  if (!failure_.empty()) return;  // the run has ended
  model_->opt.timestep = dt;
  mj_step(model_, data_);
  for (int w : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC}) {
    if (data_->warning[w].number == 0) continue;
    char reason[96];
    std::snprintf(reason, sizeof reason, "MuJoCo reset its state (a bad number) at t = %.6g", t_);
    failure_ = reason;
    return;
  }
  t_ += dt;
}

bool MujocoModel::finite() const { return failure_.empty() && EngineBody::finite(); }

Eigen::Quaterniond MujocoModel::engine_quaternion() const {
  const mjtNum* q = data_->qpos + 3;
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

Eigen::Vector3d MujocoModel::engine_omega_body() const {
  return Eigen::Vector3d(data_->qvel[3], data_->qvel[4], data_->qvel[5]);
}

}  // namespace bookspin::engines
