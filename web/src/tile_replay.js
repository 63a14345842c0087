// A tile of a comparison that the page cannot step (another engine's model: MuJoCo, Bullet and
// ODE natively, docs/engines.md) replayed as `make figures` ran it for the clip: its motion,
// a sample a frame, is made by bookspin (jobs::page_replays) and written into the scene's data by
// `bookspin explore` (`replays`: q and world-frame ω quantised to 16 bits in a data: URL,
// docs/explorer.md "Comparison"). A TileReplay is an EngineRun (engines/engine.js): step() moves
// the page's time on, and quaternion() and omegaWorld() give the sample at or before it, held
// until the next; the page reads them into a WebAssembly session as it reads a JavaScript
// engine's (Session.observe), which measures and draws them. Nothing of the motion is computed
// here.

/** What the page adds to a replayed tile's label. */
export const REPLAY_NOTE = "replay of make figures' run";

/** The little-endian 16-bit integers of data: URL `url`, each times `scale`/32767. */
export function dequantised(url, scale) {
  const binary = atob(url.slice(url.indexOf(',') + 1));
  const out = new Float64Array(binary.length >> 1);
  for (let i = 0; i < out.length; ++i) {
    const v = binary.charCodeAt(2 * i) | (binary.charCodeAt(2 * i + 1) << 8);
    out[i] = (v >= 0x8000 ? v - 0x10000 : v) * scale / 32767;
  }
  return out;
}

export class TileReplay {
  /** `replay`: one of a scene's `replays` ({tile, label, frameDt, frames, q, w, wScale});
   * `dt`: the page's step (time units). */
  constructor(replay, dt) {
    this.frames = replay.frames;
    this.frameDt = replay.frameDt;
    this.dt = dt;
    this.steps = 0;
    this.q = dequantised(replay.q, 1);
    // Each quaternion back to unit length (16 bits leave |q| within 1e-4 of 1).
    for (let i = 0; i < this.q.length; i += 4) {
      const n = Math.hypot(this.q[i], this.q[i + 1], this.q[i + 2], this.q[i + 3]);
      for (let c = 0; c < 4; ++c) this.q[i + c] /= n;
    }
    this.w = dequantised(replay.w, replay.wScale);
  }

  /** The time the replay's samples end (time units). */
  end() {
    return (this.frames - 1) * this.frameDt;
  }

  /** Whether the page's time has passed the last sample. */
  ended() {
    return this.steps * this.dt > this.end() * (1 + 1e-12);
  }

  /** The sample shown: the last at or before the page's time. */
  index() {
    return Math.max(0, Math.min(this.frames - 1, Math.floor(this.steps * this.dt / this.frameDt * (1 + 1e-12))));
  }

  step() { this.steps += 1; }
  quaternion() { const i = 4 * this.index(); return Array.from(this.q.subarray(i, i + 4)); }
  omegaWorld() { const i = 3 * this.index(); return Array.from(this.w.subarray(i, i + 3)); }
  dispose() {}
}
