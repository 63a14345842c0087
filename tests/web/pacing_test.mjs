// The page's catch-up to a time (web/src/pacing.js over web/src/runs.js, docs/explorer.md "Any
// link") under node: a time asked by the slider or a link is reached and the catch-up ends,
// whatever that time is, a whole number of steps of dt or not. The runs are the page's own Runs
// over stand-in sessions that count their steps (no physics needed: the page's time is its
// steps times dt). Seeded random times and steps, reproducible.
// Usage: node tests/web/pacing_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/pacing_test.mjs SOURCE_DIR');
const { Pacer } = await import(pathToFileURL(join(source, 'web/src/pacing.js')).href);
const { Runs } = await import(pathToFileURL(join(source, 'web/src/runs.js')).href);

/** A session that only counts its steps (Session's step, steps and diagnostics). */
function countingSession() {
  let steps = 0;
  return {
    steps: () => steps,
    step: (dt, n) => { steps += n; return true; },
    diagnostics: () => ({ momentum_direction: [1, 0, 0], omega_body: [1, 0, 0], energy_total: 1,
      orthogonality_error: 0 }),
  };
}

/** Runs (the page's own class) holding `count` runs over counting sessions. */
function countingRuns(count = 2) {
  const runs = new Runs(null, { models: ['rigid-matrix'] }, []);
  for (let i = 0; i < count; ++i) {
    runs.list.push({ session: countingSession(), engine: null, model: 'rigid-matrix', trail: [],
      history: [], diverged: '', closedForm: false });
  }
  return runs;
}

/** Mulberry32: a seeded generator of uniform numbers in [0, 1). */
function seeded(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Catches up to `target` as main.js does (a first piece, then a piece per frame), at most
 * `frames` frames; the notices shown and the frames taken. */
function catchUpTo(runs, state, target, frames = 1000) {
  const shown = [];
  const pacer = new Pacer((text) => shown.push(text));
  pacer.catchUp(runs, state, target, 200);
  let taken = 0;
  while (pacer.continue(runs, state) && taken < frames) taken += 1;
  return { pacer, shown, taken };
}

test('a time between two steps (the slider, a written link) is reached and the catch-up ends', () => {
  // The times that froze the page: fig09's slider at 8.20063603838946, the address written while playing.
  for (const [target, dt] of [[8.20063603838946, 1 / 60], [42.43333333333334, 1 / 60], [0.3, 0.004],
    [299.99999, 1 / 240]]) {
    const runs = countingRuns();
    const state = { t: 0, dt, speed: 5 };
    const { pacer, shown, taken } = catchUpTo(runs, state, target);
    const steps = Math.round(target / dt);
    assert.equal(pacer.target, null, `t = ${target}, dt = ${dt}: still catching up after ${taken} frames ` +
      `at t = ${state.t} (${shown.at(-1)})`);
    assert.ok(runs.list.every((r) => r.session.steps() === steps), `t = ${target}: steps ` +
      `${runs.list.map((r) => r.session.steps())}, not ${steps}`);
    assert.equal(state.t, steps * dt);
    assert.ok(!shown.at(-1).includes('simulating to'), `the notice still reads "${shown.at(-1)}"`);
  }
});

test('seeded random times and steps: every catch-up ends on the step nearest its time', () => {
  const random = seeded(80);
  for (let i = 0; i < 300; ++i) {
    const dt = [1 / 60, 1 / 240, 0.004, 0.01, 1e-3 * (1 + random())][i % 5];
    const target = 60 * random() * (random() < 0.2 ? 10 : 1);
    const runs = countingRuns(1 + (i % 3));
    const state = { t: 0, dt, speed: 5 };
    const { pacer } = catchUpTo(runs, state, target);
    assert.equal(pacer.target, null, `case ${i}: t = ${target}, dt = ${dt} never reached (at ${state.t})`);
    assert.ok(Math.abs(state.t - target) <= 0.5 * dt * (1 + 1e-9), `case ${i}: reached ${state.t} for ${target}`);
  }
});

test('Play after a catch-up to a time between two steps moves t on', () => {
  const runs = countingRuns();
  const state = { t: 0, dt: 1 / 60, speed: 5 };
  const { pacer } = catchUpTo(runs, state, 8.20063603838946);
  // A frame of main.js: a catch-up piece first, playing only when none is left.
  assert.equal(pacer.continue(runs, state), false, 'a catch-up piece still takes the frame');
  const before = state.t;
  pacer.play(runs, state, 10, 0);
  assert.ok(state.t > before, `t stayed at ${before} while playing`);
});
