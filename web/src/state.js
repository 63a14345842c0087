// The explorer's whole state, read from and written to the URL's query (a shared link
// reproduces the run). Every key has a default; unknown or malformed values fall back to it
// and are reported once on the page.
export const MODELS = ['particle', 'rigid-matrix', 'rigid-quaternion', 'exact'];
/** The JavaScript engines' models (web/src/engines/), in a page written with `--engines`. */
export const ENGINE_MODELS = ['cannon-es', 'rapier', 'jolt', 'jolt-gyroscopic'];
export const INTEGRATORS = ['euler', 'symplectic-euler', 'velocity-verlet', 'rk4',
  'implicit-midpoint', 'splitting', 'splitting4'];
export const BODIES = ['book', 't-handle', 'tennis-racket', 'phone', 'mesh'];  // mesh: the scene's own
export const AXES = ['smallest', 'intermediate', 'largest', 'custom'];

export const DEFAULTS = {
  scene: '',
  body: 'book',
  model: 'rigid-matrix',
  integrator: 'euler',
  normalize: true,
  damping: true,
  k: 10,
  cells: 0,          // lattice cells along the longest side (particle model, not the book); 0: default
  dt: 1 / 60,
  axis: 'custom',
  rate: 0.114819,
  w: [0.114819, 0, 0],
  jiggle: 0.001,
  seed: 2012,
  speed: 5,
  compare: false,
  model2: 'exact',
  integrator2: 'euler',
  normalize2: false,
  showL: true,
  showAxes: false,
  t: 0,
};

const num = (v, d) => { const x = Number(v); return Number.isFinite(x) ? x : d; };
const bool = (v, d) => (v === '1' || v === 'true' ? true : v === '0' || v === 'false' ? false : d);
const oneOf = (list) => (v, d) => (list.includes(v) ? v : d);

const PARSE = {
  scene: (v) => v,
  body: oneOf(BODIES), model: oneOf([...MODELS, ...ENGINE_MODELS]), integrator: oneOf(INTEGRATORS),
  model2: oneOf([...MODELS, ...ENGINE_MODELS]), integrator2: oneOf(INTEGRATORS), axis: oneOf(AXES),
  normalize: bool, damping: bool, normalize2: bool, compare: bool, showL: bool, showAxes: bool,
  k: num, cells: num, dt: num, rate: num, jiggle: num, seed: num, speed: num, t: num,
  w: (v, d) => {
    const parts = String(v).split(',').map(Number);
    return parts.length === 3 && parts.every(Number.isFinite) ? parts : d;
  },
};

/** The state of `search` (a URL query string) over `base` (defaults or a scene's settings). */
export function parseState(search, base = DEFAULTS) {
  const params = new URLSearchParams(search);
  const state = structuredClone(base);
  for (const [key, value] of params) {
    if (key in PARSE) state[key] = PARSE[key](value, state[key]);
  }
  return state;
}

/**
 * What the page will run, whatever a link or a field says, so that the tab stays responsive:
 * `dt` in [1e-6, 1000] time units (the scene's own limit is (0, 1000]; below 1e-6 one time unit
 * is more than a million steps), `speed` in [0, 10 000] time units per second, and the start
 * time `t` at most MAX_STEPS steps of `dt` (the page catches up to it in bounded pieces, one
 * per animation frame, showing its progress).
 */
export const LIMITS = { dt: [1e-6, 1000], speed: [0, 1e4] };
export const MAX_STEPS = 1e7;

/** `state` with every value outside LIMITS put back to `base`'s (a `t` beyond MAX_STEPS steps:
 * 0), and one line per value refused, saying why. */
export function withinLimits(state, base = DEFAULTS) {
  const next = { ...state };
  const notes = [];
  for (const [key, [lo, hi]] of Object.entries(LIMITS)) {
    if (!(next[key] >= lo && next[key] <= hi)) {
      notes.push(`${key} = ${next[key]} refused: the page takes ${lo} to ${hi}; ${key} = ${base[key]} instead`);
      next[key] = base[key];
    }
  }
  const steps = next.t / next.dt;
  if (!(next.t >= 0) || steps > MAX_STEPS) {
    notes.push(`t = ${next.t} refused: ${steps > MAX_STEPS ? `${steps.toPrecision(3)} steps of dt = ${next.dt}, ` +
      `more than the page's ${MAX_STEPS.toExponential()}` : 'negative'}; starting at t = 0`);
    next.t = 0;
  }
  return [next, notes];
}

/** The query string of `state`: the scene's name, and only the keys that differ from `base`
 * (what parseState starts from: DEFAULTS, or the scene's settings over them). */
export function formatState(state, base = DEFAULTS) {
  const params = new URLSearchParams();
  for (const key of Object.keys(DEFAULTS)) {
    const v = state[key];
    const d = key === 'scene' ? DEFAULTS.scene : base[key];
    if (JSON.stringify(v) === JSON.stringify(d)) continue;
    params.set(key, Array.isArray(v) ? v.join(',') : typeof v === 'boolean' ? (v ? '1' : '0') : String(v));
  }
  return params.toString();
}
