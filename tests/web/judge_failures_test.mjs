// The judge panel's table (web/src/judge.js, docs/explorer.md "Judge a motion") under node: each
// failure line of analysis::judge_motion marks the row of the measure it is about. The lines are
// the judge's own for book-intermediate-0.05's exact motion with q written x, y, z, w and ω in
// the world frame (tests/analysis/judgement_test.cpp): q's line comes first and marks the
// orientation error's row, so the table points at q, not at ω's start.
// Usage: node tests/web/judge_failures_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/judge_failures_test.mjs SOURCE_DIR');
const { failedColumns } = await import(pathToFileURL(join(source, 'web/src/judge.js')));

const XYZW = [
  "q is written x, y, z, w: bookspin reads w, x, y, z (columns qw, qx, qy, qz), so q at step 0 " +
    "reads (0, 0, 0, 1), 3.14 rad from the scenario's orientation (1, 0, 0, 0); read as x, y, " +
    "z, w, q is the exact motion's within 0.1 rad at every row",
  "starts 2 off the scenario's omega0 (limit 1e-06)",
  'energy drift 0.85 at step 785 (limit 0.01; past it from step 3)',
  '|L| drift 0.594 at step 784 (limit 0.01; past it from step 4)',
  'L turned 0.778 rad at step 2880 (limit 0.01; past it from step 1)',
  '46 turn-overs, exact 6',
  'first turn-over -11.1 time units off (limit 1.34, 5 % of T/2)',
  'orientation error 3.14 rad at step 0 (limit 0.1; past it from step 0)',
];

test("q written x, y, z, w marks the orientation error's row, and every line marks one", () => {
  const failed = failedColumns(XYZW);
  assert.equal(failed.orientation_error, XYZW[0]);
  assert.equal(failed.start_error, XYZW[1]);
  assert.equal(failed.flips, XYZW[5]);
  assert.equal(Object.keys(failed).length, XYZW.length - 1, JSON.stringify(failed));
});

test('a start turned away from the scenario marks the orientation error too', () => {
  const line = "q at step 0 is (0.707, 0.707, 0, 0), 1.57 rad from the scenario's orientation " +
    '(1, 0, 0, 0) (limit 0.1 rad)';
  const failed = failedColumns([line, 'orientation error 1.57 rad at step 87 (limit 0.1; past it from step 0)']);
  assert.deepEqual(failed, { orientation_error: line });
});
