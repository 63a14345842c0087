#pragma once
// The body of one of the page's scenes as bookspin built it (src/products/explorer.hpp: a
// book's size and mass, or `body` whole), for web/bindings.cpp's Session and
// web/judge_bindings.cpp's conformance scenarios alike. Defined in web/bindings.cpp.
#include <emscripten/val.h>

#include <string>

#include "physics/body.hpp"

namespace bookspin::web {

/// The book of `size` (a, b, c, length units) and `mass`, or a preset of `mass` and `scale`
/// (docs/physics.md §1, §12). Throws std::invalid_argument for an unknown body.
physics::Body make_body(const std::string& name, double mass, double scale, double a, double b,
                        double c);

/// The Body exactly as bookspin built it (src/products/explorer.hpp, `body`): shape, mass,
/// principal moments about x, y, z, cage size, volume, the surface 3×V (principal frame) with
/// its triangles 3×N and face colours 3×N flattened column by column, smooth. Throws
/// std::invalid_argument for a malformed one.
physics::Body body_of(const emscripten::val& spec);

}  // namespace bookspin::web
