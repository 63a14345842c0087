// The lab's store of recordings (web/src/kept_store.js, docs/phone-lab.md "The lab in a class")
// under node: the rows a page reads back split into those it lists and those it skips, each
// skipped one named by its id (or its place) and why, so that one corrupt row (an older page's,
// a write cut by a crash, another page's under the same name) never hides the others nor
// breaks the list. The rows and their verdicts are written out by hand here.
// Usage: node tests/web/kept_store_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/kept_store_test.mjs SOURCE_DIR');
const { keptRows, rowProblem, LIVE_ID } = await import(pathToFileURL(join(source, 'web/src/kept_store.js')).href);

const good = (id) => ({ id, name: `toss-${id}.csv`, when: '2026-11-29T01:02:03.000Z', samples: 400, rate: 99.5,
  api: 'Gyroscope (Generic Sensor API)', text: 't,wx,wy,wz\n0,1,2,3\n', ticked: true });

test('a good row, the row in progress and a row cut short by a hidden tab are read', () => {
  assert.equal(rowProblem(good(3)), '');
  assert.equal(rowProblem(good(LIVE_ID)), '');
  assert.equal(rowProblem({ ...good(4), cut: 'the tab was hidden' }), '');
});

test('every corrupt or foreign row is skipped and named, the others kept in order', () => {
  const rows = [
    good(1),
    'a string put by another page',
    { ...good(2), text: undefined },
    { ...good(5), when: 'yesterday' },
    { ...good(6), rate: '50' },
    { ...good(7), samples: 2.5 },
    { ...good(8), ticked: 'yes' },
    { id: 'x', name: 'other.csv' },
    { ...good(9), cut: 3 },
    { ...good(10), name: '' },
    null,
    good(11),
  ];
  const { good: listed, skipped } = keptRows(rows);
  assert.deepEqual(listed.map((r) => r.id), [1, 11]);
  assert.deepEqual(skipped, [
    'row 2 (not a recording)',
    "id 2 (no text (the recording's CSV))",
    'id 5 (its time is not a time)',
    'id 6 (its rate is not a number)',
    'id 7 (its samples are not a count)',
    'id 8 (its tick is not true or false)',
    'id "x" (its id is not a whole number)',
    'id 9 (why it was cut short is not text)',
    'id 10 (no name)',
    'row 11 (not a recording)',
  ]);
});
