#pragma once
// A scene as the explorer page reads it (docs/explorer.md): the page's state, the book, the
// run's duration, the body and the measured ω, as one JSON value. Pure: made from a Scene the
// reader validated, written by the explorer product (products/explorer.hpp).
#include "common/json_writer.hpp"
#include "scene/scene.hpp"

namespace bookspin::scene {

/// One scene as the page reads it (web/src/main.js, window.BOOKSPIN_SCENES[i]), as a plain value
/// that json_text writes: a JSON object with name, title, description, `state` (the page's
/// state, web/src/state.js: body, model, integrator, normalize, damping, k, cells, dt, axis
/// "custom" with ω0 `w` (body frame, rad per time unit), jiggle, seed, speed in time units per
/// second, the markers; a
/// [[compare]] scene compares its first tile with its last, of those the page can step itself
/// (not the other engines', docs/engines.md), when `tiles` is off, and shows every tile with
/// `tiles`, on for a [[compare]] scene), `tiles` (a [[compare]] scene's every tile: label,
/// model, integrator, normalize; the explorer product adds the `replays` of the other engines'),
/// `book` (size, mass), `duration` (the scene's run,
/// (frames − 1)·dt·steps_per_frame time units: the page's time slider spans it) and, for
/// other bodies, `body`: the Body itself as simulate builds it (shape, mass, principal moments
/// about x, y, z, cage size, volume, surface 3×V principal frame flattened column by column,
/// triangles 3×N, face colours 3×N, smooth), so that the page's physics starts from the
/// same doubles (written in shortest round-trip form) and needs no mesh reader; with
/// `measured.omega`, `measured`: its samples {t, w: 3×N body-frame ω flattened, ut, u: the
/// times and body-frame L/|L| (L = I·ω, the body's moments) of the samples with L ≠ 0}, which
/// the page draws beside its runs (docs/explorer.md). No I/O (the scene reader read the file): a
/// pure value, which `bookspin explore` writes into the page (products/explorer.hpp).
JsonObject page_data(const Scene& scene);

}  // namespace bookspin::scene
