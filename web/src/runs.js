// The physics runs of the page: one simulator session per method (web/bindings.cpp), stepped,
// recorded for the plots and the sphere's trail. Every number comes from the WebAssembly
// module, flips included (analysis::FlipDetector, fed every step); nothing is computed here.
// A JavaScript engine's run (web/src/engines/) is stepped by its engine; after every step its q
// and ω go into a WebAssembly session (Session.observe), which measures and draws it alike, and
// so do the samples of a comparison's tile the page cannot step, replayed (tile_replay.js).
import { AXES } from './state.js';
import { WITHOUT_GYROSCOPIC_TERM } from './engines/models.js';
import { TileReplay, REPLAY_NOTE } from './tile_replay.js';

/** Each run's colour, in order (the first two as before a comparison showed every tile). */
const TRAIL_COLOURS = ['#e8b00b', '#35c0f0', '#f06aa8', '#7bd389', '#b58cf2', '#f59a4e', '#d8d8d8', '#4fd8c4'];
/** Steps between records at most (one record per 0.05 time units otherwise), so that a tiny dt
 * still returns to the page between pieces of work. */
const MAX_CHUNK = 2000;
/** Records of the exact motion per advance at most (it is evaluated at each, not stepped). */
const CLOSED_FORM_RECORDS = 1000;

/** The scene's own start (body, ω0, jiggle, seed), which a replay was run from. */
const START_KEYS = ['body', 'axis', 'w', 'jiggle', 'seed'];

/** The methods of `state`: with `tiles`, every tile of its scene (docs/explorer.md,
 * "Comparison": bookspin's own models stepped, the other engines' replayed); else the first, and
 * the second in compare mode. Each {model, integrator, normalize, label (a tile's own, or none),
 * replay (the tile's motion as make figures ran it, or none)}. */
function methodsOf(state, scene) {
  if (state.tiles && scene && scene.tiles) {
    return scene.tiles.map((tile, i) => ({ ...tile,
      replay: (scene.replays || []).find((r) => r.tile === i) || null }));
  }
  const methods = [{ model: state.model, integrator: state.integrator, normalize: state.normalize }];
  if (state.compare) methods.push({ model: state.model2, integrator: state.integrator2, normalize: state.normalize2 });
  return methods;
}

function labelOf(model, integrator, normalize, engine) {
  if (engine) return engine.label + (WITHOUT_GYROSCOPIC_TERM.includes(model) ? ' (no gyroscopic term)' : '');
  if (model === 'exact') return 'exact';
  return `${model}, ${integrator}${normalize ? ', normalized' : ''}`;
}

export class Runs {
  /** `space`: the page's StateSpace (state.js: the physics' models and default book);
   * `engines`: the JavaScript engines' adapters (web/src/engines/engine.js), loaded; [] in a
   * page written without `--engines`. */
  constructor(wasm, space, scenes, engines = []) {
    this.wasm = wasm;
    this.space = space;
    this.scenes = scenes;
    this.engines = engines;
    // {session, engine (an EngineRun or null), model, integrator, normalize, colour, label, trail,
    //  history, E0, diverged}
    this.list = [];
  }

  /** The engine adapter of `model`, or undefined for bookspin's own models. */
  engineOf(model) {
    return this.engines.find((e) => e.model === model);
  }

  /**
   * The simulator's session for the state's body. The scene's own body comes whole from bookspin
   * (its `body`: moments, cage and surface as `bookspin simulate` builds them, a mesh included);
   * another preset is built by the physics from its shape, the book from the scene's size (with no
   * scene, or a scene of another body: the physics' default book).
   */
  bodySession(state) {
    const scene = this.scenes.find((s) => s.name === state.scene);
    if (scene && scene.body && state.body === scene.body.shape) return new this.wasm.Session(scene.body);
    if (state.body === 'mesh') throw new Error('no mesh body in this scene: choose a mesh scene');
    const book = scene && scene.book && !scene.body ? scene.book : this.space.book;
    if (state.body === 'book')
      return new this.wasm.Session('book', book.mass, 1, book.size[0], book.size[1], book.size[2]);
    return new this.wasm.Session(state.body, 1, 1, 1, 1, 1);
  }

  /** ω0 (body frame) of the state: a principal axis at `rate`, or the custom components. */
  static omega0(session, state) {
    if (state.axis === 'custom') return state.w.slice();
    const order = session.principalOrder();
    const w = [0, 0, 0];
    w[order[AXES.indexOf(state.axis)]] = state.rate;
    return w;
  }

  /** A fresh session of `model` configured and reset to the state's start: {session, engine},
   * `engine` the JavaScript engine's run of an engine model (else null), started from the
   * session's jiggled ω0 with the body's mass and principal moments. */
  startRun(state, model, integrator, normalize) {
    const adapter = this.engineOf(model);
    if (!adapter && !this.space.models.includes(model))
      throw new Error(`${model}: this page has no JavaScript engines (bookspin explore --engines writes them)`);
    const session = this.bodySession(state);
    try {
      if (adapter) session.configureEngine();
      else session.configure(model, integrator, normalize, state.damping, state.k, state.cells,
                             state.drag, state.dragRate);
      const w = Runs.omega0(session, state);
      session.reset(w[0], w[1], w[2], state.jiggle, state.seed);
      const engine = adapter ? adapter.start({
        mass: session.mass(), moments: Array.from(session.moments()), size: Array.from(session.cageSize()),
        omega0: Array.from(session.diagnostics().omega_body),
      }, state.dt) : null;
      return { session, engine };
    } catch (e) {
      session.delete();
      throw e;
    }
  }

  /** A replayed tile (`replay`, one of the scene's replays: TileReplay) from the state's start:
   * {session, engine}, the session measuring the replay's samples as a JavaScript engine's. The
   * replay is of the scene's own start: another start is refused (it was not run). */
  startReplay(state, replay) {
    const base = this.space.sceneBase(this.scenes, state.scene);
    const moved = START_KEYS.filter((k) => JSON.stringify(state[k]) !== JSON.stringify(base[k]));
    if (moved.length)
      throw new Error(`${replay.label}: a replay of the scene's own start (${moved.join(', ')} changed here), not shown`);
    const session = this.bodySession(state);
    session.configureEngine();
    const w = Runs.omega0(session, state);
    session.reset(w[0], w[1], w[2], state.jiggle, state.seed);
    return { session, engine: new TileReplay(replay, state.dt) };
  }

  /** `n` steps of `dt` of `run`; false when its state stopped being finite (or a replay passed
   * its last sample). */
  static step(run, dt, n) {
    if (!run.engine) return run.session.step(dt, n);
    for (let i = 0; i < n; ++i) {
      run.engine.step();
      if (run.replayed && run.engine.ended()) return false;
      const q = run.engine.quaternion(), w = run.engine.omegaWorld();
      if (!run.session.observe(q[0], q[1], q[2], q[3], w[0], w[1], w[2], dt)) return false;
    }
    return true;
  }

  /** Starts every method of `state` from t = 0; returns the error messages of those that failed. */
  rebuild(state) {
    this.dispose();
    const errors = [];
    const scene = this.scenes.find((s) => s.name === state.scene);
    methodsOf(state, scene).forEach(({ model, integrator, normalize, label, replay }, k) => {
      try {
        if (label && !replay && !this.engineOf(model) && !this.space.models.includes(model))
          throw new Error(`${label}: not in this page (no replay of it)`);
        const { session, engine } = replay ? this.startReplay(state, replay)
          : this.startRun(state, model, integrator, normalize);
        const run = { session, engine, model, integrator, normalize,
          colour: TRAIL_COLOURS[k % TRAIL_COLOURS.length],
          label: replay ? `${label} (${REPLAY_NOTE})` : label || labelOf(model, integrator, normalize, this.engineOf(model)),
          replayed: Boolean(replay), trail: [], history: [], diverged: '', closedForm: model === 'exact' };
        this.record(run, state.dt);
        run.E0 = run.history[0].E;
        this.list.push(run);
      } catch (e) {
        errors.push(typeof e === 'number' ? this.wasm.errorMessage(e) : String(e.message || e));
      }
    });
    return errors;
  }

  record(run, dt) {
    const d = run.session.diagnostics();
    const u = d.momentum_direction;
    run.trail.push([u[0], u[1], u[2]]);
    const shape = run.model === 'particle' ? d.strain_max
      : run.model === 'rigid-matrix' ? d.orthogonality_error
        : Math.abs(d.quaternion_norm - 1);
    run.history.push({ t: run.session.steps() * dt, w: Array.from(d.omega_body), E: d.energy_total, shape });
    if (run.trail.length > 20000) run.trail = run.trail.slice(10000);
    if (run.history.length > 4000) run.history = run.history.filter((_, i) => i % 2 === 0);
  }

  /** Steps every run towards time t (the step count round(t/dt)), the runs side by side in
   * pieces of 0.05 time units (at most MAX_CHUNK steps), recording after each; stops after the
   * piece that passes `deadline` (performance.now() milliseconds). Returns the time every run
   * has reached (t when done; a diverged run has stopped for good and counts as done). */
  advanceTo(t, dt, deadline = Infinity) {
    const total = Math.round(t / dt);
    const chunk = Math.max(1, Math.min(MAX_CHUNK, Math.round(0.05 / dt)));
    // The exact motion is evaluated at the time asked directly (a closed form in t): at most
    // CLOSED_FORM_RECORDS records on the way, for the plots and the trail, however far.
    const stride = new Map(this.list.map((r) => [r, r.closedForm
      ? Math.max(chunk, Math.ceil((total - r.session.steps()) / CLOSED_FORM_RECORDS)) : chunk]));
    for (let busy = true; busy;) {
      busy = false;
      for (const r of this.list) {
        const left = total - r.session.steps();
        if (left <= 0 || r.diverged) continue;
        if (!Runs.step(r, dt, Math.min(stride.get(r), left))) {
          const reason = r.session.divergenceReason();
          r.diverged = r.replayed && r.engine.ended() ? `replay ends at t = ${r.engine.end().toFixed(2)}`
            : `diverged at t = ${(r.session.steps() * dt).toFixed(3)}${reason ? ': ' + reason : ''}`;
        }
        this.record(r, dt);
        busy = true;
      }
      if (busy && performance.now() > deadline) break;
    }
    const live = this.list.filter((r) => !r.diverged).map((r) => r.session.steps());
    return Math.min(total, ...live) * dt;
  }

  /** The flip count of each run (analysis::FlipDetector on every step, docs/physics.md §14; the
   * exact model's from its closed form, analysis::exact_flip_count). */
  flips() {
    return this.list.map((r) => r.session.flips().count);
  }

  dispose() {
    for (const r of this.list) {
      if (r.engine) r.engine.dispose();
      r.session.delete();
    }
    this.list = [];
  }
}
