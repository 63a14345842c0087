// The two 2D panels, the momentum sphere and the plots, with the measured toss drawn over them
// when the scene has one (a fitted phone toss, docs/explorer.md: the measured ω as dots on the
// ω plot, its L/|L| as a dotted trail on the sphere). Each is redrawn only when what it shows
// changed; while playing, the plots (their whole history rescaled each time) ten times a second,
// the sphere every frame.
import { drawPlots } from './plots.js';

const PLOTS_EVERY_MS = 100;

/** `canvas`'s backing store at its displayed size times the screen's pixel density. */
function fitCanvas(canvas) {
  const dpr = window.devicePixelRatio || 1;
  const box = canvas.getBoundingClientRect();
  const w = Math.max(1, Math.round(box.width * dpr)), h = Math.max(1, Math.round(box.height * dpr));
  if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
}

export class Panels {
  /** `sphere` (sphere.js) draws on `sphereCanvas`; `measured()`: the scene's measured ω
   * ({t, w, ut, u}, bookspin explore) or null; `sceneSpan()`: the scene's run (plots.js: the time
   * axis at t = 0). */
  constructor(sphereCanvas, plotsCanvas, sphere, measured, timeUnit = () => 'time units', sceneSpan = () => 0) {
    Object.assign(this, { sphereCanvas, plotsCanvas, sphere, measured, timeUnit, sceneSpan });
    this.seen = { sphere: null, plots: null };
    this.plotsDrawnAt = -Infinity;
    this.spans = [];          // each plotted line's drawn height (hooks.js: plotSpans)
    this.measuredDots = 0;    // measured samples drawn as dots on the ω panel
    this.tickLabels = [];     // the plots' tick labels as drawn (hooks.js: plotTickLabels)
  }

  /** Whether `parts` differ from what `seen[name]` held; remembers them. */
  changed(name, parts) {
    const old = this.seen[name];
    this.seen[name] = parts;
    return !(old && old.length === parts.length && parts.every((p, i) => p === old[i]));
  }

  /** The sphere, then the plots, as far as they changed; `lap(part)` after each (the frame's
   * cost breakdown). */
  draw(list, t, playing, now, lap) {
    const s = this.sphereCanvas, p = this.plotsCanvas, measured = this.measured();
    if (this.changed('sphere', [s.width, s.height, measured, ...list.flatMap((r) => [r.trail, r.trail.length])]) || this.sphere.redraw) {
      this.sphere.draw(list, measured, t);
    }
    lap('sphere');
    if ((!playing || now - this.plotsDrawnAt >= PLOTS_EVERY_MS) &&
        this.changed('plots', [p.width, p.height, measured, this.timeUnit(), this.sceneSpan(), ...list.flatMap((r) => [r.history, r.history.length])])) {
      const drawn = drawPlots(p, list, measured, this.timeUnit(), this.sceneSpan());
      this.spans = drawn.spans;
      this.measuredDots = drawn.measuredDots;
      this.tickLabels = drawn.tickLabels;
      this.plotsDrawnAt = now;
    }
    lap('plots');
  }

  /** Both canvases to their displayed size; the sphere redrawn next frame. */
  resize() {
    // The sphere as wide as its column, 16/17 of that tall, in whole pixels of its backing
    // store: a fractional CSS height against a rounded store scales y apart from x, and a pick
    // lands off the point clicked.
    const dpr = window.devicePixelRatio || 1, s = this.sphereCanvas;
    s.style.height = `${Math.round(s.getBoundingClientRect().width * 16 / 17 * dpr) / dpr}px`;
    fitCanvas(this.sphereCanvas);
    fitCanvas(this.plotsCanvas);
    this.sphere.redraw = true;
  }
}
