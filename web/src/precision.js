// Numbers as a person reads them (docs/explorer.md, "Numbers at their precision"): a value with
// an uncertainty σ is printed to σ's precision, two significant digits of σ and the value to
// the same decimal place; a value without one to a few significant digits. The CSVs a panel
// downloads or the command line writes keep every digit: only what the page shows is rounded.
// Pure: no DOM, no module; tests/web/precision_test.mjs checks it under node.

/** Superscript digits for an exponent: 10⁻¹⁵. */
const SUPERSCRIPT = { '-': '⁻', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹' };
const superscript = (n) => String(n).split('').map((c) => SUPERSCRIPT[c]).join('');

/** Exponent of the leading digit of `x` (finite, not 0): 12.3 → 1, 0.0049 → −3. */
function leadingExponent(x) {
  // From the decimal text, not Math.log10, which is one off near powers of ten (log10(1000)
  // may be 2.9999999999999996).
  return Number(Math.abs(x).toExponential().split('e')[1]);
}

/** `x` rounded to 10^`place` (place ≤ 0: −place decimals), as text; no "-0". Beyond toFixed's
 * reach (more than 100 decimals, or |x| ≥ 1e21) in scientific form with the same digits. */
function atPlace(x, place) {
  const decimals = Math.max(0, -place);
  if (decimals > 100 || Math.abs(x) >= 1e21) {
    const digits = Math.max(1, leadingExponent(x) - place + 1);
    return scientific(x, digits);
  }
  const step = 10 ** Math.max(0, place);
  const text = place > 0 ? String(Math.round(x / step) * step) : x.toFixed(decimals);
  return /^-0(\.0*)?$/.test(text) ? text.slice(1) : text;
}

/** `x` as m × 10ⁿ with `digits` significant digits ("1.7 × 10⁻¹⁵"). */
function scientific(x, digits) {
  const [m, e] = x.toExponential(digits - 1).split('e');
  return `${m} × 10${superscript(Number(e))}`;
}

/** `value` to `digits` significant digits (4 unless told), as a person reads it: an integer
 * whole, plain decimals from 10⁻⁴ to 10⁶, otherwise m × 10ⁿ; trailing zeros kept (they are
 * digits); nothing (null, undefined, '') as a dash; text as it is. */
export function significant(value, digits = 4) {
  if (value === null || value === undefined || value === '') return '—';
  if (typeof value !== 'number') return String(value);
  if (!Number.isFinite(value)) return String(value);
  if (Number.isInteger(value) && Math.abs(value) < 1e15) return String(value);
  if (value === 0) return '0';
  const e = leadingExponent(Number(value.toPrecision(digits)));
  if (e < -4 || e >= 6) return scientific(value, digits);
  return atPlace(value, e - digits + 1);
}

/** `value` with the digits it was given and no more (its shortest round-trip decimal form's
 * significant digits), as significant() writes a number: a limit as the rules set it, 0.01 as
 * "0.01" and 0.000001 as "1 × 10⁻⁶", beside values in the same form. */
export function asGiven(value) {
  if (typeof value !== 'number' || !Number.isFinite(value) || value === 0) return significant(value);
  const mantissa = value.toExponential().split('e')[0].replace('-', '').replace('.', '');
  return significant(value, mantissa.length);
}

/** {value, sigma}: `value` and its uncertainty `sigma` as text, σ to two significant digits and
 * the value to σ's last decimal place ("0.348257 ± 0.0000269191" → 0.348257, 0.000027). A σ
 * that is not a positive finite number leaves the value at `significant()`'s digits and σ as
 * it is ('' where there is none). */
export function withSigma(value, sigma) {
  if (typeof value !== 'number' || !Number.isFinite(value) || typeof sigma !== 'number' ||
      !Number.isFinite(sigma) || !(sigma > 0)) {
    const s = sigma === null || sigma === undefined || sigma === '' ? '' : significant(sigma, 2);
    return { value: significant(value), sigma: s };
  }
  const rounded = Number(sigma.toPrecision(2));  // 0.0995 → 0.1: its place from the rounded σ
  const place = leadingExponent(rounded) - 1;
  return { value: atPlace(value, place), sigma: atPlace(sigma, place) };
}

/** "value ± σ" (see withSigma), with `unit` after both where given ("0.1702 ± 0.0012 /s"). */
export function plusMinus(value, sigma, unit = '') {
  const v = withSigma(value, sigma);
  const tail = unit ? ` ${unit}` : '';
  return v.sigma ? `${v.value} ± ${v.sigma}${tail}` : `${v.value}${tail}`;
}

/** Each of `values` (a vector's components) to the decimal place of one shared σ: the
 * components rounded as withSigma rounds one value, and σ once ("(−0.139228, 0.990260,
 * −0.000012)" for σ = 0.000064). */
export function vectorWithSigma(values, sigma) {
  const parts = values.map((v) => withSigma(v, sigma));
  return { values: parts.map((p) => p.value), sigma: parts.length ? parts[0].sigma : '' };
}

/** A number as the page writes it: plain or "m × 10ⁿ", a range's two ends, with "± σ" after
 * it where it has one (and a σ's degree sign). */
const NUMBER = '-?\\d+(?:\\.\\d+)?(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?';
// Not a digit of a name (I2, ω0); a range "1.82–2.71" whole too.
const WHOLE = new RegExp(`(?<![\\p{L}\\d.])(?:± )?${NUMBER}(?:–${NUMBER})?(?: ± ${NUMBER})?°?`, 'gu');

/** `text` (already HTML text: no markup inside) with each number in it, and each "value ± σ",
 * in a span of class "nb", which the page never breaks (docs/explorer.md, "Numbers at their
 * precision": a number, an interval, is never split over two lines; the text breaks at its
 * spaces and separators only). */
export function wholeNumbers(text) {
  return String(text).replace(WHOLE, (m) => `<span class="nb">${m}</span>`);
}
