// The "Judge a motion" panel (docs/explorer.md, docs/flipcheck.md): `bookspin flipcheck judge`
// in the page. A scenario is one of the page's scenes (bookspin explore wrote its data); its
// scenario JSON and exact-motion CSV come from the same code as `bookspin flipcheck export`,
// and an engine's motion CSV is judged by the same code as `judge` (web/judge_bindings.cpp:
// the motion CSV's parser, analysis::judge_motion and its table, compiled to WebAssembly).
// The judgement, the replay's poses and the export run in a Web Worker of the panel's own
// (fit_worker.js, as the lab's fit): the page draws and answers while a long motion is judged.
// Nothing is measured here: this module hands text to the module and writes out its answer.
import { takeFiles } from './file_drop.js';
import { FitWorker, Cancelled } from './fit_worker.js';
import { Replay } from './replay.js';
import { modalPanel } from './modal.js';
import { asGiven, significant, wholeNumbers } from './precision.js';
import { wellFormed } from './well_formed.js';

const $ = (id) => document.getElementById(id);
/** Text as HTML text. */
const escape = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
/** The judgement CSV's columns that hold text; every other one holds a number or nothing. */
const TEXT_COLUMNS = ['scenario', 'motion', 'verdict', 'failures', 'version', 'scenario_sha256'];
/** What each column says, for the panel's table (docs/flipcheck.md, "What judge measures"). */
const WORDS = {
  stride: 'steps between rows', last_step: 'last row (step)', start_error: '|ω(0) − ω0|/|ω0|',
  energy_drift: 'max |E/E0 − 1|', L_drift: 'max ||L|/|L0| − 1|', flips: 'turn-overs',
  flips_exact: 'exact turn-overs', first_flip: 'first turn-over (t)', first_flip_exact: 'exact first turn-over (t)',
  first_flip_error: '|first/exact − 1|', orientation_error: 'largest orientation error (rad)',
  orientation_error_step: 'largest orientation error at (step)', L_direction_error: 'largest turn of L (rad)',
  L_direction_error_step: 'largest turn of L at (step)',
  stable_spin: 'stable spin (1: yes)', tumble_time: 'tumbles at (t)', separatrix_ratio_drift: 'max |r/r0 − 1|, r = 2E·I2/L²',
  separatrix_approach: 'way to the separatrix (max)',
};

/** A measure's words as HTML, each formula's token ("|ω(0)", "ω0|/|ω0|", "2E·I2/L²") kept on one
 * line: a line breaks only at a space (docs/explorer.md, "Numbers whole"). */
const whole = (words) => words.split(' ').map((t) => (/[|/]/.test(t) ? `<span class="nb">${t}</span>` : t)).join(' ');

/** The judgement's columns that a rule of the judge bounds, and the rule's name in
 * analysis::judge_rules (docs/flipcheck.md): the value itself over the limit fails. Not
 * first_flip (its rule bounds |first − exact| over T/2, not the time shown). */
const RULE_OF = { start_error: 'start', energy_drift: 'energy_drift', L_drift: 'L_drift',
  L_direction_error: 'L_direction', orientation_error: 'orientation_error',
  separatrix_approach: 'separatrix_approach' };

/** The measure each of the judge's failure lines (analysis::judge_motion's words) is about: a
 * line's start and the judgement's column, so that the table marks the row of every failure
 * (those of no bound on the value alone too: the turn-overs, the first one's time). q's start,
 * which the judge tells first (docs/flipcheck.md, "What judge measures"), marks the orientation
 * error's row, ahead of the orientation error's own line. */
const FAILURE_OF = [
  [/^q (is written|at step 0)/, 'orientation_error'], [/^ends at step/, 'last_step'], [/^starts /, 'start_error'], [/^energy drift/, 'energy_drift'],
  [/^\|L\| drift/, 'L_drift'], [/^L turned/, 'L_direction_error'], [/^\d+ turn-overs?,/, 'flips'],
  [/^first turn-over/, 'first_flip'], [/^orientation error/, 'orientation_error'],
  [/^tumbles at/, 'tumble_time'], [/^r = 2E/, 'separatrix_approach'],
];

/** {column: its failure line} of the judge's `failures` (lines FAILURE_OF does not know: none). */
export function failedColumns(failures) {
  const out = {};
  for (const line of failures || []) {
    const hit = FAILURE_OF.find(([re]) => re.test(line));
    if (hit && !(hit[1] in out)) out[hit[1]] = line;
  }
  return out;
}

/** {column: limit} from the judge's rules (analysis::judge_rules: a line "name value" each, then
 * "columns …"): a measure's limit, for the table, where the rule of that name is a bound on
 * the column's value (its value above the limit fails). */
export function limitsOf(rulesText, columns) {
  const rules = {};
  for (const line of String(rulesText || '').split('\n')) {
    const [name, value, more] = line.trim().split(/\s+/);
    if (name && value !== undefined && more === undefined && Number.isFinite(Number(value))) rules[name] = Number(value);
  }
  const out = {};
  for (const c of columns) if (c in RULE_OF && RULE_OF[c] in rules) out[c] = rules[RULE_OF[c]];
  return out;
}

/** The SHA-256 (hex) of `text`'s UTF-8 bytes: a promise (the browser's Web Crypto). */
async function sha256Hex(text) {
  const digest = await crypto.subtle.digest('SHA-256', new TextEncoder().encode(text));
  return Array.from(new Uint8Array(digest), (b) => b.toString(16).padStart(2, '0')).join('');
}

/** Whether a scene of the page is a conformance scenario, as `flipcheck` takes one: one model
 * (no comparison: no tiles), no air drag, not at rest. */
export function isScenario(scene) {
  const s = scene.state;
  const still = s.w.every((x) => x === 0) && !(s.jiggle > 0);
  return !s.compare && !scene.tiles && (s.drag || 'none') === 'none' && !still;
}

/** The scenario of a scene, as web/judge_bindings.cpp reads it: its body (the book's size and
 * mass, or the body whole), ω0 (body frame), jiggle and seed, dt, and its steps, (frames − 1)·
 * steps_per_frame, from the scene's duration (that many steps of dt, written by bookspin). */
export function scenarioSpec(scene) {
  const s = scene.state;
  return {
    name: scene.name, book: scene.book, body: scene.body || null, w: s.w, jiggle: s.jiggle,
    seed: s.seed, dt: s.dt, steps: Math.round(scene.duration / s.dt),
  };
}

/** The module's answer {columns, cells} as one object keyed by the judgement CSV's columns:
 * text as text, an empty cell null, every other cell a number. */
function keyed({ columns, cells }) {
  const out = {};
  columns.forEach((c, i) => {
    out[c] = TEXT_COLUMNS.includes(c) ? cells[i] : cells[i] === '' ? null : Number(cells[i]);
  });
  return out;
}

/** Saves `text` as a file named `name` (a download; the page opens from disk). */
function download(name, text, type) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  document.body.appendChild(a);
  a.click();
  setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
}

/** The panel over the page's scenes (window.BOOKSPIN_SCENES) and the WebAssembly module. */
export class JudgePanel {
  constructor(wasm, scenes, currentScene) {
    this.wasm = wasm;
    // One call at a time: a new file judged (or an export) ends the one before.
    this.worker = new FitWorker(wasm);
    // The kit's scenarios (scenes/flipcheck/, `kit` in bookspin explore's data) where the page
    // holds them; in a page of other scenes, every scene flipcheck takes.
    const takes = scenes.filter(isScenario), kit = takes.filter((s) => s.kit);
    this.scenes = kit.length ? kit : takes;
    this.replay = new Replay($('judgeReplay'), $('judgeReplayTime'));
    const menu = $('judgeScenario');
    menu.innerHTML = '';
    // The menu names each scenario (a scenario's file name, short enough for the menu's width
    // on a 1366×768 screen); its title, a line of its own under the menu, wraps.
    for (const s of this.scenes) menu.add(new Option(s.name, s.name));
    $('judgeOpen').hidden = this.scenes.length === 0;
    $('judgeOpen').addEventListener('click', () => this.open(currentScene()));
    $('judgeClose').addEventListener('click', () => this.close());
    modalPanel($('judge'), $('judgeOpen'), () => this.close());
    menu.addEventListener('change', () => { this.clear(); this.showTitle(); });
    this.showTitle();
    $('judgeJson').addEventListener('click', () => this.exportFile('json'));
    $('judgeExact').addEventListener('click', () => this.exportFile('csv'));
    takeFiles($('judgeFile'), $('judgeDrop'), (files) => this.judgeFile(files[0]));
    // A link to the panel: explorer.html#judge opens it (the gallery's kit section links it),
    // once the page has its state.
    // On a scene that is no scenario (the gallery's link names none), the page goes to the
    // first scenario, so that the panel's scenario is what the page shows.
    if (location.hash === '#judge') queueMicrotask(() => this.open(currentScene(), true));
  }

  scene(name) { return this.scenes.find((s) => s.name === name); }

  /** Opens the panel on scenario `name` (the page's scene, where it is one). */
  open(name, fromLink = false) {
    if (!this.scene(name) && fromLink && this.scenes.length) {
      name = this.scenes[0].name;
      const menu = $('scene');
      menu.value = name;
      menu.dispatchEvent(new Event('change'));
    }
    if (this.scene(name)) $('judgeScenario').value = name;
    this.showTitle();
    $('judge').hidden = false;
  }

  /** The chosen scenario's title under the menu. */
  showTitle() {
    const scene = this.scene($('judgeScenario').value);
    $('judgeScenarioTitle').textContent = scene ? scene.title || '' : '';
  }

  close() { $('judge').hidden = true; this.replay.stop(); }

  clear() {
    $('judgeResult').hidden = true;
    $('judgeError').textContent = '';
    this.replay.stop();
  }

  /** The scenario JSON or the exact-motion CSV of the chosen scenario, as `bookspin flipcheck
   * export` writes it, downloaded as <scenario>.json or <scenario>-exact.csv. */
  exportFile(kind) {
    const scene = this.scene($('judgeScenario').value);
    if (!scene) return;
    $('judgeBusy').textContent = 'making the exact motion…';
    this.worker.call('flipcheckExport', [scenarioSpec(scene)]).then((files) => {
      if (files.error) { $('judgeError').textContent = `error: ${files.error}`; return; }
      if (kind === 'json') download(`${scene.name}.json`, files.json, 'application/json');
      else download(`${scene.name}-exact.csv`, files.csv, 'text/csv');
    }, (e) => { if (!(e instanceof Cancelled)) $('judgeError').textContent = `error: ${e.message}`; })
      .finally(() => { if (!this.worker.busy) $('judgeBusy').textContent = ''; });
  }

  /** {json, csv}: the files `bookspin flipcheck export` writes for scenario `name`, or {error}. */
  files(name) {
    const scene = this.scene(name);
    return scene ? this.wasm.flipcheckExport(scenarioSpec(scene)) : { error: `${name}: no such scenario in this page` };
  }

  /** Judges `csvText` (named `file`, as `judge` names a motion by its file's name) against
   * the exact motion of scenario `name`: a promise of the judgement keyed by the judgement
   * CSV's columns, with `line` (the command line's verdict line) and `failures` (a list)
   * beside them in `detail`; rejected with the command line's one line for a bad file (and
   * with Cancelled where a later call ended it). Judged in the panel's worker. */
  async judge(name, csvText, file = 'motion.csv') {
    wellFormed(file, 'motion');  // the motion's name as the module will write it, no letter eaten
    const scene = this.scene(name);
    if (!scene) throw new Error(`${name}: no such scenario in this page`);
    // The judgement records the SHA-256 of the scenario's JSON as `flipcheck export` writes it.
    const spec = scenarioSpec(scene);
    const json = this.wasm.flipcheckScenarioFile(spec);
    if (json.error) throw new Error(json.error);
    const r = await this.worker.call('judgeMotion', [spec, await sha256Hex(json), String(csvText), file]);
    if (r.error) throw new Error(r.error);
    return { row: keyed(r), line: r.line, failures: r.failures };
  }

  /** A file chosen or dropped: read, judged, shown, and replayed beside the exact motion. */
  judgeFile(file) {
    const name = $('judgeScenario').value;
    this.clear();
    $('judgeBusy').textContent = `judging ${file.name}…`;
    file.text().then((text) => this.judge(name, text, file.name)
      .then((j) => {
        this.show(j);
        return this.worker.call('motionPoses', [scenarioSpec(this.scene(name)), text, file.name]);
      })
      .then((poses) => { if (!poses.error) this.replay.start(poses, this.scene(name)); }))
      .catch((e) => { if (!(e instanceof Cancelled)) $('judgeError').textContent = `error: ${e.message}`; })
      .finally(() => { if (!this.worker.busy) $('judgeBusy').textContent = ''; });
  }

  /** The verdict, the failures in words and every number, as `judge` gives them. */
  show({ row, failures }) {
    const pass = row.verdict === 'pass';
    const verdict = $('judgeVerdict');
    verdict.textContent = `${pass ? 'PASS' : 'FAIL'}: ${row.motion} on ${row.scenario}`;
    verdict.className = pass ? 'pass' : 'fail';
    // What judged it (docs/flipcheck.md, "Versions"): bookspin's version and the scenario's SHA-256.
    // The version whole; the digest, 64 characters, breaks anywhere.
    $('judgeStamp').innerHTML = `judged by bookspin <span class="nb">${escape(row.version)}</span>; ` +
      `scenario JSON <span class="nb">SHA-256</span> <span class="digest">${escape(row.scenario_sha256)}</span>`;
    $('judgeFailures').innerHTML = '';
    for (const f of failures) $('judgeFailures').appendChild(Object.assign(document.createElement('li'), { textContent: f }));
    // The readable label first, the CSV's key second; each number to four significant digits
    // (a count whole), as the CSV holds it in the cell's title (the downloaded judgement keeps
    // every digit).
    // A measure the judge bounds shows its limit beside it, and over it reads as a failure.
    const limits = limitsOf(this.wasm.judgeRules ? this.wasm.judgeRules() : '', Object.keys(row));
    // A measure a failure line names is marked too, as the line says it (the turn-overs
    // against the exact count, the first one's time against its share of T/2).
    const failed = failedColumns(failures);
    const rows = Object.entries(row).filter(([c]) => !TEXT_COLUMNS.includes(c)).map(([c, v]) => {
      const limit = c in limits && v !== null ? limits[c] : null;
      const overLimit = limit !== null && v > limit;
      const over = overLimit || c in failed;
      // The limit with the rules' digits, not padded to four, in the values' form: 0.01, and
      // 1 × 10⁻⁶ beside a value of 3.217 × 10⁻⁷ (not 0.000001, six places to count).
      const limitText = limit === null ? '' : asGiven(limit);
      const why = c in failed ? (/\(([^)]*)\)\s*$/.exec(failed[c]) || [null, failed[c]])[1] : '';
      const bound = limit !== null ? `${overLimit ? 'over its limit' : 'limit'} ${limitText}`
        : over ? `failed: ${why}` : '';
      return `<tr${over ? ' class="over"' : ''}><th>${WORDS[c] ? whole(WORDS[c]) : c}${WORDS[c] ? `<small><code>${c.replace(/_/g, '_<wbr>')}</code></small>` : ''}</th>` +
        `<td${v === null ? '' : ` title="${v}"`}>${wholeNumbers(significant(v))}</td><td class="limit">${wholeNumbers(bound)}</td></tr>`;
    });
    $('judgeTable').innerHTML = rows.join('');
    $('judgeResult').hidden = false;
  }
}
