#include "scene/model_line.hpp"

#include <cstdio>

namespace bookspin::scene {

namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

std::string model_line(const Scene& scene) {
  const auto& m = scene.model;
  std::string line = std::string(physics::to_string(m.kind));
  if (m.kind != physics::ModelKind::exact) {
    line += ", " + std::string(physics::to_string(m.integrator));
    line += format(", dt = %.4g", scene.dt);
    if (!physics::is_engine(m.kind))  // the engines have no such switch (docs/engines.md)
      line += m.normalize ? ", normalized" : ", not normalized";
  }
  if (m.drag.law != physics::DragLaw::none)
    line += ", " + std::string(physics::to_string(m.drag.law)) + " drag" +
            format(" %.3g/time unit", m.drag.rate);
  if (m.kind == physics::ModelKind::particle) {
    line += m.damping ? ", damped" : ", undamped";
    line += format(", k = %g", m.spring_constant);
  }
  return line;
}

}  // namespace bookspin::scene
