// The bookspin explorer: src/physics compiled to WebAssembly (web/bindings.cpp) stepped live,
// the body drawn with three.js, the momentum sphere and plots on 2D canvases. No physics here:
// every number drawn comes from the WebAssembly module (docs/explorer.md).
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { parseState, formatState, DEFAULTS, MODELS, INTEGRATORS, BODIES, AXES } from './state.js';

const $ = (id) => document.getElementById(id);
const SCENES = window.BOOKSPIN_SCENES || [];   // inlined by web/make_explorer.py
const BOOK_ART = window.BOOKSPIN_BOOK_ART || null;  // data: URL of the cover, if inlined

let wasm = null;
let state = null;
const runs = [];          // one per method: {session, label, colour, trail, history, mesh, E0}
let playing = false;
let stepDebt = 0;         // fractional steps carried between animation frames
let lastFrame = null;
let framesDrawn = 0;

const TRAIL_COLOURS = ['#e8b00b', '#35c0f0'];

// ---------- physics runs ----------

function sceneBase(name) {
  const scene = SCENES.find((s) => s.name === name);
  return scene ? { ...DEFAULTS, ...scene.state, scene: name } : DEFAULTS;
}

/**
 * The simulator's session for the state's body. The scene's own body comes whole from bookspin
 * (its `body`: moments, cage and surface as `bookspin simulate` builds them, a mesh included);
 * another preset is built by the physics from its shape, the book from the scene's size.
 */
function bodySession() {
  const scene = SCENES.find((s) => s.name === state.scene);
  if (scene && scene.body && state.body === scene.body.shape) return new wasm.Session(scene.body);
  if (state.body === 'mesh') throw new Error('no mesh body in this scene: choose a mesh scene');
  const book = scene && scene.book && !scene.body ? scene.book : { size: [1.878, 2.9085, 0.5], mass: 8 };
  if (state.body === 'book')
    return new wasm.Session('book', book.mass, 1, book.size[0], book.size[1], book.size[2]);
  return new wasm.Session(state.body, 1, 1, 1, 1, 1);
}

/** ω0 (body frame) of the state: a principal axis at `rate`, or the custom components. */
function omega0(session) {
  if (state.axis === 'custom') return state.w.slice();
  const order = session.principalOrder();
  const w = [0, 0, 0];
  w[order[AXES.indexOf(state.axis)]] = state.rate;
  return w;
}

function makeRun(model, integrator, normalize, colour) {
  const session = bodySession();
  session.configure(model, integrator, normalize, state.damping, state.k, state.cells);
  const w = omega0(session);
  session.reset(w[0], w[1], w[2], state.jiggle, state.seed);
  const run = { session, model, integrator, normalize, colour, trail: [], history: [],
    label: `${model}${model === 'exact' ? '' : ', ' + integrator}${normalize && model !== 'exact' ? ', normalized' : ''}`,
    diverged: '' };
  record(run);
  run.E0 = run.history[0].E;
  return run;
}

function record(run) {
  const d = run.session.diagnostics();
  const u = d.momentum_direction;
  run.trail.push([u[0], u[1], u[2]]);
  const shape = run.model === 'particle' ? d.strain_max
    : run.model === 'rigid-matrix' ? d.orthogonality_error
    : Math.abs(d.quaternion_norm - 1);
  run.history.push({ t: run.session.steps() * state.dt, w: Array.from(d.omega_body), E: d.energy_total,
    shape, cosp: Array.from(d.cos_principal_L) });
  if (run.trail.length > 20000) { run.trail.splice(0, 10000); }
  if (run.history.length > 4000) { run.history = run.history.filter((_, i) => i % 2 === 0); }
}

function disposeRuns() {
  for (const r of runs) { r.session.delete(); if (r.mesh) bodyGroup.remove(r.mesh); }
  runs.length = 0;
}

function rebuild() {
  disposeRuns();
  const errors = [];
  const methods = [[state.model, state.integrator, state.normalize]];
  if (state.compare) methods.push([state.model2, state.integrator2, state.normalize2]);
  methods.forEach(([m, i, n], k) => {
    try {
      runs.push(makeRun(m, i, n, TRAIL_COLOURS[k]));
    } catch (e) {
      errors.push(typeof e === 'number' ? wasm.errorMessage(e) : String(e.message || e));
    }
  });
  $('message').textContent = errors.join('; ');
  runs.forEach((r, k) => { r.mesh = makeBodyMesh(r.session); bodyGroup.add(r.mesh); r.offset = k; });
  frameBodies(false);
  polhodeCache = null;
  const target = state.t;
  state.t = 0;
  if (target > 0) advanceTo(target);
  updatePoses();
  writeUrl();
}

/** Steps every run to time t (the step count round(t/dt)), recording each `dt·every`. */
function advanceTo(t) {
  const total = Math.round(t / state.dt);
  for (const r of runs) {
    let left = total - r.session.steps();
    const chunk = Math.max(1, Math.round(0.05 / state.dt));
    while (left > 0 && !r.diverged) {
      const n = Math.min(chunk, left);
      if (!r.session.step(state.dt, n)) {
        r.diverged = `diverged at t = ${(r.session.steps() * state.dt).toFixed(3)}` +
          (r.session.divergenceReason() ? ': ' + r.session.divergenceReason() : '');
      }
      left -= n;
      record(r);
    }
  }
  state.t = total * state.dt;
}

// ---------- 3D view ----------

const renderer = new THREE.WebGLRenderer({ canvas: $('view'), antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
const scene3 = new THREE.Scene();
scene3.background = new THREE.Color(0x20242c);
const camera = new THREE.PerspectiveCamera(35, 1, 0.1, 200);
camera.position.set(4.2, 2.6, 6.3);
const controls = new OrbitControls(camera, renderer.domElement);
scene3.add(new THREE.AmbientLight(0xffffff, 0.45));
const sun = new THREE.DirectionalLight(0xffffff, 1.1);
sun.position.set(4, 8, 6);
scene3.add(sun);
const bodyGroup = new THREE.Group();
scene3.add(bodyGroup);
const markers = new THREE.Group();
scene3.add(markers);

function bookMaterials() {
  // BoxGeometry faces: +x, −x, +y, −y, +z, −z. The book's faces (docs/physics.md §1):
  // spine +x, fore-edge −x, top +y, bottom −y, front cover +z, back cover −z; the images are
  // bookspin's own (bookspin explore), plain colours without them.
  const load = (face, rotation = 0) => {
    if (!BOOK_ART || !BOOK_ART[face]) return null;
    const tex = new THREE.TextureLoader().load(BOOK_ART[face]);
    tex.colorSpace = THREE.SRGBColorSpace;
    tex.center.set(0.5, 0.5);
    tex.rotation = rotation;
    return tex;
  };
  const mat = (face, colour, rotation) => {
    const map = load(face, rotation);
    return new THREE.MeshLambertMaterial(map ? { map } : { color: colour });
  };
  const pages = mat('pages', 0xf2ecd8, 0);
  return [mat('spine', 0x1f3f6a, Math.PI / 2), pages, pages, pages,
    mat('front', 0x1f4f8a, 0), mat('back', 0x7a1f1f, 0)];
}

/** A mesh in the body frame; its matrix each frame maps the cage onto the run's corners. */
function makeBodyMesh(session) {
  const size = session.cageSize();
  let geometry;
  let material;
  const v = session.surfaceVertices();
  if (v.length === 0) {
    geometry = new THREE.BoxGeometry(size[0], size[1], size[2]);
    material = bookMaterials();
  } else {
    const tri = session.surfaceTriangles();
    const col = session.surfaceColours();
    const pos = new Float32Array(tri.length * 3);
    const rgb = new Float32Array(tri.length * 3);
    for (let f = 0; f < tri.length / 3; ++f) {
      for (let k = 0; k < 3; ++k) {
        const vi = tri[3 * f + k];
        pos.set([v[3 * vi], v[3 * vi + 1], v[3 * vi + 2]], 9 * f + 3 * k);
        rgb.set([col[3 * f], col[3 * f + 1], col[3 * f + 2]], 9 * f + 3 * k);
      }
    }
    geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(rgb, 3));
    geometry.computeVertexNormals();
    material = new THREE.MeshLambertMaterial({ vertexColors: true });
  }
  const mesh = new THREE.Mesh(geometry, material);
  mesh.matrixAutoUpdate = false;
  mesh.userData.size = size;
  return mesh;
}

const arrowL = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 3, 0xffcc00, 0.4, 0.2);
markers.add(arrowL);
const axisArrows = [0xff4040, 0x40d040, 0x4080ff].map((c) => {
  const a = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 2, c, 0.25, 0.12);
  markers.add(a);
  return a;
});

/** The affine map of the cage onto the 8 world corners (corner p: bit d = side along axis d). */
function cageMatrix(corners, size) {
  const c = (p, d) => corners[3 * p + d];
  const m = new THREE.Matrix4();
  const col = (p) => [0, 1, 2].map((d) => (c(p, d) - c(0, d)));
  const ex = col(1).map((x) => x / size[0]);
  const ey = col(2).map((x) => x / size[1]);
  const ez = col(4).map((x) => x / size[2]);
  const centre = [0, 1, 2].map((d) => { let s = 0; for (let p = 0; p < 8; ++p) s += c(p, d); return s / 8; });
  m.set(ex[0], ey[0], ez[0], centre[0],
        ex[1], ey[1], ez[1], centre[1],
        ex[2], ey[2], ez[2], centre[2],
        0, 0, 0, 1);
  return { m, ex, ey, ez, centre };
}

// ---------- framing: where the bodies sit and where the camera looks from ----------

let layout = { radius: 1, step: new THREE.Vector3() };
let framedFor = '';  // the layout the camera was last fitted to

/** The radius of the sphere a body sweeps about its centre of mass: its farthest surface
 * vertex, or cage corner where it has no surface (the book). */
function sweepRadius(session) {
  const c = session.bodyCorners();
  let r = 0;
  for (let p = 0; p < 8; ++p) r = Math.max(r, Math.hypot(c[3 * p], c[3 * p + 1], c[3 * p + 2]));
  // A surface is drawn about the cage's centre (cageMatrix), which may sit off the centre of mass.
  const centre = [0, 1, 2].map((d) => { let s = 0; for (let p = 0; p < 8; ++p) s += c[3 * p + d]; return s / 8; });
  const v = session.surfaceVertices();
  let rv = 0;
  for (let i = 0; i < v.length; i += 3) rv = Math.max(rv, Math.hypot(v[i], v[i + 1], v[i + 2]));
  return rv > 0 ? Math.min(r, rv + Math.hypot(...centre)) : r;
}

/** Where run k's centre of mass is drawn: side by side (one above the other in a view taller
 * than wide), a sweep diameter and a gap apart, the pair centred on the orbit target. */
function offsetOf(k) {
  return layout.step.clone().multiplyScalar(k - (runs.length - 1) / 2);
}

/** Lays the runs out and, when the layout changed (or `force`: the view was resized), puts the
 * camera on its current line of sight at the nearest distance that shows every run's whole
 * sweep sphere (and the L arrow) inside the view with a margin. */
function frameBodies(force) {
  if (!runs.length) return;
  const r = Math.max(...runs.map((run) => sweepRadius(run.session)));
  const tall = camera.aspect < 1;
  const step = runs.length > 1 ? 2.2 * r : 0;
  const key = `${runs.length} ${r} ${tall}`;
  layout = { radius: r, step: new THREE.Vector3(tall ? 0 : step, tall ? -step : 0, 0) };
  arrowL.setLength(1.5 * r, 0.2 * r, 0.1 * r);
  axisArrows.forEach((a) => a.setLength(1.1 * r, 0.12 * r, 0.06 * r));
  if (!force && key === framedFor) return;
  framedFor = key;
  // Each sweep sphere (centre c, radius ρ) must lie within 80% of the half-angles of the view:
  // atan(|x|/z) + asin(ρ/|c|) ≤ α, horizontally and vertically, in the camera's frame.
  const rho = r * (state.showL ? 1.2 : 1);
  const halfV = Math.atan(0.8 * Math.tan(THREE.MathUtils.degToRad(camera.fov / 2)));
  const halfH = Math.atan(0.8 * Math.tan(THREE.MathUtils.degToRad(camera.fov / 2)) * camera.aspect);
  const target = controls.target.clone();
  const dir = camera.position.clone().sub(target).normalize();
  const fits = (d) => {
    camera.position.copy(target).addScaledVector(dir, d);
    camera.lookAt(target);
    camera.updateMatrixWorld();
    return runs.every((_, k) => {
      const p = offsetOf(k).add(target).applyMatrix4(camera.matrixWorldInverse);
      const z = -p.z, dist = p.length();
      if (z <= 0 || dist <= rho) return false;
      const a = Math.asin(rho / dist);
      return Math.atan(Math.abs(p.x) / z) + a <= halfH && Math.atan(Math.abs(p.y) / z) + a <= halfV;
    });
  };
  let lo = rho, hi = 200 * rho;
  for (let i = 0; i < 60; ++i) { const mid = 0.5 * (lo + hi); if (fits(mid)) hi = mid; else lo = mid; }
  fits(hi);
  camera.near = Math.max(1e-3, 0.05 * hi);
  camera.far = 20 * hi;
  camera.updateProjectionMatrix();
  controls.update();
}

function updatePoses() {
  runs.forEach((r, k) => {
    const { m, ex, ey, ez } = cageMatrix(r.session.corners(), r.mesh.userData.size);
    const shift = new THREE.Matrix4().setPosition(offsetOf(k));
    r.mesh.matrix.copy(shift.multiply(m));
    r.mesh.visible = r.session.finite();
    if (k === 0) {
      const d = r.session.diagnostics();
      const L = new THREE.Vector3(d.L[0], d.L[1], d.L[2]);
      arrowL.visible = state.showL && L.length() > 0;
      if (L.length() > 0) arrowL.setDirection(L.normalize());
      arrowL.position.copy(offsetOf(0));
      [ex, ey, ez].forEach((e, i) => {
        const a = axisArrows[i];
        a.visible = state.showAxes;
        const v = new THREE.Vector3(e[0], e[1], e[2]);
        if (v.length() > 0) a.setDirection(v.normalize());
        a.position.copy(arrowL.position);
      });
    }
  });
}

// ---------- momentum sphere (2D canvas, orthographic, drag to rotate) ----------

let polhodeCache = null;
let sphereRot = new THREE.Matrix3().set(0.80, -0.60, 0, 0.25, 0.33, 0.91, -0.55, -0.73, 0.41);

// The 2D panels draw in software (a canvas in memory, copied to the screen when it changed):
// long polylines stroked through a software WebGL (SwiftShader, headless Chromium without a
// GPU) cost a tenth of a second and more per redraw, on the CPU, in the GPU process.
const CANVAS_2D = { willReadFrequently: true };

// The polhodes and the trails drawn so far are kept on canvases of their own (layers) and
// copied in each frame, so that a frame strokes only the trail points added since the last:
// stroking every curve each frame cost most of a frame under a software WebGL (SwiftShader).
const sphereLayers = { key: null, back: null, trails: null, drawn: [] };

function layerCanvas(W, H) {
  const c = document.createElement('canvas');
  c.width = W; c.height = H;
  return c;
}

function drawSphere() {
  const cv = $('sphere');
  const g = cv.getContext('2d', CANVAS_2D);
  const W = cv.width, H = cv.height, R = Math.min(W, H) * 0.42, cx = W / 2, cy = H / 2;
  g.fillStyle = '#14171d'; g.fillRect(0, 0, W, H);
  g.strokeStyle = '#555'; g.beginPath(); g.arc(cx, cy, R, 0, 2 * Math.PI); g.stroke();
  if (!runs.length) return;
  if (!polhodeCache) {
    const I = runs[0].session.moments();
    polhodeCache = wasm.polhodes(I[0], I[1], I[2], 5, 0.03);
  }
  const e = sphereRot.elements;  // column-major
  const proj = (u) => [e[0] * u[0] + e[3] * u[1] + e[6] * u[2], e[1] * u[0] + e[4] * u[1] + e[7] * u[2],
    e[2] * u[0] + e[5] * u[1] + e[8] * u[2]];
  const curve = (ctx, pts, colour, width) => {
    ctx.lineWidth = width;
    for (let pass = 0; pass < 2; ++pass) {  // back half dim, front half bright
      ctx.strokeStyle = colour; ctx.globalAlpha = pass ? 1 : 0.25;
      ctx.beginPath();
      let pen = false;
      for (const u of pts) {
        const p = proj(u);
        const front = p[2] >= 0;
        if (front === !!pass) {
          const x = cx + R * p[0], y = cy - R * p[1];
          if (pen) ctx.lineTo(x, y); else ctx.moveTo(x, y);
          pen = true;
        } else pen = false;
      }
      ctx.stroke();
    }
    ctx.globalAlpha = 1;
  };
  // The layers hold one view (rotation, size) of one set of runs: redrawn whole when any changes.
  const key = [W, H, ...e].join() + (polhodeCache === sphereLayers.polhodes ? '' : '*');
  const trailsShrank = runs.some((r, k) => !(k in sphereLayers.drawn) || r.trail !== sphereLayers.drawn[k].trail ||
    r.trail.length < sphereLayers.drawn[k].n);
  if (key !== sphereLayers.key || sphereLayers.drawn.length !== runs.length) {
    sphereLayers.back = layerCanvas(W, H);
    const b = sphereLayers.back.getContext('2d', CANVAS_2D);
    for (const c of polhodeCache) {
      const pts = [];
      for (let i = 0; i < c.points.length; i += 3) pts.push([c.points[i], c.points[i + 1], c.points[i + 2]]);
      curve(b, pts, c.separatrix ? '#e04848' : '#7a8699', c.separatrix ? 2 : 1);
    }
    sphereLayers.polhodes = polhodeCache;
    sphereLayers.key = [W, H, ...e].join();
    sphereLayers.trails = null;
  }
  if (!sphereLayers.trails || trailsShrank) {
    sphereLayers.trails = layerCanvas(W, H);
    sphereLayers.drawn = runs.map((r) => ({ trail: r.trail, n: 0 }));
  }
  const t = sphereLayers.trails.getContext('2d', CANVAS_2D);
  runs.forEach((r, k) => {
    const done = sphereLayers.drawn[k];
    if (r.trail.length > done.n) {
      // From the last point drawn, so that the new piece joins the old.
      curve(t, r.trail.slice(Math.max(0, done.n - 1)), r.colour, 2.5);
      done.n = r.trail.length;
    }
  });
  g.drawImage(sphereLayers.back, 0, 0);
  g.drawImage(sphereLayers.trails, 0, 0);
  for (const r of runs) {
    const p = proj(r.trail[r.trail.length - 1]);
    g.fillStyle = r.colour; g.beginPath(); g.arc(cx + R * p[0], cy - R * p[1], 5, 0, 2 * Math.PI); g.fill();
  }
  g.fillStyle = '#ccc'; g.font = '14px sans-serif';
  g.fillText('L/|L| in the body frame', 8, 18);
}

(() => {
  const cv = $('sphere');
  let drag = null;
  cv.addEventListener('pointerdown', (ev) => { drag = [ev.clientX, ev.clientY]; cv.setPointerCapture(ev.pointerId); });
  cv.addEventListener('pointerup', () => { drag = null; });
  cv.addEventListener('pointermove', (ev) => {
    if (!drag) return;
    const dx = (ev.clientX - drag[0]) * 0.01, dy = (ev.clientY - drag[1]) * 0.01;
    drag = [ev.clientX, ev.clientY];
    const q = new THREE.Matrix4().makeRotationY(dx).multiply(new THREE.Matrix4().makeRotationX(dy));
    sphereRot = new THREE.Matrix3().setFromMatrix4(q).multiply(sphereRot);
    drawSphere();
  });
})();

// ---------- plots ----------

function drawPlots() {
  const cv = $('plots');
  const g = cv.getContext('2d', CANVAS_2D);
  const W = cv.width, H = cv.height;
  g.fillStyle = '#14171d'; g.fillRect(0, 0, W, H);
  if (!runs.length) return;
  const panels = [
    ['ω (body, rad/time)', (h) => h.w, 3],
    ['energy drift (E − E0)/E0', (h, r) => [(h.E - r.E0) / r.E0], 1],
    ['shape error', (h) => [h.shape], 1],
  ];
  const ph = H / panels.length;
  const tmax = Math.max(1e-9, ...runs.map((r) => r.history[r.history.length - 1].t));
  const wcol = ['#ff6060', '#60d060', '#6090ff'];
  panels.forEach(([title, f], k) => {
    const y0 = k * ph + 18, h = ph - 26;
    let lo = Infinity, hi = -Infinity;
    for (const r of runs) for (const s of r.history) for (const v of f(s, r)) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    if (!(hi > lo)) { hi = lo + 1e-12; lo -= 1e-12; }
    g.fillStyle = '#ccc'; g.font = '13px sans-serif';
    g.fillText(`${title}  [${lo.toPrecision(3)}, ${hi.toPrecision(3)}]`, 6, y0 - 4);
    g.strokeStyle = '#333'; g.strokeRect(4, y0, W - 8, h);
    runs.forEach((r, ri) => {
      const n = f(r.history[0], r).length;
      for (let c = 0; c < n; ++c) {
        g.strokeStyle = n === 3 ? wcol[c] : r.colour;
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

// ---------- flips (for the readout): sign changes of cos(intermediate axis, L) ----------

function flips(run) {
  // A flip: the body axis nearest to L at the start turns over, cos(axis, L) changes sign.
  const h = run.history;
  const axis = [0, 1, 2].reduce((a, b) => (Math.abs(h[0].cosp[b]) > Math.abs(h[0].cosp[a]) ? b : a), 0);
  let n = 0;
  let sign = Math.sign(h[0].cosp[axis]);
  for (const s of h) {
    const c = s.cosp[axis];
    if (Math.abs(c) > 0.5 && Math.sign(c) !== sign) { n += 1; sign = Math.sign(c); }
  }
  return n;
}

// ---------- controls ----------

function fillSelect(id, list) {
  $(id).innerHTML = list.map((x) => `<option value="${x}">${x}</option>`).join('');
}

function readControls() {
  state.scene = $('scene').value;
  state.body = $('body').value;
  state.model = $('model').value;
  state.integrator = $('integrator').value;
  state.normalize = $('normalize').checked;
  state.damping = $('damping').checked;
  state.k = Number($('k').value);
  state.cells = Number($('cells').value);
  state.dt = Number($('dt').value);
  state.axis = $('axis').value;
  state.rate = Number($('rate').value);
  state.w = ['wx', 'wy', 'wz'].map((id) => Number($(id).value));
  state.jiggle = Number($('jiggle').value);
  state.seed = Number($('seed').value);
  state.speed = Number($('speed').value);
  state.compare = $('compare').checked;
  state.model2 = $('model2').value;
  state.integrator2 = $('integrator2').value;
  state.normalize2 = $('normalize2').checked;
  state.showL = $('showL').checked;
  state.showAxes = $('showAxes').checked;
}

function writeControls() {
  for (const id of ['scene', 'body', 'model', 'integrator', 'k', 'cells', 'dt', 'axis', 'rate', 'jiggle',
    'seed', 'speed', 'model2', 'integrator2']) $(id).value = state[id];
  for (const id of ['normalize', 'damping', 'compare', 'normalize2', 'showL', 'showAxes']) $(id).checked = state[id];
  ['wx', 'wy', 'wz'].forEach((id, i) => { $(id).value = state.w[i]; });
  $('custom').style.display = state.axis === 'custom' ? '' : 'none';
  $('rateRow').style.display = state.axis === 'custom' ? 'none' : '';
  $('second').style.display = state.compare ? '' : 'none';
  // 'mesh' is the scene's own mesh body: offered only where the scene has one.
  const scene = SCENES.find((x) => x.name === state.scene);
  const mesh = $('body').querySelector('option[value="mesh"]');
  mesh.disabled = !(scene && scene.body && scene.body.shape === 'mesh');
  mesh.textContent = mesh.disabled ? 'mesh (a mesh scene)' : `mesh (${scene.name})`;
}

function writeUrl() {
  const q = formatState(state, sceneBase(state.scene));
  history.replaceState(null, '', q ? `?${q}` : location.pathname);
}

function setPlaying(p) {
  playing = p;
  $('play').textContent = p ? 'Pause' : 'Play';
  lastFrame = null;
  if (!p) writeUrl();
}

function readout() {
  $('time').textContent = `t = ${state.t.toFixed(2)}`;
  $('slider').max = Math.max(Number($('slider').max), Math.ceil(state.t));
  $('slider').value = state.t;
  $('status').innerHTML = runs.map((r) => {
    const h = r.history[r.history.length - 1];
    return `<div style="color:${r.colour}">${r.label}: ω = (${h.w.map((x) => x.toFixed(4)).join(', ')}), ` +
      `flips ${flips(r)}${r.diverged ? ' — ' + r.diverged : ''}</div>`;
  }).join('');
}

function wire() {
  fillSelect('scene', [''].concat(SCENES.map((s) => s.name)));
  $('scene').options[0].textContent = '(custom)';
  fillSelect('body', BODIES);
  fillSelect('model', MODELS); fillSelect('model2', MODELS);
  fillSelect('integrator', INTEGRATORS); fillSelect('integrator2', INTEGRATORS);
  fillSelect('axis', AXES);
  $('scene').addEventListener('change', () => {
    state = sceneBase($('scene').value);
    writeControls(); rebuild(); draw();
  });
  for (const el of document.querySelectorAll('#controls input, #controls select')) {
    if (el.id === 'scene' || el.id === 'slider') continue;
    el.addEventListener('change', () => {
      const view = el.id === 'showL' || el.id === 'showAxes' || el.id === 'speed';
      const t = state.t;
      readControls();
      writeControls();
      if (view) { updatePoses(); writeUrl(); } else { state.t = 0; rebuild(); }
      if (view) state.t = t;
      draw();
    });
  }
  $('play').addEventListener('click', () => setPlaying(!playing));
  $('stepOnce').addEventListener('click', () => { setPlaying(false); advanceTo(state.t + state.dt); updatePoses(); draw(); writeUrl(); });
  $('reset').addEventListener('click', () => { setPlaying(false); state.t = 0; rebuild(); draw(); });
  $('slider').addEventListener('input', () => {
    setPlaying(false);
    const target = Number($('slider').value);
    if (target < state.t) { state.t = target; rebuild(); } else { advanceTo(target); updatePoses(); }
    draw(); writeUrl();
  });
  window.addEventListener('keydown', (ev) => {
    if (ev.code === 'Space' && !(ev.target instanceof HTMLInputElement && ev.target.type === 'number')) {
      ev.preventDefault(); setPlaying(!playing);
    }
  });
  window.addEventListener('resize', resize);
}

function resize() {
  const v = $('view');
  const w = v.clientWidth, h = v.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / Math.max(1, h);
  camera.updateProjectionMatrix();
  frameBodies(true);
  if (runs.length) updatePoses();
}

// Milliseconds spent in each part of the frames so far (the benchmark's breakdown).
const costs = { physics: 0, view: 0, sphere: 0, plots: 0, readout: 0 };
let plotsDrawnAt = -Infinity;

/** Whether `parts` (arrays and numbers) differ from what `memo.seen` held; remembers them. */
function changed(memo, parts) {
  const same = memo.seen && memo.seen.length === parts.length && parts.every((p, i) => p === memo.seen[i]);
  memo.seen = parts;
  return !same;
}
const sphereSeen = {}, plotsSeen = {};

function draw() {
  let t0 = performance.now();
  const lap = (part) => { const t1 = performance.now(); costs[part] += t1 - t0; t0 = t1; };
  renderer.render(scene3, camera); lap('view');
  // The 2D panels only when what they show changed; while playing, the plots (their whole
  // history rescaled each time) ten times a second, the sphere every frame.
  const sphere = $('sphere'), plots = $('plots');
  if (changed(sphereSeen, [sphere.width, sphere.height, ...sphereRot.elements, polhodeCache,
    ...runs.flatMap((r) => [r.trail, r.trail.length])])) drawSphere();
  lap('sphere');
  if ((!playing || t0 - plotsDrawnAt >= 100) &&
      changed(plotsSeen, [plots.width, plots.height, ...runs.flatMap((r) => [r.history, r.history.length])])) {
    drawPlots();
    plotsDrawnAt = t0;
  }
  lap('plots');
  readout(); lap('readout');
  framesDrawn += 1;
}

function frame(now) {
  if (playing && runs.length) {
    if (lastFrame !== null) {
      const dtWall = Math.min(0.1, (now - lastFrame) / 1000);
      stepDebt += dtWall * state.speed / state.dt;
      const n = Math.floor(stepDebt);
      stepDebt -= n;
      const t0 = performance.now();
      if (n > 0) { advanceTo(state.t + n * state.dt); updatePoses(); }
      costs.physics += performance.now() - t0;
    }
    lastFrame = now;
  }
  controls.update();
  draw();
  requestAnimationFrame(frame);
}

// ---------- test and benchmark hooks (tests/browser/explorer_test.py) ----------

window.explorer = {
  ready: false,
  state: () => structuredClone(state),
  url: () => location.search,
  setPlaying,
  framesDrawn: () => framesDrawn,
  /** Milliseconds spent so far in the frames' physics, 3D view, sphere, plots and readout. */
  frameCosts: () => ({ ...costs }),
  /** ω (body frame) of each run at time t (steps round(t/dt) from the start). */
  omegaAt(t) { state.t = 0; rebuild(); advanceTo(t); updatePoses(); draw(); return runs.map((r) => Array.from(r.session.diagnostics().omega_body)); },
  flips: () => runs.map(flips),
  trails: () => runs.map((r) => ({ colour: r.colour, points: r.trail.length, label: r.label })),
  /** Wall-clock ns per step of a fresh run of `model`/`integrator` (benchmark). */
  nsPerStep(model, integrator, normalize, steps) {
    const s = bodySession();
    s.configure(model, integrator, normalize, state.damping, state.k, state.cells);
    const w = omega0(s);
    s.reset(w[0], w[1], w[2], state.jiggle, state.seed);
    const t0 = performance.now();
    s.step(state.dt, steps);
    const ns = (performance.now() - t0) * 1e6 / steps;
    s.delete();
    return ns;
  },
};

BookspinPhysics().then((module) => {
  wasm = module;
  const params = new URLSearchParams(location.search);
  state = parseState(location.search, sceneBase(params.get('scene') || ''));
  wire();
  writeControls();
  resize();
  rebuild();
  draw();
  window.explorer.ready = true;
  requestAnimationFrame(frame);
});
