// The Phone-toss lab's numbers as its panel shows them (web/src/lab.js, docs/phone-lab.md):
// pure functions, no page, so that node tests them (tests/web/lab_numbers_test.mjs).
import { significant, vectorWithSigma, withSigma } from './precision.js';

/** A principal axis's phone-frame components `values` (a unit vector) with its direction's σ
 * `sigmaDeg` in degrees (the body CSV's axisN_sigma_deg): each component to the precision of
 * that angle in radians (a component of a unit vector moves by at most the angle, radians), σ
 * shown in degrees: "(0.9990, 0.0410, -0.0150) ± 0.52°". Without a positive σ, each component to
 * four significant digits. */
export function axisText(values, sigmaDeg) {
  if (typeof sigmaDeg === 'number' && sigmaDeg > 0) {
    return `(${vectorWithSigma(values, sigmaDeg * Math.PI / 180).values.join(', ')}) ± ${withSigma(sigmaDeg, sigmaDeg).sigma}°`;
  }
  return `(${values.map((v) => significant(v)).join(', ')})`;
}
