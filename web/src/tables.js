// The exact motion's precession tables, built off the main thread. The exact model's ω(t) is a
// closed form (Jacobi's functions), but its orientation needs ψ(t), the precession angle about
// L, tabulated once per start (docs/physics.md §8): in WebAssembly, where long double is
// emulated in software, that takes seconds near the separatrix. A Web Worker, started from the
// text of the page's own physics script (web/make_explorer.py gives it the id
// "bookspin-physics"), builds each table with precessionTable (web/bindings.cpp) while the page
// stays live; the tables are kept per start, so Reset, a scrub back or compare mode reuse them.
// Where no worker can start, the table is built on the main thread, after the notice is drawn.

const WORKER_MAIN = `
const physics = BookspinPhysics();
onmessage = (ev) => {
  const { id, moments: m, omega0: w } = ev.data;
  physics.then((wasm) => {
    try {
      const t = wasm.precessionTable(m[0], m[1], m[2], w[0], w[1], w[2]);
      postMessage({ id, table: { degree: t.degree, width: t.width, start: t.start, coeffs: t.coeffs } },
        [t.start.buffer, t.coeffs.buffer]);
    } catch (e) {
      postMessage({ id, error: String(typeof e === 'number' ? wasm.errorMessage(e) : (e && e.message) || e) });
    }
  });
};
`;

export class PrecessionTables {
  /** `wasm`: the page's module (the fallback on the main thread). */
  constructor(wasm) {
    this.wasm = wasm;
    this.tables = new Map();  // key → Promise of {degree, width, start, coeffs}
    this.built = new Map();  // key → the table, once built
    this.waiting = new Map();  // request id → {resolve, reject}
    this.nextId = 0;
    this.worker = null;
    try {
      const source = document.getElementById('bookspin-physics').textContent;
      const url = URL.createObjectURL(new Blob([source, WORKER_MAIN], { type: 'text/javascript' }));
      this.worker = new Worker(url);
      this.worker.onmessage = (ev) => {
        const w = this.waiting.get(ev.data.id);
        this.waiting.delete(ev.data.id);
        if (!w) return;
        if (ev.data.error) w.reject(new Error(ev.data.error)); else w.resolve(ev.data.table);
      };
      this.worker.onerror = (ev) => {
        ev.preventDefault();
        this.failWorker(ev.message || 'the worker stopped');
      };
    } catch (e) {
      this.worker = null;
    }
  }

  /** The worker failed: what it was asked is built here instead. */
  failWorker(reason) {
    console.warn(`precession tables: no worker (${reason}); built on the main thread`);
    if (this.worker) this.worker.terminate();
    this.worker = null;
    const left = [...this.waiting.values()];
    this.waiting.clear();
    for (const w of left) this.buildHere(w.moments, w.omega0).then(w.resolve, w.reject);
  }

  buildHere(moments, omega0) {
    // Two animation frames first: the notice saying what is computed is on the screen.
    return new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))).then(() => {
      const t = this.wasm.precessionTable(moments[0], moments[1], moments[2], omega0[0], omega0[1], omega0[2]);
      return { degree: t.degree, width: t.width, start: t.start, coeffs: t.coeffs };
    });
  }

  /** The table of `moments` and `omega0` at once: the one built already, else built here, on the
   * main thread (the tests' and the benchmark's synchronous runs). */
  now(moments, omega0) {
    const key = [...moments, ...omega0].join();
    if (!this.built.has(key)) {
      const t = this.wasm.precessionTable(moments[0], moments[1], moments[2], omega0[0], omega0[1], omega0[2]);
      this.built.set(key, { degree: t.degree, width: t.width, start: t.start, coeffs: t.coeffs });
    }
    return this.built.get(key);
  }

  /** A Promise of the table of principal moments `moments` and body-frame start `omega0`
   * (Session.moments, Session.startOmega), built once per start. */
  get(moments, omega0) {
    const key = [...moments, ...omega0].join();
    if (this.built.has(key)) return Promise.resolve(this.built.get(key));
    if (!this.tables.has(key)) {
      const promise = this.worker ? new Promise((resolve, reject) => {
        const id = this.nextId++;
        this.waiting.set(id, { resolve, reject, moments, omega0 });
        this.worker.postMessage({ id, moments: Array.from(moments), omega0: Array.from(omega0) });
      }) : this.buildHere(moments, omega0);
      promise.then((table) => this.built.set(key, table), () => this.tables.delete(key));
      this.tables.set(key, promise);
    }
    return this.tables.get(key);
  }
}
