// The judge panel's replay (web/src/replay.js, docs/explorer.md "Judge a motion") under node,
// on a canvas that records what is drawn: each row's pose as the quaternion (w, x, y, z) the
// module gives (web/judge_bindings.cpp, motionPoses), and the row shown at each moment of the
// 20 s the whole motion takes. The expected boxes come from rotations written here as an axis
// and an angle (Rodrigues' formula), never from a quaternion read by the code under test.
// Usage: node tests/web/replay_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/replay_test.mjs SOURCE_DIR');

/** A 2D context that keeps every filled polygon ({colour, points}) and every text. */
function recordingContext() {
  const ctx = { polygons: [], texts: [], path: [], fillStyle: '', strokeStyle: '', font: '',
    textAlign: '', globalAlpha: 1 };
  Object.assign(ctx, {
    setTransform() {}, clearRect() {}, stroke() {}, closePath() {},
    beginPath() { ctx.path = []; },
    moveTo(x, y) { ctx.path.push([x, y]); },
    lineTo(x, y) { ctx.path.push([x, y]); },
    fill() { ctx.polygons.push({ colour: ctx.fillStyle, points: ctx.path.slice() }); },
    fillText(text) { ctx.texts.push(text); },
  });
  return ctx;
}

/** The page's globals replay.js uses, with a clock the test sets (ms). */
const clock = { now: 0, frames: [] };
globalThis.window = { devicePixelRatio: 1 };
globalThis.requestAnimationFrame = (f) => { clock.frames.push(f); return clock.frames.length; };
globalThis.cancelAnimationFrame = () => {};
Object.defineProperty(globalThis, 'performance', { value: { now: () => clock.now }, configurable: true });

const { Replay } = await import(pathToFileURL(join(source, 'web/src/replay.js')).href);

const W = 800, H = 300;
function replayOn() {
  const ctx = recordingContext();
  const canvas = { clientWidth: W, clientHeight: H, width: 0, height: 0, hidden: true, getContext: () => ctx };
  const label = { textContent: '' };
  return { replay: new Replay(canvas, label), ctx, label };
}

/** R (3×3, rows) of the rotation by `angle` about the unit `axis`: Rodrigues' formula. */
function rodrigues(axis, angle) {
  const n = Math.hypot(...axis), [x, y, z] = axis.map((v) => v / n);
  const c = Math.cos(angle), s = Math.sin(angle), C = 1 - c;
  return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
    [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
    [z * x * C - y * s, z * y * C + x * s, c + z * z * C]];
}
/** The unit quaternion (w, x, y, z) of the same rotation: cos(θ/2), sin(θ/2)·axis. */
function quaternion(axis, angle) {
  const n = Math.hypot(...axis);
  return [Math.cos(angle / 2), ...axis.map((v) => (Math.sin(angle / 2) * v) / n)];
}

// A book with three different edges, so that a box turned wrongly is drawn wider or narrower.
const SIZE = [1, 3, 0.5];
const scene = { book: { size: SIZE } };
const FRONT = '#2b4c8c', BACK = '#3a5ea8';  // the covers, body +z and −z, as the 3D view draws them

/** The width on screen of the polygons drawn left (x < W/2) or right of the middle. */
function width(polygons, left) {
  const xs = polygons.filter((p) => (p.points[0][0] < W / 2) === left).flatMap((p) => p.points.map(([x]) => x));
  return Math.max(...xs) - Math.min(...xs);
}

test('each row is drawn turned by its quaternion (w, x, y, z), body to world', () => {
  // Axis and angle; the replay's view looks along +y from a little above (replay.js's box()),
  // so a cover whose normal points to −y is seen and one to +y is not.
  const cases = [
    { axis: [0, 0, 1], angle: Math.PI / 2, cover: FRONT },     // x → y, y → −x: width b
    { axis: [1, 0, 0], angle: Math.PI / 2, cover: FRONT },     // +z → −y: the front cover faces us
    { axis: [1, 0, 0], angle: -Math.PI / 2, cover: BACK },     // +z → +y: the back cover faces us
    { axis: [1, 2, 3], angle: 0.9, cover: null },
    { axis: [-2, 0.5, 1], angle: 2.4, cover: null },
  ];
  for (const { axis, angle, cover } of cases) {
    const { replay, ctx } = replayOn();
    replay.poses = { t: [0], q: quaternion(axis, angle), qExact: [1, 0, 0, 0] };
    replay.half = SIZE.map((s) => s / 2);
    replay.draw(0);
    const R = rodrigues(axis, angle);
    // The box's extent along world x: Σ_j |R_xj|·edge_j; the unturned box's is edge a.
    const want = R[0].reduce((sum, r, j) => sum + Math.abs(r) * SIZE[j], 0) / SIZE[0];
    const got = width(ctx.polygons, true) / width(ctx.polygons, false);
    assert.ok(Math.abs(got - want) < 1e-9, `turned by ${angle} about ${axis}: drawn ${got} times as wide as the unturned box, expected ${want}`);
    const covers = ctx.polygons.filter((p) => p.points[0][0] < W / 2 && (p.colour === FRONT || p.colour === BACK)).map((p) => p.colour);
    if (cover) assert.deepEqual(covers, [cover], `turned by ${angle} about ${axis}: covers drawn ${covers}`);
  }
});

test('between two rows the replay shows the earlier one, the whole motion in 20 s', () => {
  const n = 8;
  const t = Array.from({ length: n }, (_, i) => 0.25 * i);
  // Row i turned by i·10° about z, drawn beside the unturned box: its width on screen,
  // cos θ·a + sin θ·b, grows with i (θ below atan(b/a) = 71.6°), so the row drawn is read back
  // from the width, and from the label's time.
  const angle = (i) => (i * 10 * Math.PI) / 180;
  const widthOf = (i) => Math.cos(angle(i)) * SIZE[0] + Math.sin(angle(i)) * SIZE[1];
  const q = t.flatMap((_, i) => quaternion([0, 0, 1], angle(i)));
  const qExact = t.flatMap(() => [1, 0, 0, 0]);
  const { replay, ctx, label } = replayOn();
  clock.now = 1000;
  clock.frames = [];
  replay.start({ t, q, qExact }, scene);
  const playSeconds = 20;
  for (let i = 0; i < n; ++i) {
    for (const part of [0.01, 0.5, 0.99]) {
      clock.now = 1000 + ((i + part) / n) * playSeconds * 1000;
      ctx.polygons = [];
      clock.frames.shift()();
      const ratio = width(ctx.polygons, true) / width(ctx.polygons, false) / SIZE[0];
      const drawn = t.map((_, k) => Math.abs(ratio - widthOf(k))).reduce((best, e, k, all) => (e < all[best] ? k : best), 0);
      assert.equal(drawn, i, `${part} of the way from row ${i} to the next, row ${drawn} is drawn`);
      assert.ok(Math.abs(ratio - widthOf(i)) < 1e-9);
      assert.equal(label.textContent, `t = ${t[i].toFixed(2)}`, `${part} of the way from row ${i} to the next`);
    }
  }
  replay.stop();
});
