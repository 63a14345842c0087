// cannon-es judged by flipcheck in every scenario, under node's own test runner (node --test).
import { test } from "node:test";
import assert from "node:assert/strict";
import { World, Body, Box, Vec3 } from "cannon-es";
import { scenarios, scenario, judge } from "flipcheck";

function run(s) { // the engine stepped from the scenario's start: t, q (w, x, y, z), omegaWorld
  const world = new World({ gravity: new Vec3(0, 0, 0), allowSleep: false });
  const body = new Body({ mass: s.mass, shape: new Box(new Vec3(0.5, 0.5, 0.5)), linearDamping: 0, angularDamping: 0 });
  body.inertia.set(...s.principal_moments); body.invInertia.set(...s.principal_moments.map((i) => 1 / i));
  body.updateInertiaWorld(true); body.angularVelocity.set(...s.omega0_world); world.addBody(body);
  const t = new Float64Array(s.steps + 1), q = new Float64Array(4 * t.length), omegaWorld = new Float64Array(3 * t.length);
  for (let n = 0; n <= s.steps; world.step(s.dt), n++) {
    const { w, x, y, z } = body.quaternion; t[n] = n * s.dt; q.set([w, x, y, z], 4 * n); omegaWorld.set(body.angularVelocity.toArray(), 3 * n);
  }
  return { t, q, omegaWorld };
}

for (const name of scenarios()) // cannon-es has no gyroscopic term: omega stays fixed in the world
  test(`cannon-es in ${name}`, () => {
    const j = judge(name, run(scenario(name)));
    assert.deepEqual([j.verdict, j.flips], ["fail", 0], j.line); // fails, and never turns the book over
  });
