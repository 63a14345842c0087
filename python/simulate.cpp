// bookspin.simulate: a scene's run as `bookspin simulate` writes it (docs/outputs.md, "Output
// files"): every column of the diagnostics CSV, from jobs::diagnostics_table.
#include "analysis/frame_source.hpp"
#include "bindings.hpp"
#include "jobs/simulation.hpp"

namespace bookspin::python {

namespace {

const char* kDoc = R"(simulate(scene, overrides=None) -> dict[str, numpy.ndarray]

Runs a scene's physics without rendering, as `bookspin simulate SCENE --csv F` does, and
returns every column of its diagnostics CSV (docs/physics.md §9, docs/outputs.md), in the
CSV's order, each a float64 array of shape (N,), one value per frame (frame 0 = the start):
  frame, t (time units), omega_x..omega_z (body frame, rad per time unit), L_x..L_z (world
  frame), energy_kinetic, energy_potential, energy_total, cos_x_L..cos_z_L, strain_max,
  orthogonality_error, quaternion_norm, cos_smallest_L, cos_intermediate_L, cos_largest_L,
  q_w..q_z (R body to world, w >= 0), com_x..com_z (world).
The very numbers of the CSV; NaN where the CSV has an empty cell (the cosines with L for a
body at rest). A run that diverges stops at its last finite frame, with a UserWarning, as the
command line warns.

Arguments:
  scene      a path (str or os.PathLike) to a TOML scene, or the TOML text itself (a str
             holding a newline or '=' that names no file; "scene-text.toml" in
             messages, its scene name scene-text unless scene.name gives one)
  overrides  a dict {"time.frames": 120, "model.kind": "exact", ...}, each applied as
             `--set KEY=VALUE` (the value spelled in TOML: bool, int, float, str, list)

Raises bookspin.Error with the command line's one line for a bad scene or override and for a
comparison scene ([[compare]]); KeyboardInterrupt on Ctrl-C. The GIL is released while it
runs.)";

py::dict simulate(const py::object& scene_input, const py::object& overrides) {
  const scene::Scene scene = scene_arg(scene_input, overrides);
  for (const std::string& warning : scene.warnings) warn(warning);
  jobs::require_one_run(scene);
  jobs::DiagnosticsTable table;
  {
    const StopPoll stop = python_stop();
    py::gil_scoped_release release;
    table = jobs::diagnostics_table(scene, stop);
  }
  py::dict out;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const std::vector<double>& values = table.values[c];
    py::array_t<double> column = new_array(values.size());
    std::copy(values.begin(), values.end(), column.mutable_data());
    out[py::str(table.columns[c])] = column;
  }
  if (table.result.diverged_at) {
    warn(analysis::divergence_warning(
        scene.name + ": simulation", *table.result.diverged_at, table.result.divergence_reason,
        "kept the " + std::to_string(table.result.rows) + " rows before it"));
  }
  return out;
}

}  // namespace

void add_simulate(py::module_& m) {
  m.def("simulate", &simulate, py::arg("scene"), py::arg("overrides") = py::none(), kDoc);
}

}  // namespace bookspin::python
