// A seeded property of the judge at the npm door (docs/flipcheck.md, "Thresholds"), run by
// tests/npm/npm_package_test.py in a project with the package installed: over random scenario
// JSONs (the box's, with random moments, ω0, dt and steps), the exact motion (exactMotion), q
// negated on random rows and every thinning the rules allow pass (a thinning they do not allow
// is refused, naming why); rows turned, a time shift, ω scaled, q in x, y, z, w order and a
// dropped row never pass. Prints one line per scenario and "PASS" or throws.
import { exactMotion, judge, scenario } from "flipcheck";

let seed = 8182;
function random() {  // a small seeded generator (xorshift), the same draws on every run
  seed ^= seed << 13; seed ^= seed >>> 17; seed ^= seed << 5;
  return ((seed >>> 0) % 1000003) / 1000003;
}

/** The judgement, or {refused: message} for an Error. */
function answer(spec, motion) {
  try {
    return judge(spec, motion);
  } catch (e) {
    if (e.message.includes("\n")) throw new Error(`a refusal of two lines: ${e.message}`);
    return { refused: e.message };
  }
}

function rows(m, keep) {
  const out = { t: [], q: [], omegaWorld: [] };
  for (let i = 0; i < m.t.length; ++i) {
    if (!keep(i)) continue;
    out.t.push(m.t[i]);
    out.q.push(Array.from(m.q.slice(4 * i, 4 * i + 4)));
    out.omegaWorld.push(Array.from(m.omegaWorld.slice(3 * i, 3 * i + 3)));
  }
  return out;
}

const base = scenario("mujoco-test-box");
let flipping = 0;
for (let k = 0; k < 8; ++k) {
  const spec = { ...base, scenario: `random-${k}` };
  spec.principal_moments = [1 + 9 * random(), 1 + 9 * random(), 1 + 9 * random()];
  const w = [random() - 0.5, random() - 0.5, random() - 0.5];
  const norm = Math.hypot(...w), rate = 0.5 + 2.5 * random();
  spec.omega0_body = w.map((x) => (rate * x) / norm);
  spec.omega0_world = spec.omega0_body;
  spec.dt = 0.005 + 0.045 * random();
  spec.steps = 100 * Math.round((40 + 60 * random()) / spec.dt / 100);
  const m = exactMotion(spec);
  const all = rows(m, () => true);
  const exact = answer(spec, all);
  if (!exact.pass) throw new Error(`${spec.scenario}: the exact motion: ${exact.line ?? exact.refused}`);
  flipping += exact.flips_exact > 0 ? 1 : 0;
  const negated = rows(m, () => true);
  negated.q = negated.q.map((q) => (random() < 0.5 ? q.map((x) => -x) : q));
  if (!answer(spec, negated).pass) throw new Error(`${spec.scenario}: q negated fails`);
  for (const stride of [2, 4, 5, 10, 20, 50, 100]) {
    const thin = answer(spec, rows(m, (i) => i % stride === 0));
    if (thin.refused ? !thin.refused.includes("too far apart") : !thin.pass)
      throw new Error(`${spec.scenario}: every ${stride}th row: ${thin.line ?? thin.refused}`);
  }
  const first = 1 + Math.floor(random() * (m.t.length - 30));
  const angle = 0.2 + 2.8 * random(), c = Math.cos(angle / 2), s = Math.sin(angle / 2);
  const turned = rows(m, () => true);
  for (let i = first; i < first + 20; ++i) {  // about world z: q ← (c, 0, 0, s)·q
    const [qw, qx, qy, qz] = turned.q[i];
    turned.q[i] = [c * qw - s * qz, c * qx - s * qy, c * qy + s * qx, c * qz + s * qw];
    const [wx, wy, wz] = turned.omegaWorld[i];
    turned.omegaWorld[i] = [Math.cos(angle) * wx - Math.sin(angle) * wy, Math.sin(angle) * wx + Math.cos(angle) * wy, wz];
  }
  const lag = Math.max(1, Math.round((0.3 + 0.7 * random()) / rate / spec.dt));
  const shifted = rows(m, (i) => i + lag < m.t.length);
  shifted.t = shifted.t.map((_, i) => all.t[i]);  // row i holds the motion lag steps later
  const scaled = rows(m, () => true);
  scaled.omegaWorld = scaled.omegaWorld.map((v) => v.map((x) => x * (random() < 0.5 ? 0.9 : 1.1)));
  const swapped = rows(m, () => true);
  swapped.q = swapped.q.map(([qw, qx, qy, qz]) => [qx, qy, qz, qw]);
  const dropped = rows(m, (i) => i !== first);
  for (const [what, motion] of [["rows turned", turned], ["shifted", shifted], ["omega scaled", scaled],
    ["q as x, y, z, w", swapped], ["a row dropped", dropped]]) {
    const j = answer(spec, motion);
    if (j.pass) throw new Error(`${spec.scenario}: ${what} passes: ${j.line}`);
  }
  console.log(`${spec.scenario}: exact passes (${exact.flips}/${exact.flips_exact}); every corruption fails or is refused`);
}
if (flipping < 2) throw new Error(`only ${flipping} random scenarios turn over`);
console.log("PASS");
