// The explorer's plots' axes (web/src/plots.js): round ticks (steps of 1, 2 or 5 × 10ⁿ) within
// a panel's range, and their labels with the decimals the step needs, or m×10ⁿ for a drift of
// round-off size. The expected ticks are worked out here by hand.
// Usage: node tests/web/plots_ticks_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/plots_ticks_test.mjs SOURCE_DIR');
const { niceTicks, tickLabel } = await import(pathToFileURL(join(source, 'web/src/plots.js')).href);

const labels = (lo, hi, count) => {
  const { ticks, step } = niceTicks(lo, hi, count);
  return ticks.map((v) => tickLabel(v, step));
};

test('ω in rad per time unit: tens, or twos across a narrower range', () => {
  assert.deepEqual(labels(-12.3, 15.1, 4), ['-10', '0', '10']);
  assert.deepEqual(labels(-3.1, 4.2, 4), ['-2', '0', '2', '4']);
  assert.deepEqual(labels(0.99, 1.01, 4), ['0.99', '1.00', '1.01']);
});

test('a drift of round-off size is written m×10ⁿ, zero as 0', () => {
  assert.deepEqual(labels(-1e-6, 1e-6, 4), ['-1e-6', '-5e-7', '0', '5e-7', '1e-6']);
  assert.deepEqual(labels(-3e-7, 2e-6, 2), ['0', '2e-6']);  // 2.3e-6 in two steps: 2e-6
  // A tick between powers of ten keeps its digit: 1.5e-3, not 2e-3 (its step 5e-4).
  assert.deepEqual(labels(0, 2e-3, 4), ['0', '5e-4', '1e-3', '1.5e-3', '2e-3']);
});

test('time from 0: every tick inside the range, none beyond it', () => {
  const { ticks, step } = niceTicks(0, 37.5, 4);
  assert.equal(step, 10);
  assert.deepEqual(ticks, [0, 10, 20, 30]);
  for (const [lo, hi] of [[0, 1], [-7.7, 0.3], [123, 456], [1e-9, 3e-9]]) {
    const t = niceTicks(lo, hi, 3);
    assert.ok(t.ticks.length >= 2 && t.ticks.length <= 4, `${lo}…${hi}: ${t.ticks}`);
    for (const v of t.ticks) assert.ok(v >= lo - 1e-12 * Math.abs(hi) && v <= hi * (1 + 1e-12) + 1e-300, `${v} in ${lo}…${hi}`);
  }
});

test('every axis has at least two labelled ticks, different, within its range', () => {
  // fig09 at t = 227 at 1280×720: a panel's range of -0.2 to 0.9 in two steps was 0 alone.
  assert.deepEqual(labels(-0.2, 0.9, 2), ['0', '0.5']);
  assert.deepEqual(labels(17.81, 17.825, 3), ['17.81', '17.82']);
  // Seeded ranges of every size and place (a linear congruential generator: the same each run).
  let seed = 87;
  const random = () => { seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648; };
  for (let k = 0; k < 20000; ++k) {
    const span = 10 ** (-12 + 24 * random()), lo = (random() - 0.5) * span * 10 ** (4 * random());
    const hi = lo + span, count = 1 + Math.floor(5 * random());
    const { ticks, step } = niceTicks(lo, hi, count);
    const shown = ticks.map((v) => tickLabel(v, step));
    const where = `${lo}…${hi} in ${count}: ${shown}`;
    assert.ok(ticks.length >= 2, where);
    assert.ok(ticks.length <= Math.max(count, 3) + 1 + 1, where);
    for (const v of ticks) assert.ok(v >= lo - 1e-9 * step && v <= hi + 1e-9 * step, where);
    assert.equal(new Set(shown).size, shown.length, where);
  }
});
