#pragma once
// The one error mapping of the page's bindings (web/judge_bindings.cpp, web/fit_bindings.cpp):
// what a command line prints after "bookspin: error: " becomes the answer's `error`, as its
// run_guarded does (docs/architecture.md, "Errors").
#include <emscripten/val.h>

#include <exception>
#include <string>

#include "common/errors.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::web {

/// f()'s answer; {error: the one line} for an InputError or an ExactHorizonError, {error:
/// "internal error: …"} for any other exception.
template <typename F>
emscripten::val guarded(F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    emscripten::val out = emscripten::val::object();
    out.set("error", std::string(e.what()));
    return out;
  } catch (const physics::ExactHorizonError& e) {
    // A time past the exact motion's horizon (docs/physics.md §8): the input's, as the command
    // line's run_guarded says it.
    emscripten::val out = emscripten::val::object();
    out.set("error", std::string(e.what()));
    return out;
  } catch (const std::exception& e) {
    emscripten::val out = emscripten::val::object();
    out.set("error", std::string("internal error: ") + e.what());
    return out;
  }
}

}  // namespace bookspin::web
