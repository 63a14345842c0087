// Run inside the temporary project where the npm package `flipcheck` and cannon-es are installed
// (tests/npm/npm_package_test.py): cannon-es stepped from every scenario's start, as
// examples/flipcheck-npm/engine.test.mjs steps it, each motion written as the CSV `judge` reads
// (a row every stride steps, at most 20000 rows) and judged by the package twice, as arrays and
// as that CSV's text; and the package's errors for bad input. Usage: node cannon_motions.mjs OUT
import { writeFileSync } from "node:fs";
import { World, Body, Box, Vec3 } from "cannon-es";
import { scenarios, scenario, judge, judgeCsv } from "flipcheck";

const out = process.argv[2];
const result = { judged: {}, errors: {} };
for (const name of scenarios()) {
  const s = scenario(name);
  let stride = Math.ceil(s.steps / 20000);
  while (s.steps % stride) stride++;
  const world = new World({ gravity: new Vec3(0, 0, 0), allowSleep: false });
  const body = new Body({ mass: s.mass, shape: new Box(new Vec3(0.5, 0.5, 0.5)), linearDamping: 0, angularDamping: 0 });
  body.inertia.set(...s.principal_moments);
  body.invInertia.set(...s.principal_moments.map((i) => 1 / i));
  body.updateInertiaWorld(true);
  body.angularVelocity.set(...s.omega0_world);
  world.addBody(body);
  const t = [], q = [], omegaWorld = [], lines = ["t,qw,qx,qy,qz,wx_world,wy_world,wz_world"];
  for (let n = 0; n <= s.steps; world.step(s.dt), n++) {
    if (n % stride) continue;
    const { w, x, y, z } = body.quaternion;
    const row = [n * s.dt, w, x, y, z, ...body.angularVelocity.toArray()];
    t.push(row[0]); q.push(row.slice(1, 5)); omegaWorld.push(row.slice(5));
    lines.push(row.map(String).join(","));
  }
  const file = `${name}-cannon-es.csv`;
  const text = lines.join("\n") + "\n";
  writeFileSync(`${out}/${file}`, text);
  result.judged[name] = {
    file,
    arrays: judge(name, { t, q, omegaWorld }, { motion: file }),
    csv: judgeCsv(name, text, { file }),
  };
}
const tryIt = (f) => { try { f(); return null; } catch (e) { return e instanceof Error ? e.message : `not an Error: ${e}`; } };
result.errors.nan = tryIt(() => judgeCsv("mujoco-test-box", "t,qw,qx,qy,qz,wx,wy,wz\n0,1,0,0,0,1,2,3\n0.01,1,0,0,0,nan,2,3\n", { file: "nan.csv" }));
result.errors.shape = tryIt(() => judge("mujoco-test-box", { t: [0], q: [1, 0, 0, 0], omegaWorld: [1, 2] }));
result.errors.scenario = tryIt(() => scenario("no-such-scenario"));
// q as a BigInt64Array, and a scenario that is JSON null: each named (they were "Cannot convert
// a BigInt value to a number" and 'no scenario "null"').
result.errors.bigint = tryIt(() => judge("mujoco-test-box", { t: [0], q: new BigInt64Array([1n, 0n, 0n, 0n]), omegaWorld: [1, 2, 3] }));
result.errors.nullScenario = tryIt(() => judge(null, { t: [0], q: [1, 0, 0, 0], omegaWorld: [1, 2, 3] }));
writeFileSync(`${out}/judgements.json`, JSON.stringify(result));
