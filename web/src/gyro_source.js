// The phone's gyroscope as the lab reads it (docs/phone-lab.md, "Recording in the page"):
// `Gyroscope` (the Generic Sensor API) or `DeviceMotionEvent.rotationRate` in rad/s, the first
// reading waited for, and the one-line reasons a recording cannot start or goes on no further.

const DEGREE = Math.PI / 180;

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
