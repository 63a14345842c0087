// The Phone-toss lab's numbers (web/src/lab_numbers.js, docs/phone-lab.md): a principal axis's
// components to the precision its σ in degrees allows, worked out here by hand.
// Usage: node tests/web/lab_numbers_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/lab_numbers_test.mjs SOURCE_DIR');
const { axisText } = await import(pathToFileURL(join(source, 'web/src/lab_numbers.js')).href);

test("an axis's components are rounded to its σ in radians, σ shown in degrees", () => {
  // 0.52° is 0.0091 rad: the components to four decimals (σ's two significant digits); read
  // as radians, 0.52 would round them to one decimal.
  assert.equal(axisText([0.99912345, 0.04112345, -0.01512345], 0.52), '(0.9991, 0.0411, -0.0151) ± 0.52°');
  // 5.3° is 0.092 rad: three decimals.
  assert.equal(axisText([0.99912345, 0.04112345, -0.01512345], 5.3), '(0.999, 0.041, -0.015) ± 5.3°');
  // No σ: four significant digits.
  assert.equal(axisText([0.99912345, 0.04112345, -0.01512345], null), '(0.9991, 0.04112, -0.01512)');
});
