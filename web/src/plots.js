// The live plots beside the view: ω (body frame), the energy drift and the shape error of each
// run against time, from the runs' recorded diagnostics (web/src/runs.js).
import { CANVAS_2D } from './sphere.js';

const PANELS = [
  ['ω (body, rad/time)', (h) => h.w],
  ['energy drift (E − E0)/E0', (h, r) => [(h.E - r.E0) / r.E0]],
  ['shape error', (h) => [h.shape]],
];
const OMEGA_COLOURS = ['#ff6060', '#60d060', '#6090ff'];

/** Draws the three panels of `runs` on `canvas`. */
export function drawPlots(canvas, runs) {
  const g = canvas.getContext('2d', CANVAS_2D);
  const W = canvas.width, H = canvas.height;
  g.fillStyle = '#14171d'; g.fillRect(0, 0, W, H);
  if (!runs.length) return;
  const ph = H / PANELS.length;
  const tmax = Math.max(1e-9, ...runs.map((r) => r.history[r.history.length - 1].t));
  PANELS.forEach(([title, f], k) => {
    const y0 = k * ph + 18, h = ph - 26;
    let lo = Infinity, hi = -Infinity;
    for (const r of runs) {
      for (const s of r.history) {
        for (const v of f(s, r)) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
      }
    }
    if (!(hi > lo)) { hi = lo + 1e-12; lo -= 1e-12; }
    g.fillStyle = '#ccc'; g.font = '13px sans-serif';
    g.fillText(`${title}  [${lo.toPrecision(3)}, ${hi.toPrecision(3)}]`, 6, y0 - 4);
    g.strokeStyle = '#333'; g.strokeRect(4, y0, W - 8, h);
    runs.forEach((r, ri) => {
      const n = f(r.history[0], r).length;
      for (let c = 0; c < n; ++c) {
        g.strokeStyle = n === 3 ? OMEGA_COLOURS[c] : r.colour;
        g.setLineDash(ri ? [4, 3] : []);
        g.beginPath();
        // One pixel column at a time: its first, lowest, highest and last point (the curve's
        // envelope, at a fraction of the points when the history is longer than the plot is wide).
        let col = null, first, low, high, last, pen = false;
        const flush = () => {
          if (col === null) return;
          for (const y of [first, low, high, last]) { if (pen) g.lineTo(col, y); else g.moveTo(col, y); pen = true; }
        };
        for (const s of r.history) {
          const v = f(s, r)[c];
          if (!Number.isFinite(v)) continue;
          const x = Math.round(4 + (W - 8) * s.t / tmax), y = y0 + h - h * (v - lo) / (hi - lo);
          if (x !== col) { flush(); col = x; first = low = high = last = y; } else {
            low = Math.min(low, y); high = Math.max(high, y); last = y;
          }
        }
        flush();
        g.stroke();
      }
    });
    g.setLineDash([]);
  });
}
