#pragma once
// The diagnostics CSV sink (issue 2 §7): one row per frame, columns fixed.
#include <string>

#include "physics/simulator.hpp"

namespace bookspin::video {

/// The header line (no newline): frame,t,omega_x,…,quaternion_norm.
const std::string& diagnostics_csv_header();

/// One row (no newline) for `frame`; numbers in shortest round-trip form (std::to_chars), so
/// the same state always gives the same bytes. Frames: omega body, L world (physics.md §9).
std::string diagnostics_csv_row(int frame, const physics::Diagnostics& d);

}  // namespace bookspin::video
