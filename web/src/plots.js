// The live plots beside the view: ω (body frame), the energy drift and the shape error of each
// run against time, from the runs' recorded diagnostics (web/src/runs.js). Drawn in CSS pixels
// on a backing store at the screen's density (main.js sizes it). Each panel's scale has a floor:
// a range narrower than the floor is widened to it about its middle, so round-off (a rigid
// body's 1e-16 energy drift, an orthonormal matrix's 1e-16 shape error) is drawn as the flat
// line it is, not stretched to fill the panel.
import { CANVAS_2D } from './sphere.js';
import { OMEGA_COLOURS } from './colours.js';

/** [title, values of a record, the smallest half-range drawn] */
const PANELS = [
  ['ω (body, rad/time)', (h) => h.w, 1e-9],
  ['energy drift (E − E0)/E0', (h, r) => [(h.E - r.E0) / r.E0], 1e-6],
  ['shape error', (h) => [h.shape], 1e-6],
];
const FONT_PX = 16;
const DASH = [6, 4];  // the second run's lines

/** `[lo, hi]` widened about its middle to at least ±`floor`. */
export function flooredRange(lo, hi, floor) {
  if (!(hi >= lo)) return [-floor, floor];
  if (hi - lo >= 2 * floor) return [lo, hi];
  const mid = 0.5 * (lo + hi);
  return [mid - floor, mid + floor];
}

/** The samples of `measured` (the scene's measured ω, bookspin explore: {t, w 3×N flattened})
 * up to time `tmax`: [[t, [wx, wy, wz]], ...]. */
function measuredUpTo(measured, tmax) {
  const out = [];
  if (!measured) return out;
  for (let i = 0; i < measured.t.length && measured.t[i] <= tmax; ++i)
    out.push([measured.t[i], measured.w.slice(3 * i, 3 * i + 3)]);
  return out;
}

/** Draws the three panels of `runs` on `canvas`, with a legend of the runs and a time axis,
 * and the scene's `measured` ω (or null) up to the runs' time as dots on the ω panel; returns
 * {spans: each line's drawn height in CSS pixels, {panel, run, component, px}; measuredDots:
 * how many measured samples were drawn}. */
export function drawPlots(canvas, runs, measured = null) {
  const g = canvas.getContext('2d', CANVAS_2D);
  const scale = canvas.width / Math.max(1, canvas.clientWidth || canvas.width);
  g.setTransform(scale, 0, 0, scale, 0, 0);
  const W = canvas.width / scale, H = canvas.height / scale;
  g.fillStyle = '#14171d'; g.fillRect(0, 0, W, H);
  if (!runs.length) return { spans: [], measuredDots: 0 };
  g.font = `${FONT_PX}px sans-serif`;
  // Legend: each run's line style and method.
  let y = FONT_PX + 2;
  runs.forEach((r, ri) => {
    g.strokeStyle = r.colour; g.lineWidth = 2; g.setLineDash(ri ? DASH : []);
    g.beginPath(); g.moveTo(6, y - 5); g.lineTo(30, y - 5); g.stroke();
    g.setLineDash([]);
    g.fillStyle = r.colour; g.fillText(r.label, 36, y);
    y += FONT_PX + 4;
  });
  if (measured) {
    g.fillStyle = '#ddd';
    for (let c = 0; c < 3; ++c) { g.fillStyle = OMEGA_COLOURS[c]; g.beginPath(); g.arc(12 + 8 * c, y - 5, 3, 0, 2 * Math.PI); g.fill(); }
    g.fillStyle = '#ddd'; g.fillText('measured (the scene\'s measured ω)', 36, y);
    y += FONT_PX + 4;
  }
  const axisH = FONT_PX + 6;  // the time axis under the last panel
  const top = y;
  const ph = (H - top - axisH) / PANELS.length;
  const tmax = Math.max(1e-9, ...runs.map((r) => r.history[r.history.length - 1].t));
  const samples = measuredUpTo(measured, tmax);
  g.lineWidth = 1;
  const spans = [];  // how tall each line is drawn (CSS px): the tests' flat-line check
  PANELS.forEach(([title, f, floor], k) => {
    const y0 = top + k * ph + FONT_PX + 4, h = Math.max(4, ph - FONT_PX - 8);
    let lo = Infinity, hi = -Infinity;
    for (const r of runs) {
      for (const s of r.history) {
        for (const v of f(s, r)) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
      }
    }
    if (k === 0) for (const [, w] of samples) for (const v of w) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    [lo, hi] = flooredRange(lo, hi, floor);
    g.fillStyle = '#ddd';
    let x = 6;
    g.fillText(title, x, y0 - 4);
    x += g.measureText(title).width + 8;
    if (k === 0) {
      ['x', 'y', 'z'].forEach((c, i) => {
        g.fillStyle = OMEGA_COLOURS[i]; g.fillText(c, x, y0 - 4); x += g.measureText(c).width + 6;
      });
    }
    g.fillStyle = '#aaa';
    const range = `${lo.toPrecision(2)} … ${hi.toPrecision(2)}`;
    g.fillText(range, W - 6 - g.measureText(range).width, y0 + h - 4);
    g.strokeStyle = '#3a3f48'; g.strokeRect(4, y0, W - 8, h);
    runs.forEach((r, ri) => {
      const n = f(r.history[0], r).length;
      for (let c = 0; c < n; ++c) {
        g.strokeStyle = n === 3 ? OMEGA_COLOURS[c] : r.colour;
        g.setLineDash(ri ? DASH : []);
        g.beginPath();
        // One pixel column at a time: its first, lowest, highest and last point (the curve's
        // envelope, at a fraction of the points when the history is longer than the plot is wide).
        let col = null, first, low, high, last, pen = false, top = Infinity, bottom = -Infinity;
        const flush = () => {
          if (col === null) return;
          for (const yy of [first, low, high, last]) { if (pen) g.lineTo(col, yy); else g.moveTo(col, yy); pen = true; }
        };
        for (const s of r.history) {
          const v = f(s, r)[c];
          if (!Number.isFinite(v)) continue;
          const px = Math.round(4 + (W - 8) * s.t / tmax), py = y0 + h - h * (v - lo) / (hi - lo);
          top = Math.min(top, py); bottom = Math.max(bottom, py);
          if (px !== col) { flush(); col = px; first = low = high = last = py; } else {
            low = Math.min(low, py); high = Math.max(high, py); last = py;
          }
        }
        flush();
        g.stroke();
        spans.push({ panel: title, run: r.label, component: c, px: bottom - top });
      }
    });
    g.setLineDash([]);
    // The measured ω: a dot a sample and component, under the runs' lines' colours.
    if (k === 0) {
      for (const [t, w] of samples) {
        const px = 4 + (W - 8) * t / tmax;
        w.forEach((v, c) => {
          g.fillStyle = OMEGA_COLOURS[c];
          g.beginPath(); g.arc(px, y0 + h - h * (v - lo) / (hi - lo), 2, 0, 2 * Math.PI); g.fill();
        });
      }
    }
  });
  // The time axis: 0 at the left, the latest t at the right.
  g.fillStyle = '#aaa';
  const end = `t = ${tmax.toFixed(1)}`;
  g.fillText('t = 0', 4, H - 6);
  g.fillText(end, W - 4 - g.measureText(end).width, H - 6);
  return { spans, measuredDots: samples.length };
}
