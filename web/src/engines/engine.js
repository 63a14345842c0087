// What every JavaScript engine adapter of the page offers (docs/explorer.md, "JavaScript
// engines"). An adapter is a plain object:
//   model:  the name the page's model selects and URL use ('cannon-es', 'rapier', …), from
//           models.js, the one list of the engines' names;
//   label:  what the page shows;
//   load(): a promise that resolves once the package is ready (Rapier and Jolt compile their
//           WebAssembly here; it is inlined in the page, so this works from file://);
//   start(body, dt): an EngineRun of one free body.
// `body`, from the page's WebAssembly session, so that every method starts alike:
//   mass:    mass units;
//   moments: [Ix, Iy, Iz], the principal moments about body x, y, z (mass·length²), given to
//            the engine explicitly, never computed by it from a collision shape;
//   size:    [a, b, c], the cage's edges (length units), for engines that need a shape;
//   omega0:  [x, y, z], ω at t = 0 (rad per time unit), world frame = body frame at the start
//            (the page's jiggled start, I⁻¹·L0, docs/physics.md §5).
// An EngineRun steps with no gravity, no damping and no sleeping, at the page's `dt`:
//   step():        one step of dt;
//   quaternion():  [w, x, y, z], body → world, as the engine stores it;
//   omegaWorld():  [x, y, z], ω in the world frame (rad per time unit);
//   dispose():     frees what the engine allocated.
// The page reads q and ω after every step into its WebAssembly session (Session.observe in
// web/bindings.cpp), which gives the diagnostics, the drawing and the flip count, as for its
// own models. No physics or measuring is written here.

/** The adapter's EngineRun stepped `n` times from a body's start: [q, ω world] at the end
 * (a convenience for tests and benchmarks, here once for every adapter). */
export function runSteps(run, n) {
  for (let i = 0; i < n; ++i) run.step();
  return [run.quaternion(), run.omegaWorld()];
}
