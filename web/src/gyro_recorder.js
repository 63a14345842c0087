// "Record a toss" in the "Phone-toss lab" panel (docs/phone-lab.md, "Recording in the page"):
// the phone that shows the page records its own gyroscope. The W3C Generic Sensor API's
// `Gyroscope` (rad/s about the device's x, y, z, each reading with its own `timestamp`) where
// the browser has it, else `DeviceMotionEvent.rotationRate` (deg/s, each event's `timeStamp`).
// The samples become a phyphox-style CSV, the very text the page offers for download and hands
// to the lab's drop path, so `bookspin fit` of the download fits what the page fitted. Nothing
// is fitted here: this module reads the sensor, draws the live trace and writes the CSV.
import { OMEGA_COLOURS } from './colours.js';
import { chartCanvas } from './plots.js';

const $ = (id) => document.getElementById(id);
const DEGREE = Math.PI / 180;

/** Samples a turn below which the page warns before the fit: the flight finder takes ω's
 * derivative from a quadratic over five samples (src/fit/flights.cpp, kHalfWindow = 2 each
 * side), which cannot follow a turn sampled more coarsely (docs/phone-lab.md, "Recording in
 * the page"). */
export const MIN_SAMPLES_PER_TURN = 5;

/** The phyphox export's header, as src/fit/recording.cpp reads it (is_phyphox_gyro_header). */
export const PHYPHOX_HEADER = '"Time (s)","Gyroscope x (rad/s)","Gyroscope y (rad/s)","Gyroscope z (rad/s)","Absolute (rad/s)"';

/** The API names the file and the page state. */
export const GYROSCOPE_API = 'Gyroscope (Generic Sensor API)';
export const MOTION_API = 'DeviceMotionEvent.rotationRate';

/** ω (rad/s, device x, y, z) of a `DeviceMotionEvent.rotationRate` (deg/s): alpha about x,
 * beta about y, gamma about z, as Chromium, Firefox for Android and Safari on iOS report them
 * and the Device Orientation specification now states (docs/phone-lab.md, "Recording in the
 * page", which gives the sources); null where the browser gives no rate. */
export function omegaOfRotationRate(rate) {
  if (!rate || rate.alpha === null || rate.beta === null || rate.gamma === null) return null;
  return [rate.alpha * DEGREE, rate.beta * DEGREE, rate.gamma * DEGREE];
}

/** The median step (s) between the samples' times `t` (s), 0 for fewer than two. */
function medianStep(t) {
  const steps = [];
  for (let i = 1; i < t.length; ++i) steps.push(t[i] - t[i - 1]);
  if (!steps.length) return 0;
  steps.sort((a, b) => a - b);
  return steps[Math.floor(steps.length / 2)];
}

/** `samples` ([{stamp (ms), x, y, z (rad/s)}], in order) as {text, rate (Hz), samples}: a
 * phyphox-style CSV, time from the first sample in s, its comment lines (the reader leaves out
 * lines starting with '#') naming the API and the rate. A sample whose stamp does not follow
 * the previous one's is left out (the reader refuses times that do not increase). */
export function recordingCsv(samples, api) {
  const kept = [];
  for (const s of samples) if (!kept.length || s.stamp > kept[kept.length - 1].stamp) kept.push(s);
  const t0 = kept.length ? kept[0].stamp : 0;
  const t = kept.map((s) => (s.stamp - t0) / 1000);
  const step = medianStep(t);
  const rate = step > 0 ? 1 / step : 0;
  const lines = [
    `# recorded in the bookspin explorer page through ${api}: ${kept.length} samples, ${rate.toFixed(1)} Hz (the median step ${(step * 1000).toFixed(2)} ms)`,
    '# times from each reading\'s own time stamp, from the first; ω in rad/s about the device\'s x, y, z',
    PHYPHOX_HEADER,
  ];
  kept.forEach((s, k) => lines.push([t[k], s.x, s.y, s.z, Math.hypot(s.x, s.y, s.z)].map(String).join(',')));
  return { text: lines.join('\n') + '\n', rate, samples: kept.length, step };
}

/** One line where `samples` are too sparse for their fastest turn (fewer than
 * MIN_SAMPLES_PER_TURN a turn), '' otherwise. */
export function rateProblem(samples, step) {
  let fastest = 0;
  for (const s of samples) fastest = Math.max(fastest, Math.hypot(s.x, s.y, s.z));
  if (!(step > 0) || !(fastest > 0)) return '';
  const perTurn = 2 * Math.PI / (fastest * step);
  if (perTurn >= MIN_SAMPLES_PER_TURN) return '';
  return `the gyroscope gave ${(1 / step).toFixed(0)} Hz: ${perTurn.toFixed(1)} samples a turn at the fastest ` +
    `${fastest.toFixed(1)} rad/s, fewer than the ${MIN_SAMPLES_PER_TURN} the flight finder needs: ` +
    'throw it spinning slower, or record with phyphox (up to 500 Hz) and drop its export';
}

/** The one-line reasons a recording cannot start or goes on no further, each with what to do. */
export const LIMITS = {
  insecure: 'not a secure context: a browser gives sensors only to a page over https or on localhost; host the page so (docs/phone-lab.md, "Recording in the page")',
  noGyroscope: 'no gyroscope: this browser or device gives the page no rotation rate; record with phyphox and drop its export here',
  denied: 'permission denied: the browser refused the motion sensors; allow them in the site\'s settings and tap Record again',
  hidden: 'recording stopped: the tab was hidden (a hidden page gets no readings); keep the page in front while recording and record again',
  silent: 'no gyroscope: no reading came within 5 s of asking (this browser or device gives the page no rotation rate); record with phyphox and drop its export here',
};

/** ms without a first reading after which the sensor counts as absent (LIMITS.silent): a
 * phone's gyroscope reads every 10–20 ms, and a browser with none may send nothing at all. */
export const FIRST_READING_MS = 5000;

/** The sensor: start() reads `Gyroscope` or, failing that (or with `preferMotion`),
 * `devicemotion`; each sample ({stamp (ms), x, y, z (rad/s)}) goes to `onSample`. */
export class GyroSource {
  constructor(onSample) {
    this.onSample = onSample;
    this.preferMotion = false;
    this.api = '';
    this.stopper = null;
  }

  /** A promise that settles once the first reading came (resolved with the API's name) or the
   * sensor cannot be read (rejected with one of LIMITS). Called from a tap, so that a browser
   * asking permission (iOS's DeviceMotionEvent.requestPermission) may ask. */
  start() {
    if (!window.isSecureContext) return Promise.reject(new Error(LIMITS.insecure));
    const asked = typeof DeviceMotionEvent !== 'undefined' && typeof DeviceMotionEvent.requestPermission === 'function'
      && (this.preferMotion || typeof Gyroscope === 'undefined')
      ? DeviceMotionEvent.requestPermission() : Promise.resolve('granted');
    return asked.then((state) => {
      if (state !== 'granted') throw new Error(LIMITS.denied);
      if (!this.preferMotion && typeof Gyroscope !== 'undefined') return this.startGyroscope();
      if (typeof DeviceMotionEvent !== 'undefined') return this.startMotion();
      throw new Error(LIMITS.noGyroscope);
    }, () => { throw new Error(LIMITS.denied); });
  }

  startGyroscope() {
    return new Promise((resolve, reject) => {
      let sensor;
      try {
        // The highest rate the browser gives: it caps a higher frequency at its own.
        sensor = new Gyroscope({ frequency: 1000, referenceFrame: 'device' });
      } catch (e) {
        reject(new Error(e.name === 'SecurityError' ? LIMITS.denied : LIMITS.noGyroscope));
        return;
      }
      let started = false;
      sensor.addEventListener('reading', () => {
        this.onSample({ stamp: sensor.timestamp, x: sensor.x, y: sensor.y, z: sensor.z });
        if (!started) { started = true; resolve(GYROSCOPE_API); }
      });
      sensor.addEventListener('error', (e) => {
        sensor.stop();
        const line = e.error && e.error.name === 'NotAllowedError' ? LIMITS.denied : LIMITS.noGyroscope;
        if (!started) reject(new Error(line)); else this.onError(line);
      });
      this.api = GYROSCOPE_API;
      this.stopper = () => sensor.stop();
      sensor.start();
      this.untilFirst(() => started, reject);
    });
  }

  startMotion() {
    return new Promise((resolve, reject) => {
      let started = false;
      const listener = (e) => {
        const omega = omegaOfRotationRate(e.rotationRate);
        if (!omega) {
          // An event without a rate: the device has no gyroscope (Chromium sends one so).
          if (!started) { this.stop(); reject(new Error(LIMITS.noGyroscope)); }
          return;
        }
        this.onSample({ stamp: e.timeStamp, x: omega[0], y: omega[1], z: omega[2] });
        if (!started) { started = true; resolve(MOTION_API); }
      };
      window.addEventListener('devicemotion', listener);
      this.api = MOTION_API;
      this.stopper = () => window.removeEventListener('devicemotion', listener);
      this.untilFirst(() => started, reject);
    });
  }

  /** After permission was given: where no reading came (`started()` false) within
   * FIRST_READING_MS, the sensor is stopped and `reject`ed with LIMITS.silent. */
  untilFirst(started, reject) {
    const stopper = this.stopper;
    setTimeout(() => {
      if (started() || this.stopper !== stopper) return;
      this.stop();
      reject(new Error(LIMITS.silent));
    }, FIRST_READING_MS);
  }

  /** A failure after the first reading: set by the recorder. */
  onError() {}

  stop() {
    if (this.stopper) this.stopper();
    this.stopper = null;
  }
}

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

/** The "Record a toss" row of the lab: Record/Stop, the set time, the live trace, the state
 * line, the download; a finished recording goes to `fit(file, pooledWith)` (a File, and the
 * previous recording's File where the student asked to pool them, else null). */
export class TossRecorder {
  constructor(fit) {
    this.fit = fit;
    this.samples = [];
    this.recording = false;
    this.previous = null;
    this.last = null;
    this.source = new GyroSource((s) => this.samples.push(s));
    this.source.onError = (line) => this.finish(line);
    this.timer = 0;
    $('labRecord').addEventListener('click', () => (this.recording ? this.finish('') : this.start()));
    document.addEventListener('visibilitychange', () => {
      if (document.hidden && this.recording) this.finish(LIMITS.hidden);
    });
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

  say(text, error = false) {
    $('labRecordState').textContent = text;
    $('labRecordState').classList.toggle('error', error);
  }

  start() {
    this.samples = [];
    this.recording = true;
    $('labRecord').textContent = 'Stop';
    this.trace(true);
    $('labRecordSave').hidden = true;
    this.say('asking for the gyroscope…');
    this.source.start().then((api) => {
      if (!this.recording) return;
      const seconds = Number($('labRecordSeconds').value) || 20;
      this.say(`recording through ${api}: tap Stop, or it stops after ${seconds} s`);
      this.timer = setTimeout(() => this.finish(''), seconds * 1000);
      const frame = () => {
        if (!this.recording) return;
        drawTrace(this.trace(true), this.samples);
        requestAnimationFrame(frame);
      };
      requestAnimationFrame(frame);
    }, (e) => {
      this.recording = false;
      this.source.stop();
      $('labRecord').textContent = 'Record a toss';
      this.trace(false);
      this.say(`error: ${e.message}`, true);
    });
  }

  /** Stops; `why` (one of LIMITS) where the recording cannot be fitted, '' for a tap or the set
   * time: then the CSV is written, offered, checked for its rate and fitted. */
  finish(why) {
    if (!this.recording) return;
    this.recording = false;
    clearTimeout(this.timer);
    this.source.stop();
    $('labRecord').textContent = 'Record a toss';
    drawTrace(this.trace(true), this.samples);
    if (why) { this.say(`error: ${why}`, true); return; }
    const csv = recordingCsv(this.samples, this.source.api);
    if (csv.samples < 10) {
      this.say(`error: ${csv.samples} samples recorded, at least 10 are needed: record for longer`, true);
      return;
    }
    const stamp = new Date().toISOString().slice(0, 19).replace(/[T:]/g, '-');
    const name = `toss-${stamp}-${this.source.api === GYROSCOPE_API ? 'gyroscope' : 'devicemotion'}-${Math.round(csv.rate)}Hz.csv`;
    const file = new File([csv.text], name, { type: 'text/csv' });
    this.last = { name, text: csv.text, api: this.source.api, rate: csv.rate, samples: csv.samples };
    const save = $('labRecordSave');
    if (save.href) URL.revokeObjectURL(save.href);
    save.href = URL.createObjectURL(file);
    save.download = name;
    save.textContent = `Download ${name}`;
    save.hidden = false;
    const problem = rateProblem(this.samples, csv.step);
    this.say(`${csv.samples} samples through ${this.source.api}, ${csv.rate.toFixed(1)} Hz` +
      (problem ? `; warning: ${problem}` : ''), Boolean(problem));
    const pooled = $('labRecordPool').checked ? this.previous : null;
    this.previous = file;
    this.fit(file, pooled);
  }
}
