#pragma once
// The conformance kit's scenario of a scene file and bookspin's own methods run from its start
// (`bookspin flipcheck`, docs/flipcheck.md); the judgement itself, pure, is judgement.hpp's.
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "analysis/judgement.hpp"
#include "common/stop.hpp"
#include "physics/simulator.hpp"
#include "scene/scene.hpp"

namespace bookspin::analysis {

/// The scenario of a scene: its body and start, dt = time.dt and (frames − 1)·steps_per_frame
/// steps (a sweep's and `simulate`'s run). Throws InputError for a comparison scene and for a
/// body at rest (no ω0, no jiggle: every measure would divide by zero).
Scenario scenario_of(const scene::Scene& scene);

/// The SHA-256 (64 lowercase hex digits) of the scenario's file as `flipcheck export` writes it
/// (scenario_file.hpp, byte for byte OUT/<scenario>.json): a judgement's `scenario_sha256`, the
/// scenario's identity (docs/flipcheck.md, "Versions").
std::string scenario_sha256(const Scenario& scenario);

/// `method` (one of bookspin's models × integrators or an engine's mode, made by
/// engines::make_model() as the accuracy report makes it, with `model`'s other settings) run
/// from the scenario's start for its steps, a row every `stride` steps from step 0: q from
/// Simulator::orientation(), ω (body frame) from its diagnostics. A run whose state stops being
/// finite ends at its last finite row (judge_motion says where it ended). `stop` is asked every
/// row ("flipcheck steps"): a signal throws Interrupted. Throws InputError where the model
/// refuses the scenario's body.
std::vector<MotionSample> simulated_motion(const Scenario& scenario, const Method& method,
                                           const physics::ModelConfig& model, long long stride,
                                           const StopPoll& stop = {});

}  // namespace bookspin::analysis
