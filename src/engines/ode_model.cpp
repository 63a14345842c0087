#include "engines/ode_model.hpp"

#include <mutex>
#include <new>

namespace bookspin::engines {

namespace {

// dInitODE2 once per process; each thread that creates a world gets ODE's per-thread data.
void init_ode_for_this_thread() {
  static std::once_flag once;
  std::call_once(once, [] { dInitODE2(0); });
  dAllocateODEDataForThread(dAllocateMaskAll);
}

}  // namespace

OdeModel::OdeModel(const physics::Body& body, physics::Integrator integrator)
    : EngineBody(body), integrator_(integrator) {
  init_ode_for_this_thread();
  // Each world its own stepping implementation: ODE's global default one is not safe from two
  // threads at once (ode/objects.h, dWorldSetStepThreadingImplementation), and sweeps and
  // accuracy runs step one model per thread.
  threading_ = dThreadingAllocateSelfThreadedImplementation();
  if (threading_ == nullptr) throw std::bad_alloc();
  world_ = dWorldCreate();
  dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(threading_),
                                       threading_);
  dWorldSetGravity(world_, 0, 0, 0);
  body_id_ = dBodyCreate(world_);
  dMass mass;
  const Eigen::Vector3d& I = body.moments;
  dMassSetParameters(&mass, body.cage.mass, 0, 0, 0, I.x(), I.y(), I.z(), 0, 0, 0);
  dBodySetMass(body_id_, &mass);
  dBodySetGyroscopicMode(body_id_, integrator == physics::Integrator::none ? 0 : 1);
  reset(physics::InitialState{});
}

OdeModel::~OdeModel() {
  dWorldDestroy(world_);  // destroys the body too
  dThreadingFreeImplementation(threading_);
}

void OdeModel::reset(const physics::InitialState& initial) {
  dBodySetPosition(body_id_, 0, 0, 0);
  const dQuaternion identity = {1, 0, 0, 0};
  dBodySetQuaternion(body_id_, identity);
  dBodySetLinearVel(body_id_, 0, 0, 0);
  const Eigen::Vector3d omega = initial_omega(initial);  // world = body frame at reset
  dBodySetAngularVel(body_id_, omega.x(), omega.y(), omega.z());
  t_ = 0.0;
}

void OdeModel::step(double dt) {
  if (integrator_ == physics::Integrator::quickstep)
    dWorldQuickStep(world_, dt);
  else
    dWorldStep(world_, dt);
  t_ += dt;
}

Eigen::Quaterniond OdeModel::engine_quaternion() const {
  const dReal* q = dBodyGetQuaternion(body_id_);
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

// ODE keeps ω in the world frame: ω_body = Rᵀ ω_world (dBodyVectorFromWorld).
Eigen::Vector3d OdeModel::engine_omega_body() const {
  const dReal* w = dBodyGetAngularVel(body_id_);
  dVector3 body;
  dBodyVectorFromWorld(body_id_, w[0], w[1], w[2], body);
  return Eigen::Vector3d(body[0], body[1], body[2]);
}

}  // namespace bookspin::engines
