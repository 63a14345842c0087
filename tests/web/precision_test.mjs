// The page's numbers at their precision (web/src/precision.js, docs/explorer.md): σ to two
// significant digits and the value to σ's decimal place, a σ too small for a fixed format still
// shown, a value without σ to a few significant digits. The expected texts are written out
// here by hand, from the issue's own examples where there is one.
// Usage: node tests/web/precision_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/precision_test.mjs SOURCE_DIR');
const { significant, withSigma, plusMinus, vectorWithSigma, asGiven, wholeNumbers } =
  await import(pathToFileURL(join(source, 'web/src/precision.js')).href);

test('a value is rounded to the decimal place of its σ, σ to two significant digits', () => {
  // The lab's moment ratios, as the page printed them before.
  assert.deepEqual(withSigma(0.348257, 0.0000269191), { value: '0.348257', sigma: '0.000027' });
  assert.deepEqual(withSigma(0.680021, 0.0000329498), { value: '0.680021', sigma: '0.000033' });
  assert.deepEqual(withSigma(12.669034229758324, 0.43), { value: '12.67', sigma: '0.43' });
  assert.deepEqual(withSigma(-3.14159, 0.0123), { value: '-3.142', sigma: '0.012' });
  // σ of one digit or more: the value rounded to whole tens, hundreds.
  assert.deepEqual(withSigma(12345.6, 123), { value: '12350', sigma: '120' });
  assert.deepEqual(withSigma(7.77, 2.5), { value: '7.8', sigma: '2.5' });
});

test('σ that rounds up to the next power of ten keeps two significant digits', () => {
  assert.deepEqual(withSigma(0.123456, 0.0996), { value: '0.12', sigma: '0.10' });
  assert.deepEqual(withSigma(5.4321, 0.996), { value: '5.4', sigma: '1.0' });
});

test('a σ that a fixed format rounds to zero is shown with the digits it needs', () => {
  // "drag 0.170 ± 0.000 /s" and "(± 0.0000, ± 0.0000)" in the lab before.
  assert.equal(plusMinus(0.170234567, 0.000123, '/s'), '0.17023 ± 0.00012 /s');
  assert.equal(plusMinus(0.9, 0.00000004), '0.900000000 ± 0.000000040');
  assert.notEqual(withSigma(1, 1e-30).sigma.replace(/[0.]/g, ''), '');
});

test('the value keeps trailing zeros to σ\'s place and never reads "-0"', () => {
  assert.deepEqual(withSigma(0.5, 0.0012), { value: '0.5000', sigma: '0.0012' });
  assert.deepEqual(withSigma(-0.00001, 0.0012), { value: '0.0000', sigma: '0.0012' });
});

test('without a usable σ the value is printed to significant digits and σ as given', () => {
  assert.deepEqual(withSigma(0.348257123, null), { value: '0.3483', sigma: '' });
  assert.deepEqual(withSigma(0.348257123, 0), { value: '0.3483', sigma: '0' });
  assert.deepEqual(withSigma(0.348257123, NaN), { value: '0.3483', sigma: 'NaN' });
  assert.equal(plusMinus(2.5, undefined, 's'), '2.500 s');
});

test('a number without σ: integers whole, four significant digits, powers of ten readable', () => {
  // The judge panel's "12.669034229758324" and "1.6653345369377348e-15" before.
  assert.equal(significant(12.669034229758324), '12.67');
  assert.equal(significant(1.6653345369377348e-15), '1.665 × 10⁻¹⁵');
  assert.equal(significant(-2.5e7), '-25000000');
  assert.equal(significant(2.5e7 + 0.5), '2.500 × 10⁷');
  assert.equal(significant(54), '54');
  assert.equal(significant(0), '0');
  assert.equal(significant(999.96), '1000');
  assert.equal(significant(0.00012346), '0.0001235');
  assert.equal(significant(0.000012346), '1.235 × 10⁻⁵');
  assert.equal(significant(0.1234567, 2), '0.12');
  assert.equal(significant(null), '—');
  assert.equal(significant(''), '—');
  assert.equal(significant('yes'), 'yes');
  assert.equal(significant(Infinity), 'Infinity');
});

test('a vector shares one σ: each component to its place', () => {
  // An axis with σ 0.00368° (6.4e-5 rad): "(-0.139228, 0.99026, -0.000011956)" before.
  const rad = 0.00368122 * Math.PI / 180;
  assert.deepEqual(vectorWithSigma([-0.139228, 0.99026, -0.000011956], rad),
    { values: ['-0.139228', '0.990260', '-0.000012'], sigma: '0.000064' });
});

test('no printed number has more digits than σ allows', () => {
  // Random values and σ over many decades: σ's text has two significant digits, the value's
  // last digit is at σ's last decimal place.
  let seed = 7;
  const random = () => { seed = (seed * 16807) % 2147483647; return seed / 2147483647; };
  for (let i = 0; i < 2000; ++i) {
    const sigma = 10 ** (-12 + 14 * random());
    const value = (random() - 0.5) * 10 ** (-6 + 12 * random());
    const { value: v, sigma: s } = withSigma(value, sigma);
    const significantDigits = s.replace('.', '').replace(/^0+/, '');
    assert.equal(significantDigits.replace(/0+$/, '').length <= 2 && significantDigits.length >= 2 ||
      /^\d+0+$/.test(s), true, `σ ${sigma} printed ${s}`);
    const decimals = (t) => (t.includes('.') ? t.split('.')[1].length : 0);
    assert.equal(decimals(v), decimals(s), `${value} ± ${sigma} printed ${v} ± ${s}`);
    assert.ok(Math.abs(Number(v) - value) <= 0.5 * 10 ** -decimals(s) * (1 + 1e-9) + Math.abs(value) * 1e-15 ||
      decimals(s) === 0, `${value} printed ${v}`);
  }
});

test('powers of ten from 10⁶ on and under 10⁻⁴, in every decade; plain between', () => {
  // A number that is not whole, in each decade from 10⁻¹² to 10¹⁴: m × 10ⁿ exactly where its
  // leading digit is at 10⁶ or more or under 10⁻⁴ (a rule switching a decade late printed
  // 1234567.8 as "1235000", seven digits where four are known).
  for (let e = -12; e <= 14; ++e) {
    const x = 1.23456789123 * 10 ** e;
    if (Number.isInteger(x)) continue;  // a count is whole
    const text = significant(x);
    if (e >= 6 || e < -4) {
      const power = String(e).split('').map((c) => '⁻⁰¹²³⁴⁵⁶⁷⁸⁹'['-0123456789'.indexOf(c)]).join('');
      assert.equal(text, `1.235 × 10${power}`, `${x} printed ${text}`);
    } else {
      assert.doesNotMatch(text, /×/, `${x} printed ${text}`);
      assert.equal(Number(text), Number(x.toPrecision(4)), `${x} printed ${text}`);
    }
  }
  assert.equal(significant(1234567.8), '1.235 × 10⁶');
  assert.equal(significant(999999.7), '1.000 × 10⁶');
  assert.equal(significant(-123456.78), '-123500');
});

test("the readout's ω: four decimals, a run running away by the number rule on one line", async () => {
  const { omegaText } = await import(pathToFileURL(join(source, 'web/src/readout.js')).href);
  // A diverged run's ω printed by toFixed(4) as "6.264803277982017e+50", over two lines.
  assert.equal(omegaText(6.264803277982017e+50), '6.265 × 10⁵⁰');
  assert.equal(omegaText(-2.0000004), '-2.0000');
  assert.equal(omegaText(-0.00001), '0.0000');
  assert.equal(omegaText(1234.56789), '1234.5679');
  assert.equal(omegaText(12345.678), '12350');
  assert.equal(omegaText(1.5e7 + 0.25), '1.500 × 10⁷');
  for (let e = -3; e <= 300; e += 7) {
    const text = omegaText(-3.3 * 10 ** e);
    assert.ok(text.length <= 16 && !/e[+-]/.test(text), `ω ${-3.3 * 10 ** e} printed ${text}`);
  }
});

test('a limit keeps the digits it was given, in the form of the values beside it', () => {
  // The judge's limits (analysis::judge_rules): "limit 0.000001" read as six places to count.
  assert.equal(asGiven(0.000001), '1 × 10⁻⁶');
  assert.equal(asGiven(1e-10), '1 × 10⁻¹⁰');
  assert.equal(asGiven(2.5e-7), '2.5 × 10⁻⁷');
  assert.equal(asGiven(0.01), '0.01');
  assert.equal(asGiven(0.05), '0.05');
  assert.equal(asGiven(0.001), '0.001');
  assert.equal(asGiven(0.5), '0.5');
  assert.equal(asGiven(3), '3');
  assert.equal(asGiven(1e6), '1000000');
  assert.equal(asGiven(1e30), '1 × 10³⁰');
  // A value shown beside it by significant() is in the same form from 10⁻⁴ down.
  assert.equal(significant(3.217e-7), '3.217 × 10⁻⁷');
});

test('each number, interval and range is kept whole in a span the page never breaks', () => {
  const nb = (t) => `<span class="nb">${t}</span>`;
  // The judge's cells on a phone ("0.484" over "3", "limit 1 ×" over "10⁻⁶").
  assert.equal(wholeNumbers('0.4843'), nb('0.4843'));
  assert.equal(wholeNumbers('limit 1 × 10⁻⁶'), `limit ${nb('1 × 10⁻⁶')}`);
  assert.equal(wholeNumbers('over its limit 3.217 × 10⁻⁷'), `over its limit ${nb('3.217 × 10⁻⁷')}`);
  // A value with its σ, a range, a vector's components (it breaks after their commas).
  assert.equal(wholeNumbers('0.1702 ± 0.0012 /s'), `${nb('0.1702 ± 0.0012')} /s`);
  assert.equal(wholeNumbers('toss 4: a.csv 10.081–11.534 s'), `toss ${nb('4')}: a.csv ${nb('10.081–11.534')} s`);
  assert.equal(wholeNumbers('(-0.139228, 0.990260) ± 0.5°'), `(${nb('-0.139228')}, ${nb('0.990260')}) ${nb('± 0.5°')}`);
  // Not a digit of a name.
  assert.equal(wholeNumbers('ω0 x, I2/I3'), 'ω0 x, I2/I3');
});
