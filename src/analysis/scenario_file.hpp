#pragma once
// A conformance scenario as the kit publishes it: the JSON file `flipcheck export` writes
// (docs/flipcheck.md, "export: what an engine needs"), pure, which the explorer page and the
// npm package compile; its SHA-256, a judgement's `scenario_sha256`, is conformance.hpp's.
#include <string>
#include <string_view>

#include "analysis/judgement.hpp"
#include "common/json_writer.hpp"

namespace bookspin::analysis {

/// The scenario file's JSON: units, mass, principal moments (body x, y, z), q0 (identity), ω0
/// in the body and the world frame (start_omega, rad per time unit), dt, steps, and the name of
/// its exact motion's CSV.
JsonValue scenario_json(const Scenario& scenario);

/// The bytes of OUT/<scenario>.json: scenario_json indented, a newline at the end. No I/O.
std::string scenario_file(const Scenario& scenario);

/// The scenario of a scenario file's JSON `text` (what scenario_file() writes, edited or not),
/// `file` naming it in messages: the one reader of `bookspin flipcheck judge OUT/<scenario>.json`,
/// Python's and the npm package's (npm/flipcheck_bindings.cpp, handed a file's text or an
/// object written as JSON), so that every door refuses in the same words. Strings are read by
/// common's read_json_string; of a key given twice the last counts. Every field is taken as
/// written or refused by name: `scenario` (a name), `mass`, `principal_moments`,
/// `omega0_body` (or `omega0_world` alone), `dt` and `steps` (a whole number) as check_scenario()
/// allows them; `q0`, where given, the identity (either sign); `omega0_world` beside
/// `omega0_body` equal to it (to 1e-12 relative); other fields are ignored. The start is
/// omega0_body, the jiggle already in it. Throws InputError "FILE: NUL byte at line L (not a
/// text file: a binary file, or text saved as UTF-16)" (common's nul_byte_problem, as a scene
/// or a recording), "FILE: not valid JSON: … at line L, column C", "FILE: nested more than 64
/// deep at line L, column C" (the npm package's words for an object, at its key path), "FILE:
/// holds JSON null, not a scenario (…)" for a JSON value that is no object, and "NAME: FIELD:
/// reason" for a field.
Scenario scenario_from_json(std::string_view text, const std::string& file);

}  // namespace bookspin::analysis
