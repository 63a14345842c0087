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
// Bad input (a scenario that is missing, not a regular file (a FIFO, a device: refused before it
// is opened) or that `bookspin flipcheck judge` refuses, in its words;
// an unknown option) and a missing npm package get one line, exit 2, with nothing written;
// --check says only whether the packages are there. An OUT that is no folder (a regular file, a
// FIFO, a device such as /dev/full) or a motion that cannot be written: one line naming it,
// `cannot write "OUT": reason`, exit 1, as npx says it (the npm package's makeOutputFolder).
//
// Usage: node web/flipcheck-engines.mjs [--check] [--refine K] [--only NAME,...] [--flipcheck DIR] OUT SCENARIO.json...
//   --flipcheck DIR (or FLIPCHECK_PACKAGE=DIR): the npm package flipcheck (`make npm`:
//     BUILD/npm/package), whose readScenario reads every scenario: the one reader of
//     `bookspin flipcheck judge`, Python and npx, so a bad scenario is refused here in their words.
//   --refine K: each scenario at dt/K, K times the steps, rows at the same times (the motions
//     named ...+dt-over-K): what a smaller step does (docs/flipcheck.md, "What an engine's user
//     should do"); not in `make figures`.
//   --only NAME,...: only the engines whose motion name (without the version) is listed, e.g.
//     babylonjs-havok,jolt-physics+gyroscopic.
import { createHash } from 'node:crypto';
import { existsSync, readFileSync, readdirSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const MAX_ROWS = 20000;
// The engines need a collision shape; its size does not enter the motion, since every adapter
// is given the moments explicitly (web/src/engines/engine.js). A unit cube.
const SHAPE = [1, 1, 1];
const WEB = fileURLToPath(new URL('.', import.meta.url));
// The npm packages the adapters import (web/package.json; scripts/install-deps.sh installs
// them), checked before any adapter is imported.
const PACKAGES = ['cannon-es', '@dimforge/rapier3d-compat', 'jolt-physics', '@babylonjs/havok',
  'ammo.js', 'oimo', 'mujoco-js'];

/** Bad input or a missing package: one line, exit 2, nothing written. */
const refuse = (line) => {
  console.error(`flipcheck-engines: ${line}`);
  process.exit(2);
};
const usage = () => refuse('usage: node web/flipcheck-engines.mjs [--check] [--refine K] [--only NAME,...] [--flipcheck DIR] OUT SCENARIO.json...');
const args = process.argv.slice(2);
let refine = 1, only = null, check = false, flipcheck = process.env.FLIPCHECK_PACKAGE || null;
while (args.length && args[0].startsWith('--')) {
  if (args[0] === '--check') {
    args.shift();
    check = true;
    continue;
  }
  const [flag, value] = args.splice(0, 2);
  if (flag === '--refine' && /^[1-9][0-9]*$/.test(value ?? '')) refine = Number(value);
  else if (flag === '--only' && value) only = value.split(',');
  else if (flag === '--flipcheck' && value) flipcheck = value;
  else usage();
}
const absent = PACKAGES.filter((p) => !existsSync(join(WEB, 'node_modules', p, 'package.json')));
if (absent.length > 0)
  refuse(`the npm package${absent.length > 1 ? 's' : ''} ${absent.join(', ')} ` +
         `${absent.length > 1 ? 'are' : 'is'} not installed in ${join(WEB, 'node_modules')} ` +
         `(scripts/install-deps.sh installs ${absent.length > 1 ? 'them' : 'it'}: npm ci in web/)`);
// --check: only whether every package is in place (scripts/figures.sh asks before it runs this).
if (check) {
  console.log(`flipcheck-engines: the ${PACKAGES.length} packages are in place`);
  process.exit(0);
}
const [out, ...scenarios] = args;
if (!out || scenarios.length === 0) usage();

/** A module of the adapters, imported now that its package is known to be there. */
const adapter = async (file) => {
  try {
    return await import(`./src/engines/${file}`);
  } catch (e) {
    refuse(`web/src/engines/${file}: ${String(e.message).split('\n')[0]} ` +
           '(scripts/install-deps.sh installs the packages again: npm ci in web/)');
  }
};
const { cannon } = await adapter('cannon.js');
const { rapier } = await adapter('rapier.js');
const { jolt, joltGyroscopic } = await adapter('jolt.js');
const { havok } = await adapter('havok.js');
const { ammo } = await adapter('ammo.js');
const { oimo } = await adapter('oimo.js');
const { mujocoEuler, mujocoRk4, mujocoImplicit, mujocoImplicitfast } = await adapter('mujoco.js');
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
/** The npm package flipcheck (`make npm`: BUILD/npm/package, or an installed
 * node_modules/flipcheck), whose readScenario is the one reader of a scenario JSON that
 * `bookspin flipcheck judge`, Python and npx read it with (analysis::scenario_from_json,
 * compiled): a scenario this runner takes, every door takes; one it refuses, every door refuses
 * in the same words. Imported once the engines' packages are known to be there. */
const reader = async () => {
  if (!flipcheck) refuse('the npm package flipcheck, the scenario reader, is not named: ' +
                         '--flipcheck DIR or FLIPCHECK_PACKAGE=DIR (make npm builds BUILD/npm/package)');
  const index = join(flipcheck, 'index.mjs');
  if (!existsSync(index)) refuse(`${flipcheck}: no npm package flipcheck there (no index.mjs; make npm builds BUILD/npm/package)`);
  const files = await import(pathToFileURL(join(flipcheck, 'files.mjs')).href);
  return [(await import(pathToFileURL(index).href)).readScenario, files.notAFileReason,
    files.makeOutputFolder, files.readReason];
};
const [readScenario, notAFileReason, makeOutputFolder, readReason] = await reader();
/** An output that cannot be written: one line naming it, exit 1 (npx's words and status). */
const cannotWrite = (path, why) => {
  console.error(`flipcheck-engines: error: cannot write "${path}": ${why}`);
  process.exit(1);
};
/** writeFileSync, or the one line naming `path` and exit 1 (a full disk, /dev/full). */
const write = (path, text) => {
  try {
    writeFileSync(path, text);
  } catch (e) {
    cannotWrite(path, { ENOSPC: 'No space left on device', EACCES: 'Permission denied' }[e.code] ?? e.message);
  }
};
/** A scenario file's JSON read by the one reader, or its one line naming the file. Only a
 * regular file is opened (a FIFO with no writer or a device is refused, never waited on). */
const scenarioOf = (file) => {
  let text;
  try {
    const why = notAFileReason(statSync(file));
    if (why) refuse(`${file}: ${why}`);
    text = readFileSync(file, 'utf8');
  } catch (e) {
    refuse(`${file}: ${readReason(e)}`);
  }
  try {
    return readScenario(text, file);
  } catch (e) {
    refuse(e.message);
  }
};
const parsed = scenarios.map((file) => [file, scenarioOf(file)]);
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

const notAFolder = makeOutputFolder(out);
if (notAFolder) cannotWrite(out, notAFolder);
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
    write(join(out, name), lines.join('\n') + '\n');
    console.log(`${basename(file)}: ${engine.label}: ${lines.length - 1} rows (stride ${stride}) -> ${name}`);
  }
}
write(manifestPath, manifest);
