// The judged motion replayed beside the exact one (the "Judge a motion" panel, judge.js): the
// body's box drawn in each orientation the motion CSV gives and in the exact motion's at the
// same t (web/judge_bindings.cpp, motionPoses), on a 2D canvas, orthographic, world z up. The
// orientations come from the module; this draws them and computes nothing of the motion.

/** R (body → world, row-major 3×3) of the unit quaternion (w, x, y, z) at `q[4i…]`. */
function rotation(q, i) {
  const [w, x, y, z] = [q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]];
  return [
    1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
    2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
    2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y),
  ];
}

const apply = (R, v) => [0, 1, 2].map((r) => R[3 * r] * v[0] + R[3 * r + 1] * v[1] + R[3 * r + 2] * v[2]);
/** The six faces: the body axis of the normal (0, 1, 2) and its sign. */
const FACES = [[0, 1], [0, -1], [1, 1], [1, -1], [2, 1], [2, -1]];
/** Each face's colour: the book's covers blue, its edges cream, as the 3D view draws it. */
const FACE_COLOURS = ['#e9e0c8', '#e9e0c8', '#d8cfb5', '#d8cfb5', '#2b4c8c', '#3a5ea8'];
/** Seconds a whole motion takes to play. */
const PLAY_SECONDS = 20;

export class Replay {
  constructor(canvas, label) {
    this.canvas = canvas;
    this.label = label;
    this.timer = null;
    this.stop();
  }

  /** Plays `poses` ({t, q, qExact}) of the scene's body (its cage size), looping. */
  start(poses, scene) {
    this.stop();
    this.poses = poses;
    this.half = (scene.body ? scene.body.cage : scene.book.size).map((s) => s / 2);
    this.canvas.hidden = false;
    const n = poses.t.length;
    const started = performance.now();
    const frame = () => {
      const f = ((performance.now() - started) / 1000 / PLAY_SECONDS) % 1;
      this.draw(Math.min(n - 1, Math.floor(f * n)));
      this.timer = requestAnimationFrame(frame);
    };
    frame();
  }

  stop() {
    if (this.timer !== null) cancelAnimationFrame(this.timer);
    this.timer = null;
    this.canvas.hidden = true;
    // No backing store while hidden: a canvas's pixels are its displayed size × devicePixelRatio.
    this.canvas.width = 0;
    this.canvas.height = 0;
    this.label.textContent = '';
  }

  /** Row `i`: the motion on the left, the exact motion on the right. */
  draw(i) {
    const c = this.canvas, ctx = c.getContext('2d');
    const dpr = window.devicePixelRatio || 1;
    const w = c.clientWidth, h = c.clientHeight;
    if (c.width !== Math.round(w * dpr)) { c.width = Math.round(w * dpr); c.height = Math.round(h * dpr); }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, w, h);
    const size = Math.max(...this.half) * 2.1;
    const scale = Math.min(w / 2, h) / (size * 1.15);
    this.box(ctx, rotation(this.poses.q, i), w / 4, h / 2 + 8, scale);
    this.box(ctx, rotation(this.poses.qExact, i), (3 * w) / 4, h / 2 + 8, scale);
    ctx.fillStyle = '#ddd';
    ctx.font = '16px sans-serif';
    ctx.textAlign = 'center';
    ctx.fillText('this motion', w / 4, 18);
    ctx.fillText('exact motion', (3 * w) / 4, 18);
    this.label.textContent = `t = ${this.poses.t[i].toFixed(2)}`;
  }

  /** The box rotated by R, orthographic, centred at (cx, cy). */
  box(ctx, R, cx, cy, scale) {
    const tilt = 0.35, ct = Math.cos(tilt), st = Math.sin(tilt);
    // Seen from −y, a little above: screen up = (0, sin, cos), towards the viewer (0, −cos, sin).
    const project = (p) => [cx + scale * p[0], cy - scale * (ct * p[2] + st * p[1])];
    const faces = FACES.map(([axis, sign], k) => {
      const normal = apply(R, [0, 1, 2].map((a) => (a === axis ? sign : 0)));
      const [u, v] = [0, 1, 2].filter((a) => a !== axis);
      const corners = [[1, 1], [1, -1], [-1, -1], [-1, 1]].map(([su, sv]) => {
        const b = [0, 0, 0];
        b[axis] = sign * this.half[axis];
        b[u] = su * this.half[u];
        b[v] = sv * this.half[v];
        return project(apply(R, b));
      });
      const facing = -ct * normal[1] + st * normal[2];  // > 0: towards the viewer
      return { corners, facing, colour: FACE_COLOURS[k] };
    });
    for (const f of faces.filter((x) => x.facing > 0)) {
      ctx.beginPath();
      f.corners.forEach(([x, y], j) => (j ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
      ctx.closePath();
      ctx.fillStyle = f.colour;
      ctx.globalAlpha = 0.55 + 0.45 * Math.min(1, f.facing);
      ctx.fill();
      ctx.globalAlpha = 1;
      ctx.strokeStyle = '#101216';
      ctx.stroke();
    }
  }
}
