// The table of docs/explorer.md ("JavaScript engines"): each JavaScript engine of the page
// (web/src/engines/) and two of bookspin's own methods against the exact motion, for the book of
// scenes/exact-unstable-x.toml (the physics' default book: physicsDefaults) spun near its
// intermediate axis, ω0 = (5, 0.01, 0.02) rad/s in the body frame, no jiggle, over 20 s at
// dt = 1/60 and 1/240: flips (analysis::FlipDetector), the first flip, and
// |ω − ω_exact| / |ω_exact| at t = 20 (body frame). Everything as the page does it: the
// WebAssembly physics (Session; an engine's q and ω through Session.observe).
// Usage: node web/engines-table.mjs BUILD/web/bookspin_physics.js
import { createRequire } from 'node:module';
import { cannon } from './src/engines/cannon.js';
import { rapier } from './src/engines/rapier.js';
import { jolt, joltGyroscopic } from './src/engines/jolt.js';

const BookspinPhysics = createRequire(import.meta.url)(process.argv[2]);
const wasm = await BookspinPhysics();
const W0 = [5, 0.01, 0.02];
const T = 20;
const { size, mass } = wasm.physicsDefaults().book;
const book = () => new wasm.Session('book', mass, 1, size[0], size[1], size[2]);

function measure(session, step, dt) {
  const n = Math.round(T / dt);
  if (!step(session, dt, n)) throw new Error('diverged');
  const f = session.flips();
  return { flips: f.count, first: f.first, omega: Array.from(session.diagnostics().omega_body) };
}

function own(model, integrator) {
  return (dt) => {
    const s = book();
    s.configure(model, integrator, true, false, 10, 0);
    s.reset(...W0, 0, 2012);
    const out = measure(s, (x, h, n) => x.step(h, n), dt);
    s.delete();
    return out;
  };
}

function engine(adapter) {
  return (dt) => {
    const s = book();
    s.configureEngine();
    s.reset(...W0, 0, 2012);
    const run = adapter.start({ mass: s.mass(), moments: Array.from(s.moments()),
      size: Array.from(s.cageSize()), omega0: Array.from(s.diagnostics().omega_body) }, dt);
    const out = measure(s, (x, h, n) => {
      for (let i = 0; i < n; ++i) {
        run.step();
        const q = run.quaternion(), w = run.omegaWorld();
        if (!x.observe(q[0], q[1], q[2], q[3], w[0], w[1], w[2], h)) return false;
      }
      return true;
    }, dt);
    run.dispose();
    s.delete();
    return out;
  };
}

const methods = [['exact motion', own('exact', 'euler')],
  ['bookspin rigid-quaternion, RK4', own('rigid-quaternion', 'rk4')],
  ['cannon-es 0.20', engine(cannon)], ['Rapier 0.21', engine(rapier)],
  ['Jolt 1.1', engine(jolt)], ['Jolt 1.1, mApplyGyroscopicForce', engine(joltGyroscopic)]];
for (const e of [cannon, rapier, jolt]) await e.load();
await joltGyroscopic.load();
console.log('| method | dt | flips in 20 s | first flip (s) | \\|ω − ω_exact\\| / \\|ω_exact\\| at t = 20 |');
console.log('|---|---|---:|---:|---:|');
for (const dt of [1 / 60, 1 / 240]) {
  const exact = methods[0][1](dt);
  const norm = (v) => Math.hypot(...v);
  for (const [name, run] of methods) {
    const r = name === 'exact motion' ? exact : run(dt);
    const err = norm(r.omega.map((x, i) => x - exact.omega[i])) / norm(exact.omega);
    console.log(`| ${name} | 1/${Math.round(1 / dt)} | ${r.flips} | ${r.first === null ? '—' : r.first.toFixed(3)} | ` +
      `${name === 'exact motion' ? '0' : err.toPrecision(2)} |`);
  }
}
