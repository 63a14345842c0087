// The momentum sphere: L/|L| in the body frame on a 2D canvas, orthographic, with the polhodes
// and separatrices of the body (physics::polhode_family through the WebAssembly module) and each
// run's trail. Drag (mouse or touch) turns it; a click or tap on it picks the start direction of
// L there (`onPick(u)`, u a body-frame unit vector). By keyboard (docs/explorer.md, "The page"):
// focused, it draws a cross at its centre; the arrow keys turn it under the cross (Shift: finer)
// and Enter or Space picks the direction under the cross.
import * as THREE from 'three';

// The 2D panels draw in software (a canvas in memory, copied to the screen when it changed):
// long polylines stroked through a software WebGL (SwiftShader, headless Chromium without a
// GPU) cost a tenth of a second and more per redraw, on the CPU, in the GPU process.
export const CANVAS_2D = { willReadFrequently: true };

/** Whether the page is on a touch screen (its main pointer coarse): its words say "tap", not
 * "click" (index.html's hints likewise, by the same media query). */
export const touchScreen = () => typeof matchMedia === 'function' && matchMedia('(pointer: coarse)').matches;
const DRAG_PIXELS = 5;  // a press that moves less than this is a click, not a drag
const DOT_REACH_PX = 10;  // a click this close to a drawn L dot (CSS px) picks that dot's L
const FONT_PX = 16;
const KEY_TURN = Math.PI / 36;  // an arrow key's turn of the sphere (5°; with Shift, 1°)
/** The principal axes by ascending moment (physics::principal_order), as the sphere names them. */
const AXIS_NAMES = ['smallest', 'intermediate', 'largest'];

function layerCanvas(W, H) {
  const c = document.createElement('canvas');
  c.width = W; c.height = H;
  return c;
}

/** The nearest and farthest distances from (cx, cy) of the box [x0, x1] × [y0, y1]. */
function boxReach(x0, y0, x1, y1, cx, cy) {
  const near = Math.hypot(Math.max(x0 - cx, 0, cx - x1), Math.max(y0 - cy, 0, cy - y1));
  const far = Math.hypot(Math.max(Math.abs(x0 - cx), Math.abs(x1 - cx)), Math.max(Math.abs(y0 - cy), Math.abs(y1 - cy)));
  return [near, far];
}

/** A label at (x, y) (its left end and baseline; `w` wide, `font` pixels high, on a patch
 * `pad` pixels wider each side, as drawAxes draws it) moved the least, along the line from the
 * disc's centre (cx, cy) and across it by up to two lines, until its patch clears the outline
 * (radius R) by `gap` (wholly inside the disc, or wholly outside it and within `area`,
 * [left, top, right, bottom]) and overlaps none of the patches `taken`; where nothing is, where
 * it was. Returns [x, y]; with `reach` (pixels), moved at most that far along the line, and null
 * where nothing is within it. */
export function clearOfCircle({ x, y, w, font, pad }, { cx, cy, R, gap }, area, taken = [], reach = null) {
  const patch = (px, py) => [px - pad, py - 0.9 * font, px + w + pad, py + 0.25 * font];
  const clear = (px, py) => {
    const [x0, y0, x1, y1] = patch(px, py);
    if (taken.some((t) => x0 < t[2] && t[0] < x1 && y0 < t[3] && t[1] < y1)) return false;
    const [near, far] = boxReach(x0, y0, x1, y1, cx, cy);
    if (far <= R - gap) return true;
    return near >= R + gap && x0 >= area[0] && y0 >= area[1] && x1 <= area[2] && y1 <= area[3];
  };
  const [x0, y0, x1, y1] = patch(x, y);
  const dx = 0.5 * (x0 + x1) - cx, dy = 0.5 * (y0 + y1) - cy, d = Math.hypot(dx, dy) || 1;
  const across = [0, 1, -1, 2, -2].map((n) => n * 1.2 * font);
  for (let step = 0; step <= (reach === null ? 2 * R : reach); ++step) {
    for (const side of across) {
      for (const sign of step ? [-1, 1] : [1]) {
        const px = x + (sign * step * dx - side * dy) / d, py = y + (sign * step * dy + side * dx) / d;
        if (clear(px, py)) return [px, py];
      }
    }
  }
  return reach === null ? [x, y] : null;
}

export class Sphere {
  constructor(canvas, wasm, onPick) {
    this.canvas = canvas;
    this.wasm = wasm;
    this.onPick = onPick;
    // body → view (orthographic: x right, y up, z towards the viewer)
    this.rotation = new THREE.Matrix3().set(0.80, -0.60, 0, 0.25, 0.33, 0.91, -0.55, -0.73, 0.41);
    this.polhodes = null;
    this.moments = '';
    // The polhodes and the trails drawn so far are kept on canvases of their own (layers) and
    // copied in each frame, so that a frame strokes only the trail points added since the last.
    this.layers = { key: null, back: null, trails: null, drawn: [] };
    this.redraw = true;
    this.axisLabels = [];  // the axis names drawn
    this.axisLabelBoxes = [];  // and their patches: {text, box: [left, top, right, bottom]}
    this.dots = [];  // the L dots drawn: {x, y (canvas pixels), u (body-frame L/|L|)}
    this.measuredPoints = 0;  // the points of the measured L/|L| trail drawn
    this.wire();
  }

  /** Backing-store pixels per CSS pixel (main.js sizes the canvas at the screen's density). */
  scale() {
    return this.canvas.width / Math.max(1, this.canvas.clientWidth || this.canvas.width);
  }

  geometry() {
    const W = this.canvas.width, H = this.canvas.height;
    // Room above the disc for the title, around it for the axes' names.
    return { W, H, R: Math.min(W, H) * 0.36, cx: W / 2, cy: H / 2 + 0.03 * H };
  }

  project(u) {
    const e = this.rotation.elements;  // column-major
    return [e[0] * u[0] + e[3] * u[1] + e[6] * u[2], e[1] * u[0] + e[4] * u[1] + e[7] * u[2],
      e[2] * u[0] + e[5] * u[1] + e[8] * u[2]];
  }

  /** The body-frame unit vector under canvas pixel (x, y) on the sphere's front half, or null
   * outside the disc: the view point (X, Y, √(1 − X² − Y²)) taken back through the inverse of
   * the view rotation. */
  bodyDirectionAt(x, y) {
    const { R, cx, cy } = this.geometry();
    const X = (x - cx) / R, Y = (cy - y) / R;
    const rr = X * X + Y * Y;
    if (rr > 1) return null;
    const v = new THREE.Vector3(X, Y, Math.sqrt(1 - rr));
    v.applyMatrix3(this.rotation.clone().invert());
    return v.normalize().toArray();
  }

  wire() {
    const cv = this.canvas;
    let press = null;
    const pixel = (ev) => {
      const box = cv.getBoundingClientRect();
      return [(ev.clientX - box.left) * cv.width / box.width, (ev.clientY - box.top) * cv.height / box.height];
    };
    cv.addEventListener('pointerdown', (ev) => {
      press = { start: [ev.clientX, ev.clientY], last: [ev.clientX, ev.clientY], dragged: false };
      cv.setPointerCapture(ev.pointerId);
    });
    cv.addEventListener('pointermove', (ev) => {
      if (!press) return;
      if (Math.hypot(ev.clientX - press.start[0], ev.clientY - press.start[1]) >= DRAG_PIXELS) press.dragged = true;
      if (!press.dragged) return;
      const dx = (ev.clientX - press.last[0]) * 0.01, dy = (ev.clientY - press.last[1]) * 0.01;
      press.last = [ev.clientX, ev.clientY];
      this.turn(dx, dy);
    });
    cv.addEventListener('pointerup', (ev) => {
      const was = press;
      press = null;
      if (!was || was.dragged) return;
      const [x, y] = pixel(ev);
      // On a drawn L dot (front or back: the dot a student sees and aims at), the L it marks;
      // elsewhere the front half's point under the pointer.
      const reach = DOT_REACH_PX * this.scale();
      const dot = this.dots.find((d) => Math.hypot(d.x - x, d.y - y) <= reach);
      const u = dot ? dot.u : this.bodyDirectionAt(x, y);
      if (u) this.onPick(u);
    });
    cv.addEventListener('pointercancel', () => { press = null; });
    const turns = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
    cv.addEventListener('keydown', (ev) => {
      if (ev.ctrlKey || ev.metaKey || ev.altKey) return;
      if (ev.code in turns) {
        const [dx, dy] = turns[ev.code].map((n) => n * KEY_TURN / (ev.shiftKey ? 5 : 1));
        this.turn(dx, dy);
      } else if (ev.key === 'Enter' || ev.code === 'Space') {
        const { cx, cy } = this.geometry();
        this.onPick(this.bodyDirectionAt(cx, cy));
      } else {
        return;
      }
      ev.preventDefault();
      this.sayCross();
    });
    for (const what of ['focus', 'blur']) cv.addEventListener(what, () => { this.redraw = true; this.sayCross(); });
  }

  /** Turns the view as a drag of (dx, dy) (rad about the view's y and x axes) does. */
  turn(dx, dy) {
    const q = new THREE.Matrix4().makeRotationY(dx).multiply(new THREE.Matrix4().makeRotationX(dy));
    this.rotation = new THREE.Matrix3().setFromMatrix4(q).multiply(this.rotation);
    this.redraw = true;
  }

  /** Whether the keyboard is on the sphere: its cross is drawn. */
  focused() {
    return typeof document !== 'undefined' && document.activeElement === this.canvas;
  }

  /** The direction under the cross in words, for a screen reader (the canvas' description). */
  sayCross() {
    const words = document.getElementById('sphereCross');
    if (!words) return;
    const { cx, cy } = this.geometry();
    const u = this.bodyDirectionAt(cx, cy).map((c) => (Math.abs(c) < 0.005 ? 0 : c).toFixed(2));
    words.textContent = `the cross is on L/|L| = (${u.join(', ')}) in the body frame; Enter starts L there`;
  }

  curve(ctx, pts, colour, width) {
    const { R, cx, cy } = this.geometry();
    ctx.lineWidth = width * this.scale();
    for (let pass = 0; pass < 2; ++pass) {  // back half dim, front half bright
      ctx.strokeStyle = colour; ctx.globalAlpha = pass ? 1 : 0.25;
      ctx.beginPath();
      let pen = false;
      for (const u of pts) {
        const p = this.project(u);
        if ((p[2] >= 0) === !!pass) {
          const x = cx + R * p[0], y = cy - R * p[1];
          if (pen) ctx.lineTo(x, y); else ctx.moveTo(x, y);
          pen = true;
        } else pen = false;
      }
      ctx.stroke();
    }
    ctx.globalAlpha = 1;
  }

  /** The measured L/|L| up to time `t`: a small dot a sample (the far half dimmed). */
  drawMeasured(g, measured, t) {
    const { R, cx, cy } = this.geometry();
    const k = this.scale();
    g.fillStyle = '#f4f4f4';
    let n = 0;
    for (; n < measured.ut.length && measured.ut[n] <= t; ++n) {
      const p = this.project(measured.u.slice(3 * n, 3 * n + 3));
      g.globalAlpha = p[2] >= 0 ? 0.9 : 0.3;
      g.beginPath(); g.arc(cx + R * p[0], cy - R * p[1], 1.8 * k, 0, 2 * Math.PI); g.fill();
    }
    g.globalAlpha = 1;
    this.measuredPoints = n;
  }

  /** The body's principal axes where they pierce the sphere, named by moment (`order`: body
   * axes by ascending moment); the ends on the far side dimmed, each named only where its name
   * fits within two lines of its point, clear of the near ends' names by a margin (it is the
   * other end of an axis named on the near side: at 1024×600 the far names were pushed up to
   * three lines away, into a stack with the near ones). */
  drawAxes(g, order) {
    const { R, cx, cy } = this.geometry();
    const k = this.scale();
    g.font = `${FONT_PX * k}px sans-serif`;
    this.axisLabels = [];
    this.axisLabelBoxes = [];
    const ends = [];
    order.forEach((axis, rank) => {
      for (const sign of [1, -1]) {
        const u = [0, 0, 0];
        u[axis] = sign;
        const p = this.project(u);
        ends.push({ p, x: cx + R * p[0], y: cy - R * p[1], text: `${sign > 0 ? '+' : '−'}${'xyz'[axis]} ${AXIS_NAMES[rank]}` });
      }
    });
    // The near ends' names first, then the far ends' (dimmed), placed around them.
    const taken = [];
    const margin = 4 * k;  // kept between two names' patches
    for (const { p, x, y, text } of ends.filter((e) => e.p[2] >= 0).concat(ends.filter((e) => e.p[2] < 0))) {
      const near = p[2] >= 0;
      g.globalAlpha = near ? 1 : 0.35;
      g.fillStyle = '#e6e6e6';
      g.beginPath(); g.arc(x, y, 3 * k, 0, 2 * Math.PI); g.fill();
      g.globalAlpha = 1;
      const w = g.measureText(text).width;
      // Beside its point, on the side the axis points to, kept on the canvas; then clear of the
      // disc's outline and of the names placed before it (below the sphere's title line).
      const tx0 = Math.min(Math.max(x + (p[0] >= 0 ? 6 * k : -6 * k - w), 2 * k), this.canvas.width - w - 2 * k);
      const ty0 = Math.min(Math.max(y + (p[1] >= 0 ? -6 * k : FONT_PX * k + 2 * k), FONT_PX * k), this.canvas.height - 4 * k);
      const spaced = taken.map((t) => [t[0] - margin, t[1] - margin, t[2] + margin, t[3] + margin]);
      const at = clearOfCircle({ x: tx0, y: ty0, w, font: FONT_PX * k, pad: 2 * k }, { cx, cy, R, gap: 3 * k },
        [0, (FONT_PX + 6) * k, this.canvas.width, this.canvas.height], spaced, near ? null : 2 * FONT_PX * k);
      if (!at) continue;
      const [tx, ty] = at;
      const box = [tx - 2 * k, ty - 0.9 * FONT_PX * k, tx + w + 2 * k, ty + 0.25 * FONT_PX * k];
      taken.push(box);
      // On a patch of the canvas's background, so that no curve runs through the name; a far
      // end's name in grey.
      g.fillStyle = 'rgba(20, 23, 29, 0.85)';
      g.fillRect(box[0], box[1], box[2] - box[0], box[3] - box[1]);
      g.fillStyle = near ? '#e6e6e6' : '#8a8f98';
      g.fillText(text, tx, ty);
      this.axisLabels.push(text);
      this.axisLabelBoxes.push({ text, box });
    }
    g.globalAlpha = 1;
  }

  /** Draws the sphere for `runs` (the first run's body gives the polhodes), and the scene's
   * `measured` L/|L| ({ut, u}: times and body-frame unit vectors, bookspin explore; or null) up
   * to `time` as a white dotted trail. */
  draw(runs, measured = null, time = 0) {
    const g = this.canvas.getContext('2d', CANVAS_2D);
    const { W, H, R, cx, cy } = this.geometry();
    g.fillStyle = '#14171d'; g.fillRect(0, 0, W, H);
    const k = this.scale();
    g.lineWidth = k;
    g.strokeStyle = '#555'; g.beginPath(); g.arc(cx, cy, R, 0, 2 * Math.PI); g.stroke();
    // The caption within the canvas: on a narrow one (a 1024-wide screen's 260 px) its short
    // form, at 12 px at least.
    const act = touchScreen() ? 'tap' : 'click', keys = this.focused();
    let caption = keys ? 'arrows: turn · Enter: start L at +' : `L/|L| in the body frame · ${act}: start here`, px = FONT_PX;
    g.font = `${px * k}px sans-serif`;
    if (g.measureText(caption).width > W - 16 * k) caption = keys ? 'arrows · Enter: start at +' : `L/|L|, body frame · ${act}: start`;
    while (px > 12 && g.measureText(caption).width > W - 16 * k) g.font = `${--px * k}px sans-serif`;
    g.fillStyle = '#ccc';
    g.fillText(caption, 8 * k, (FONT_PX + 2) * k);
    g.font = `${FONT_PX * k}px sans-serif`;
    this.dots = [];
    this.measuredPoints = 0;
    if (!runs.length) return;
    const I = runs[0].session.moments();
    if (I.join() !== this.moments) {
      this.polhodes = this.wasm.polhodes(I[0], I[1], I[2], 5, 0.03);
      this.moments = I.join();
    }
    const L = this.layers;
    const key = [W, H, ...this.rotation.elements, this.moments].join();
    if (key !== L.key || L.drawn.length !== runs.length) {
      L.back = layerCanvas(W, H);
      const b = L.back.getContext('2d', CANVAS_2D);
      for (const c of this.polhodes) {
        const pts = [];
        for (let i = 0; i < c.points.length; i += 3) pts.push([c.points[i], c.points[i + 1], c.points[i + 2]]);
        this.curve(b, pts, c.separatrix ? '#e04848' : '#7a8699', c.separatrix ? 2 : 1);
      }
      L.key = key;
      L.trails = null;
    }
    const shrank = runs.some((r, k) => !(k in L.drawn) || r.trail !== L.drawn[k].trail || r.trail.length < L.drawn[k].n);
    if (!L.trails || shrank) {
      L.trails = layerCanvas(W, H);
      L.drawn = runs.map((r) => ({ trail: r.trail, n: 0 }));
    }
    const t = L.trails.getContext('2d', CANVAS_2D);
    runs.forEach((r, k) => {
      const done = L.drawn[k];
      if (r.trail.length > done.n) {
        // From the last point drawn, so that the new piece joins the old.
        this.curve(t, r.trail.slice(Math.max(0, done.n - 1)), r.colour, 2.5);
        done.n = r.trail.length;
      }
    });
    g.drawImage(L.back, 0, 0);
    g.drawImage(L.trails, 0, 0);
    if (measured) this.drawMeasured(g, measured, time);
    this.drawAxes(g, runs[0].session.principalOrder());
    // Each run's current L: a filled dot on the front half, a dim ring on the far side.
    for (const r of runs) {
      const u = r.trail[r.trail.length - 1];
      const p = this.project(u);
      const x = cx + R * p[0], y = cy - R * p[1];
      g.beginPath(); g.arc(x, y, 6 * k, 0, 2 * Math.PI);
      if (p[2] >= 0) { g.fillStyle = r.colour; g.fill(); } else {
        g.globalAlpha = 0.45; g.strokeStyle = r.colour; g.lineWidth = 2 * k; g.stroke(); g.globalAlpha = 1;
      }
      this.dots.push({ x, y, u: u.slice() });
    }
    if (keys) {
      // The keyboard's cross: where Enter starts L, dark-edged so that it shows on any curve.
      const arm = 10 * k;
      for (const [colour, width] of [['#14171d', 5], ['#f0d060', 2]]) {
        g.strokeStyle = colour; g.lineWidth = width * k;
        g.beginPath(); g.moveTo(cx - arm, cy); g.lineTo(cx + arm, cy); g.moveTo(cx, cy - arm); g.lineTo(cx, cy + arm); g.stroke();
      }
    }
    this.redraw = false;
  }
}
