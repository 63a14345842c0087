// The one mapping of bookspin's exceptions into Python's (docs/python.md, "Errors"); the
// command line's is src/cli/run_guarded.cpp, and the two say the same line:
//   InputError                 bookspin.Error (a ValueError): the command line's one line
//   OutputError                OSError: `cannot write "PATH": reason`
//   Interrupted                KeyboardInterrupt (Ctrl-C during a long call)
//   RenderError, EncoderError  RuntimeError: the command line's line (no usable EGL, an encoder)
//   anything else              RuntimeError "internal error: …" (a bug)
// pybind11's own exceptions (a wrong argument type, a Python error raised inside a call) pass
// through untouched.
#include "common/errors.hpp"

#include <Python.h>

#include <chrono>
#include <csignal>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "render/render_error.hpp"
#include "scene/toml_reader.hpp"
#include "video/video.hpp"

namespace bookspin::python {

namespace {

PyObject* error_type = nullptr;  ///< bookspin.Error

/// Raises `type` with `message` (its controls escaped) read as UTF-8 with surrogateescape: a
/// path whose name is bytes that are no UTF-8 reads as os.listdir gives it, where
/// PyErr_SetString would raise a UnicodeDecodeError in the error's place.
void set_error(PyObject* type, const std::string& message) {
  const std::string text = scene::escape_controls(message);
  PyObject* value =
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "surrogateescape");
  if (value == nullptr) return;  // MemoryError, set
  PyErr_SetObject(type, value);
  Py_DECREF(value);
}

}  // namespace

void add_errors(py::module_& m) {
  static py::exception<InputError> error(m, "Error", PyExc_ValueError);
  error.doc() =
      "Bad input (a scene, an override, an array, a motion): the command line's one line, "
      "\"FILE:LINE: KEY: reason\" where it has a file. A subclass of ValueError.";
  error_type = error.ptr();
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const py::error_already_set&) {
      throw;  // a Python error: pybind11 restores it
    } catch (const py::builtin_exception&) {
      throw;  // pybind11's own (TypeError of a wrong argument, …)
    } catch (const std::bad_alloc&) {
      throw;  // MemoryError, pybind11's
    } catch (const Interrupted&) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const InputError& e) {
      set_error(error_type, e.what());
    } catch (const OutputError& e) {
      set_error(PyExc_OSError, e.what());
    } catch (const render::RenderError& e) {
      set_error(PyExc_RuntimeError, e.what());
    } catch (const video::EncoderError& e) {
      set_error(PyExc_RuntimeError, e.what());
    } catch (const std::exception& e) {
      set_error(PyExc_RuntimeError, std::string("internal error: ") + e.what());
    }
  });
}

namespace {

volatile std::sig_atomic_t terminated = 0;
extern "C" void on_termination(int signal) { terminated = signal; }

/// SIGTERM and SIGHUP during a long call, where Python leaves them to their default action (which
/// would end the process mid-write, its temporaries left in the output folder): recorded while
/// the call runs, so that it stops as from Ctrl-C and removes what it began; once the call has
/// unwound the handlers are restored and the signal raised again, ending the process as it
/// would have (exit 128 + signal, nothing written). docs/outputs.md, "Signals". A handler the
/// program set itself (signal.signal) is left alone.
class TerminationGuard {
 public:
  TerminationGuard() {
    terminated = 0;
    for (int i = 0; i < 2; ++i) {
      struct sigaction current {};
      sigaction(kSignals[i], nullptr, &current);
      if (current.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = on_termination;
      sigemptyset(&action.sa_mask);
      installed_[i] = sigaction(kSignals[i], &action, &previous_[i]) == 0;
    }
  }
  ~TerminationGuard() {
    for (int i = 0; i < 2; ++i)
      if (installed_[i]) sigaction(kSignals[i], &previous_[i], nullptr);
    const int signal = terminated;
    terminated = 0;
    if (signal != 0) std::raise(signal);  // the default action, now restored
  }
  TerminationGuard(const TerminationGuard&) = delete;
  TerminationGuard& operator=(const TerminationGuard&) = delete;
  static int received() { return terminated; }

 private:
  static constexpr int kSignals[2] = {SIGTERM, SIGHUP};
  bool installed_[2] = {false, false};
  struct sigaction previous_[2]{};
};

}  // namespace

StopPoll python_stop() {
  using Clock = std::chrono::steady_clock;
  // The calls that take it run on the caller's thread alone: the time of the last look needs
  // no lock. Every 50 ms at most, so that a loop of short steps is not slowed by the GIL.
  auto last = std::make_shared<Clock::time_point>(Clock::now());
  auto guard = std::make_shared<TerminationGuard>();
  return [last, guard](std::string_view) -> int {
    if (const int signal = TerminationGuard::received()) return signal;
    const Clock::time_point now = Clock::now();
    if (now - *last < std::chrono::milliseconds(50)) return 0;
    *last = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) return 0;
    // The handler raised (KeyboardInterrupt for SIGINT): the call stops as the command line
    // does, and errors.cpp raises KeyboardInterrupt again at the door.
    PyErr_Clear();
    return SIGINT;
  };
}

void warn(const std::string& message) {
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 1) != 0) throw py::error_already_set();
}

}  // namespace bookspin::python
