// bookspin.flipcheck: the conformance kit (docs/flipcheck.md) from Python. Its scenarios are
// the scene files of a folder (the copy of scenes/flipcheck/ the module carries beside itself,
// bookspin-scenarios/, unless told another); export gives a scenario's start and its exact motion
// as jobs makes them for `bookspin flipcheck export`, judge the judgement analysis makes for
// `bookspin flipcheck judge`, of a motion given as arrays (jobs::motion_from_rows: the motion
// file's rules).
#include "products/flipcheck.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/conformance.hpp"
#include "analysis/judgement.hpp"
#include "analysis/scenario_file.hpp"
#include "bindings.hpp"
#include "common/errors.hpp"
#include "common/json_writer.hpp"
#include "common/text_file.hpp"
#include "common/text_lines.hpp"
#include "jobs/exact_motion.hpp"
#include "jobs/motion_csv.hpp"

namespace bookspin::python {

namespace {

namespace fs = std::filesystem;

/// The folder of scenarios: `directory`, or bookspin.flipcheck.scenario_dir.
fs::path scenario_dir(const py::object& directory) {
  py::object dir = directory;
  if (dir.is_none()) dir = py::module_::import("bookspin").attr("flipcheck").attr("scenario_dir");
  bool ok = false;
  const std::string text = path_arg(dir, ok, "directory");
  if (!ok) throw InputError("directory: expected a path (str or os.PathLike)");
  return text;
}

std::vector<std::string> scenario_names(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec))
    if (entry.path().extension() == ".toml" && entry.is_regular_file(ec))
      names.push_back(entry.path().stem().string());
  if (ec) throw InputError(dir.string() + ": cannot list the scenarios: " + ec.message());
  std::sort(names.begin(), names.end());
  return names;
}

/// A scenario by name (a file NAME.toml of the folder) or by path (os.PathLike, or a str that
/// ends in .toml, in any case, or holds a '/'), read as `bookspin flipcheck` reads it.
scene::Scene scenario_scene(const py::object& scenario, const py::object& directory) {
  bool ok = false;
  const std::string text = path_text(scenario, ok, "scenario");
  if (!ok) throw InputError("scenario: expected a name or a path, got a non-str");
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw InputError("scenario: holds a NUL byte at character " + std::to_string(nul + 1) +
                     " (a name or a path is one line of text)");
  const bool path = !py::isinstance<py::str>(scenario) || text.find('/') != std::string::npos ||
                    products::has_extension(text, ".toml");
  if (path) return scene::parse_scene(text);
  const fs::path dir = scenario_dir(directory);
  const fs::path file = dir / (text + ".toml");
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) {
    std::string known;
    for (const std::string& name : scenario_names(dir)) known += (known.empty() ? "" : ", ") + name;
    throw InputError("flipcheck: no scenario " + quoted_name(text) + " in " + dir.string() +
                     " (there: " + known + ")");
  }
  return scene::parse_scene(file);
}

/// The scenario a judgement is of: a name or a scene file (scenario_scene), or the scenario
/// JSON `bookspin flipcheck export` wrote (a path ending in .json, in any case), as the command
/// line reads it.
analysis::Scenario judged_scenario(const py::object& scenario, const py::object& directory) {
  bool ok = false;
  const std::string text = path_text(scenario, ok, "scenario");
  if (ok && text.find('\0') == std::string::npos && products::is_scenario_json(text))
    return analysis::scenario_from_json(read_text_file(text, "the scenario file"), text);
  return analysis::scenario_of(scenario_scene(scenario, directory));
}

/// The scenarios the module carries: the folder bookspin-scenarios/ beside the module's own
/// file (BUILD/python/ as CMake builds it, site-packages/ where pip installed the wheel), so
/// that it needs nothing from the source tree it was built from.
std::string carried_scenario_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&carried_scenario_dir), &info) == 0 ||
      info.dli_fname == nullptr)
    throw std::runtime_error("flipcheck: cannot find the module's own file (dladdr)");
  return (fs::path(info.dli_fname).parent_path() / "bookspin-scenarios").string();
}

/// Whether a judgement's verdict is a pass; otherwise AssertionError with its reasons.
const char* kAssertPassesDoc =
    R"(assert_passes(scenario, t, q, omega_world, directory=None, motion="motion") -> dict

judge(...) for a test suite (pytest): returns the judgement (judge's dict) when its verdict is
"pass", and otherwise raises AssertionError whose message is the line `bookspin flipcheck
judge` prints for the same motion, its reasons in words, the motion's name where the command
line names the file:
  book-intermediate-0.05 motion: FAIL (energy drift 0.484 at step 3000 (limit 0.01; past it
  from step 230); |L| drift 0.218 at step 3000 (limit 0.01; past it from step 246); L turned
  0.0304 rad at step 800 (limit 0.01; past it from step 229); orientation error 3.14 rad at
  step 1455 (limit 0.1; past it from step 241)): turn-overs 6/6, energy drift 0.484, ...
each failure with its value, its limit, the step where it is worst and the first step past the
limit (docs/flipcheck.md, "Thresholds").
Arguments as judge's; bad input raises bookspin.Error, as there.)";

const char* kScenariosDoc = R"(scenarios(directory=None) -> list[str]

The names of the conformance scenarios (docs/flipcheck.md, "The scenarios"): the stems of the
.toml files of `directory`, sorted. directory=None reads bookspin.flipcheck.scenario_dir, the
copy of scenes/flipcheck/ the module carries beside itself (set it to use another folder).)";

py::list scenarios(const py::object& directory) {
  py::list out;
  for (const std::string& name : scenario_names(scenario_dir(directory))) out.append(name);
  return out;
}

const char* kExportDoc =
    R"(export(scenario, directory=None) -> tuple[dict, dict[str, numpy.ndarray]]

What `bookspin flipcheck export SCENARIO` writes, as values: the scenario's JSON
(OUT/<scenario>.json: units, mass, principal_moments, q0, omega0_body, omega0_world, dt, steps,
...) as a dict, and its exact motion at every step n = 0 ... steps, t = n dt
(OUT/<scenario>-exact.csv), as float64 arrays:
  t            (N,)    time units, N = steps + 1
  q            (N, 4)  R(t) body to world, w, x, y, z, w >= 0
  omega_body   (N, 3)  rad per time unit, body frame
  omega_world  (N, 3)  world frame
  L_world      (N, 3)  angular momentum, world frame
  E            (N,)    kinetic energy
`scenario` is a name of scenarios() (looked up in `directory`, as there) or a path to a scene
file. Raises bookspin.Error for an unknown name or a bad scene file; KeyboardInterrupt on
Ctrl-C. The GIL is released while it computes.)";

py::tuple export_scenario(const py::object& scenario_input, const py::object& directory) {
  const scene::Scene scene = scenario_scene(scenario_input, directory);
  const analysis::Scenario scenario = analysis::scenario_of(scene);
  jobs::ExactMotion motion;
  {
    const StopPoll stop = python_stop();
    py::gil_scoped_release release;
    motion = jobs::exact_motion(scenario, stop);
  }
  const std::string json =
      json_text(analysis::scenario_json(motion.scenario), "flipcheck scenario");
  const py::object start = py::module_::import("json").attr("loads")(json);
  const py::dict arrays = exact_rows_arrays(motion.rows, true);
  return py::make_tuple(start, arrays);
}

const char* kJudgeDoc =
    R"(judge(scenario, t, q, omega_world, directory=None, motion="motion") -> dict

Judges a motion against the scenario's exact motion from the same start, as `bookspin
flipcheck judge SCENARIO MOTION.csv` judges the same motion written as a CSV
(docs/flipcheck.md, "What judge measures" and "The judgement CSV"). Returns the judgement
CSV's row as a dict, in its column order: scenario (str), motion (str: the `motion` argument,
where the command line puts the file's name), verdict ("pass" or "fail"), stride, last_step,
flips, flips_exact, stable_spin (int), start_error, energy_drift, L_drift, first_flip,
first_flip_exact, first_flip_error, orientation_error, tumble_time, separatrix_ratio_drift,
separatrix_approach (float, None where the CSV's cell is empty), failures (str, "; " between
reasons, "" for a pass), version (str: bookspin.__version__, the version that judged) and
scenario_sha256 (str: the SHA-256 of the scenario's JSON as `bookspin flipcheck export` writes
it).

Arguments (float64, or anything numpy turns into it):
  scenario     a name of scenarios(), a path to a scene file, or the scenario JSON `bookspin
               flipcheck export` wrote (a path ending in .json)
  t            (N,)    time units: 0, then every stride steps of the scenario's dt (to 1e-6 of
                       a step), none past its last step
  q            (N, 4)  orientation, body to world, w, x, y, z (any norm but 0, either sign)
  omega_world  (N, 3)  angular velocity, world frame, rad per time unit
Raises bookspin.Error for an unknown scenario, a wrong shape, a row the motion file's rules
refuse ("flipcheck.judge: t[3]: t = 0.013 is not a whole number of steps of dt = 0.01"), rows
too far apart to show the exact motion's turn-overs ("flipcheck.judge: rows every 1000 steps
... write a row at least every 62 steps"), and a `motion` that is not a str or holds a NUL or
a line break. The GIL is released while it judges; KeyboardInterrupt on Ctrl-C.)";

/// A judgement CSV cell as Python: a number (None for an empty cell), or its text (an int where
/// it is a whole number: the counts and the flag).
py::object cell_value(const std::string& column, const CsvCell& cell) {
  if (const CsvNumber* number = std::get_if<CsvNumber>(&cell))
    return number->value ? py::object(py::float_(*number->value)) : py::object(py::none());
  const std::string& text = std::get<std::string>(cell);
  const bool whole =
      column != "version" && column != "scenario_sha256" && !text.empty() &&
      std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (whole) return py::int_(std::stoll(text));
  return py::str(text);
}

/// A motion judged: the judgement CSV's row as a dict, and the verdict with its line
/// (analysis::verdict_line, what `bookspin flipcheck judge` prints for it).
struct Judged {
  py::dict row;
  bool pass = false;
  std::string line;
};

/// InputError for an array given as (columns, N), N = len(t) rows, where (N, columns) is meant
/// (matrix_arg would say "expected shape (4, 4)", the row count taken from its first axis).
void refuse_transposed(const py::object& value, const char* name, std::size_t columns,
                       std::size_t rows) {
  py::tuple shape;
  try {
    shape = py::module_::import("numpy").attr("shape")(value);
  } catch (const py::error_already_set& e) {
    // numpy's "inhomogeneous shape" ValueError names no argument: this one is named.
    if (!e.matches(PyExc_ValueError)) throw;
    throw InputError(std::string(name) + ": its rows are of different lengths (a ragged list): " +
                     "expected shape (" + std::to_string(rows) + ", " + std::to_string(columns) +
                     "), N = len(t) rows of " + std::to_string(columns) + " numbers each");
  }
  if (shape.size() != 2 || rows == columns) return;
  const auto first = shape[0].cast<std::size_t>(), second = shape[1].cast<std::size_t>();
  if (first == columns && second == rows)
    throw InputError(std::string(name) + ": expected shape (" + std::to_string(rows) + ", " +
                     std::to_string(columns) + "), N = len(t) rows, got (" + std::to_string(first) +
                     ", " + std::to_string(second) +
                     "): a row per time, its components across (give " + name + ".T)");
}

/// The `motion` argument: a name (str) of at most one line and no NUL, or InputError naming it.
std::string motion_name_of(const py::object& motion) {
  if (!py::isinstance<py::str>(motion))
    throw InputError("flipcheck.judge: motion: expected a name (str), got " +
                     std::string(py::str(py::type::of(motion).attr("__name__"))));
  const std::string name = unicode_arg(motion, "flipcheck.judge: motion");
  for (const char ch : name)
    if (ch == '\0' || ch == '\n' || ch == '\r')
      throw InputError(std::string("flipcheck.judge: motion: a name holds ") +
                       (ch == '\0' ? "a NUL byte" : "a line break") + ": give it on one line");
  return name;
}

Judged judged(const py::object& scenario_input, const py::object& t_arg, const py::object& q_arg,
              const py::object& omega_arg, const py::object& directory,
              const py::object& motion_arg) {
  const std::string motion_name = motion_name_of(motion_arg);
  const analysis::Scenario scenario = judged_scenario(scenario_input, directory);
  const std::vector<double> t = vector_arg(t_arg, "t", -1);
  refuse_transposed(q_arg, "q", 4, t.size());
  refuse_transposed(omega_arg, "omega_world", 3, t.size());
  const std::vector<double> q = matrix_arg(q_arg, "q", -1, 4);
  const std::vector<double> omega = matrix_arg(omega_arg, "omega_world", -1, 3);
  same_rows({{"t", t.size()}, {"q", q.size() / 4}, {"omega_world", omega.size() / 3}});
  CsvTable table;
  Judged out;
  {
    const StopPoll stop = python_stop();
    py::gil_scoped_release release;
    std::vector<std::array<double, 8>> rows(t.size());
    for (std::size_t i = 0; i < t.size(); ++i)
      rows[i] = {t[i],         q[4 * i],     q[4 * i + 1],     q[4 * i + 2],
                 q[4 * i + 3], omega[3 * i], omega[3 * i + 1], omega[3 * i + 2]};
    const jobs::MotionFile motion = jobs::motion_from_rows(
        rows, jobs::OmegaFrame::world, "flipcheck.judge", scenario.dt, scenario.steps);
    analysis::Conformance result;
    try {
      result = analysis::judge_motion(scenario, motion.rows, {}, stop);
    } catch (const InputError& e) {
      throw InputError(std::string("flipcheck.judge: ") + e.what());
    }
    table = analysis::judgement_table(scenario, analysis::scenario_sha256(scenario),
                                      {{{}, motion_name, result}});
    out.pass = result.pass();
    out.line = scenario.name + " " + motion_name + ": " + analysis::verdict_line(result);
  }
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    out.row[py::str(table.columns[c])] = cell_value(table.columns[c], table.rows.at(0).at(c));
  return out;
}

py::dict judge(const py::object& scenario_input, const py::object& t_arg, const py::object& q_arg,
               const py::object& omega_arg, const py::object& directory,
               const py::object& motion_name) {
  return judged(scenario_input, t_arg, q_arg, omega_arg, directory, motion_name).row;
}

py::dict assert_passes(const py::object& scenario_input, const py::object& t_arg,
                       const py::object& q_arg, const py::object& omega_arg,
                       const py::object& directory, const py::object& motion_name) {
  Judged j = judged(scenario_input, t_arg, q_arg, omega_arg, directory, motion_name);
  if (!j.pass) {
    PyErr_SetString(PyExc_AssertionError, j.line.c_str());
    throw py::error_already_set();
  }
  return j.row;
}

}  // namespace

void add_flipcheck(py::module_& m) {
  py::module_ flipcheck = m.def_submodule(
      "flipcheck",
      "The conformance kit (docs/flipcheck.md): scenarios, each one's start and exact motion, "
      "and the judgement of any engine's motion against it, as `bookspin flipcheck` gives them.");
  flipcheck.attr("scenario_dir") = carried_scenario_dir();
  flipcheck.def("scenarios", &scenarios, py::arg("directory") = py::none(), kScenariosDoc);
  flipcheck.def("export", &export_scenario, py::arg("scenario"), py::arg("directory") = py::none(),
                kExportDoc);
  flipcheck.def("judge", &judge, py::arg("scenario"), py::arg("t"), py::arg("q"),
                py::arg("omega_world"), py::arg("directory") = py::none(),
                py::arg("motion") = "motion", kJudgeDoc);
  flipcheck.def("assert_passes", &assert_passes, py::arg("scenario"), py::arg("t"), py::arg("q"),
                py::arg("omega_world"), py::arg("directory") = py::none(),
                py::arg("motion") = "motion", kAssertPassesDoc);
}

}  // namespace bookspin::python
