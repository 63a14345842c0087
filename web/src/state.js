// The explorer's whole state, read from and written to the URL's query (a shared link
// reproduces the run). Every key has a default; unknown or malformed values fall back to it
// and are reported once on the page.
export const MODELS = ['particle', 'rigid-matrix', 'rigid-quaternion', 'exact'];
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
  body: oneOf(BODIES), model: oneOf(MODELS), integrator: oneOf(INTEGRATORS),
  model2: oneOf(MODELS), integrator2: oneOf(INTEGRATORS), axis: oneOf(AXES),
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
