#pragma once
// One conformance scenario's export as a value (`bookspin flipcheck export`, docs/flipcheck.md):
// the scenario made from its scene once, its exact motion at every step and the bytes of the
// two files the product only writes.
#include "common/stop.hpp"
#include "jobs/exact_motion.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

/// The two files `flipcheck export` writes for `scene` (OUT/<scenario>.json and
/// OUT/<scenario>-exact.csv, export_files): its scenario (analysis::scenario_of), the exact
/// motion from its jiggled start at every step (exact_motion), freed once spelled. `stop` is
/// polled every few thousand rows and throws Interrupted. Throws InputError, naming the
/// scenario, where the motion overflows a double or dt × steps is beyond its time horizon.
ExportFiles scenario_export(const scene::Scene& scene, const StopPoll& stop = {});

}  // namespace bookspin::jobs
