// The 3D view: the bodies drawn with three.js under an orbit camera (mouse and touch), the L
// arrow and the body axes. Positions come from the WebAssembly module: a surface as bookspin
// draws it (the lattice's own, or carried by the clip stage's trilinear cage), the book's box
// carried by the same cage; nothing is deformed here.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

/** How many of the book's cover images have loaded (each load: the view drawn again). */
const artLoads = { count: 0 };

function bookMaterials(art) {
  // BoxGeometry faces: +x, −x, +y, −y, +z, −z. The book's faces (docs/physics.md §1):
  // spine +x, fore-edge −x, top +y, bottom −y, front cover +z, back cover −z; the images are
  // bookspin's own (bookspin explore), plain colours without them.
  const load = (face, rotation) => {
    if (!art || !art[face]) return null;
    const tex = new THREE.TextureLoader().load(art[face], () => { artLoads.count += 1; });
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

/** A body's mesh and how to pose it: `update(session)` writes its world vertices. */
function makeBody(session, art) {
  const v = session.surfaceVertices();
  if (v.length === 0) {
    // The book: a box whose rest vertices (its corners, one set per face) the cage carries.
    const size = session.cageSize();
    const geometry = new THREE.BoxGeometry(size[0], size[1], size[2]);
    const position = geometry.getAttribute('position');
    const rest = Float64Array.from(position.array);
    const mesh = new THREE.Mesh(geometry, bookMaterials(art));
    const update = (s) => {
      position.array.set(s.carry(rest));
      position.needsUpdate = true;
      geometry.computeVertexNormals();
    };
    return { mesh, update };
  }
  const tri = session.surfaceTriangles();
  const col = session.surfaceColours();
  const pos = new Float32Array(tri.length * 3);
  const rgb = new Float32Array(tri.length * 3);
  for (let f = 0; f < tri.length / 3; ++f) {
    for (let k = 0; k < 3; ++k) rgb.set([col[3 * f], col[3 * f + 1], col[3 * f + 2]], 9 * f + 3 * k);
  }
  const geometry = new THREE.BufferGeometry();
  const position = new THREE.BufferAttribute(pos, 3);
  geometry.setAttribute('position', position);
  geometry.setAttribute('color', new THREE.BufferAttribute(rgb, 3));
  const mesh = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ vertexColors: true }));
  const update = (s) => {
    const w = s.surfaceWorld();
    for (let i = 0; i < tri.length; ++i) {
      const vi = tri[i];
      pos[3 * i] = w[3 * vi]; pos[3 * i + 1] = w[3 * vi + 1]; pos[3 * i + 2] = w[3 * vi + 2];
    }
    position.needsUpdate = true;
    geometry.computeVertexNormals();
    geometry.computeBoundingSphere();
  };
  return { mesh, update };
}

/** The radius of the sphere a body sweeps about its centre of mass: its farthest surface
 * vertex, or cage corner where it has no surface (the book). */
function sweepRadius(session) {
  const c = session.bodyCorners();
  let r = 0;
  for (let p = 0; p < 8; ++p) r = Math.max(r, Math.hypot(c[3 * p], c[3 * p + 1], c[3 * p + 2]));
  const v = session.surfaceVertices();
  let rv = 0;
  for (let i = 0; i < v.length; i += 3) rv = Math.max(rv, Math.hypot(v[i], v[i + 1], v[i + 2]));
  return rv > 0 ? Math.min(r, rv) : r;
}

/** A run's label under its body in a grid of many: its name up to its first parenthesis, and
 * "· replay" for a tile replayed as make figures ran it (runs.js). */
export function shortLabel(run) {
  const name = run.label.split(' (')[0];
  return run.replayed ? `${name} · replay` : name;
}

/** The camera's first line of sight (from the orbit target), where resetCamera() puts it back. */
const HOME = [4.2, 2.6, 6.3];

export class View3D {
  constructor(canvas, art) {
    this.art = art;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    // At the screen's pixel density (a phone at 3×: sharp), the backing store the displayed
    // size times devicePixelRatio (resize()).
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0x20242c);
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.1, 200);
    this.camera.position.set(...HOME);
    this.controls = new OrbitControls(this.camera, canvas);  // mouse, wheel and touch
    // Each run's label, under the body it names (the method's name, in its colour).
    this.labels = [];
    this.scene.add(new THREE.AmbientLight(0xffffff, 0.45));
    const sun = new THREE.DirectionalLight(0xffffff, 1.1);
    sun.position.set(4, 8, 6);
    this.scene.add(sun);
    this.bodies = new THREE.Group();
    this.scene.add(this.bodies);
    this.drawn = [];  // {mesh, update} per run
    this.arrowL = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 3, 0xffcc00, 0.4, 0.2);
    this.scene.add(this.arrowL);
    this.axisArrows = [0xff4040, 0x40d040, 0x4080ff].map((c) => {
      const a = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 2, c, 0.25, 0.12);
      this.scene.add(a);
      return a;
    });
    this.layout = { radius: 1, spacing: 0, pitch: 0, room: 0, cols: 1, rows: 1, count: 0, right: new THREE.Vector3(1, 0, 0), up: new THREE.Vector3(0, 1, 0) };
    this.framedFor = '';
    // Whether the picture drawn last is out of date (a pose, new bodies, the camera moved, a new
    // size, a cover loaded): render() draws only then, so that a paused page asks no frame of
    // the GPU (in software, a frame of this view took the CPU a tap's answer needed: docs/
    // explorer.md, "Every tap answered at once").
    this.stale = true;
    this.artSeen = 0;
    this.controls.addEventListener('change', () => { this.stale = true; });
  }

  /** New bodies for new runs (their sessions). */
  setRuns(runs, showL) {
    for (const d of this.drawn) { this.bodies.remove(d.mesh); d.mesh.geometry.dispose(); }
    this.drawn = runs.map((r) => makeBody(r.session, this.art));
    for (const d of this.drawn) this.bodies.add(d.mesh);
    for (const l of this.labels) l.remove();
    // Labels only where there is more than one body to tell apart (compare mode).
    this.labels = runs.length > 1 ? runs.map((r) => {
      const l = document.createElement('div');
      l.className = runs.length > 2 ? 'bodyLabel small' : 'bodyLabel';
      l.style.color = r.colour;
      // More than two: the method's name without its parenthesis, and "replay" where it is one
      // (the readout and the plots' legend name it whole).
      l.textContent = runs.length > 2 ? shortLabel(r) : r.label;
      // Where the view is short of room (frame(): a landscape phone), the name alone.
      l.dataset.full = l.textContent;
      l.dataset.brief = runs.length > 2 ? r.label.split(' (')[0] : r.label;
      l.title = r.label;
      this.renderer.domElement.parentElement.appendChild(l);
      return l;
    }) : [];
    this.frame(runs, showL, false);
  }

  /** The camera back on its first line of sight, framing every body again. */
  resetCamera(runs, showL) {
    this.controls.target.set(0, 0, 0);
    this.camera.position.set(...HOME);
    this.frame(runs, showL, true);
  }

  /** Each label under its body as drawn now (the bottom of its moved cage corners, world,
   * session.corners, projected to the view's CSS pixels), centred on its cell of the grid and
   * no wider than the cells are apart on the screen, so that neighbours' names never meet. */
  placeLabels(runs) {
    if (!this.labels.length) return;
    const v = this.renderer.domElement;
    const w = v.clientWidth, h = v.clientHeight;
    this.camera.updateMatrixWorld();
    const screenX = (p) => (p.clone().project(this.camera).x + 1) / 2 * w;
    const cellX = runs.map((r, k) => screenX(this.offsetOf(k)));
    const { cols } = this.layout;
    const apart = cols > 1 ? Math.abs(cellX[1] - cellX[0]) : w;
    runs.forEach((r, k) => {
      const label = this.labels[k];
      if (!label) return;
      const c = r.session.corners(), offset = this.offsetOf(k);
      let left = Infinity, right = -Infinity, bottom = -Infinity;
      for (let p = 0; p < 8; ++p) {
        const q = new THREE.Vector3(c[3 * p], c[3 * p + 1], c[3 * p + 2]).add(offset).project(this.camera);
        const x = (q.x + 1) / 2 * w, y = (1 - q.y) / 2 * h;
        left = Math.min(left, x); right = Math.max(right, x); bottom = Math.max(bottom, y);
      }
      // Within its cell of the grid: a long name wraps under its body.
      label.style.left = `${cols > 1 ? cellX[k] : (left + right) / 2}px`;
      label.style.maxWidth = `${Math.max(60, Math.min(apart, w) - 12)}px`;
      // Under its body, but never past the view's bottom, however many lines it wraps to: the
      // box the labels lie in, which shrinks at once when the readout's strip grows (the
      // canvas keeps its old height until the resize that follows: a label placed by it ran
      // 10 px past the view's bottom).
      label.hidden = !Number.isFinite(bottom);
      const floor = Math.min(h, v.parentElement ? v.parentElement.clientHeight : h);
      label.style.top = `${Math.max(0, Math.min(bottom + 6, floor - label.offsetHeight - 4))}px`;
    });
  }

  /** How far the farthest moved cage corner of any run lies from its body's centre, in sweep
   * radii of the layout (1 or less: every body within the room framed for it; more: a body
   * that grows, a particle lattice or a quaternion left unnormalized, docs/physics.md §13). */
  growth(runs) {
    let far = 0;
    for (const r of runs) {
      if (!r.session.finite()) return Infinity;
      const c = r.session.corners();
      for (let p = 0; p < 8; ++p) far = Math.max(far, Math.hypot(c[3 * p], c[3 * p + 1], c[3 * p + 2]));
    }
    return far / this.layout.radius;
  }

  /** Where run k of n is drawn: in a grid of `cols` columns (side by side for two, one above
   * the other in a view taller than wide), a sweep diameter and a gap apart, row by row from the
   * top left, the set centred on the orbit target. */
  offsetOf(k) {
    const { cols, rows, spacing, pitch, room, right, up } = this.layout;
    const col = k % cols, row = Math.floor(k / cols);
    return right.clone().multiplyScalar((col - (cols - 1) / 2) * spacing)
      .addScaledVector(up, ((rows - 1) / 2 - row) * pitch + room / 2);
  }

  /** The tallest label's height (CSS px) when it may be `width` px wide (placeLabels' width:
   * its cell's less 12 px). */
  labelHeight(width) {
    let h = 0;
    for (const l of this.labels) {
      l.style.maxWidth = `${Math.max(60, width - 12)}px`;
      h = Math.max(h, l.offsetHeight);
    }
    return h;
  }

  /** The grid of n bodies in a view w × h CSS px that draws them largest with each label's
   * room under its body, clear of the row below (its tallest label as wrapped in its cell, and
   * 10 px), and its cells at least as wide as the longest word of a label (and placeLabels' 12
   * px: a narrower cell ran a word into its neighbour's), as wide as the view lets them be: {cols, rows, rho: a body's sweep
   * radius in px, cell: the columns' pitch in px, room: the label's px}. The bodies' spheres
   * and the labels under the last row within 80 % of the view, as frame() fits them (a
   * landscape phone's tiles: labels of three lines lay over the lower row's books). */
  gridFor(n, w, h) {
    let word = 0;
    for (const l of this.labels) {
      const was = l.style.width;
      l.style.width = 'min-content';
      word = Math.max(word, l.offsetWidth + 12);
      l.style.width = was;
    }
    const largest = (fits) => {
      let lo = 0, hi = Math.max(w, h);
      for (let i = 0; i < 40; ++i) { const mid = 0.5 * (lo + hi); if (fits(mid)) lo = mid; else hi = mid; }
      return lo;
    };
    let best = null;
    for (let cols = 1; cols <= n; ++cols) {
      const rows = Math.ceil(n / cols);
      const wide = largest((rho) => (cols - 1) * Math.max(2.5 * rho, word) + 2 * rho <= 0.8 * w);
      // As wide as the view lets the columns stand apart: the labels on fewer lines.
      const cellOf = (rho) => Math.max(2.5 * rho, word, cols > 1 ? (0.8 * w - 2 * rho) / (cols - 1) : 0);
      // The largest rho whose rows, each max(2.5 rho, 2 rho + room) apart, and the last row's
      // label fit 80 % of the height.
      const tall = (room) => largest((rho) => (rows - 1) * Math.max(2.5 * rho, 2 * rho + room) + 2 * rho + room <= 0.8 * h);
      let rho = Math.min(wide, tall(0)), room = 0;
      if (this.labels.length) {
        // The labels wrap to the cells' width, which the radius sets: a few rounds to agree.
        for (let i = 0; i < 4; ++i) {
          room = this.labelHeight(cellOf(rho)) + 10;
          rho = Math.min(wide, tall(room));
        }
        room = Math.max(room, this.labelHeight(cellOf(rho)) + 10);
      }
      if (!best || rho > best.rho + 1e-9) best = { cols, rows, rho, room, cell: cellOf(rho) };
    }
    return best;
  }

  /** Lays the runs out and, when the layout changed (or `force`: the view was resized), puts
   * the camera on its current line of sight at the nearest distance that shows every run's
   * whole sweep sphere (and the L arrow) inside the view with a margin. */
  frame(runs, showL, force) {
    this.stale = true;
    if (!runs.length) return;
    const camera = this.camera;
    const r = Math.max(...runs.map((run) => sweepRadius(run.session)));
    // The columns that need the least distance to show every body: the grid's width against
    // the view's aspect, its height (two side by side, or one above the other when taller).
    const n = runs.length;
    const v = this.renderer.domElement, w = v.clientWidth, h = v.clientHeight;
    let cols = 1, grid = null;
    if (n > 1 && w > 0 && h > 0) {
      // The labels whole, or by the name alone (no "· replay": the readout says it) where that
      // draws the bodies a quarter larger.
      const worded = (form) => { for (const l of this.labels) l.textContent = l.dataset[form]; return this.gridFor(n, w, h); };
      const whole = worded('full'), brief = this.labels.some((l) => l.dataset.brief !== l.dataset.full) ? worded('brief') : whole;
      grid = brief.rho > 1.25 * whole.rho ? brief : worded('full');
      cols = grid.cols;
    } else {
      const extent = (c) => Math.max(c / camera.aspect, Math.ceil(n / c));
      for (let c = 2; c <= n; ++c) if (extent(c) < extent(cols)) cols = c;
    }
    const rows = Math.ceil(n / cols);
    // The labels' room in world units: px at the grid's scale (rho px a sweep radius r).
    const perPx = grid && grid.rho > 0 ? r / grid.rho : 0;
    let room = grid ? grid.room * perPx : 0;
    const key = `${n} ${r} ${cols} ${room.toPrecision(3)} ${grid ? grid.cell.toPrecision(3) : ''}`;
    // The same grid as framed last: its layout kept (with the label room frame() measured at the
    // scale drawn: recomputed here, the rows stood closer than the camera was framed for).
    if (!force && key === this.framedFor) return;
    // Two bodies side by side along world x (or y); a grid of more in the plane of the view as
    // the camera looks now, so that its rows stand apart on the screen, with room for the labels.
    const right = new THREE.Vector3(1, 0, 0), up = new THREE.Vector3(0, 1, 0);
    if (n > 2) {
      camera.lookAt(this.controls.target);
      camera.updateMatrixWorld();
      right.setFromMatrixColumn(camera.matrixWorld, 0);
      up.setFromMatrixColumn(camera.matrixWorld, 1);
    }
    const base = n > 2 ? 2.5 * r : n > 1 ? 2.2 * r : 0;
    const spacing = Math.max(base, grid ? grid.cell * perPx : 0);
    this.layout = { radius: r, spacing, pitch: Math.max(base, 2 * r + room), room, cols, rows, count: n, right, up };
    this.arrowL.setLength(1.5 * r, 0.2 * r, 0.1 * r);
    this.axisArrows.forEach((a) => a.setLength(1.1 * r, 0.12 * r, 0.06 * r));
    this.framedFor = key;
    // Each sweep sphere (centre c, radius ρ) must lie within 80% of the half-angles of the
    // view: atan(|x|/z) + asin(ρ/|c|) ≤ α, horizontally and vertically, in the camera's frame.
    const rho = r * (showL ? 1.2 : 1);
    const tanV = 0.8 * Math.tan(THREE.MathUtils.degToRad(camera.fov / 2));
    const halfV = Math.atan(tanV), halfH = Math.atan(tanV * camera.aspect);
    const target = this.controls.target.clone();
    const dir = camera.position.clone().sub(target).normalize();
    const fits = (d) => {
      camera.position.copy(target).addScaledVector(dir, d);
      camera.lookAt(target);
      camera.updateMatrixWorld();
      return runs.every((_, k) => {
        const p = this.offsetOf(k).add(target).applyMatrix4(camera.matrixWorldInverse);
        const z = -p.z, dist = p.length();
        if (z <= 0 || dist <= rho) return false;
        const a = Math.asin(rho / dist);
        // The foot of its label's room, under its sweep sphere, in the view too.
        const foot = this.offsetOf(k).addScaledVector(this.layout.up, -(r + room)).add(target)
          .applyMatrix4(camera.matrixWorldInverse);
        if (room > 0 && (-foot.z <= 0 || Math.atan(Math.abs(foot.y) / -foot.z) > halfV)) return false;
        // Its label's cell (as wide as the columns are apart) across the view too.
        if (room > 0) {
          for (const side of [-0.5, 0.5]) {
            const e = this.offsetOf(k).addScaledVector(this.layout.right, side * this.layout.spacing).add(target)
              .applyMatrix4(camera.matrixWorldInverse);
            if (-e.z <= 0 || Math.atan(Math.abs(e.x) / -e.z) > halfH) return false;
          }
        }
        return Math.atan(Math.abs(p.x) / z) + a <= halfH && Math.atan(Math.abs(p.y) / z) + a <= halfV;
      });
    };
    const nearest = () => {
      let lo = rho, hi = 200 * rho;
      for (let i = 0; i < 60; ++i) { const mid = 0.5 * (lo + hi); if (fits(mid)) hi = mid; else lo = mid; }
      fits(hi);
      return hi;
    };
    let hi = nearest();
    // The grid's scale was gridFor's estimate: at the scale drawn, a label wrapped in its cell
    // may need more room; the room made its height and the view fitted again.
    for (let pass = 0; room > 0 && pass < 3; ++pass) {
      const a = target.clone().project(camera), b = target.clone().add(this.layout.right).project(camera);
      const pxPerUnit = Math.abs(b.x - a.x) / 2 * w;
      if (!(pxPerUnit > 0)) break;
      const need = (this.labelHeight(this.layout.spacing * pxPerUnit) + 10) / pxPerUnit;
      if (need <= 1.02 * room) break;
      room = need;
      this.layout.room = room;
      this.layout.pitch = Math.max(base, 2 * r + room);
      hi = nearest();
    }
    camera.near = Math.max(1e-3, 0.05 * hi);
    camera.far = 20 * hi;
    camera.updateProjectionMatrix();
    this.controls.update();
  }

  /** Moves each body to its run's state, the L arrow and body axes to the first run's. */
  pose(runs, showL, showAxes) {
    this.stale = true;
    runs.forEach((r, k) => {
      const d = this.drawn[k];
      d.mesh.visible = r.session.finite();
      if (!d.mesh.visible) return;
      d.update(r.session);
      d.mesh.position.copy(this.offsetOf(k));
    });
    if (!runs.length) return;
    const first = runs[0].session;
    const finite = first.finite();
    const L = new THREE.Vector3(...first.diagnostics().L);
    this.arrowL.visible = showL && finite && L.length() > 0;
    if (L.length() > 0) this.arrowL.setDirection(L.normalize());
    this.arrowL.position.copy(this.offsetOf(0));
    const R = finite ? first.orientation() : null;  // body → world, column-major
    this.axisArrows.forEach((a, i) => {
      a.visible = showAxes && finite;
      if (R) a.setDirection(new THREE.Vector3(R[3 * i], R[3 * i + 1], R[3 * i + 2]));
      a.position.copy(this.arrowL.position);
    });
    this.placeLabels(runs);
  }

  resize(runs, showL) {
    const v = this.renderer.domElement;
    const w = v.clientWidth, h = v.clientHeight;
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / Math.max(1, h);
    this.camera.updateProjectionMatrix();
    this.frame(runs, showL, true);
  }

  /** Draws the view where it changed since it was drawn last (this.stale); true where it drew. */
  render(runs) {
    this.controls.update();
    if (artLoads.count !== this.artSeen) { this.artSeen = artLoads.count; this.stale = true; }
    if (!this.stale) return false;
    this.stale = false;
    if (runs) this.placeLabels(runs);
    this.renderer.render(this.scene, this.camera);
    return true;
  }
}
