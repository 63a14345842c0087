// The JavaScript engines' adapters (web/src/engines/*.js, docs/explorer.md "JavaScript
// engines", docs/flipcheck.md "Any engine") under node, each mode of each: what the page and
// web/flipcheck-engines.mjs ask of an engine (web/src/engines/engine.js: no damping, one step
// of the given dt per call, the quaternion (w, x, y, z) body → world), checked against the
// motion of a free rigid body in closed form:
//   - a spin about a principal axis is steady (ω × Iω = 0): after 1000 steps |ω| is its start's
//     (any damping, an engine's default included, lowers it), and after k steps the body has
//     turned by |ω|·k·dt about that axis, the quaternion (cos θ/2, 0, 0, sin θ/2), from the
//     first step on (an engine stepped at its own default step, or by a fixed step of its own
//     with the remainder carried to the next call, turns by another angle);
//   - from a start off every axis, the engines without a gyroscopic term (docs/explorer.md:
//     cannon-es, Jolt without mApplyGyroscopicForce, Havok, oimo) keep ω fixed in the world,
//     and those with it (Rapier, Jolt with the flag, Ammo.js, MuJoCo with each integrator) keep
//     the angular momentum L = R I Rᵀ ω fixed in the world while ω moves.
// Skipped (77) where web/node_modules lacks a package (scripts/install-deps.sh); a failure
// under CI=true. About 5 s.
// Usage: node tests/web/engines_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/engines_test.mjs SOURCE_DIR');
const web = join(source, 'web');
const PACKAGES = ['cannon-es', '@dimforge/rapier3d-compat', 'jolt-physics', '@babylonjs/havok',
  'ammo.js', 'oimo', 'mujoco-js'];
const absent = PACKAGES.filter((p) => !existsSync(join(web, 'node_modules', p, 'package.json')));
if (absent.length) {
  console.log(`skipped: ${absent.join(', ')} not in web/node_modules (scripts/install-deps.sh)`);
  process.exit(process.env.CI === 'true' ? 1 : 77);
}
const load = (file) => import(pathToFileURL(join(web, 'src', 'engines', file)).href);
const { cannon } = await load('cannon.js');
const { rapier } = await load('rapier.js');
const { jolt, joltGyroscopic } = await load('jolt.js');
const { havok } = await load('havok.js');
const { ammo } = await load('ammo.js');
const { oimo } = await load('oimo.js');
const { mujocoEuler, mujocoRk4, mujocoImplicit, mujocoImplicitfast } = await load('mujoco.js');
havok.wasmBinary = readFileSync(join(web, 'node_modules', '@babylonjs', 'havok', 'lib', 'esm', 'HavokPhysics.wasm'));
const WITHOUT_GYROSCOPIC_TERM = [cannon, jolt, havok, oimo];
const WITH_IT = [rapier, joltGyroscopic, ammo, mujocoEuler, mujocoRk4, mujocoImplicit, mujocoImplicitfast];
const ENGINES = [...WITHOUT_GYROSCOPIC_TERM, ...WITH_IT];
for (const e of ENGINES) await e.load();
const name = (e) => e.label;

// A body with three different moments (mass·length²), its box's edges, and a step that is none
// of the engines' defaults (1/60 for Rapier, oimo and Bullet's fixed step; 0.002 for MuJoCo).
const MOMENTS = [1, 2, 3];
const BODY = { mass: 1, moments: MOMENTS, size: [2.2, 1.8, 0.6] };
const DT = 0.01;
const norm = (v) => Math.hypot(...v);

/** R (rows) of the unit quaternion (w, x, y, z), body → world. */
function rotation([w, x, y, z]) {
  return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
    [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
    [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]];
}
const times = (M, v) => M.map((row) => row[0] * v[0] + row[1] * v[1] + row[2] * v[2]);
const transpose = (M) => [0, 1, 2].map((j) => M.map((row) => row[j]));
/** L in the world: R I Rᵀ ω (ω in the world). */
function momentum(q, omega) {
  const R = rotation(q);
  const body = times(transpose(R), omega);
  return times(R, body.map((w, i) => MOMENTS[i] * w));
}

test('a spin about a principal axis keeps its rate and turns by |ω|·t from the first step', () => {
  const rate = 2;
  for (const engine of ENGINES) {
    const run = engine.start({ ...BODY, omega0: [0, 0, rate] }, DT);
    try {
      for (let k = 1; k <= 1000; ++k) {
        run.step();
        if (k > 20 && k % 100 !== 0) continue;
        const q = run.quaternion();
        const theta = rate * k * DT;
        const want = [Math.cos(theta / 2), 0, 0, Math.sin(theta / 2)];
        const s = Math.sign(q.reduce((sum, c, i) => sum + c * want[i], 0)) || 1;  // q and −q: one rotation
        const err = Math.max(...q.map((c, i) => Math.abs(s * c - want[i])));
        // A component of q is off by half the angle's error: 1e-3 of the angle allowed (a
        // first-order step's own error is (ω dt)²/12 of it).
        assert.ok(err < 5e-4 * theta + 1e-6, `${name(engine)}: after ${k} steps of ${DT} q = ${q}, ` +
          `expected a turn of ${theta} about z, (w, x, y, z) = ${want}`);
      }
      // Undamped, |ω| loses nothing: a damping c takes e^(−c t) of it, 1 % at c = 0.001 per time
      // unit. (Rapier's step gains a little: 4e-4 of |ω| here, its energy rise of
      // docs/explorer.md; Jolt's gyroscopic step leaves 1e-5 of |ω| off the axis, single
      // precision.)
      const w = run.omegaWorld();
      const gain = norm(w) / rate - 1;
      console.log(`${name(engine)}: |ω| after 10 time units ${gain.toExponential(2)} from its start`);
      assert.ok(gain > -1e-5 && gain < 1e-3 && Math.abs(w[0]) + Math.abs(w[1]) < 1e-4 * rate,
        `${name(engine)}: ω = ${w} after 10 time units of a steady spin at ${rate} about z`);
    } finally {
      run.dispose();
    }
  }
});

test('off every axis: ω fixed in the world without the gyroscopic term, L fixed with it', () => {
  const omega0 = [0.4, 0.3, 2];
  const L0 = omega0.map((w, i) => MOMENTS[i] * w);
  for (const engine of ENGINES) {
    const run = engine.start({ ...BODY, omega0 }, DT);
    try {
      for (let k = 0; k < 200; ++k) run.step();
      const w = run.omegaWorld(), q = run.quaternion();
      const wMoved = norm(w.map((x, i) => x - omega0[i])) / norm(omega0);
      const L = momentum(q, w);
      const lMoved = norm(L.map((x, i) => x - L0[i])) / norm(L0);
      console.log(`${name(engine)}: ω moved ${wMoved.toExponential(2)}, L moved ${lMoved.toExponential(2)} of its start`);
      if (WITHOUT_GYROSCOPIC_TERM.includes(engine)) {
        assert.ok(wMoved < 1e-5, `${name(engine)} has no gyroscopic term: ω fixed in the world, yet it moved ${wMoved} of |ω0|`);
      } else {
        assert.ok(lMoved < 1e-2 && wMoved > 0.05, `${name(engine)}: L moved ${lMoved} of |L0| (ω ${wMoved}): ` +
          'the gyroscopic term keeps L and turns ω');
      }
    } finally {
      run.dispose();
    }
  }
});
