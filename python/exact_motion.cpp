// bookspin.exact_motion: the exact torque-free motion at given times (docs/physics.md §8), the
// rows jobs::exact_motion_at makes, which are the exact model's and flipcheck export's.
#include "jobs/exact_motion.hpp"

#include "bindings.hpp"

namespace bookspin::python {

namespace {

const char* kDoc = R"(exact_motion(moments, omega0, t) -> dict[str, numpy.ndarray]

The exact torque-free motion of a rigid body (Jacobi elliptic functions and the precession
about L in closed form; docs/physics.md §8), evaluated at every time of t. The body starts at
the identity orientation (body frame = world frame at t = 0) with body-frame angular velocity
omega0; no jiggle is added. The same numbers as the exact model's (model.kind = "exact") and
as `bookspin flipcheck export`'s CSV (physics::ExactRotation::state).

Arguments (float64, or anything numpy turns into it):
  moments  (3,)  principal moments of inertia about body x, y, z, mass * length^2, each > 0
  omega0   (3,)  angular velocity at t = 0, body frame, rad per time unit
  t        (N,)  times, time units, any order

Returns a dict of float64 arrays:
  q            (N, 4)  orientation R(t), body to world, as a unit quaternion w, x, y, z with
                       w >= 0 (v_world = q v_body q^-1)
  omega_body   (N, 3)  angular velocity, body frame, rad per time unit
  omega_world  (N, 3)  R(t) omega_body, world frame
  L_world      (N, 3)  angular momentum R(t) I_body omega_body, world frame (constant)
  E            (N,)    kinetic energy 1/2 omega . I_body omega (constant)

Raises bookspin.Error for a wrong shape, a complex array, a moment that is not finite and
positive, an omega0 or t that is not finite, an omega0 component beyond ±1e6, a motion whose
energy, |L| or largest |omega| overflows a double, or a t beyond the motion's time horizon (where its phase or
precession angle is more than a long double carries: docs/physics.md §8, "How far in time"),
each before any row; KeyboardInterrupt on Ctrl-C. The GIL is released while it computes.)";

py::dict exact_motion(const py::object& moments_arg, const py::object& omega0_arg,
                      const py::object& t_arg) {
  const Eigen::Vector3d moments = vector3_arg(moments_arg, "moments");
  const Eigen::Vector3d omega0 = vector3_arg(omega0_arg, "omega0");
  const std::vector<double> t = vector_arg(t_arg, "t", -1);
  // The rows go straight into the arrays (no vector of rows to copy: docs/performance-physics.md,
  // "The exact motion per row").
  ExactArrays arrays(t.size(), false);
  {
    const StopPoll stop = python_stop();
    py::gil_scoped_release release;
    jobs::exact_motion_each(
        moments, omega0, t, stop,
        [&arrays](std::size_t i, const jobs::ExactMotionRow& row) { arrays.set(i, row); });
  }
  return arrays.dict();
}

}  // namespace

void add_exact_motion(py::module_& m) {
  m.def("exact_motion", &exact_motion, py::arg("moments"), py::arg("omega0"), py::arg("t"), kDoc);
}

}  // namespace bookspin::python
