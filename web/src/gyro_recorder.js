// "Record a toss" in the "Phone-toss lab" panel (docs/phone-lab.md, "Recording in the page"):
// the phone that shows the page records its own gyroscope. The W3C Generic Sensor API's
// `Gyroscope` (rad/s about the device's x, y, z, each reading with its own `timestamp`) where
// the browser has it, else `DeviceMotionEvent.rotationRate` (deg/s, each event's `timeStamp`).
// The samples become a phyphox-style CSV, the very text the page offers for download and hands
// to the lab's drop path, so `bookspin fit` of the download fits what the page fitted. Nothing
// is fitted here: this module runs the Record/Stop row, draws the live trace and keeps the
// recordings; the sensor is gyro_source.js's, the CSV and its checks recording_csv.js's.
import { OMEGA_COLOURS } from './colours.js';
import { chartCanvas } from './plots.js';
import { LIVE_ID, keptRows, keptStore } from './kept_store.js';
import { tossId } from './class_outbox.js';
import { afterPaint } from './after_paint.js';
import { GYROSCOPE_API, LIMITS, GyroSource } from './gyro_source.js';
import { recordingCsv, PageLag, busyProblem, rateProblem } from './recording_csv.js';

const $ = (id) => document.getElementById(id);
/** Says `text` in the lab's live region (a screen reader reads it; focus stays where it is). */
export function announce(text) { if ($('labSpoken')) $('labSpoken').textContent = text; }

/** Draws the last `span` seconds of `samples` on `canvas`: |ω| in white, x, y, z in their
 * colours, against s. */
function drawTrace(canvas, samples, span = 5) {
  const { g, w, h } = chartCanvas(canvas, 320, 120);
  g.font = '12px sans-serif';
  g.fillStyle = '#bbb';
  const n = samples.length;
  if (n < 2) { g.fillText('waiting for the gyroscope…', 8, 18); return; }
  const tEnd = samples[n - 1].stamp / 1000, tStart = Math.max(samples[0].stamp / 1000, tEnd - span);
  let top = 1;
  let first = n - 1;
  while (first > 0 && samples[first - 1].stamp / 1000 >= tStart) --first;
  for (let i = first; i < n; ++i) top = Math.max(top, Math.hypot(samples[i].x, samples[i].y, samples[i].z));
  const x = (t) => 4 + (t - tStart) / Math.max(tEnd - tStart, 1e-3) * (w - 8);
  const y = (v) => 22 + (top - v) / (2 * top) * (h - 26);
  g.fillText(`|ω| up to ${top.toFixed(1)} rad/s, the last ${span} s`, 8, 14);
  g.strokeStyle = '#555'; g.beginPath(); g.moveTo(4, y(0)); g.lineTo(w - 4, y(0)); g.stroke();
  const line = (colour, value) => {
    g.strokeStyle = colour; g.lineWidth = 1.2; g.beginPath();
    for (let i = first; i < n; ++i) g[i > first ? 'lineTo' : 'moveTo'](x(samples[i].stamp / 1000), y(value(samples[i])));
    g.stroke();
  };
  ['x', 'y', 'z'].forEach((c, k) => line(OMEGA_COLOURS[k], (s) => s[c]));
  line('#eee', (s) => Math.hypot(s.x, s.y, s.z));
}

/** ms after a Stop during which a tap on the button starts nothing: a nervous second tap of a
 * double tap (80 ms apart) must not start a recording over the toss just kept. */
export const AFTER_STOP_MS = 600;

/** ms between two drawings of the live trace while recording: four a second. Each drawing is
 * the page's work and a frame to composite; ten a second took, on a slowed page over a software
 * GPU, the CPU that the Stop's frame needed (docs/explorer.md, "Every tap answered at once"). */
export const TRACE_MS = 250;
/** How often the recording in progress is written to the store (ms): a reload loses at most
 * this much of it. */
export const LIVE_MS = 1000;

/** The local time `d` as a file name's stamp, YYYY-MM-DD-hh-mm-ss (the phone's own clock). */
export function localStamp(d) {
  const p = (n) => String(n).padStart(2, '0');
  return `${d.getFullYear()}-${p(d.getMonth() + 1)}-${p(d.getDate())}-${p(d.getHours())}-${p(d.getMinutes())}-${p(d.getSeconds())}`;
}

/** The "Record a toss" row of the lab: Record/Stop, the set time, the live trace, the state
 * line, and the list of every recording of the page's life (#labRecordings: each one's name,
 * local time, samples and rate, its tick for the pooled fit, its download and its remove).
 * A finished recording goes to `fit(files)` (an array of File: the new one alone, or the
 * ticked ones with it where the student asked to pool them), which returns a promise that
 * settles when the fit has ended. Stop acts once: from the Stop until the fit has ended (and
 * AFTER_STOP_MS past the Stop) a tap starts nothing, nor does a tap queued behind the fit. */
export class TossRecorder {
  constructor(fit, onRecording = () => {}) {
    this.fit = fit;
    /** Told true when a recording starts (asking for the sensor), false when it ends: the page
     * then does nothing else (main.js pauses the run and draws no frame). */
    this.onRecording = onRecording;
    this.samples = [];
    /** idle, asking (for the sensor), recording, fitting. */
    this.phase = 'idle';
    /** Taps whose time stamp is before this (ms, performance.now()'s clock) start nothing. */
    this.readyAt = 0;
    /** Every recording kept: {id, name, when (Date), samples, rate, api, text, ticked, url,
     * toss (its id for a class, class_outbox.js)}. */
    this.kept = [];
    /** The class's hooks (class_join.js): told each recording as it is kept, before it is
     * stored; and each row of the list as it is drawn, with its recording. */
    this.onKept = () => {};
    this.onRow = () => {};
    /** Asked before a recording is removed (class_join.js: a toss its class holds asks the
     * student first): a promise of whether to remove it. */
    this.beforeRemove = () => Promise.resolve(true);
    this.nextId = 1;
    this.source = new GyroSource((s) => this.samples.push(s));
    this.source.onError = (line) => this.finish(line);
    this.lag = new PageLag();
    this.timer = 0;
    // The recordings of earlier visits, where the browser keeps them (IndexedDB): a row this
    // page cannot read (an older page's, a write cut by a crash) skipped and named, the others
    // listed; the recording a reload cut short (the row in progress) kept and said.
    this.store = keptStore().then((store) => store.all().then((rows) => {
      const { good, skipped } = keptRows(rows);
      const live = good.find((r) => r.id === LIVE_ID);
      const earlier = good.filter((r) => r.id !== LIVE_ID).map((r) => ({ ...r, when: new Date(r.when) })).sort((a, b) => a.id - b.id);
      this.kept = [...earlier, ...this.kept.filter((k) => !earlier.some((e) => e.id === k.id))];
      this.nextId = Math.max(this.nextId, ...this.kept.map((k) => k.id + 1));
      if (live) this.kept.push({ ...live, id: this.nextId++, when: new Date(live.when), ticked: false, toss: tossId(), cut: 'the page was reloaded or left while it recorded' });
      this.storage = 'kept in this browser across reloads until you remove them (or clear the site\'s data)' +
        (skipped.length ? `; skipped ${skipped.length === 1 ? 'a row' : `${skipped.length} rows`} of the store that ${skipped.length === 1 ? 'is' : 'are'} no recording this page reads: ${skipped.join(', ')}` : '');
      this.list();
      this.sayCut(store);
      return store;
    })).catch((e) => {
      this.storage = e && e.name === 'StoreVersionError'
        ? `not kept across a reload: ${e.message}; download the ones to keep`
        : `not kept across a reload: this browser gives the page no storage (${(e && e.message) || e}); download the ones to keep`;
      this.list();
      return null;
    });
    this.storage = '';
    $('labRecord').addEventListener('click', (e) => this.tap(e));
    // A finger down on the button (a Stop coming): the live trace is not drawn until it is up.
    $('labRecord').addEventListener('pointerdown', () => { this.pressed = true; });
    for (const type of ['pointerup', 'pointercancel', 'pointerleave'])
      $('labRecord').addEventListener(type, () => { this.pressed = false; });
    $('labRecordFit').addEventListener('click', () => this.fitTicked());
    // The bar's height, left free at the panel's foot where the bar is fixed there (a phone).
    if (typeof ResizeObserver === 'function')
      new ResizeObserver(() => $('lab').style.setProperty('--lab-bar', `${$('labRecordRow').offsetHeight}px`))
        .observe($('labRecordRow'));
    document.addEventListener('visibilitychange', () => {
      if (document.hidden) {
        this.interrupt('the tab was hidden (a hidden page gets no readings)');
        return;
      }
      // Back on the page: what it said when the tab was hidden was said.
      for (const k of this.kept) if (k.cut) { delete k.cut; this.save(k); }
    });
    // A reload or a tab left while recording: the samples so far written once more (the row in
    // progress, written every LIVE_MS while recording), kept by the next page.
    window.addEventListener('pagehide', () => this.saveLive());
  }

  get recording() { return this.phase === 'recording'; }

  /** A tap on Record/Stop: Stop while recording; Record only when idle and not a tap from
   * before the last Stop settled (a double tap's second, or one queued behind the fit). */
  tap(e) {
    if (this.phase === 'recording') { this.finish(''); return; }
    if (this.phase !== 'idle') return;
    if (e && e.timeStamp < this.readyAt) return;
    this.start();
  }

  /** The button as the phase says. */
  button() {
    const busy = this.phase === 'asking' || this.phase === 'recording';
    if (busy !== Boolean(this.quiet)) { this.quiet = busy; this.onRecording(busy); }
    const b = $('labRecord');
    b.textContent = this.phase === 'recording' ? 'Stop' : this.phase === 'fitting' ? 'fitting…' : 'Record a toss';
    b.disabled = this.phase === 'fitting' || this.phase === 'asking';
  }

  /** The live trace's canvas, made under the state line when `shown` (none before a recording
   * starts, none left where it could not start). */
  trace(shown) {
    let canvas = $('labRecordTrace');
    if (shown && !canvas) {
      canvas = document.createElement('canvas');
      canvas.id = 'labRecordTrace';
      canvas.setAttribute('role', 'img');
      canvas.setAttribute('aria-label', 'the recording so far: |ω| in white, ω about x red, y green, z blue, the last 5 s');
      $('labRecordState').after(canvas);
    } else if (!shown && canvas) {
      canvas.remove();
      canvas = null;
    }
    return canvas;
  }

  /** The button, the state line and the live trace `canvas` scrolled into the panel's view
   * where any is out of it (a landscape phone: the trace was below the fold while recording).
   * Where the button is in the bar fixed at the lab's foot (a phone), the state line and the
   * trace are scrolled above the bar, the bar itself not moved. */
  inView(canvas) {
    const bar = $('labRecordRow'), row = bar.getBoundingClientRect(), end = canvas.getBoundingClientRect();
    if (getComputedStyle(bar).position !== 'fixed') {
      if (row.top < 0 || end.bottom > innerHeight) bar.scrollIntoView({ block: 'start' });
      return;
    }
    const state = $('labRecordState').getBoundingClientRect();
    if (state.top < 0 || end.bottom > row.top) $('lab').scrollBy(0, end.bottom - row.top + 8);
  }

  say(text, error = false) {
    $('labRecordState').textContent = text;
    announce(text);
    $('labRecordState').classList.toggle('error', error);
  }

  /** The seconds after which a recording stops: the field's value within its own min and max
   * (2 to 300 s), written back where it was outside them. */
  seconds() {
    const field = $('labRecordSeconds');
    const lo = Number(field.min) || 2, hi = Number(field.max) || 300;
    const given = Number(field.value);
    const seconds = Number.isFinite(given) && field.value !== '' ? Math.min(hi, Math.max(lo, Math.round(given))) : 20;
    if (String(seconds) !== field.value) field.value = String(seconds);
    return seconds;
  }

  /** Record: the button and the state line answer at once; the sensor is asked in the same
   * tap (a browser asking permission needs the tap); the live trace's canvas is made and
   * scrolled into view, and the recording said, after that answer is on the screen
   * (afterPaint). */
  start() {
    this.samples = [];
    this.phase = 'asking';
    this.button();
    this.say('asking for the gyroscope…');
    const painted = afterPaint();
    painted.then(() => { if (this.phase === 'asking' || this.recording) this.inView(this.trace(true)); });
    // The sensor is asked now; the page says it records (the button, the state line, the live
    // trace) once the answer's frame is on the screen, not before. Its readings are kept from
    // the first.
    Promise.all([this.source.start(), painted]).then(([api]) => {
      if (this.phase !== 'asking') return;
      this.phase = 'recording';
      this.button();
      const seconds = this.seconds();
      this.say(`recording through ${api}: tap Stop, or it stops after ${seconds} s`);
      this.timer = setTimeout(() => this.finish(''), seconds * 1000);
      this.lag.start();
      // The live trace ten times a second, not every frame: the sensor's readings come first.
      let saved = performance.now();
      const frame = () => {
        if (!this.recording) return;
        // Not while a finger is on Stop: its tap's frame comes first.
        if (!this.pressed) drawTrace(this.trace(true), this.samples);
        if (performance.now() - saved >= LIVE_MS) { saved = performance.now(); this.saveLive(); }
        setTimeout(frame, TRACE_MS);
      };
      frame();
    }, (e) => {
      if (this.phase !== 'asking') return;
      this.phase = 'idle';
      this.source.stop();
      this.button();
      this.trace(false);
      this.say(`error: ${e.message}`, true);
    });
  }

  /** Stops the sensor and the page's lag watch (this.lagged): the samples so far as a CSV
   * ({text, rate, samples, step}). */
  stopSensor() {
    this.phase = 'idle';
    this.readyAt = performance.now() + AFTER_STOP_MS;
    clearTimeout(this.timer);
    this.source.stop();
    this.lagged = this.lag.stop();
    this.button();
    // The trace's last drawing after the button's new words are painted.
    const samples = this.samples;
    afterPaint().then(() => { const canvas = $('labRecordTrace'); if (canvas) drawTrace(canvas, samples); });
    return recordingCsv(this.samples, this.source.api);
  }

  /** A recording cut short by `why` (the lab closed, Back, the tab hidden): stopped, and what
   * was recorded kept in the list, not ticked and not fitted, saying so. Nothing while not
   * recording (asking for the sensor: the request is dropped). */
  interrupt(why) {
    if (this.phase === 'asking') { this.phase = 'idle'; this.source.stop(); this.button(); this.trace(false); return; }
    if (!this.recording) return;
    const csv = this.stopSensor();
    if (csv.samples < 10) {
      this.say(`recording stopped: ${why}; ${csv.samples} samples, too few to keep`, true);
      this.dropLive();
      return;
    }
    const kept = this.keep(csv, false, document.hidden ? why : '');
    this.say(`recording stopped: ${why}; its ${csv.samples} samples are kept below as ${kept.name}, ` +
      'not fitted (tick it and tap Fit the ticked)', true);
  }

  /** Stops; `why` (one of LIMITS) where the recording cannot be fitted, '' for a tap or the set
   * time: then the CSV is kept in the list, checked for its rate and fitted (with the ticked
   * ones where "fit with the ticked recordings" is on). A recording too short says so and
   * leaves the earlier result and the list as they were. The sensor stops, the button says
   * "fitting…" and the state line the samples at once; the list and the fit follow after that
   * is painted (fitKept). */
  finish(why) {
    if (!this.recording) return;
    const csv = this.stopSensor();
    if (why) { this.say(`error: ${why}`, true); this.dropLive(); return; }
    if (csv.samples < 10) {
      this.dropLive();
      this.say(`error: ${csv.samples} samples recorded, at least 10 are needed: record for longer ` +
        '(the result and the recordings before it stand)', true);
      return;
    }
    const pool = $('labRecordPool').checked;
    const others = pool ? this.kept.filter((k) => k.ticked) : [];
    // A busy page first: its fix is another (nothing else running), not a slower throw.
    const problem = busyProblem(csv, this.lagged) || rateProblem(this.samples, csv.step);
    this.say(`${csv.samples} samples through ${this.source.api}, ${csv.rate.toFixed(1)} Hz` +
      (problem ? `; warning: ${problem}` : ''), Boolean(problem));
    this.fitKept(others, csv);
  }

  /** The file name of a recording `csv` stopped at `when`: the local time, the API, the rate,
   * a number added where the list holds the name already. */
  fileName(csv, when) {
    const kind = this.source.api === GYROSCOPE_API ? 'gyroscope' : 'devicemotion';
    let name = `toss-${localStamp(when)}-${kind}-${Math.round(csv.rate)}Hz.csv`;
    for (let n = 2; this.kept.some((k) => k.name === name); ++n)
      name = `toss-${localStamp(when)}-${n}-${kind}-${Math.round(csv.rate)}Hz.csv`;
    return name;
  }

  /** `csv` kept in the list as a new recording (`ticked` or not; `cut`: why it was cut short
   * while the page was hidden, said again by the next page where this one is not seen again),
   * its download made; stored in place of the row in progress. */
  keep(csv, ticked, cut = '') {
    const when = new Date();
    const kept = { id: this.nextId++, name: this.fileName(csv, when), when, samples: csv.samples, rate: csv.rate, api: this.source.api, text: csv.text, ticked, toss: tossId() };
    if (cut) kept.cut = cut;
    this.kept.push(kept);
    this.onKept(kept);
    this.save(kept, true);
    this.list();
    return kept;
  }

  /** The recording in progress written to the store (the row LIVE_ID: what a reload cuts short
   * is kept by the next page), where it has samples enough to keep. */
  saveLive() {
    if (!this.recording || this.samples.length < 10) return;
    const csv = recordingCsv(this.samples, this.source.api);
    const when = new Date();
    const row = { id: LIVE_ID, name: this.fileName(csv, when), when: when.toISOString(), samples: csv.samples, rate: csv.rate, api: this.source.api, text: csv.text, ticked: false };
    this.store.then((store) => store && store.put(row)).catch(() => {});
  }

  /** The row in progress removed (a recording ended with nothing to keep). */
  dropLive() {
    this.store.then((store) => store && store.remove(LIVE_ID)).catch(() => {});
  }

  /** Says which recordings the page found cut short (a reload, a tab left while recording) and
   * kept, then stores them as said. */
  sayCut(store) {
    const cut = this.kept.filter((k) => k.cut);
    if (!cut.length) return;
    this.say(`${cut.length === 1 ? 'a recording' : `${cut.length} recordings`} cut short before this page loaded ` +
      `(${[...new Set(cut.map((k) => k.cut))].join('; ')}) ${cut.length === 1 ? 'is' : 'are'} kept below as ` +
      `${cut.map((k) => k.name).join(', ')}, not fitted (tick and tap Fit the ticked)`, true);
    for (const k of cut) { delete k.cut; this.save(k, true, store); }
  }

  /** The recordings `which` fitted as one body (in the list's order), and `csv` (a recording
   * just stopped: recordingCsv's value) kept in the list, ticked, and fitted after them; Record
   * waits for it. The button says "fitting…" at once; the new row and the fit come after that
   * is painted (afterPaint), a frame later. */
  fitKept(which, csv = null) {
    this.phase = 'fitting';
    this.button();
    return afterPaint().then(() => {
      const all = csv ? [...which, this.keep(csv, true)] : which;
      return this.fit(all.map((k) => new File([k.text], k.name, { type: 'text/csv' })));
    }).finally(() => {
      this.phase = 'idle';
      // A tap that came while the fit held the page is older than this: it starts nothing.
      this.readyAt = Math.max(this.readyAt, performance.now());
      this.button();
    });
  }

  /** "Fit the ticked": the ticked recordings fitted as one body. */
  fitTicked() {
    if (this.phase !== 'idle') return;
    const ticked = this.kept.filter((k) => k.ticked);
    if (!ticked.length) { this.say('error: no recording ticked: tick the ones to fit together', true); return; }
    this.fitKept(ticked);
  }

  /** The list drawn afresh: a row a recording, newest last. */
  list() {
    const box = $('labRecordings');
    const list = $('labRecordList');
    box.hidden = !this.kept.length;
    $('labRecordKept').textContent = this.storage;
    list.textContent = '';
    for (const k of this.kept) {
      if (!k.url) k.url = URL.createObjectURL(new File([k.text], k.name, { type: 'text/csv' }));
      const row = document.createElement('li');
      row.dataset.name = k.name;
      const label = document.createElement('label');
      const tick = document.createElement('input');
      tick.type = 'checkbox';
      tick.checked = k.ticked;
      tick.addEventListener('change', () => { k.ticked = tick.checked; this.save(k); });
      label.append(tick, ` ${k.name}`);
      const about = document.createElement('span');
      about.className = 'about';
      about.textContent = `${k.when.toLocaleTimeString()}, ${k.samples} samples, ${k.rate.toFixed(1)} Hz`;
      const save = document.createElement('a');
      save.href = k.url;
      save.download = k.name;
      save.textContent = 'Download';
      const remove = document.createElement('button');
      remove.textContent = 'Remove';
      remove.setAttribute('aria-label', `remove ${k.name}`);
      remove.addEventListener('click', () => this.beforeRemove(k).then((yes) => { if (yes) this.remove(k); }));
      row.append(label, about, save, remove);
      this.onRow(row, k);
      list.append(row);
    }
  }

  /** `k` written to the browser's storage (where it gives the page some); with `settle`, in
   * the place of the row in progress, in one transaction. */
  save(k, settle = false, known = null) {
    const row = { id: k.id, name: k.name, when: k.when.toISOString(), samples: k.samples, rate: k.rate, api: k.api, text: k.text, ticked: k.ticked, toss: k.toss };
    if (k.cut) row.cut = k.cut;
    (known ? Promise.resolve(known) : this.store).then((store) => store && (settle ? store.settle(row) : store.put(row))).catch((e) => {
      this.storage = `not kept across a reload: the browser refused to store it (${(e && e.message) || e}); download the ones to keep`;
      $('labRecordKept').textContent = this.storage;
    });
  }

  remove(k) {
    this.store.then((store) => store && store.remove(k.id)).catch(() => {});
    this.kept = this.kept.filter((x) => x !== k);
    if (k.url) URL.revokeObjectURL(k.url);
    this.list();
  }
}
