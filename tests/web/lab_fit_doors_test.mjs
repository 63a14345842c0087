// The lab's fit and `bookspin fit` on ill-conditioned tosses (docs/phone-lab.md, "Recording in the
// page"): the page's WebAssembly module (web/build.sh, its objects cached in the build tree)
// and the command line given the same file. Where the fit can end at two places (moments poorly
// determined: a recording with no still stretch thinned as a browser thins it, a flight cut too
// short to flip), which one it takes must not hang on the two solvers' round-off: both doors
// refuse it alike, or give the same moments, the same flights, the same half periods (or none)
// and the same flags, to 1e-6, and σ within a factor 1.5 or both over a quarter of the ratio; or,
// where a door's body is still far from rigid after the restarts (I1/I3 under 0.01), both so with
// no σ and no prediction, the same tosses and flags (their numbers aside). Relation over
// 12-29-59 and 12-44-51 thinned with six seeds each, seed 10 of 12-29-59 and seeds held out from
// the fixes (31-34, 31-33),
// and the longest flight of each of the seven development recordings cut to 0.35, 0.4 and 0.5 s,
// and tests/fit/recordings/12-29-59-browser-55Hz.csv, where they parted (0.45 : 0.999 : 1 with
// no σ against 0.55 : 0.57 : 1) before a fit at the edge I2 = I3 was fitted again from rigid
// bodies (src/fit/rigid_restart.hpp).
// Skipped (77) where em++, the real recordings or the build's program is missing; a failure
// under CI=true.
// Usage: node tests/web/lab_fit_doors_test.mjs SOURCE_DIR BUILD_DIR BOOKSPIN
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const [source, build, bookspin] = process.argv.slice(2);
if (!source || !build || !bookspin) throw new Error('usage: node lab_fit_doors_test.mjs SOURCE_DIR BUILD_DIR BOOKSPIN');
const skip = (why) => {
  console.log(why);
  process.exit(process.env.CI === 'true' ? 1 : 77);
};
const real = join(source, '..', 'shared', 'recordings-real', 'dvarkian-2022-05-03');
if (!existsSync(real)) skip(`no real recordings at ${real}`);
if (!existsSync(bookspin)) skip(`no ${bookspin}`);
try {
  execFileSync('em++', ['--version'], { stdio: 'ignore' });
} catch {
  skip('em++ not found (apt-get install emscripten): the page\'s module is not built');
}
// Through web/build.sh, under its lock: the browser tests build the same module at once.
execFileSync('bash', [join(source, 'web/build.sh'), build], { stdio: 'inherit' });
const BookspinPhysics = createRequire(import.meta.url)(join(build, 'web', 'bookspin_physics.js'));

const work = mkdtempSync(join(tmpdir(), 'bookspin-lab-fit-doors-'));
process.on('exit', () => rmSync(work, { recursive: true, force: true }));

/** RFC 4180 rows of `text`. */
function csvRows(text) {
  const rows = [];
  let row = [], cell = '', quoted = false;
  for (let i = 0; i < text.length; ++i) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') { cell += '"'; ++i; } else if (c === '"') quoted = false; else cell += c;
    } else if (c === '"') quoted = true;
    else if (c === ',') { row.push(cell); cell = ''; } else if (c === '\n' || c === '\r') {
      if (c === '\r' && text[i + 1] === '\n') ++i;
      row.push(cell); rows.push(row); row = []; cell = '';
    } else cell += c;
  }
  if (cell !== '' || row.length) { row.push(cell); rows.push(row); }
  return rows;
}

/** A recording's rows: [header, [t, wx, wy, wz, |w|] …] as text. */
function recording(name) {
  const dir = join(real, name);
  const file = readdirSync(dir).find((f) => f.endsWith('.csv'));
  const rows = csvRows(readFileSync(join(dir, file), 'utf8')).filter((r) => r.length >= 4);
  return { header: rows[0], rows: rows.slice(1) };
}

/** A seeded uniform number in [0, 1) (mulberry32). */
function random(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const write = (file, header, rows) => {
  writeFileSync(file, [header, ...rows].map((r) => r.join(',')).join('\n') + '\n');
  return file;
};

/** `bookspin fit FILE`: {error} (its line) or {body, tosses} (the CSVs' rows keyed). */
function cliFit(file) {
  const name = file.split('/').pop().replace(/\.csv$/, '');
  const out = join(work, 'out', name);
  const r = spawnSync(bookspin, ['fit', file, '-o', out, '--force'], { encoding: 'utf8' });
  if (r.status !== 0) return { error: r.stderr.trim().replace(/^bookspin: error: /, '') };
  const keyed = (f) => {
    const [header, ...rows] = csvRows(readFileSync(join(out, f), 'utf8')).filter((x) => x.length > 1);
    return rows.map((row) => Object.fromEntries(header.map((h, i) => [h, row[i]])));
  };
  return { body: keyed(`${name}-fit-body.csv`)[0], tosses: keyed(`${name}-fit.csv`) };
}

const number = (v) => (v === '' || v === null || v === undefined ? null : Number(v));
const suspect = (body) => {
  const [i1, i2] = [number(body.I1_over_I3), number(body.I2_over_I3)];
  return i1 < 0.01 || i1 + i2 < 0.95;  // src/fit/rigid_restart.hpp, fitted_no_rigid_body
};
const close = (a, b) => (a === null && b === null) || (a !== null && b !== null && Math.abs(a - b) <= 1e-6 * Math.max(1, Math.abs(a)));

test('the lab and bookspin fit agree on ill-conditioned tosses', async () => {
  const wasm = await BookspinPhysics();
  const files = [];
  // Thinned as a browser thins a 100 Hz recording: a poll each 1/55 s ± 30 %, the latest reading,
  // stamped when it arrives (up to 1 ms later).
  // Seeds 1-6 of each, where the fixes were found; seed 10 of 12-29-59, where a restart's needle
  // decided the page's body (a restart that ends at a suspect body is passed over); 31-34 and
  // 31-33, held out: never looked at before the fixes.
  const seeds = { '12-29-59': [1, 2, 3, 4, 5, 6, 10, 31, 32, 33, 34], '12-44-51': [1, 2, 3, 4, 5, 6, 31, 32, 33] };
  for (const name of ['12-29-59', '12-44-51']) {
    const { header, rows } = recording(name);
    const t = rows.map((r) => Number(r[0]));
    for (const seed of seeds[name]) {
      const u = random(seed);
      const kept = [];
      let last = -1;
      for (let poll = t[0], i = 0; poll <= t[t.length - 1]; poll += (1 + 0.3 * (2 * u() - 1)) / 55) {
        while (i + 1 < t.length && t[i + 1] <= poll) ++i;
        if (i === last) continue;
        last = i;
        kept.push([(t[i] + 0.001 * u()).toFixed(6), ...rows[i].slice(1)]);
      }
      files.push(write(join(work, `${name}-browser-${seed}.csv`), header, kept));
    }
  }
  // 12-29-59 thinned so by Python's random (tests/fit/recordings/README.md): the command line's
  // fit ended at the edge I2 = I3, the page's did not.
  files.push(join(source, 'tests/fit/recordings/12-29-59-browser-55Hz.csv'));
  // The longest flight of each recording, cut to its first 0.35, 0.4 and 0.5 s.
  for (const name of readdirSync(real).filter((n) => /^\d\d-\d\d-\d\d$/.test(n)).sort()) {
    const whole = cliFit(join(real, name));
    assert.ok(!whole.error, `${name}: ${whole.error}`);
    const longest = whole.tosses.reduce((a, b) => (b.t_end - b.t_start > a.t_end - a.t_start ? b : a));
    const { header, rows } = recording(name);
    for (const seconds of [0.35, 0.4, 0.5]) {
      const from = Number(longest.t_start);
      const cut = rows.filter((r) => Number(r[0]) >= from && Number(r[0]) <= from + seconds);
      files.push(write(join(work, `${name}-first-${seconds}s.csv`), header, cut));
    }
  }
  const parted = [];
  let suspects = 0;
  for (const file of files) {
    const name = file.split('/').pop();
    const cli = cliFit(file);
    const page = wasm.fitRecording(name, readFileSync(file).toString('latin1'), 'linear', '', null);
    if (cli.error || page.error) {
      if (cli.error !== page.error) parted.push(`${name}: the command line says ${cli.error ?? 'nothing'}, the page ${page.error ?? 'nothing'}`);
      continue;
    }
    const differ = [];
    // A body the restarts left far from rigid (src/fit/rigid_restart.hpp, fitted_no_rigid_body:
    // I1/I3 under 0.01, or I1 + I2 under 0.95 I3) lies where a flat cost let each solver stop:
    // which needle hangs on round-off.
    // Then the same verdict: both suspect, neither with σ or a predicted half period, the same
    // tosses and the same flags, their numbers aside.
    if (suspect(cli.body) || suspect(page.body)) {
      if (!suspect(cli.body) || !suspect(page.body)) differ.push(`a suspect body in one door: ${cli.body.I1_over_I3} : ${cli.body.I2_over_I3} against ${page.body.I1_over_I3} : ${page.body.I2_over_I3}`);
      if (cli.body.I1_sigma !== '' || page.body.I1_sigma !== null) differ.push(`σ on a suspect body: ${cli.body.I1_sigma || 'none'} against ${page.body.I1_sigma ?? 'none'}`);
      if (cli.tosses.length !== page.tosses.length) differ.push(`${cli.tosses.length} tosses against ${page.tosses.length}`);
      cli.tosses.forEach((toss, k) => {
        const other = page.tosses[k] || {};
        if (toss.half_period_predicted !== '' || number(other.half_period_predicted) !== null) differ.push(`toss ${k + 1} predicted on a suspect body: ${toss.half_period_predicted || 'none'} against ${other.half_period_predicted ?? 'none'}`);
        // The same flag, its numbers aside (a residual's share of |ω| is the needle's own).
        const reason = (flag) => (flag || '').replace(/\d+(\.\d+)?/g, 'N');
        if (reason(toss.flag) !== reason(other.flag)) differ.push(`toss ${k + 1} flag "${toss.flag}" against "${other.flag}"`);
      });
      if (differ.length) parted.push(`${name}: ${differ.join('; ')}`);
      ++suspects;
      continue;
    }
    for (const column of ['I1_over_I3', 'I2_over_I3'])
      if (!close(number(cli.body[column]), number(page.body[column]))) differ.push(`${column} ${cli.body[column]} against ${page.body[column]}`);
    if ((cli.body.I1_sigma === '') !== (page.body.I1_sigma === null)) differ.push(`σ ${cli.body.I1_sigma || 'none'} against ${page.body.I1_sigma ?? 'none'}`);
    // σ where both give it: within a factor 1.5, or both over a quarter of the ratio (the moments
    // poorly determined; a fold fitted without a toss may end at a needle, and where hangs on
    // round-off: docs/phone-lab.md, "The fit").
    for (const i of [1, 2]) {
      const a = number(cli.body[`I${i}_sigma`]), b = number(page.body[`I${i}_sigma`]), value = number(cli.body[`I${i}_over_I3`]);
      if (a === null || b === null) continue;
      const poor = Math.min(a, b) > 0.25 * value;
      if (!poor && Math.max(a, b) > 1.5 * Math.min(a, b)) differ.push(`I${i}_sigma ${a} against ${b}`);
    }
    if (cli.tosses.length !== page.tosses.length) differ.push(`${cli.tosses.length} tosses against ${page.tosses.length}`);
    cli.tosses.forEach((toss, k) => {
      const other = page.tosses[k] || {};
      for (const column of ['t_start', 't_end', 'half_period_measured', 'half_period_fitted', 'half_period_predicted'])
        if (!close(number(toss[column]), number(other[column]))) differ.push(`toss ${k + 1} ${column} ${toss[column] || 'none'} against ${other[column] ?? 'none'}`);
      if ((toss.flag || '') !== (other.flag || '')) differ.push(`toss ${k + 1} flag "${toss.flag}" against "${other.flag}"`);
    });
    if (differ.length) parted.push(`${name}: ${differ.join('; ')}`);
  }
  assert.ok(files.length >= 38);
  console.log(`${files.length} recordings, ${suspects} of them fitted to a suspect body in a door`);
  assert.deepEqual(parted, [], `the doors part on ${parted.length} of ${files.length}:\n${parted.join('\n')}`);
});
