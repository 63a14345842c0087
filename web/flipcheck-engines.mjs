// The conformance kit run by outside engines (docs/flipcheck.md, "Any engine"): every
// JavaScript engine of the page (web/src/engines/: cannon-es, Rapier, Jolt without and with
// mApplyGyroscopicForce, the npm packages of web/package-lock.json) runs every scenario that
// `bookspin flipcheck export` wrote, from nothing but the scenario's JSON (mass, principal
// moments, ω0 in the world frame, dt, steps), and writes the motion file that `bookspin
// flipcheck judge` reads: t,qw,qx,qy,qz,wx_world,wy_world,wz_world, the start and then every
// `stride` steps, the smallest divisor of the steps that keeps to MAX_ROWS rows after the start
// (judge takes any stride; a whole number of them reaches the scenario's last step).
// Nothing here measures: the judging is bookspin's.
//
// Usage: node web/flipcheck-engines.mjs OUT SCENARIO.json...
//   writes OUT/<scenario>-<engine>.csv (engine: cannon-es, rapier, jolt, jolt-gyroscopic)
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { cannon } from './src/engines/cannon.js';
import { rapier } from './src/engines/rapier.js';
import { jolt, joltGyroscopic } from './src/engines/jolt.js';

const MAX_ROWS = 20000;
// The engines need a collision shape; its size does not enter the motion, since every adapter
// is given the moments explicitly (web/src/engines/engine.js). A unit cube.
const SHAPE = [1, 1, 1];

const [out, ...scenarios] = process.argv.slice(2);
if (!out || scenarios.length === 0) {
  console.error('usage: node web/flipcheck-engines.mjs OUT SCENARIO.json...');
  process.exit(2);
}
mkdirSync(out, { recursive: true });
const engines = [cannon, rapier, jolt, joltGyroscopic];
for (const e of engines) await e.load();

/** A number as the CSV holds it: shortest round-trip form (JavaScript's own). */
const text = (x) => {
  if (!Number.isFinite(x)) throw new Error(`non-finite value ${x} in a motion`);
  return String(x);
};

for (const file of scenarios) {
  const s = JSON.parse(readFileSync(file, 'utf8'));
  let stride = Math.max(1, Math.ceil(s.steps / MAX_ROWS));
  while (s.steps % stride !== 0) ++stride;
  const body = { mass: s.mass, moments: s.principal_moments, size: SHAPE, omega0: s.omega0_world };
  for (const engine of engines) {
    const run = engine.start(body, s.dt);
    const lines = ['t,qw,qx,qy,qz,wx_world,wy_world,wz_world'];
    const row = (step) => {
      const q = run.quaternion(), w = run.omegaWorld();
      lines.push([step * s.dt, ...q, ...w].map(text).join(','));
    };
    row(0);
    for (let step = 1; step <= s.steps; ++step) {
      run.step();
      if (step % stride !== 0) continue;
      try {
        row(step);
      } catch {
        break;  // the file ends where the engine blew up; judge says so
      }
    }
    run.dispose();
    const name = `${s.scenario}-${engine.model}.csv`;
    writeFileSync(join(out, name), lines.join('\n') + '\n');
    console.log(`${basename(file)}: ${engine.label}: ${lines.length - 1} rows (stride ${stride}) -> ${name}`);
  }
}
