#pragma once
// A conformance scenario as the kit publishes it: the JSON file `flipcheck export` writes
// (docs/flipcheck.md, "export: what an engine needs"), pure, which the explorer page and the
// npm package compile; its SHA-256, a judgement's `scenario_sha256`, is conformance.hpp's.
#include <string>

#include "analysis/judgement.hpp"
#include "common/json_writer.hpp"

namespace bookspin::analysis {

/// The scenario file's JSON: units, mass, principal moments (body x, y, z), q0 (identity), ω0
/// in the body and the world frame (start_omega, rad per time unit), dt, steps, and the name of
/// its exact motion's CSV.
JsonValue scenario_json(const Scenario& scenario);

/// The bytes of OUT/<scenario>.json: scenario_json indented, a newline at the end. No I/O.
std::string scenario_file(const Scenario& scenario);

}  // namespace bookspin::analysis
