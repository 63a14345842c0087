// The live plots beside the view: ω (body frame), the energy drift and the shape error of each
// run against time, from the runs' recorded diagnostics (web/src/runs.js). Drawn in CSS pixels
// on a backing store at the screen's density (main.js sizes it). Each panel's scale has a floor:
// a range narrower than the floor is widened to it about its middle, so round-off (a rigid
// body's 1e-16 energy drift, an orthonormal matrix's 1e-16 shape error) is drawn as the flat
// line it is, not stretched to fill the panel.
import { CANVAS_2D } from './sphere.js';
import { OMEGA_COLOURS } from './colours.js';

/** A chart's canvas made ready: its backing store at its displayed size (`width` × `height` CSS
 * pixels where it has none yet) times the screen's density, drawn in CSS pixels, cleared to the
 * panels' dark ground; {g: its 2D context, w, h: CSS pixels}. */
export function chartCanvas(canvas, width, height) {
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.clientWidth || width, h = canvas.clientHeight || height;
  canvas.width = Math.round(w * dpr); canvas.height = Math.round(h * dpr);
  // In software, as the panels (sphere.js, CANVAS_2D): the lab's live trace and each toss's
  // chart through a software WebGL held the frame after Stop for seconds, the page's main
  // thread waiting on the GPU process (docs/explorer.md, "Every tap answered at once").
  const g = canvas.getContext('2d', CANVAS_2D);
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.fillStyle = '#14161b'; g.fillRect(0, 0, w, h);
  return { g, w, h };
}

/** [title, values of a record, the smallest half-range drawn] */
const PANELS = [
  ['ω (body, rad/time)', (h) => h.w, 1e-9],
  ['energy drift (E − E0)/E0', (h, r) => [(h.E - r.E0) / r.E0], 1e-6],
  ['shape error', (h) => [h.shape], 1e-6],
];
const FONT_PX = 16;
const TICK_PX = 13;  // the axes' tick labels (at least 12 px: docs/explorer.md)
/** Each run's line: the first solid, the second dashed, then dotted and dash-dotted ones. */
const DASHES = [[], [6, 4], [2, 3], [10, 3, 2, 3], [12, 5], [4, 2, 1, 2], [1, 4], [8, 2, 2, 2, 2, 2]];
const dashOf = (ri) => DASHES[ri % DASHES.length];

/** `[lo, hi]` widened about its middle to at least ±`floor`. */
export function flooredRange(lo, hi, floor) {
  if (!(hi >= lo)) return [-floor, floor];
  if (hi - lo >= 2 * floor) return [lo, hi];
  const mid = 0.5 * (lo + hi);
  return [mid - floor, mid + floor];
}

/** Round ticks ("1-2-5" steps) within [lo, hi], at most `count` + 1 of them and never fewer
 * than two, so that an axis's labels say its range (a range of -0.2 to 0.9 in two steps is 0
 * and 0.5, not 0 alone): {ticks, step}. */
export function niceTicks(lo, hi, count = 3) {
  const span = hi - lo;
  if (!(span > 0) || !Number.isFinite(span)) return { ticks: [lo], step: 0 };
  const magnitude = 10 ** Math.floor(Math.log10(span / Math.max(1, count)));
  // The round steps from the largest that gives at most `count` intervals downwards.
  const steps = [10, 5, 2, 1, 0.5, 0.2, 0.1].map((m) => m * magnitude);
  let at = steps.findIndex((s, i) => i + 1 === steps.length || span / steps[i + 1] > count);
  for (;; ++at) {
    const step = steps[at], ticks = [];
    for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
      ticks.push(Math.abs(v) < 1e-9 * step ? 0 : v);
    if (ticks.length >= 2 || at + 1 === steps.length) return { ticks, step };
  }
}

/** A tick's label: the decimals its step needs, or m×10ⁿ (as "2e-6") for steps under 10⁻³ or
 * from 10⁵ on. */
export function tickLabel(v, step) {
  if (v === 0) return '0';
  if (step > 0 && (step < 1e-3 || step >= 1e5)) {
    // The fewest mantissa decimals that show the tick's value: 1e-6, 1.5e-3 for a step of 5e-4.
    for (let decimals = 0; decimals < 15; ++decimals) {
      const text = v.toExponential(decimals);
      if (Math.abs(Number(text) - v) <= 1e-6 * step) return text.replace('e+', 'e');
    }
    return v.toExponential(15).replace('e+', 'e');
  }
  const decimals = step > 0 ? Math.max(0, -Math.floor(Math.log10(step) + 1e-9)) : 2;
  return v.toFixed(decimals);
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

/** `text` in lines no wider than `width` on `g` (its font), broken after a comma or at a space
 * (a word longer than the width alone on its line). */
export function wrapped(g, text, width) {
  const words = text.split(' ');
  const lines = [];
  let line = '';
  for (const word of words) {
    const next = line ? `${line} ${word}` : word;
    if (line && g.measureText(next).width > width) { lines.push(line); line = word; } else line = next;
  }
  if (line) lines.push(line);
  return lines;
}

/** Draws the three panels of `runs` on `canvas`, with a legend of the runs and a time axis,
 * and the scene's `measured` ω (or null) up to the runs' time as dots on the ω panel; returns
 * {spans: each line's drawn height in CSS pixels, {panel, run, component, px}; measuredDots:
 * how many measured samples were drawn}. `timeUnit`: the time axis's unit ('s' for a toss
 * measured in seconds, docs/explorer.md). `span`: the scene's run (the time slider's end),
 * the time axis's width while the runs are at t = 0 (a scene just opened: its ticks were
 * "0 2e-10 4e-10"). */
export function drawPlots(canvas, runs, measured = null, timeUnit = 'time units', span = 0) {
  const g = canvas.getContext('2d', CANVAS_2D);
  const scale = canvas.width / Math.max(1, canvas.clientWidth || canvas.width);
  g.setTransform(scale, 0, 0, scale, 0, 0);
  const W = canvas.width / scale, H = canvas.height / scale;
  g.fillStyle = '#14171d'; g.fillRect(0, 0, W, H);
  if (!runs.length) return { spans: [], measuredDots: 0 };
  g.font = `${FONT_PX}px sans-serif`;
  // Legend: each run's line style and method (more than two: two to a row, each name without
  // its parenthesis, "(its default)", and cut to its half of the width where still longer; the
  // readout and the books' labels name them whole).
  let y = FONT_PX + 2;
  const perRow = runs.length > 2 ? 2 : 1, cell = (W - 4) / perRow;
  runs.forEach((r, ri) => {
    const x = 6 + (ri % perRow) * cell;
    g.strokeStyle = r.colour; g.lineWidth = 2; g.setLineDash(dashOf(ri));
    g.beginPath(); g.moveTo(x, y - 5); g.lineTo(x + 24, y - 5); g.stroke();
    g.setLineDash([]);
    g.fillStyle = r.colour;
    let label = r.label;
    if (perRow > 1 && g.measureText(label).width > cell - 36) label = label.replace(/ \([^)]*\)/g, '') || label;
    if (perRow > 1) while (label.length > 1 && g.measureText(label).width > cell - 36) label = label.slice(0, -2) + '…';
    // One to a row: the whole name, on as many lines as its width needs (a tile's long label,
    // "flexible: damped particle lattice, velocity Verlet", ran past the canvas's right edge).
    const lines = perRow > 1 ? [label] : wrapped(g, label, cell - 36);
    lines.forEach((line, li) => {
      g.fillText(line, x + 30, y);
      if (li < lines.length - 1) y += FONT_PX + 2;
    });
    if (ri % perRow === perRow - 1 || ri === runs.length - 1) y += FONT_PX + 4;
  });
  if (measured) {
    g.fillStyle = '#ddd';
    for (let c = 0; c < 3; ++c) { g.fillStyle = OMEGA_COLOURS[c]; g.beginPath(); g.arc(12 + 8 * c, y - 5, 3, 0, 2 * Math.PI); g.fill(); }
    // Its words shortened where the column is narrow (at 1024×600 they ran past the canvas).
    const words = ['measured (the scene\'s measured ω)', 'measured ω', 'measured'].find((x) => 36 + g.measureText(x).width <= W - 4) || 'measured';
    g.fillStyle = '#ddd'; g.fillText(words, 36, y);
    y += FONT_PX + 4;
  }
  const axisH = FONT_PX + 10;  // the time axis under the last panel
  const top = y;
  const ph = (H - top - axisH) / PANELS.length;
  const last = Math.max(...runs.map((r) => r.history[r.history.length - 1].t));
  const tmax = last > 0 ? last : span > 0 ? span : 1;
  // The measurement up to the runs' time, not the axis's end (at t = 0: none of it yet).
  const samples = measuredUpTo(measured, Math.max(last, 1e-9));
  g.lineWidth = 1;
  const spans = [];  // how tall each line is drawn (CSS px): the tests' flat-line check
  const tickLabels = [];  // each drawn tick label: {axis, value, step, text} (the tests' digits check)
  // Each panel's range and ticks first: the widest tick label sets the plots' left margin.
  const panels = PANELS.map(([title0, f, floor], k) => {
    const title = timeUnit === 's' ? title0.replace('rad/time', 'rad/s') : title0;
    // The title's line over the panel, its descenders (the parentheses, "y") clear of the top
    // tick label by 2 px (on a phone's 2× screen they met).
    const y0 = top + k * ph + FONT_PX + 6, h = Math.max(4, ph - FONT_PX - 10);
    let lo = Infinity, hi = -Infinity;
    for (const r of runs) {
      for (const s of r.history) {
        for (const v of f(s, r)) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
      }
    }
    if (k === 0) for (const [, w] of samples) for (const v of w) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    [lo, hi] = flooredRange(lo, hi, floor);
    return { title, f, y0, h, lo, hi, ...niceTicks(lo, hi, h > 90 ? 4 : 2) };
  });
  g.font = `${TICK_PX}px sans-serif`;
  let margin = 0;
  for (const p of panels) for (const v of p.ticks) margin = Math.max(margin, g.measureText(tickLabel(v, p.step)).width);
  g.font = `${FONT_PX}px sans-serif`;
  const x0 = 4 + Math.ceil(margin) + 6, x1 = W - 4;  // the plots' left and right edges
  const xOf = (t) => x0 + (x1 - x0) * t / tmax;
  panels.forEach(({ title, f, y0, h, lo, hi, ticks, step }, k) => {
    g.fillStyle = '#ddd';
    let x = 6;
    g.fillText(title, x, y0 - 6);
    x += g.measureText(title).width + 8;
    if (k === 0) {
      ['x', 'y', 'z'].forEach((c, i) => {
        g.fillStyle = OMEGA_COLOURS[i]; g.fillText(c, x, y0 - 6); x += g.measureText(c).width + 6;
      });
    }
    // The value axis: round ticks, their labels in the margin at the left, a faint line across
    // the plot at each.
    g.font = `${TICK_PX}px sans-serif`;
    g.textBaseline = 'middle';
    for (const v of ticks) {
      const ty = y0 + h - h * (v - lo) / (hi - lo);
      g.strokeStyle = '#2a2e36'; g.beginPath(); g.moveTo(x0, ty); g.lineTo(x1, ty); g.stroke();
      const label = tickLabel(v, step);
      tickLabels.push({ axis: title, value: v, step, text: label });
      g.fillStyle = '#aaa';
      g.fillText(label, x0 - 4 - g.measureText(label).width, Math.min(y0 + h - TICK_PX / 2, Math.max(y0 + TICK_PX / 2, ty)));
    }
    g.textBaseline = 'alphabetic';
    g.font = `${FONT_PX}px sans-serif`;
    g.strokeStyle = '#3a3f48'; g.strokeRect(x0, y0, x1 - x0, h);
    runs.forEach((r, ri) => {
      const n = f(r.history[0], r).length;
      for (let c = 0; c < n; ++c) {
        g.strokeStyle = n === 3 ? OMEGA_COLOURS[c] : r.colour;
        g.setLineDash(dashOf(ri));
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
          const px = Math.round(xOf(s.t)), py = y0 + h - h * (v - lo) / (hi - lo);
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
        const px = xOf(t);
        w.forEach((v, c) => {
          g.fillStyle = OMEGA_COLOURS[c];
          g.beginPath(); g.arc(px, y0 + h - h * (v - lo) / (hi - lo), 2, 0, 2 * Math.PI); g.fill();
        });
      }
    }
  });
  // The time axis: round ticks of t under the last panel, its name at the right.
  g.fillStyle = '#aaa';
  g.font = `${TICK_PX}px sans-serif`;
  // The axis's name at the right; the ticks over the times whose labels end left of it (at
  // least two of them: before the first step, tmax at its floor, 0 and the floor).
  const name = `t (${timeUnit})`;
  const nameX = W - 4 - g.measureText(name).width;
  const room = Math.max(0, nameX - 8 - g.measureText(tickLabel(tmax, tmax / 4)).width / 2 - x0);
  const tShown = tmax * Math.min(1, room / Math.max(1, x1 - x0));
  const time = niceTicks(0, tShown, Math.max(1, Math.floor(room / 90)));
  for (const v of time.ticks) {
    const label = tickLabel(v, time.step);
    const tx = Math.max(4, xOf(v) - g.measureText(label).width / 2);
    if (tx + g.measureText(label).width < nameX - 8) {
      g.fillText(label, tx, H - 6);
      tickLabels.push({ axis: 't', value: v, step: time.step, text: label });
    }
  }
  g.fillText(name, nameX, H - 6);
  g.font = `${FONT_PX}px sans-serif`;
  return { spans, measuredDots: samples.length, tickLabels };
}
