// A long label on the explorer's plots (web/src/plots.js, wrapped): broken into lines no wider
// than the width asked, at spaces, greedily (no line could have taken the next word), every
// word kept in order, and a word wider than the width alone on its line. A fake 2D context
// measures 7 px per character; the expected lines are written out by hand.
// Usage: node tests/web/plots_wrap_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/plots_wrap_test.mjs SOURCE_DIR');
const { wrapped } = await import(pathToFileURL(join(source, 'web/src/plots.js')).href);

const g = { measureText: (text) => ({ width: 7 * text.length }) };

test('a tile\'s long label is broken at spaces into lines within the width', () => {
  const label = 'flexible: damped particle lattice, velocity Verlet';
  assert.deepEqual(wrapped(g, label, 7 * 20),
    ['flexible: damped', 'particle lattice,', 'velocity Verlet']);
  assert.deepEqual(wrapped(g, label, 7 * label.length), [label]);  // exactly fits: one line
  assert.deepEqual(wrapped(g, label, 7 * (label.length - 1)),
    ['flexible: damped particle lattice, velocity', 'Verlet']);
  assert.deepEqual(wrapped(g, 'a bb', 7 * 4), ['a bb']);
  assert.deepEqual(wrapped(g, 'a bb', 7 * 3), ['a', 'bb']);
  assert.deepEqual(wrapped(g, '', 100), []);
});

test('a word wider than the width is alone on its line, and nothing is lost', () => {
  assert.deepEqual(wrapped(g, 'x supercalifragilistic y', 7 * 5), ['x', 'supercalifragilistic', 'y']);
  assert.deepEqual(wrapped(g, 'supercalifragilistic', 7 * 5), ['supercalifragilistic']);
  // Seeded random labels: the lines rejoin to the text, each fits or is one word, and no line
  // could have taken the next line's first word.
  let seed = 7;
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  for (let k = 0; k < 200; k++) {
    const words = Array.from({ length: 1 + Math.floor(random() * 12) },
      () => 'w'.repeat(1 + Math.floor(random() * 9)));
    const width = 7 * (3 + Math.floor(random() * 25));
    const lines = wrapped(g, words.join(' '), width);
    assert.equal(lines.join(' '), words.join(' '));
    lines.forEach((line, i) => {
      assert.ok(g.measureText(line).width <= width || !line.includes(' '), line);
      if (i + 1 < lines.length) {
        const next = `${line} ${lines[i + 1].split(' ')[0]}`;
        assert.ok(g.measureText(next).width > width, `${line} | ${lines[i + 1]}`);
      }
    });
  }
});
