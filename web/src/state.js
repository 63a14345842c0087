// The explorer's whole state, read from and written to the URL's query (a shared link
// reproduces the run). Every key has a default; unknown or malformed values fall back to it
// and are reported once on the page. The names a state may hold and the defaults the physics
// owns come from the WebAssembly module (web/bindings.cpp: physicsNames, physicsDefaults), the
// JavaScript engines' models from engines/models.js; the rest are the page's own choices.
import { ENGINE_MODELS } from './engines/models.js';

export const AXES = ['smallest', 'intermediate', 'largest', 'custom'];
/** The air drag's laws (docs/physics.md §21, physics::DragLaw). */
export const DRAG_LAWS = ['none', 'linear', 'quadratic'];

const num = (v, d) => { const x = Number(v); return Number.isFinite(x) ? x : d; };
const bool = (v, d) => (v === '1' || v === 'true' ? true : v === '0' || v === 'false' ? false : d);
const oneOf = (list) => (v, d) => (list.includes(v) ? v : d);

/** The states the page can be in: the physics' names and defaults (`wasm`, the WebAssembly
 * module), reading and writing the URL's query. */
export class StateSpace {
  constructor(wasm) {
    const names = wasm.physicsNames();
    const physics = wasm.physicsDefaults();
    /** bookspin's own models (src/physics), in the physics' order. */
    this.models = names.models;
    /** The JavaScript engines' models, known even in a page without them (a link may name one). */
    this.engineModels = ENGINE_MODELS;
    /** Every integrator of the models, and {model: the integrators it accepts} (physics::supports). */
    this.integrators = names.integrators;
    this.supports = names.supports;
    /** The body shapes ('mesh': a mesh scene's own body). */
    this.bodies = names.bodies;
    /** The default book {size: [a, b, c], mass} (physics::Book). */
    this.book = physics.book;
    /** The state with no scene: the physics' defaults (k, cells, damping, ω0) and the page's. */
    this.defaults = {
      scene: '',
      body: 'book',
      model: 'rigid-matrix',
      integrator: 'euler',
      normalize: true,
      damping: physics.damping,
      k: physics.k,
      cells: physics.cells,  // lattice cells along the longest side (particle model, not the book); 0: default
      drag: 'none',  // air drag on the rotation (docs/physics.md §21): none, linear, quadratic
      dragRate: 0,   // its rate, 1 per time unit (a fitted toss's scene: per second)
      dt: 1 / 60,
      axis: 'custom',
      rate: physics.rate,
      w: physics.w,
      jiggle: 0.001,
      seed: 2012,
      speed: 5,
      compare: false,
      tiles: false,  // a comparison scene's every tile (docs/explorer.md, "Comparison")
      model2: 'exact',
      integrator2: 'euler',
      normalize2: false,
      showL: true,
      showAxes: false,
      t: 0,
    };
    const models = oneOf([...this.models, ...this.engineModels]);
    const integrators = oneOf(this.integrators);
    this.parsers = {
      scene: (v) => v,
      body: oneOf(this.bodies), model: models, integrator: integrators,
      model2: models, integrator2: integrators, axis: oneOf(AXES),
      normalize: bool, damping: bool, normalize2: bool, compare: bool, tiles: bool, showL: bool, showAxes: bool,
      drag: oneOf(DRAG_LAWS), dragRate: num,
      k: num, cells: num, dt: num, rate: num, jiggle: num, seed: num, speed: num, t: num,
      w: (v, d) => {
        const parts = String(v).split(',').map(Number);
        return parts.length === 3 && parts.every(Number.isFinite) ? parts : d;
      },
    };
  }

  /** The state a scene of `scenes` starts from: the defaults under the scene's own settings
   * (the defaults where there is no scene of that name). */
  sceneBase(scenes, name) {
    const scene = scenes.find((s) => s.name === name);
    return scene ? { ...this.defaults, ...scene.state, scene: name } : this.defaults;
  }

  /** The state of `search` (a URL query string) over `base` (defaults or a scene's settings). */
  parse(search, base = this.defaults) {
    const params = new URLSearchParams(search);
    const state = structuredClone(base);
    for (const [key, value] of params) {
      if (key in this.parsers) state[key] = this.parsers[key](value, state[key]);
    }
    return state;
  }

  /** The query string of `state`: the scene's name, and only the keys that differ from `base`
   * (what parse starts from: the defaults, or the scene's settings over them). */
  format(state, base = this.defaults) {
    const params = new URLSearchParams();
    for (const key of Object.keys(this.defaults)) {
      const v = state[key];
      const d = key === 'scene' ? this.defaults.scene : base[key];
      if (JSON.stringify(v) === JSON.stringify(d)) continue;
      params.set(key, Array.isArray(v) ? v.join(',') : typeof v === 'boolean' ? (v ? '1' : '0') : String(v));
    }
    return params.toString();
  }
}

/**
 * What the page will run, whatever a link or a field says, so that the tab stays responsive
 * and never shows NaN: `dt` in [1e-6, 1000] time units (the scene's own limit is (0, 1000];
 * below 1e-6 one time unit is more than a million steps), `speed` in [0, 10 000] time units
 * per second, the start time `t` at most MAX_STEPS steps of `dt` (the page catches up to it in
 * bounded pieces, one per animation frame, showing its progress); and the scene's own limits
 * (src/scene/limits.hpp, scenes/README.md) for the spring constant `k` (1e-12 … 1e12: the
 * scene's is positive), the lattice's `cells` (0 … 64), the spin `rate` and each component of
 * ω0 `w` (−1e6 … 1e6 rad per time unit), the `jiggle` (0 … 1e6), the `seed` (0 … 2^53,
 * the integers a link can carry exactly) and the drag's rate `dragRate` (−1000 … 1000 per time
 * unit).
 */
export const LIMITS = {
  dt: [1e-6, 1000], speed: [0, 1e4], k: [1e-12, 1e12], cells: [0, 64], rate: [-1e6, 1e6],
  jiggle: [0, 1e6], seed: [0, 2 ** 53], dragRate: [-1e3, 1e3],
};
/** Each component of ω0 (`w`), rad per time unit. */
export const W_LIMIT = 1e6;
export const MAX_STEPS = 1e7;

/** `state` with every value outside LIMITS put back to `base`'s (a `t` beyond MAX_STEPS steps:
 * 0), and one line per value refused, saying why. */
export function withinLimits(state, base) {
  const next = { ...state };
  const notes = [];
  for (const [key, [lo, hi]] of Object.entries(LIMITS)) {
    if (!(next[key] >= lo && next[key] <= hi)) {
      notes.push(`${key} = ${next[key]} refused: the page takes ${lo} to ${hi}; ${key} = ${base[key]} instead`);
      next[key] = base[key];
    }
  }
  if (!(Array.isArray(next.w) && next.w.every((x) => Math.abs(x) <= W_LIMIT))) {
    notes.push(`w = ${next.w} refused: the page takes each component from ${-W_LIMIT} to ${W_LIMIT}; ` +
      `w = ${base.w} instead`);
    next.w = base.w;
  }
  const steps = next.t / next.dt;
  if (!(next.t >= 0) || steps > MAX_STEPS) {
    const count = Number.isFinite(steps) ? `${steps.toPrecision(3)} steps` : 'more steps than a number holds';
    notes.push(`t = ${next.t} refused: ${steps > MAX_STEPS ? `${count} of dt = ${next.dt}, ` +
      `more than the page's ${MAX_STEPS.toExponential()}` : 'negative'}; starting at t = 0`);
    next.t = 0;
  }
  return [next, notes];
}
