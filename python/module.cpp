// The Python module `bookspin` (docs/python.md): one file per concept (exact_motion.cpp,
// simulate.cpp, flipcheck.cpp, fit.cpp, frames.cpp, render.cpp), the errors mapped in one
// (errors.cpp).
#include "bindings.hpp"
#include "common/version.hpp"

PYBIND11_MODULE(bookspin, m) {
  m.doc() =
      "bookspin from Python: the exact motion of a rigid body, a scene's simulation, the "
      "conformance kit (bookspin.flipcheck) and the phone-toss lab's fit, the same numbers as the "
      "bookspin command line, as numpy float64 arrays; a scene's frames as numpy images "
      "(bookspin.frames) and its clip (bookspin.render), the same pictures as bookspin render. "
      "Bad input raises bookspin.Error (a ValueError) with the command "
      "line's one line. docs/python.md.";
  // The one version (VERSION, docs/flipcheck.md "Versions"): the wheel's and `bookspin
  // --version`'s.
  m.attr("__version__") = bookspin::version();
  bookspin::python::add_errors(m);
  bookspin::python::add_exact_motion(m);
  bookspin::python::add_simulate(m);
  bookspin::python::add_flipcheck(m);
  bookspin::python::add_fit(m);
  bookspin::python::add_live_fit(m);
  bookspin::python::add_frames(m);
  bookspin::python::add_render(m);
}
