// A recording as the lab makes it from the sensor's readings (docs/phone-lab.md, "Recording in
// the page"): its CSV as the fit reads it, the sensor's own rate and the readings the page
// dropped, how long the page itself was held up, and the one-line problems said before the fit.

/** Samples a turn below which the page warns before the fit: the flight finder takes ω's
 * derivative from a quadratic over five samples (src/fit/flights.cpp, kHalfWindow = 2 each
 * side), which cannot follow a turn sampled more coarsely (docs/phone-lab.md, "Recording in
 * the page"). */
export const MIN_SAMPLES_PER_TURN = 5;

/** The phyphox export's header, as src/fit/recording.cpp reads it (is_phyphox_gyro_header). */
export const PHYPHOX_HEADER = '"Time (s)","Gyroscope x (rad/s)","Gyroscope y (rad/s)","Gyroscope z (rad/s)","Absolute (rad/s)"';

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
  return { text: lines.join('\n') + '\n', rate, samples: kept.length, step, times: t };
}

/** The sensor's own step and what the page dropped of its readings, from the time stamps `t`
 * (s): the sensor's step is the commonest step (to 1 ms), a step over 1.5 of it a gap where
 * the page was too busy to take the readings between (round(step / own) - 1 of them):
 * {own (s), dropped, gap (the longest step, s)}; own 0 for fewer than three samples. */
export function droppedReadings(t) {
  const counts = new Map();
  for (let i = 1; i < t.length; ++i) {
    const ms = Math.round((t[i] - t[i - 1]) * 1000);
    if (ms > 0) counts.set(ms, (counts.get(ms) || 0) + 1);
  }
  let own = 0, most = 0;
  for (const [ms, n] of counts) if (n > most || (n === most && ms < own)) { own = ms; most = n; }
  own /= 1000;
  let dropped = 0, gap = 0;
  for (let i = 1; i < t.length; ++i) {
    const step = t[i] - t[i - 1];
    gap = Math.max(gap, step);
    if (own > 0 && step > 1.5 * own) dropped += Math.round(step / own) - 1;
  }
  return { own, dropped, gap };
}

/** The share of the sensor's readings a page may drop before the note says it was busy. */
export const BUSY_SHARE = 0.1;

/** The heartbeat (ms) of PageLag: a timer the page asks for this often while recording. */
export const LAG_BEAT_MS = 20;
/** The share of a recording the page may be held up (PageLag) before the note says it was
 * busy. A steady busy page keeps the readings at its own pace, every step alike, so the stamps
 * alone (droppedReadings) cannot tell it from a slow sensor; the page's own clock can. */
export const LAG_SHARE = 0.25;

/** How long the page could not run while recording: a timer asked every LAG_BEAT_MS, each
 * beat's lateness (past the beat) summed. Held up by its own long tasks or by a phone whose
 * CPU goes to other apps alike; measured on the page's clock, not from the sensor's stamps. */
export class PageLag {
  start() {
    this.stop();
    this.begun = this.last = performance.now();
    this.held = 0;
    this.longest = 0;
    const beat = () => {
      const now = performance.now();
      const late = Math.max(0, now - this.last - LAG_BEAT_MS);
      this.held += late;
      this.longest = Math.max(this.longest, late);
      this.last = now;
      this.timer = setTimeout(beat, LAG_BEAT_MS);
    };
    this.timer = setTimeout(beat, LAG_BEAT_MS);
  }

  /** Stops the heartbeat: {share (of the time since start, 0 to 1), longest (s)}. */
  stop() {
    clearTimeout(this.timer);
    this.timer = 0;
    const span = this.begun === undefined ? 0 : performance.now() - this.begun;
    return { share: span > 0 ? Math.min(1, this.held / span) : 0, longest: (this.longest || 0) / 1000 };
  }
}

/** One line where the page was too busy to take the sensor's readings, '' otherwise: held up
 * for more than LAG_SHARE of the recording (`lag`, PageLag's), or more than BUSY_SHARE of the
 * readings dropped against the commonest step (`csv` recordingCsv's value, with its times). */
export function busyProblem(csv, lag = { share: 0, longest: 0 }) {
  const fix = 'not a slow sensor: close the other apps and tabs, keep the phone\'s battery saver off, and record again';
  if (lag.share > LAG_SHARE)
    return `the page was busy: it could not run for ${(100 * lag.share).toFixed(0)} % of the recording ` +
      `(up to ${lag.longest.toFixed(2)} s at a time), so it took ${csv.samples} readings at ` +
      `${csv.rate.toFixed(0)} Hz, ${fix}`;
  const { own, dropped, gap } = droppedReadings(csv.times);
  if (!(own > 0) || dropped <= BUSY_SHARE * (csv.samples + dropped)) return '';
  return `the page was busy: it took ${csv.samples} of about ${csv.samples + dropped} readings the gyroscope gave at ` +
    `${(1 / own).toFixed(0)} Hz (gaps up to ${gap.toFixed(2)} s), ${fix}`;
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
