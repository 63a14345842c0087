// The conformance kit run by outside engines (docs/flipcheck.md, "Any engine"): every
// JavaScript engine pinned by web/package-lock.json (the page's adapters of web/src/engines/:
// cannon-es, Rapier, Jolt without and with mApplyGyroscopicForce, Havok; and, under node only,
// Ammo.js, oimo and MuJoCo's WebAssembly module with each of its integrators) runs every
// scenario that `bookspin flipcheck export` wrote, from nothing but the scenario's JSON (mass,
// principal moments, ω0 in the world frame, dt, steps), and writes the motion file that
// `bookspin flipcheck judge` reads: t,qw,qx,qy,qz,wx_world,wy_world,wz_world, the start and
// then every `stride` steps, the smallest divisor of the steps that keeps to MAX_ROWS rows after
// the start (judge takes any stride; a whole number of them reaches the scenario's last step).
// Nothing here measures: the judging is bookspin's.
//
// Each file is named <scenario>-<package>@<version>[+<mode>].csv, the package's name with its
// scope's '@' dropped and '/' as '-' (babylonjs-havok@1.3.14, jolt-physics@1.1.0+gyroscopic),
// the version read from the installed package's package.json: the league's row names the
// package and version that made it.
//
// Cached like every product: OUT/manifest.json records the SHA-256 of each scenario JSON, of
// the lockfile, of this script and of every adapter, and node's version; when it is unchanged
// and every motion file is in place, nothing is run or written ("up to date"). Otherwise OUT's
// motion files are all written again and any other CSV there is removed.
//
// Usage: node web/flipcheck-engines.mjs [--refine K] [--only NAME,...] OUT SCENARIO.json...
//   --refine K: each scenario at dt/K, K times the steps, rows at the same times (the motions
//     named ...+dt-over-K): what a smaller step does (docs/flipcheck.md, "What an engine's user
//     should do"); not in `make figures`.
//   --only NAME,...: only the engines whose motion name (without the version) is listed, e.g.
//     babylonjs-havok,jolt-physics+gyroscopic.
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { cannon } from './src/engines/cannon.js';
import { rapier } from './src/engines/rapier.js';
import { jolt, joltGyroscopic } from './src/engines/jolt.js';
import { havok } from './src/engines/havok.js';
import { ammo } from './src/engines/ammo.js';
import { oimo } from './src/engines/oimo.js';
import { mujocoEuler, mujocoRk4, mujocoImplicit, mujocoImplicitfast } from './src/engines/mujoco.js';

const MAX_ROWS = 20000;
// The engines need a collision shape; its size does not enter the motion, since every adapter
// is given the moments explicitly (web/src/engines/engine.js). A unit cube.
const SHAPE = [1, 1, 1];
const WEB = fileURLToPath(new URL('.', import.meta.url));

const usage = () => {
  console.error('usage: node web/flipcheck-engines.mjs [--refine K] [--only NAME,...] OUT SCENARIO.json...');
  process.exit(2);
};
const args = process.argv.slice(2);
let refine = 1, only = null;
while (args.length && args[0].startsWith('--')) {
  const [flag, value] = args.splice(0, 2);
  if (flag === '--refine' && /^[1-9][0-9]*$/.test(value ?? '')) refine = Number(value);
  else if (flag === '--only' && value) only = value.split(',');
  else usage();
}
const [out, ...scenarios] = args;
if (!out || scenarios.length === 0) usage();
const packageSlug = (e) => e.package.replace(/^@/, '').replace('/', '-');
const engines = [cannon, rapier, jolt, joltGyroscopic, havok, ammo, oimo,
  mujocoEuler, mujocoRk4, mujocoImplicit, mujocoImplicitfast]
  .filter((e) => !only || only.includes(packageSlug(e) + (e.mode ? `+${e.mode}` : '')));
if (engines.length === 0) usage();

/** The installed package's version (web/node_modules/<package>/package.json). */
const version = (pkg) => JSON.parse(readFileSync(join(WEB, 'node_modules', pkg, 'package.json'), 'utf8')).version;
/** The motion's name: the package and version that made it, and the mode. */
const motionName = (e) => `${packageSlug(e)}@${version(e.package)}` + (e.mode ? `+${e.mode}` : '') +
  (refine > 1 ? `+dt-over-${refine}` : '');

const sha256 = (file) => createHash('sha256').update(readFileSync(file)).digest('hex');
const inputs = [join(WEB, 'package-lock.json'), fileURLToPath(import.meta.url),
  ...readdirSync(join(WEB, 'src', 'engines')).sort().map((f) => join(WEB, 'src', 'engines', f))];
const parsed = scenarios.map((file) => [file, JSON.parse(readFileSync(file, 'utf8'))]);
const outputs = parsed.flatMap(([, s]) => engines.map((e) => `${s.scenario}-${motionName(e)}.csv`));
const manifest = JSON.stringify({
  node: process.version,
  inputs: Object.fromEntries(inputs.map((f) => [basename(f), sha256(f)])),
  scenarios: Object.fromEntries(scenarios.map((f) => [basename(f), sha256(f)])),
  refine,
  motions: outputs,
}, null, 1) + '\n';
const manifestPath = join(out, 'manifest.json');
if (existsSync(manifestPath) && readFileSync(manifestPath, 'utf8') === manifest &&
    outputs.every((f) => existsSync(join(out, f)))) {
  console.log(`flipcheck engines: ${outputs.length} motions up to date in ${out}`);
  process.exit(0);
}

mkdirSync(out, { recursive: true });
rmSync(manifestPath, { force: true });
for (const f of readdirSync(out)) if (f.endsWith('.csv')) rmSync(join(out, f));
havok.wasmBinary = readFileSync(join(WEB, 'node_modules', '@babylonjs', 'havok', 'lib', 'esm', 'HavokPhysics.wasm'));
for (const e of engines) await e.load();

/** A number as the CSV holds it: shortest round-trip form (JavaScript's own). */
const text = (x) => {
  if (!Number.isFinite(x)) throw new Error(`non-finite value ${x} in a motion`);
  return String(x);
};

for (const [file, s] of parsed) {
  let stride = Math.max(1, Math.ceil(s.steps / MAX_ROWS));
  while (s.steps % stride !== 0) ++stride;
  const dt = s.dt / refine, steps = s.steps * refine;
  stride *= refine;
  const body = { mass: s.mass, moments: s.principal_moments, size: SHAPE, omega0: s.omega0_world };
  for (const engine of engines) {
    const run = engine.start(body, dt);
    const lines = ['t,qw,qx,qy,qz,wx_world,wy_world,wz_world'];
    const row = (step) => {
      const q = run.quaternion(), w = run.omegaWorld();
      lines.push([(step / refine) * s.dt, ...q, ...w].map(text).join(','));
    };
    row(0);
    for (let step = 1; step <= steps; ++step) {
      run.step();
      if (step % stride !== 0) continue;
      try {
        row(step);
      } catch {
        break;  // the file ends where the engine blew up; judge says so
      }
    }
    run.dispose();
    const name = `${s.scenario}-${motionName(engine)}.csv`;
    writeFileSync(join(out, name), lines.join('\n') + '\n');
    console.log(`${basename(file)}: ${engine.label}: ${lines.length - 1} rows (stride ${stride}) -> ${name}`);
  }
}
writeFileSync(manifestPath, manifest);
