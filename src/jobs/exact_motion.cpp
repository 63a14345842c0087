#include "jobs/exact_motion.hpp"

#include <Eigen/Geometry>

#include "physics/exact_solution.hpp"

namespace bookspin::jobs {

ExactMotion exact_motion(const analysis::Scenario& scenario, const StopPoll& stop) {
  ExactMotion motion;
  motion.scenario = scenario;
  motion.mass = scenario.body.cage.mass;
  motion.omega0_body = analysis::start_omega(scenario);
  motion.omega0_world = motion.omega0_body;
  const Eigen::Vector3d& moments = scenario.body.moments;
  const physics::ExactRotation exact(moments, motion.omega0_body);
  motion.rows.reserve(static_cast<std::size_t>(scenario.steps) + 1);
  for (long long n = 0; n <= scenario.steps; ++n) {
    if (n % 4096 == 0) stop_if_asked(stop, "flipcheck exact motion");
    ExactMotionRow row;
    row.t = static_cast<double>(n) * scenario.dt;
    const Eigen::Matrix3d R = exact.orientation(row.t);
    Eigen::Quaterniond q(R);
    q.normalize();
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();
    row.q = Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
    row.omega_body = exact.omega_body(row.t);
    row.omega_world = R * row.omega_body;
    row.L = R * moments.cwiseProduct(row.omega_body);
    row.E = 0.5 * row.omega_body.dot(moments.cwiseProduct(row.omega_body));
    motion.rows.push_back(row);
  }
  return motion;
}

}  // namespace bookspin::jobs
