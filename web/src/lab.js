// The "Phone-toss lab" panel (docs/explorer.md, docs/phone-lab.md): `bookspin fit` in the page.
// A recording (a phyphox export's zip or its Raw Data.csv, any dialect the command line reads,
// or a t,wx,wy,wz CSV) is handed to the module as its bytes and fitted by the same code and the
// same solver as the command line's (web/fit_bindings.cpp: src/fit with Ceres, compiled to
// WebAssembly); the panel shows the body's moment ratios and axes, each toss's row and its
// chart (measured and fitted ω), and plays each toss in the explorer beside its measurement, as
// `bookspin explore` plays a toss scene the command line wrote. Nothing is fitted here: this
// module hands bytes to the module and writes out its answer.
import { recordingsOf, takeFiles } from './file_drop.js';

const $ = (id) => document.getElementById(id);
const OMEGA_COLOURS = ['#ff6060', '#60d060', '#6090ff'];
/** What each toss column says (docs/outputs.md, "The fit"). */
const TOSS_WORDS = {
  recording: 'its recording', t_start: 'start (s)', t_end: 'end (s)', omega0_x: 'ω0 x (rad/s)', omega0_y: 'ω0 y (rad/s)',
  omega0_z: 'ω0 z (rad/s)', half_period_measured: 'T/2 measured (s)', half_period_fitted: 'T/2 fitted (s)',
  half_period_predicted: 'T/2 predicted (s)', predicted_from_tosses: 'predicted from (tosses)',
  predicted_from_seconds: 'predicted from (s of flight)', residual_rms: 'residual RMS (rad/s)', L_decay: '|L| loss (1/s)',
  drag_rate: 'drag rate (1/s)', drag_rate_sigma: 'σ drag rate (1/s)',
  saturated: 'samples at the gyroscope’s range (left out)', stable: 'stable (no flip)',
  poor_fit: 'flagged', flag: 'why',
};

/** `value` for a table cell: a number to 6 significant digits, nothing as a dash, text as
 * HTML text. */
function cell(value) {
  if (value === null || value === undefined || value === '') return '—';
  if (typeof value === 'number') return String(Number(value.toPrecision(6)));
  return String(value).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
}

/** Plots toss `chart` ({t, measured, fitted}: ω, phone frame, 3×N flattened) on `canvas`: the
 * measured samples as dots, the fitted ω as lines, x red, y green, z blue, against seconds. */
export function drawTossChart(canvas, chart) {
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.clientWidth || 320, h = canvas.clientHeight || 180;
  canvas.width = Math.round(w * dpr); canvas.height = Math.round(h * dpr);
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.fillStyle = '#14161b'; g.fillRect(0, 0, w, h);
  const n = chart.t.length;
  if (n < 2) return;
  let lo = Infinity, hi = -Infinity;
  for (const v of [...chart.measured, ...chart.fitted]) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  if (!(hi > lo)) { lo -= 1; hi += 1; }
  const left = 44, right = 8, top = 8, bottom = 22;
  const x = (t) => left + (t - chart.t[0]) / (chart.t[n - 1] - chart.t[0]) * (w - left - right);
  const y = (v) => top + (hi - v) / (hi - lo) * (h - top - bottom);
  g.strokeStyle = '#555'; g.lineWidth = 1;
  g.beginPath(); g.moveTo(left, y(0)); g.lineTo(w - right, y(0)); g.stroke();
  g.fillStyle = '#bbb'; g.font = '12px sans-serif';
  g.fillText(`${cell(hi)} rad/s`, 2, top + 10); g.fillText(cell(lo), 2, h - bottom);
  g.fillText(`${cell(chart.t[0])} s`, left, h - 6);
  const legend = 'dots: measured · lines: fitted';
  g.fillText(legend, w - right - g.measureText(legend).width, top + 10);
  const end = `${cell(chart.t[n - 1])} s`;
  g.fillText(end, w - right - g.measureText(end).width, h - 6);
  for (let c = 0; c < 3; ++c) {
    g.fillStyle = OMEGA_COLOURS[c];
    for (let i = 0; i < n; ++i) g.fillRect(x(chart.t[i]) - 1, y(chart.measured[3 * i + c]) - 1, 2, 2);
    g.strokeStyle = OMEGA_COLOURS[c]; g.lineWidth = 1.5;
    g.beginPath();
    for (let i = 0; i < n; ++i) g[i ? 'lineTo' : 'moveTo'](x(chart.t[i]), y(chart.fitted[3 * i + c]));
    g.stroke();
  }
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

  constructor(wasm, play) {
    this.wasm = wasm;
    this.play = play;
    this.result = null;
    this.skipped = [];
    $('labOpen').addEventListener('click', () => this.open());
    $('labClose').addEventListener('click', () => this.close());
    window.addEventListener('keydown', (e) => { if (e.key === 'Escape' && !$('lab').hidden) this.close(); });
    takeFiles($('labFile'), $('labDrop'), (files, paths) => this.fitFiles(files, paths));
    // A link to the panel: explorer.html#lab opens it (the gallery's lab section links it).
    if (location.hash === '#lab') queueMicrotask(() => this.open());
  }

  open() { $('lab').hidden = false; }
  close() { $('lab').hidden = true; }

  clear() {
    $('labResult').hidden = true;
    $('labError').textContent = '';
  }

  /** Fits the recording `bytes` (a Uint8Array, or text), named `file` as the command line names
   * a recording by its file's name, under the air drag law `drag` (none, linear, quadratic:
   * `bookspin fit --drag`): a promise of {recording, body (the -fit-body.csv row keyed by its
   * columns), tosses (the -fit.csv rows), summary (the lines the command prints), charts,
   * scenes (each toss as the page's scene data)}; rejected with the command line's one line
   * (without "bookspin: error: ") for a bad file. */
  fit(file, bytes, drag = 'linear') {
    return new Promise((resolve, reject) => {
      // A turn of the event loop first: the panel says "fitting…" before the module works.
      setTimeout(() => {
        try {
          const r = this.wasm.fitRecording(String(file), bytes, String(drag));
          if (r.error) reject(new Error(r.error)); else resolve(r);
        } catch (e) { reject(e); }
      }, 0);
    });
  }

  /** Several recordings of one body (`bookspin fit FILE1 FILE2 … --drag DRAG`, docs/phone-lab.md,
   * "A class's recordings"): `files` an array of {name, bytes, meta} (meta, optional: an
   * export's [{name: 'time.csv' or 'device.csv', bytes}]); a promise of fit()'s value plus
   * fitted (the names fitted) and refused ([{file, error}]), those that cannot be read left out;
   * rejected when none can be read. */
  fitMany(files, drag = 'linear') {
    return new Promise((resolve, reject) => {
      setTimeout(() => {
        try {
          const r = this.wasm.fitRecordings(files, String(drag));
          if (r.error) reject(new Error(r.error)); else resolve(r);
        } catch (e) { reject(e); }
      }, 0);
    });
  }

  /** Files chosen or dropped (`paths`: each one's name, or its path in a dropped folder): the
   * recordings among them (file_drop.js, recordingsOf) read as bytes, fitted (several as one
   * body), shown; a folder's other files skipped and named. */
  fitFiles(files, paths = files.map((f) => f.webkitRelativePath || f.name)) {
    this.clear();
    const { recordings, skipped } = recordingsOf(paths);
    this.skipped = skipped;
    if (!recordings.length) {
      $('labError').textContent = `error: no recording among ${paths.join(', ')} (a phyphox export's Raw Data.csv or zip, or a t,wx,wy,wz CSV)`;
      return;
    }
    $('labBusy').textContent = `fitting ${recordings.map((r) => r.path).join(', ')}…`;
    const started = performance.now();
    const drag = $('labDrag').value;
    const bytes = (k) => files[k].arrayBuffer().then((b) => new Uint8Array(b));
    Promise.all(recordings.map((r) => Promise.all([bytes(r.index), ...r.meta.map((m) => bytes(m.index))])
      .then(([own, ...meta]) => ({ name: r.path, bytes: own, meta: r.meta.map((m, k) => ({ name: m.name, bytes: meta[k] })) }))))
      .then((given) => (given.length === 1 && !given[0].meta.length
        ? this.fit(given[0].name, given[0].bytes, drag)
        : this.fitMany(given, drag)))
      .then((r) => { this.show(r, performance.now() - started); })
      .catch((e) => { $('labError').textContent = `error: ${e.message}`; })
      .finally(() => { $('labBusy').textContent = ''; });
  }

  /** The body, the summary, each toss's row, chart and play button. */
  show(r, ms) {
    this.result = r;
    const b = r.body;
    const sigma = (k) => (b[k] === null ? '' : ` ± ${cell(b[k])}`);
    $('labBody').innerHTML =
      `<tr><th>I1 : I2 : I3</th><td>${cell(b.I1_over_I3)}${sigma('I1_sigma')} : ${cell(b.I2_over_I3)}${sigma('I2_sigma')} : 1 (${cell(b.moments)})</td></tr>` +
      [1, 2, 3].map((a) => `<tr><th>axis ${a} (phone x, y, z)</th><td>(${cell(b[`axis${a}_x`])}, ${cell(b[`axis${a}_y`])}, ${cell(b[`axis${a}_z`])})${b[`axis${a}_sigma_deg`] === null ? '' : ` ± ${cell(b[`axis${a}_sigma_deg`])}°`}</td></tr>`).join('') +
      `<tr><th>tosses, drag</th><td>${cell(b.tosses)}, ${cell(b.drag)}</td></tr>`;
    // Several files: which were fitted as one body and which were refused, and why.
    // (One export with its meta/ is fitted as several are, but says nothing of it.)
    const files = [];
    if (r.fitted && (r.fitted.length > 1 || r.refused.length)) {
      files.push(`fitted as one body: ${r.fitted.join(', ')}`);
      for (const x of r.refused) files.push(`refused ${x.file}: ${x.error}`);
    }
    if (this.skipped.length) files.push(`skipped (not a recording): ${this.skipped.join(', ')}`);
    $('labSummary').textContent = [...files, ...r.summary].join('\n') + `\n(fitted in the page in ${(ms / 1000).toFixed(1)} s)`;
    const list = $('labTosses');
    list.innerHTML = '';
    r.tosses.forEach((t, k) => {
      const box = document.createElement('div');
      box.className = 'toss';
      const head = document.createElement('div');
      head.className = 'tossHead';
      const title = document.createElement('strong');
      title.textContent = `toss ${t.toss}: ${t.recording ? `${t.recording} ` : ''}${cell(t.t_start)}–${cell(t.t_end)} s` +
        (t.stable === 'yes' ? ' (stable)' : '') + (t.poor_fit === 'yes' ? ' (flagged)' : '');
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
      box.appendChild(canvas);
      const table = document.createElement('table');
      table.innerHTML = Object.entries(t).filter(([c]) => c !== 'toss').map(([c, v]) =>
        `<tr><th><code>${c}</code><small>${TOSS_WORDS[c] || ''}</small></th><td>${cell(v)}</td></tr>`).join('');
      box.appendChild(table);
      list.appendChild(box);
    });
    $('labResult').hidden = false;
    // Charts after the layout: their size is the canvas's CSS size.
    requestAnimationFrame(() => r.tosses.forEach((t, k) => drawTossChart(list.children[k].querySelector('canvas'), r.charts[k])));
  }
}
