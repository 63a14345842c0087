// What a student is told of a failed fit (web/src/fit_failure.js, docs/phone-lab.md "When a fit
// fails") and how a typed class code is read (web/src/class_join.js, classCode), under node:
// the fit's "no free flight found" line (as src/fit/flights.cpp writes it, its thresholds in it)
// becomes one sentence saying what to do, with its numbers, the line kept whole one tap away; a
// short line is shown as it is; a long other line is cut to its first clause; the class's pooled
// fit that failed is told by the server's own sentence where it gives one. A code typed in lower
// case, with spaces or dashes, or in full-width letters is the code the projector shows.
// Usage: node tests/web/fit_failure_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/fit_failure_test.mjs SOURCE_DIR');
const { fitFailure, classFitFailure, failureHtml, LONG_LINE } =
  await import(pathToFileURL(join(source, 'web/src/fit_failure.js')).href);
const { classCode } = await import(pathToFileURL(join(source, 'web/src/class_join.js')).href);

const html = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);

// The finder's line for a recording held in the hand, tossed too briefly, then too slowly
// (src/fit/flights.cpp, throw_no_flight: std::to_string's six places, the reasons' own).
const held = 'toss-2026-11-29-10-00-01-gyroscope-60Hz.csv: no free flight found (0.000000–4.116667 s: no ' +
  'torque-free stretch of 0.300 s or longer (held, or a flight too short to fit); 5.016667–9.983333 s: ' +
  'turning slower than 2.000 rad/s); name the flights by hand in the field flights by hand (START:END in ' +
  "seconds of the recording's clock, e.g. 1.2:1.9) after a look at its chart";

test('no flight: one sentence saying what to do, its numbers the fit\'s, the line whole one tap away', () => {
  const f = fitFailure(held);
  assert.equal(f.sentence, 'No flight in this recording: record again, throwing the phone spinning so that it flies ' +
    'free for at least 0.3 s before you catch it.');
  assert.equal(f.detail, held);
  const slow = fitFailure('a.csv: no free flight found (0.100000–2.000000 s: turning slower than 2.000 rad/s)');
  assert.equal(slow.sentence, 'No flight in this recording: record again, spinning the phone faster as you throw it ' +
    '(at least 2 rad/s, a turn in 3.1 s).');
  assert.equal(fitFailure('a.csv: no free flight found').sentence,
    'No flight in this recording: record again, throwing the phone spinning into the air and catching it.');
  // Shown: the sentence, the line in a <details> (closed: one tap away), both as text.
  const shown = failureHtml(f, 'error: ', html);
  assert.match(shown, /^<span class="failureSentence">error: No flight in this recording: record again/);
  assert.match(shown, /<details class="failureDetail"><summary>the fit's own words<\/summary><p>toss-2026/);
  assert.ok(!shown.includes('<details open'));
});

test('a short line is shown as it is; a long one cut to its first clause', () => {
  const short = 'flights by hand 2:1: the end is not after the start';
  assert.deepEqual(fitFailure(short), { sentence: short, detail: '' });
  assert.equal(failureHtml(fitFailure(short), 'error: ', html), `<span class="failureSentence">error: ${short}</span>`);
  const long = `x.csv: the same samples as y.csv; ${'a clause of detail, '.repeat(20)}`;
  assert.ok(long.length > LONG_LINE);
  const f = fitFailure(long);
  assert.equal(f.sentence, "x.csv: the same samples as y.csv (the fit's own words below)");
  assert.equal(f.detail, long);
  const words = fitFailure(`${'word '.repeat(80)}`.trim());
  assert.ok([...words.sentence].length <= 160 + "… (the fit's own words below)".length, words.sentence);
  assert.ok(words.sentence.includes('word…'), words.sentence);
});

test('the class\'s failed fit: the server\'s sentence where it gives one, else one made from its line', () => {
  assert.equal(classFitFailure({ ratios: [0.5, 0.8], error: null }), null);
  assert.equal(classFitFailure(null), null);
  const line = 'class-K7PQ2M/ana-3.csv: the same samples as class-K7PQ2M/ben-1.csv; leave one out';
  assert.deepEqual(classFitFailure({ ratios: null, error: line, error_summary: 'Ask your teacher to leave out ana-3.' }),
    { sentence: 'Ask your teacher to leave out ana-3.', detail: line });
  assert.deepEqual(classFitFailure({ ratios: null, error: line }), {
    sentence: "The class's body could not be fitted (class-K7PQ2M/ana-3.csv: the same samples as class-K7PQ2M/ben-1.csv): " +
      'your teacher sees the class\'s tosses on the projector and can leave out the one that breaks it.', detail: line });
  // A server that says nothing of the failure: recordings fitted and no body is one.
  assert.deepEqual(classFitFailure({ tosses: 0, recordings: 1, ratios: null, sigma: null }), {
    sentence: "The class's body could not be fitted from its 1 recording: your teacher sees the class's tosses on the " +
      'projector and can leave out the one that breaks it.', detail: '' });
  // Nothing held yet, or not fitted yet: no failure.
  assert.equal(classFitFailure({ tosses: 0, recordings: 0, ratios: null, sigma: null }), null);
});

test('a class code typed in lower case, with spaces, dashes or full-width letters is the projector\'s', () => {
  for (const typed of ['K7PQ2M', 'k7pq2m', ' k7pq 2m ', 'K7P-Q2M', 'k7p–q2m', 'Ｋ７ＰＱ２Ｍ', 'k7pq\t2m\n'])
    assert.equal(classCode(typed), 'K7PQ2M', JSON.stringify(typed));
  assert.equal(classCode(''), '');
  assert.equal(classCode('NOPE42'), 'NOPE42');
});
