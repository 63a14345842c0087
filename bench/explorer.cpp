// Bench section: ns per step of the explorer page's methods (docs/explorer.md), natively, for
// bench/explorer_bench.py to set beside the same runs in WebAssembly. The loop is the page's:
// web/bindings.cpp's Session::step, a step, a finiteness check, then the flip detector fed
// the step's flip signal (analysis::flip_signal of the simulator), on the scene's body,
// initial state, dt and model settings, normalization on (every model but exact). The exact
// model, which the page evaluates once per call (its flips are its closed form's), is timed per
// evaluation: here each step() is one, in the page each call of one step (explorer.nsPerStep).
#include <chrono>
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "analysis/motion.hpp"
#include "bench/sections.hpp"
#include "physics/simulator.hpp"
#include "scene/scene.hpp"

namespace bookspin::bench {

namespace {

/// Wall-clock seconds: the page's performance.now() is wall time too.
double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

void bench_explorer(const BenchContext& c) {
  const scene::Scene scene = scene::parse_scene(c.options.scene_path);
  std::vector<analysis::Method> methods = analysis::all_methods();
  methods.push_back({physics::ModelKind::exact, physics::Integrator::euler});
  const long steps = c.options.explorer_steps;
  for (const analysis::Method& m : methods) {
    physics::ModelConfig config = scene.model;
    config.kind = m.kind;
    config.integrator = m.integrator;
    config.normalize = true;
    auto sim = physics::make_simulator(scene.body, config);
    double best = 0.0;
    long done = 0;
    const bool exact = m.kind == physics::ModelKind::exact;
    for (int r = 0; r < c.options.rounds; ++r) {
      sim->reset(scene.initial);
      analysis::FlipDetector flips;
      const double start = wall_seconds();
      long i = 0;
      while (i < steps) {
        sim->step(scene.dt);
        ++i;
        if (!sim->finite()) break;
        // The exact model: one evaluation per step here, as the page's one per call.
        if (!exact)
          flips.observe(static_cast<double>(i) * scene.dt,
                        analysis::flip_signal(*sim, scene.body.moments));
      }
      const double ns = (wall_seconds() - start) * 1e9 / static_cast<double>(i);
      if (r == 0 || ns < best) best = ns;
      done = i;
    }
    volatile double keep = sim->corners()(0, 0);  // the steps' result stays observable
    (void)keep;
    std::string name = std::string(physics::to_string(m.kind));
    if (m.kind != physics::ModelKind::exact) {
      name += ' ';
      name += physics::to_string(m.integrator);
    }
    c.report->add({"explorer", name, best, "ns/step",
                   std::to_string(done) + " steps of dt " + std::to_string(scene.dt) +
                       ", best of " + std::to_string(c.options.rounds) + ", wall time"});
  }
}

}  // namespace bookspin::bench
