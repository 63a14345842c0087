#include "analysis/scenario_file.hpp"

namespace bookspin::analysis {

namespace {

JsonValue vector_json(const Eigen::Vector3d& v) { return {JsonArray{{v.x()}, {v.y()}, {v.z()}}}; }

}  // namespace

JsonValue scenario_json(const Scenario& s) {
  // q0 is the identity, so ω0 in the world frame is ω0 in the body frame.
  const Eigen::Vector3d omega0 = start_omega(s);
  JsonObject units{{"time", {std::string("time unit (any: the motion scales with 1/time)")}},
                   {"length", {std::string("length unit")}},
                   {"mass", {std::string("mass unit")}},
                   {"angle", {std::string("radian")}},
                   {"angular_velocity", {std::string("rad per time unit")}},
                   {"moments", {std::string("mass * length^2")}}};
  JsonObject object{
      {"scenario", {s.name}},
      {"units", {std::move(units), true}},
      {"mass", {s.body.cage.mass}},
      {"principal_moments", vector_json(s.body.moments)},
      {"principal_axes", {std::string("body x, y, z (the moments are about these axes)")}},
      {"q0", {JsonArray{{1.0}, {0.0}, {0.0}, {0.0}}}},
      {"q_convention", {std::string("w, x, y, z; body to world")}},
      {"omega0_body", vector_json(omega0)},
      {"omega0_world", vector_json(omega0)},
      {"dt", {JsonNumber{s.dt, NumberStyle::shortest}}},
      {"steps", {static_cast<std::int64_t>(s.steps)}},
      {"gravity", {std::string("none; no damping, no contacts")}},
      {"exact_motion", {s.name + "-exact.csv"}},
  };
  return {std::move(object), true};
}

std::string scenario_file(const Scenario& scenario) {
  const JsonValue json = scenario_json(scenario);
  return json_text(json, "flipcheck scenario", JsonLayout::indented) + "\n";
}

}  // namespace bookspin::analysis
