#pragma once
// A conformance kit's scenario by name and its exact motion as an engine writes it: the rows
// the judge's and the conformance tests hold a judgement to (docs/flipcheck.md).
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "analysis/conformance.hpp"
#include "analysis/judgement.hpp"
#include "physics/exact_solution.hpp"
#include "scene/scene.hpp"

namespace bookspin::analysis::scenario_rows {

/// The scenario of scenes/flipcheck/<name>.toml.
inline Scenario scenario(const std::string& name) {
  return scenario_of(
      scene::parse_scene(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/flipcheck/" + name + ".toml"));
}

/// The exact motion of `s` every `stride` steps (q from R(t), ω body), as an engine writes it.
inline std::vector<MotionSample> exact_rows(const Scenario& s, long long stride) {
  const physics::ExactRotation exact(s.body.moments, start_omega(s));
  std::vector<MotionSample> rows;
  for (long long n = 0; n <= s.steps; n += stride) {
    const double t = static_cast<double>(n) * s.dt;
    rows.push_back({n, Eigen::Quaterniond(exact.orientation(t)), exact.omega_body(t)});
  }
  return rows;
}

}  // namespace bookspin::analysis::scenario_rows
