// The "Phone-toss lab" panel (docs/explorer.md, docs/phone-lab.md): `bookspin fit` in the page.
// A recording (a phyphox export's zip or its Raw Data.csv, any dialect the command line reads,
// or a t,wx,wy,wz CSV) is handed to the module as its bytes and fitted by the same code and the
// same solver as the command line's (web/fit_bindings.cpp: src/fit with Ceres, compiled to
// WebAssembly); the panel shows the body's moment ratios and axes, each toss's row and its
// chart (measured and fitted ω), and plays each toss in the explorer beside its measurement, as
// `bookspin explore` plays a toss scene the command line wrote. The fit runs in a Web Worker
// (fit_worker.js): the page draws and answers during it, says its progress, and its Cancel
// leaves the result before as it was. Nothing is fitted here: this module hands bytes to the
// module and writes out its answer.
import { recordingsOf, takeFiles } from './file_drop.js';
import { modalPanel } from './modal.js';
import { plusMinus, significant, wholeNumbers } from './precision.js';
import { axisText } from './lab_numbers.js';
import { OMEGA_COLOURS } from './colours.js';
import { chartCanvas, niceTicks, tickLabel } from './plots.js';
import { TossRecorder, announce } from './gyro_recorder.js';
import { FitWorker, Cancelled } from './fit_worker.js';
import { loneSurrogateProblem } from './well_formed.js';
import { failureHtml, fitFailure } from './fit_failure.js';

/** The outcome table's columns (LabPanel.showOutcome). */
const OUTCOME_COLUMNS = ['toss', 'recording', 'flight (s)', 'T/2 measured (s)', 'T/2 predicted ± 2σ (s)', 'within 2σ'];

const $ = (id) => document.getElementById(id);
/** What each toss column says (docs/outputs.md, "The fit"). */
const TOSS_WORDS = {
  recording: 'its recording', t_start: 'start (s)', t_end: 'end (s)', omega0_x: 'ω0 x (rad/s)', omega0_y: 'ω0 y (rad/s)',
  omega0_z: 'ω0 z (rad/s)', half_period_measured: 'T/2 measured (s)', half_period_fitted: 'T/2 fitted (s)',
  half_period_predicted: 'T/2 predicted ± σ (s)', half_period_predicted_sigma: 'σ T/2 predicted (s)',
  half_period_propagated_sigma: 'σ propagated from its inputs (s)', prediction_interval: 'interval calibrated by',
  predicted_from_tosses: 'predicted from (tosses)',
  predicted_from_seconds: 'predicted from (s of flight)', predicted_window: 'predicted from its first (s)', not_predicted: 'not predicted, why', residual_rms: 'residual RMS (rad/s)', L_decay: '|L| loss (1/s)',
  drag_rate: 'drag rate ± σ (1/s)', drag_rate_sigma: 'σ drag rate (1/s)',
  saturated: 'samples at the gyroscope’s range', stable: 'stable (no flip)',
  poor_fit: 'flagged', flag: 'why',
};

/** Text as HTML text. */
const html = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);

/** `value` for a table cell, at its precision (precision.js): a number to 4 significant digits
 * (an integer whole), nothing as a dash, text as HTML text. */
function cell(value) { return html(significant(value)); }

/** A toss column shown to a fixed decimal place: the flight's ends and half periods are times
 * on the gyroscope's clock, read to the millisecond (as the command's summary prints them). */
const MILLISECONDS = new Set(['t_start', 't_end', 'half_period_measured', 'half_period_fitted', 'half_period_predicted']);

/** A toss's `column` and `value` as the panel shows them (its σ beside it where the table has
 * one: drag_rate ± drag_rate_sigma), and the full value as the CSV holds it, for a title. */
function tossCell(toss, column, value) {
  if (typeof value !== 'number') return cell(value);
  if (column === 'drag_rate') return html(plusMinus(value, toss.drag_rate_sigma));
  if (column === 'drag_rate_sigma' || column === 'half_period_predicted_sigma' || column === 'half_period_propagated_sigma') return html(significant(value, 2));
  if (column === 'half_period_predicted' && typeof toss.half_period_predicted_sigma === 'number') return html(plusMinus(value, toss.half_period_predicted_sigma));
  if (column === 'residual_rms' || column === 'L_decay') return html(significant(value, 2));
  if (MILLISECONDS.has(column)) return html(value.toFixed(3));
  return cell(value);
}

/** A table row: the readable label first, the CSV's key second (small, as code; the key alone
 * where there are no words), the value;
 * the value as the CSV holds it in the cell's title; `wraps`: words (a recording's name, a
 * flag's why) that wrap within the panel, where a number keeps to one line. */
function labelledRow(key, words, shown, full, wraps = false) {
  const title = full === undefined || full === null ? '' : ` title="${html(full)}"`;
  // The key breaks after its underscores only (half_period_propagated_sigma, 28 characters,
  // held a phone's toss table 14 px past its panel once numbers kept whole).
  const code = words && words !== key ? `<small><code>${html(key).replace(/_/g, '_<wbr>')}</code></small>` : '';
  const cls = wraps ? ' class="words"' : '';
  return `<tr><th>${html(words || key)}${code}</th><td${title}${cls}>${wraps ? shown : wholeNumbers(shown)}</td></tr>`;
}

/** Plots toss `chart` ({t, measured, fitted}: ω, phone frame, 3×N flattened) on `canvas`: the
 * measured samples as dots, the fitted ω as lines, x red, y green, z blue (keyed in the plot's
 * corner), against seconds. */
export function drawTossChart(canvas, chart) {
  const { g, w, h } = chartCanvas(canvas, 320, 180);
  const n = chart.t.length;
  if (n < 2) return;
  let lo = Infinity, hi = -Infinity;
  for (const v of [...chart.measured, ...chart.fitted]) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  if (!(hi > lo)) { lo -= 1; hi += 1; }
  g.font = '12px sans-serif';
  // Axes (plots.js's round ticks): ω in a margin at the left, seconds under the plot; the
  // legend above it, clear of the data.
  const values = niceTicks(lo, hi, h > 160 ? 4 : 3);
  let margin = 0;
  for (const v of values.ticks) margin = Math.max(margin, g.measureText(tickLabel(v, values.step)).width);
  // The title at the left, the legend ("• measured  — fitted") at the right of the line above
  // the plot, or on a line of its own under the title where both do not fit with 12 px between
  // (a phone: the legend was drawn over "against t (s)").
  const title = 'ω (rad/s), phone frame, against t (s)';
  const legendWidth = 7 + 2.5 + g.measureText('measured').width + 12 + 12 + 6 + g.measureText('fitted').width;
  const left = Math.ceil(margin) + 10, right = 8;
  const titleX = Math.min(left, Math.max(4, w - right - g.measureText(title).width));
  const own = titleX + g.measureText(title).width + 12 + legendWidth > w - right;
  const legendY = own ? 30 : 14, top = own ? 38 : 22, bottom = 20;
  const t0 = chart.t[0], t1 = chart.t[n - 1];
  const x = (t) => left + (t - t0) / (t1 - t0) * (w - left - right);
  const y = (v) => top + (hi - v) / (hi - lo) * (h - top - bottom);
  g.lineWidth = 1;
  g.fillStyle = '#bbb';
  g.textBaseline = 'middle';
  for (const v of values.ticks) {
    g.strokeStyle = v === 0 ? '#555' : '#2a2e36';
    g.beginPath(); g.moveTo(left, y(v)); g.lineTo(w - right, y(v)); g.stroke();
    const label = tickLabel(v, values.step);
    g.fillText(label, left - 4 - g.measureText(label).width, y(v));
  }
  g.textBaseline = 'alphabetic';
  const times = niceTicks(t0, t1, Math.max(2, Math.floor((w - left - right) / 80)));
  for (const v of times.ticks) {
    const label = tickLabel(v, times.step);
    g.fillText(label, Math.max(left, Math.min(w - right - g.measureText(label).width, x(v) - g.measureText(label).width / 2)), h - 5);
  }
  g.strokeStyle = '#555'; g.strokeRect(left, top, w - left - right, h - top - bottom);
  g.fillText(title, titleX, 14);
  // The legend, right-aligned: "• measured  — fitted", the marks in the text's colour.
  const fittedX = w - right - g.measureText('fitted').width;
  const lineX = fittedX - 18;
  const measuredX = lineX - 12 - g.measureText('measured').width;
  g.fillText('fitted', fittedX, legendY);
  g.fillText('measured', measuredX, legendY);
  g.beginPath(); g.arc(measuredX - 7, legendY - 4, 2.5, 0, 2 * Math.PI); g.fill();
  g.strokeStyle = '#bbb'; g.lineWidth = 1.5;
  g.beginPath(); g.moveTo(lineX, legendY - 4); g.lineTo(lineX + 12, legendY - 4); g.stroke();
  // The key of the three components, inside the plot's top-left corner on a dark patch: x, y, z
  // in their colours (the legend above says which mark is measured and which fitted).
  const keyWidth = ['x', 'y', 'z'].reduce((sum, c) => sum + g.measureText(c).width + 8, 4);
  g.fillStyle = '#14161b'; g.fillRect(left + 1, top + 1, keyWidth, 16);
  let keyX = left + 5;
  ['x', 'y', 'z'].forEach((label, c) => {
    g.fillStyle = OMEGA_COLOURS[c];
    g.fillText(label, keyX, top + 13);
    keyX += g.measureText(label).width + 8;
  });
  // Lines first, thin; the measured samples over them as dots, so that each can be picked out.
  for (let c = 0; c < 3; ++c) {
    g.strokeStyle = OMEGA_COLOURS[c]; g.lineWidth = 1;
    g.beginPath();
    for (let i = 0; i < n; ++i) g[i ? 'lineTo' : 'moveTo'](x(chart.t[i]), y(chart.fitted[3 * i + c]));
    g.stroke();
  }
  for (let c = 0; c < 3; ++c) {
    g.fillStyle = OMEGA_COLOURS[c];
    for (let i = 0; i < n; ++i) {
      g.beginPath(); g.arc(x(chart.t[i]), y(chart.measured[3 * i + c]), 1.8, 0, 2 * Math.PI); g.fill();
    }
  }
}

/** The result's first line as a screen reader hears it: what was fitted, the body's ratios
 * and the outcome table's first row (its measured and predicted T/2). */
export function spokenResult(r) {
  const b = r.body;
  const first = r.tosses[0];
  let row = '';
  if (first) {
    const ms3 = (v) => (typeof v === 'number' ? `${v.toFixed(3)} s` : 'none');
    const p = first.half_period_predicted, s = first.half_period_predicted_sigma;
    row = `; toss 1: T/2 measured ${ms3(first.half_period_measured)}, ` +
      (typeof p === 'number' && typeof s === 'number' ? `predicted ${plusMinus(p, 2 * s)} s` : typeof p === 'number' ? `predicted ${ms3(p)}` : 'not predicted');
  }
  // A fit that describes no motion read is said with it, as the command says it first.
  const warned = fitWarnings(r.summary).map((line) => `; ${line}`).join('');
  return `fitted ${r.recording}: ${r.tosses.length} toss${r.tosses.length === 1 ? '' : 'es'}, I1 : I2 : I3 = ` +
    `${plusMinus(b.I1_over_I3, b.I1_sigma)} : ${plusMinus(b.I2_over_I3, b.I2_sigma)} : 1${row}${warned}; the result is below`;
}

const isWarning = (line) => line.startsWith('warning: ');

/** The summary's warnings (src/fit/fit_tables.cpp, fit_summary: a toss whose fit leaves a large
 * share of |ω| unexplained, said right after the result table, before anything else). */
export function fitWarnings(summary) {
  return (summary || []).filter(isWarning);
}

/** A stage of the fit as the worker tells it (web/fit_bindings.cpp: "read" NAME INDEX COUNT
 * before each recording, then the fit's own stages: "fit flights", "fit" with the solver's
 * iterations so far, "fit charts" before each toss's chart, `charts` of them so far): [the busy
 * line's words, the words said once (without the iterations)]. */
export function fitProgress(stage, details, charts) {
  if (stage === 'read') {
    const line = `reading ${details[0]} (${details[1] + 1} of ${details[2]})`;
    return [line, line];
  }
  if (stage === 'fit flights') return ['finding the flights', 'finding the flights'];
  if (stage === 'fit') return [`fitting the body and each toss (solver step ${details[0]})`, 'fitting the body and each toss'];
  if (stage === 'fit charts') return [`toss ${charts}: its chart and scene`, `toss ${charts}: its chart and scene`];
  return [stage, stage];
}

/** The panel over the WebAssembly module; `play(scene)` plays a toss's scene in the explorer. */
export class LabPanel {
  /** The `play` of a page with scenes `scenes` (the page's list) and `controls`: a fitted toss
   * is added to the scenes (or in place of an earlier fit's of the same name) and chosen, as
   * the scene menu chooses one. */
  static playAsScene(scenes, controls) {
    return (scene) => {
      const at = scenes.findIndex((s) => s.name === scene.name);
      if (at >= 0) scenes[at] = scene; else scenes.push(scene);
      controls.addScene(scene);
      $('scene').value = scene.name;
      $('scene').dispatchEvent(new Event('change'));
    };
  }

  /** `onRecording(yes)`: told when a recording starts and ends (main.js: the page then does
   * nothing else, so that the sensor's readings reach the recorder on a slow phone). */
  constructor(wasm, play, onRecording = () => {}) {
    this.wasm = wasm;
    this.worker = new FitWorker(wasm);
    this.play = play;
    this.result = null;
    this.skipped = [];
    $('labOpen').addEventListener('click', () => this.open());
    $('labClose').addEventListener('click', () => this.close());
    $('labCancel').addEventListener('click', () => this.cancel());
    modalPanel($('lab'), $('labOpen'), () => this.close());
    takeFiles([$('labFile'), $('labFolder')], $('labDrop'), (files, paths) => this.fitFiles(files, paths));
    // A toss recorded by this phone's gyroscope (gyro_recorder.js): its CSV fitted as a dropped
    // one is, with the ticked recordings where the student asked to pool them.
    this.recorder = new TossRecorder((files) => this.fitFiles(files), onRecording);
    // The lab closed (Close, Escape, Back) while recording: the recording stops and is kept.
    new MutationObserver(() => {
      if ($('lab').hidden) this.recorder.interrupt('the lab was closed');
    }).observe($('lab'), { attributes: true, attributeFilter: ['hidden'] });
    // The flights by hand changed: the last recording given is fitted again with them.
    this.given = null;
    $('labFlights').addEventListener('change', () => { if (this.given) this.fitFiles(...this.given); });
    // A link to the panel: explorer.html#lab opens it (the gallery's lab section links it).
    if (location.hash === '#lab') queueMicrotask(() => this.open());
  }

  /** The panel opened: its head (the title, Close) in the first frame, alone on its ground;
   * the rest laid out and painted in the next frame, asked for once the first is painted
   * (docs/explorer.md, "Every tap answered at once"): a whole screen of the lab rastered and
   * composited at once held the tap's answer past 200 ms on a software GPU. Not afterPaint():
   * where the first frame took under 16 ms it waits 400 ms, and the panel stood empty so long. */
  open() {
    const lab = $('lab');
    if (!lab.hidden) return;
    lab.classList.add('opening');
    lab.hidden = false;
    requestAnimationFrame(() => setTimeout(() => lab.classList.remove('opening'), 0));
  }
  close() { $('lab').hidden = true; }

  clear() {
    $('labResult').hidden = true;
    $('labError').textContent = '';
  }

  /** Fits the recording `bytes` (a Uint8Array, or text), named `file` as the command line names
   * a recording by its file's name, under the air drag law `drag` (none, linear, quadratic:
   * `bookspin fit --drag`), of the flights `tosses` by hand ("START:END, …" s, `bookspin fit
   * --tosses`' syntax; blank: the flights found): a promise of {recording, body (the -fit-body.csv row keyed by its
   * columns), tosses (the -fit.csv rows), summary (the lines the command prints), charts,
   * scenes (each toss as the page's scene data)}; rejected with the command line's one line
   * (without "bookspin: error: ") for a bad file or range, a range's naming the field, and
   * with Cancelled by cancel() or a later fit. Run in the lab's worker (fit_worker.js);
   * `onProgress(stage, …details)` is told each stage (fitProgress's words). */
  fit(file, bytes, drag = 'linear', tosses = '', onProgress = () => {}) {
    const problem = loneSurrogateProblem(String(file), 'recording') || loneSurrogateProblem(String(tosses), 'flights by hand');
    if (problem) return Promise.reject(new Error(problem));
    return this.worker.call('fitRecording', [String(file), bytes, String(drag), String(tosses)], onProgress)
      .then((r) => { if (r.error) throw new Error(r.error); return r; });
  }

  /** Several recordings of one body (`bookspin fit FILE1 FILE2 … --drag DRAG`, docs/phone-lab.md,
   * "A class's recordings"): `files` an array of {name, bytes, meta} (meta, optional: an
   * export's [{name: 'time.csv' or 'device.csv', bytes}]); a promise of fit()'s value plus
   * fitted (the names fitted) and refused ([{file, error}]), those that cannot be read left out;
   * rejected when none can be read, and for flights by hand `tosses` with two or more read
   * (their times are one recording's: the command line refuses --tosses so). In the worker,
   * as fit(). */
  fitMany(files, drag = 'linear', tosses = '', onProgress = () => {}) {
    const problem = files.map((f) => loneSurrogateProblem(f.name, 'recording')).find(Boolean) ||
      loneSurrogateProblem(String(tosses), 'flights by hand');
    if (problem) return Promise.reject(new Error(problem));
    return this.worker.call('fitRecordings', [files, String(drag), String(tosses)], onProgress)
      .then((r) => { if (r.error) throw new Error(r.error); return r; });
  }

  /** Cancel the fit: the fit in flight ended (its worker terminated); fitFiles then leaves the
   * result, the error and the list as they were before it, and says so. */
  cancel() {
    if (!this.worker.busy) return;
    this.worker.cancel();
  }

  /** Files chosen or dropped (`paths`: each one's name, or its path in a dropped folder): the
   * recordings among them (file_drop.js, recordingsOf) read as bytes, fitted (several as one
   * body) in the worker, of the flights by hand in the panel's field (none: those found),
   * shown; a folder's other files skipped and named; a promise that settles when the fit has
   * ended. Until then the result, the error and the list before it stay as they were (a fit
   * cancelled leaves them so); its progress is said in the busy line and the live region; a
   * later fit ends this one. */
  fitFiles(files, paths = files.map((f) => f.webkitRelativePath || f.name)) {
    if (this.recorder.recording) {
      $('labError').textContent = 'error: recording: a fit waits until the recording stops (tap Stop, then fit again)';
      return Promise.resolve();
    }
    const mine = this.generation = (this.generation || 0) + 1;
    const earlier = this.given;
    this.given = [files, paths];
    const { recordings, skipped } = recordingsOf(paths);
    if (!recordings.length) {
      // A fit in flight ends (a later one's ask stands), saying nothing of itself.
      this.worker.cancel();
      $('labBusy').textContent = '';
      $('labCancel').hidden = true;
      this.clear();
      this.skipped = skipped;
      $('labError').textContent = `error: no recording among ${paths.join(', ')} (a phyphox export's Raw Data.csv or zip, or a t,wx,wy,wz CSV)`;
      announce($('labError').textContent);
      return Promise.resolve();
    }
    const what = `fitting ${recordings.map((r) => r.path).join(', ')}…`;
    $('labBusy').textContent = what;
    $('labCancel').hidden = false;
    announce(what);
    let said = '', charts = 0;
    const progress = (stage, ...details) => {
      if (mine !== this.generation) return;
      if (stage === 'fit charts') charts += 1;
      const [line, spoken] = fitProgress(stage, details, charts);
      $('labBusy').textContent = `${what} ${line}`;
      // Said once a stage (each recording read, each toss's chart): not each solver step.
      if (spoken !== said) { said = spoken; announce(spoken); }
    };
    const started = performance.now();
    const drag = $('labDrag').value;
    const tosses = $('labFlights').value;
    const bytes = (k) => files[k].arrayBuffer().then((b) => new Uint8Array(b));
    const current = () => mine === this.generation;
    return Promise.all(recordings.map((r) => Promise.all([bytes(r.index), ...r.meta.map((m) => bytes(m.index))])
      .then(([own, ...meta]) => ({ name: r.path, bytes: own, meta: r.meta.map((m, k) => ({ name: m.name, bytes: meta[k] })) }))))
      .then((given) => {
        if (!current()) throw new Cancelled();
        return given.length === 1 && !given[0].meta.length
          ? this.fit(given[0].name, given[0].bytes, drag, tosses, progress)
          : this.fitMany(given, drag, tosses, progress);
      })
      .then((r) => {
        if (!current()) return;
        this.clear();
        this.skipped = skipped;
        this.show(r, performance.now() - started);
      })
      .catch((e) => {
        if (!current()) return;
        if (e instanceof Cancelled) {
          // Cancel: as before the fit, the files a change of the flights fits again too.
          this.given = earlier;
          $('labBusy').textContent = 'fit cancelled: the result and the recordings before it stand';
          announce($('labBusy').textContent);
          return;
        }
        this.clear();
        this.skipped = skipped;
        this.showFailure(e.message);
      })
      .finally(() => {
        if (!current()) return;
        if ($('labBusy').textContent.startsWith(what)) $('labBusy').textContent = '';
        $('labCancel').hidden = true;
      });
  }

  /** A fit's failure, the fit's line `line`: as it is where it is short; a long one, and one that
   * found no flight, as one sentence saying what to do with the line one tap away
   * (fit_failure.js). The sentence is said. */
  showFailure(line) {
    const f = fitFailure(line);
    if (f.detail) $('labError').innerHTML = failureHtml(f, 'error: ', html);
    else $('labError').textContent = `error: ${f.sentence}`;
    announce(`error: ${f.sentence}`);
  }

  /** Every stretch the finder dropped, a line each (`bookspin fit --verbose`'s lines), folded
   * under the summary, which counts those too slow for a flight in one line. */
  showDropped(lines) {
    let box = $('labDropped');
    if (!box) {
      box = document.createElement('details');
      box.id = 'labDropped';
      $('labSummary').after(box);
    }
    box.hidden = !lines.length;
    box.innerHTML = `<summary>every stretch of motion dropped (${lines.length})</summary><pre>${html(lines.join('\n'))}</pre>`;
  }

  /** The result as one table above everything else (docs/phone-lab.md, "Reading the
   * result"): toss, its recording, its flight, T/2 measured, T/2 predicted ± 2σ (its calibrated
   * σ; "uncalibrated" with none; "not predicted" and why in its title), and whether the
   * measurement lies within 2σ: the values of r.tosses (the -fit.csv's rows). */
  showOutcome(r) {
    let table = $('labOutcome');
    if (!table) {
      table = document.createElement('table');
      table.id = 'labOutcome';
      table.className = 'labOutcome';
      // It scrolls sideways on a phone: the keyboard reaches it to scroll it (its caption names it).
      table.tabIndex = 0;
      $('labResult').insertBefore(table, $('labResult').firstChild);
    }
    const ms3 = (v) => (typeof v === 'number' ? v.toFixed(3) : '–');
    const rows = r.tosses.map((t) => {
      const own = t.recording || r.recording;
      const measured = t.half_period_measured, predicted = t.half_period_predicted;
      const sigma = t.half_period_predicted_sigma;
      let shown = 'not predicted', within = '–', title = t.not_predicted || '';
      if (typeof predicted === 'number' && typeof sigma === 'number') {
        shown = plusMinus(predicted, 2 * sigma);
        title = t.prediction_interval || '';
        if (typeof measured === 'number') within = Math.abs(measured - predicted) <= 2 * sigma ? 'yes' : 'no';
      } else if (typeof predicted === 'number') {
        shown = `${predicted.toFixed(3)} (uncalibrated)`;
        title = t.prediction_interval || '';
      }
      // Each cell named by its column (data-label): on a phone a toss is a card of named lines
      // (index.html, #labOutcome).
      const [a, b, c, d, e, f] = OUTCOME_COLUMNS.map((name) => `data-label="${html(name)}"`);
      return `<tr><td ${a}>${html(t.toss)}</td><td ${b} class="words">${html(own)}</td>` +
        `<td ${c}>${html(ms3(t.t_start))}–${html(ms3(t.t_end))}</td><td ${d}>${html(ms3(measured))}</td>` +
        `<td ${e} title="${html(title)}">${html(shown)}</td><td ${f}>${html(within)}</td></tr>`;
    });
    table.innerHTML = '<caption>T/2 measured against T/2 predicted from the other tosses</caption>' +
      `<tr>${OUTCOME_COLUMNS.map((name) => `<th>${html(name)}</th>`).join('')}</tr>` + rows.join('');
  }

  /** The body, the summary, each toss's row, chart and play button. */
  show(r, ms) {
    this.result = r;
    const b = r.body;
    const ratio = (k, sigma) => html(plusMinus(b[k], b[sigma]));
    const ratios = `${b.I1_over_I3} : ${b.I2_over_I3} : 1`;
    const axis = (a) => {
      const values = [b[`axis${a}_x`], b[`axis${a}_y`], b[`axis${a}_z`]];
      const deg = b[`axis${a}_sigma_deg`];
      // The components of a unit vector to the angle's precision in radians, σ in degrees.
      const shown = axisText(values, deg);
      return labelledRow(`axis${a}_x, _y, _z`, `axis ${a} (phone x, y, z)`, html(shown), `(${values.join(', ')}) ± ${deg}°`);
    };
    $('labBody').innerHTML =
      labelledRow('I1_over_I3 : I2_over_I3 : 1', 'I1 : I2 : I3',
        `${ratio('I1_over_I3', 'I1_sigma')} : ${ratio('I2_over_I3', 'I2_sigma')} : 1 (${cell(b.moments)})`, ratios) +
      [1, 2, 3].map(axis).join('') +
      labelledRow('tosses, drag', '', `${cell(b.tosses)}, ${cell(b.drag)}`);
    // Several files: which were fitted as one body and which were refused, and why.
    // (One export with its meta/ is fitted as several are, but says nothing of it.)
    // The recording fitted named first (several: the pool's name, then each file below).
    const files = [`recording: ${r.recording}`];
    if (r.fitted && (r.fitted.length > 1 || r.refused.length)) {
      files.push(`fitted as one body: ${r.fitted.join(', ')}`);
      for (const x of r.refused) files.push(`refused ${x.file}: ${x.error}`);
    }
    if (this.skipped.length) files.push(`skipped (not a recording): ${this.skipped.join(', ')}`);
    // The result first: one table, a row a toss (the summary's own first lines, fit_result_lines,
    // which the table shows, are left out of the text below it).
    this.showOutcome(r);
    // The warnings next, above the body whose values they say not to trust, as the command
    // prints them right after its result table (fit_summary); not again in the text below.
    const warnings = fitWarnings(r.summary);
    $('labWarnings').hidden = !warnings.length;
    $('labWarnings').innerHTML = warnings.map((line) => `<p>${wholeNumbers(html(line))}</p>`).join('');
    const details = r.summary.slice(2 + r.tosses.length).filter((line) => !isWarning(line));
    // Its numbers, intervals and ranges whole (precision.js, wholeNumbers); it breaks at spaces.
    $('labSummary').innerHTML = wholeNumbers(html([...files, ...details].join('\n') + `\n(fitted in the page in ${(ms / 1000).toFixed(1)} s)`));
    this.showDropped(r.dropped || []);
    const list = $('labTosses');
    list.innerHTML = '';
    r.tosses.forEach((t, k) => {
      const box = document.createElement('div');
      box.className = 'toss';
      const head = document.createElement('div');
      head.className = 'tossHead';
      const title = document.createElement('strong');
      // Named by its own recording and times (the table's, or alone the recording's own).
      const own = t.recording || r.charts[k].recording || r.recording;
      title.innerHTML = wholeNumbers(html(`toss ${t.toss}: ${own} ${t.t_start.toFixed(3)}–${t.t_end.toFixed(3)} s` +
        (t.stable === 'yes' ? ' (stable)' : '') + (t.poor_fit === 'yes' ? ' (flagged)' : '')));
      head.appendChild(title);
      if (r.scenes[k]) {
        const button = document.createElement('button');
        button.textContent = 'Play beside the measurement';
        button.addEventListener('click', () => { this.close(); this.play(r.scenes[k]); });
        head.appendChild(button);
      }
      box.appendChild(head);
      const canvas = document.createElement('canvas');
      canvas.className = 'tossChart';
      canvas.setAttribute('role', 'img');
      canvas.setAttribute('aria-label', `toss ${t.toss}: ω measured (dots) and fitted (lines) against t, x red, y green, z blue; ` +
        'the numbers in the table beside it');
      box.appendChild(canvas);
      const table = document.createElement('table');
      // drag_rate_sigma is shown beside drag_rate, half_period_predicted_sigma beside its value.
      const beside = (c) => (c === 'drag_rate_sigma' && typeof t.drag_rate === 'number')
        || (c === 'half_period_predicted_sigma' && typeof t.half_period_predicted === 'number');
      table.innerHTML = Object.entries(t).filter(([c]) => c !== 'toss' && !beside(c))
        .map(([c, v]) => labelledRow(c, TOSS_WORDS[c], tossCell(t, c, v), v, typeof v === 'string')).join('');
      box.appendChild(table);
      list.appendChild(box);
    });
    $('labResult').hidden = false;
    // The result's first line said: the body's ratios and the first toss's row of the table.
    announce(spokenResult(r));
    // Charts after the layout: their size is the canvas's CSS size (drawn again when the window
    // changes size: a phone turned, all at once). As the fit lands, one a frame: six at once
    // held a 6x slowed page for 0.5 s after the fit.
    const chart = (k) => {
      const canvas = list.children[k] && list.children[k].querySelector('canvas');
      if (canvas) drawTossChart(canvas, r.charts[k]);
    };
    const oneAFrame = (k) => {
      if (this.result !== r || k >= r.tosses.length) return;
      chart(k);
      requestAnimationFrame(() => oneAFrame(k + 1));
    };
    requestAnimationFrame(() => oneAFrame(0));
    if (this.redrawCharts) window.removeEventListener('resize', this.redrawCharts);
    this.redrawCharts = () => requestAnimationFrame(() => r.tosses.forEach((t, k) => chart(k)));
    window.addEventListener('resize', this.redrawCharts);
  }
}
