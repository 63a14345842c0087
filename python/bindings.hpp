#pragma once
// The Python module's pieces (docs/python.md): one file per concept, each adding its functions
// to the module; what they share is here. The module is a door, as the command line is: it
// turns Python values into the pure stages' requests, calls them with the GIL released, and
// presents their values as numpy arrays and dicts. Errors are mapped in one place (errors.cpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "common/stop.hpp"
#include "jobs/exact_motion.hpp"
#include "scene/scene.hpp"

namespace bookspin::python {

namespace py = pybind11;

/// Adds bookspin.Error and the one translation of bookspin's exceptions into Python's.
void add_errors(py::module_& m);
/// bookspin.exact_motion.
void add_exact_motion(py::module_& m);
/// bookspin.simulate.
void add_simulate(py::module_& m);
/// The submodule bookspin.flipcheck: scenarios, export, judge.
void add_flipcheck(py::module_& m);
/// bookspin.fit and its value bookspin.Fit.
void add_fit(py::module_& m);
/// bookspin.prepare_recording and bookspin.live_fit, and their values.
void add_live_fit(py::module_& m);
/// bookspin.frames and its iterator, bookspin.Frames.
void add_frames(py::module_& m);
/// bookspin.render.
void add_render(py::module_& m);

/// A stop poll for a long call with the GIL released: a few times a second it takes the GIL
/// and asks Python whether a signal came (PyErr_CheckSignals); Ctrl-C then throws Interrupted,
/// which errors.cpp turns into KeyboardInterrupt.
StopPoll python_stop();

/// `value` as a float64 array of shape (`n`,), for argument `name`; InputError "NAME: expected
/// shape (n,), got (…)" otherwise (`n` < 0: any length), and for a dtype numpy casts to
/// float64 only unsafely (complex, text: not numpy's same_kind) or a copy too large for memory.
std::vector<double> vector_arg(const py::handle& value, const char* name, long n);
/// `value` as a 3-vector (shape (3,)).
Eigen::Vector3d vector3_arg(const py::handle& value, const char* name);
/// `value` as a float64 array of shape (`rows`, `columns`), row-major (`rows` < 0: any), refused
/// as vector_arg's.
std::vector<double> matrix_arg(const py::handle& value, const char* name, long rows, long columns);

/// InputError where arrays that go together (a name and its rows each, the first given first)
/// differ in length: names the one whose count the others do not share ("t: 10 rows, but q and
/// omega_world have 3001: one row of each per time").
void same_rows(const std::vector<std::pair<const char*, std::size_t>>& arrays);

/// A float64 array of shape (n,) or (n, columns), uninitialized.
py::array_t<double> new_array(std::size_t n, std::size_t columns = 0);

/// Exact-motion rows as arrays: `q` (N, 4) w, x, y, z, `omega_body`, `omega_world`, `L_world`
/// (N, 3) and `E` (N,), and with `with_t` their times `t` (N,) too (jobs/exact_motion.hpp).
/// Made with the GIL held; set() writes one row through raw pointers, so it may run without it.
class ExactArrays {
 public:
  ExactArrays(std::size_t n, bool with_t);
  void set(std::size_t i, const jobs::ExactMotionRow& row);
  py::dict dict() const;

 private:
  bool with_t_;
  py::array_t<double> t_, q_, omega_body_, omega_world_, L_world_, E_;
  jobs::ExactRowArrays into_;  ///< where set() writes: the arrays' data
};

/// `rows` as ExactArrays' dict.
py::dict exact_rows_arrays(const std::vector<jobs::ExactMotionRow>& rows, bool with_t);

/// A scene given as a path (os.PathLike, or a str that names a file or holds neither a newline
/// nor '=') or as TOML text (any other str, named "scene-text.toml" in messages), with `overrides`
/// (a dict or None) applied as `--set KEY=VALUE` (each value spelled in TOML). Read with the GIL
/// held (the reading is short). InputError for a bad scene, as the command line's.
scene::Scene scene_arg(const py::handle& scene, const py::handle& overrides);

/// Python's `os.fspath(value)` for a str or an os.PathLike as the bytes the OS takes
/// (os.fsencode: a name os.listdir gave for bytes that are no UTF-8 is those bytes again), else
/// an empty string with `ok` false. A lone surrogate no file's name gives (U+D800) is
/// InputError naming `argument` (unicode_arg()'s words), never pybind11's "Unable to cast".
std::string path_text(const py::handle& value, bool& ok, const std::string& argument);

/// path_text() of a path that is opened: also a NUL is InputError naming `argument` ("holds a
/// NUL byte at character N"), where the OS would have opened the path cut at it.
std::string path_arg(const py::handle& value, bool& ok, const std::string& argument);

/// The str `text` in UTF-8, or InputError naming `argument` where it holds a lone surrogate
/// (U+D800 … U+DFFF, which no UTF-8 holds): `ARGUMENT: "m\ud800x" holds a lone surrogate
/// (U+D800) at character 2: no UTF-8 text holds one`, in the npm package's words.
std::string unicode_arg(const py::handle& text, const std::string& argument);

/// unicode_arg() of a value that must be a str: anything else is InputError naming `argument`
/// (`ARGUMENT: expected a str, got int`), never pybind11's TypeError.
std::string text_arg(const py::handle& value, const std::string& argument);

/// A progress bar of `total` steps from tqdm (`tqdm.auto.tqdm`: a widget in a notebook, a bar on
/// stderr in a terminal), made at the first update; none where `show` is false or tqdm cannot
/// be imported. Make and destroy it with the GIL held; update() may be called with the GIL
/// released (it takes it, at most every 100 ms and at the last step). A bar that fails is
/// dropped: a progress bar never stops the call it shows.
class ProgressBar {
 public:
  ProgressBar(bool show, int total, std::string description, std::string unit);
  ~ProgressBar();  ///< closes the bar
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  /// `done` of the total steps are done.
  void update(int done);

 private:
  bool show_;
  int total_;
  std::string description_;
  std::string unit_;
  py::object bar_;  ///< tqdm's, once made
  int shown_ = 0;   ///< the steps the bar shows
  std::chrono::steady_clock::time_point last_;
};

/// Issues `message` as a Python UserWarning (the command line prints it as "bookspin: warning:").
void warn(const std::string& message);

}  // namespace bookspin::python
