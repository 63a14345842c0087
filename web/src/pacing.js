// How much physics the page does at once, so that no link or value freezes the tab: values
// outside the page's limits are refused (state.js, withinLimits), a time to reach (a link's `t`,
// the slider) is caught up to in pieces, one per animation frame after a first longer one, and
// playing does at most a frame's budget of steps, dropping the rest. The notice line says what
// was refused and how far a catch-up has got.
import { withinLimits } from './state.js';

/** Milliseconds of physics per animation frame at most, and in one go after a change. */
export const FRAME_BUDGET_MS = 25;
export const FIRST_BUDGET_MS = 200;

export class Pacer {
  /** `show(text)`: puts the notice line on the page. */
  constructor(show) {
    this.show = show;
    this.target = null;  // a time still to catch up to (null: none)
    this.refused = [];   // values refused by withinLimits, shown until the next change
    this.slow = '';      // playing slower than asked
  }

  /** `state` within the page's limits (refused values back to `base`'s), the refusals shown. */
  limit(state, base) {
    const [next, refused] = withinLimits(state, base);
    this.refused = refused;
    this.notice(next);
    return next;
  }

  /** Steps `runs` towards time `target` for at most `ms` milliseconds; sets and returns
   * state.t, the time reached. While it is short of `target`, continue() goes on. `target` is
   * taken to the whole step nearest it, round(target/dt)·dt, the time Runs.advanceTo stops at:
   * a time between two steps (a slider's value, a link's t = 42.43333333333334) would
   * otherwise never be reached, the catch-up left at 100 % for ever and Play held by it. */
  catchUp(runs, state, target, ms) {
    this.target = Math.round(target / state.dt) * state.dt;
    state.t = runs.advanceTo(this.target, state.dt, performance.now() + ms);
    if (state.t >= this.target) this.target = null;
    this.notice(state);
    return state.t;
  }

  /** Whether a catch-up is left; one frame's piece of it. */
  continue(runs, state) {
    if (this.target === null) return false;
    this.catchUp(runs, state, this.target, FRAME_BUDGET_MS);
    return true;
  }

  /** Playing: `n` more steps of state.dt, as many as fit in a frame's budget from `t0`. */
  play(runs, state, n, t0) {
    const want = state.t + n * state.dt;
    state.t = runs.advanceTo(want, state.dt, t0 + FRAME_BUDGET_MS);
    // Reached to the step (t is a whole number of steps of dt, `want` a sum of them).
    this.slow = state.t < want - 0.5 * state.dt ? `speed ${state.speed} is more than this machine steps: playing slower` : '';
    this.notice(state);
  }

  /** Forgets a catch-up (the runs were started anew). */
  stop() {
    this.target = null;
    this.slow = '';
  }

  notice(state) {
    const lines = [...this.refused];
    if (this.target !== null)
      lines.push(`simulating to t = ${Number(this.target.toPrecision(6))}: ${(100 * state.t / this.target).toFixed(1)}% (Reset stops)`);
    if (this.slow) lines.push(this.slow);
    this.show(lines.join('; '));
  }
}
