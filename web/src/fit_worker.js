// The lab's fit and the judge off the page's main thread (docs/explorer.md, "The lab's fit in a
// worker"; docs/phone-lab.md, "The lab in a class"): a Web Worker made of the very physics'
// script the page runs (index.html's #bookspinPhysics, web/make_explorer.py) and the page's
// own WebAssembly bytes, so its answers are the main thread's to the last digit. The worker is
// a Blob URL of that text: the page is one file that opens from disk (file://, where a worker
// from a file's URL is refused) and over http alike. While it fits, the page draws and answers
// (Close, Escape, Cancel); the fit's progress (each recording read, then the fit's stages, as
// web/fit_bindings.cpp tells them) comes back as messages; cancel() ends the worker at once.
// Nothing is fitted here: this module carries calls to the module and its answers back.
import { physicsBytes } from './packed.js';
import { loneSurrogateInArguments } from './well_formed.js';

/** The worker's own code, run as its text after the physics' script (so it uses nothing of
 * this module's scope): it loads the module from the bytes of its {load} message, then answers
 * each {id, method, args} with {id, result} or {id, error}; a method given `progress: true`
 * gets a last argument that posts {id, progress: [stage, …details]}, at most one "fit" stage
 * (each solver iteration) a PROGRESS_MS. */
function workerMain() {
  const PROGRESS_MS = 250;
  // The calls wait for the module: the bytes come a moment after the first call.
  let load;
  const loaded = new Promise((resolve) => { load = resolve; });
  self.onmessage = (e) => {
    const m = e.data;
    if (m.load) {
      load(BookspinPhysics(m.load.wasmBinary ? { wasmBinary: m.load.wasmBinary } : {}));
      return;
    }
    loaded.then((wasm) => {
      let iterations = 0, last = 0, stage = '';
      const progress = (name, ...details) => {
        if (name === 'fit') {
          ++iterations;
          const now = performance.now();
          if (stage === 'fit' && now - last < PROGRESS_MS) return;
          last = now;
          details = [iterations];
        }
        stage = name;
        self.postMessage({ id: m.id, progress: [name, ...details] });
      };
      const args = m.progress ? [...m.args, progress] : m.args;
      let result;
      try {
        result = wasm[m.method](...args);
      } catch (err) {
        self.postMessage({ id: m.id, error: String((err && err.message) || err) });
        return;
      }
      self.postMessage({ id: m.id, result });
    }, (err) => self.postMessage({ id: m.id, error: `the module did not load: ${(err && err.message) || err}` }));
  };
}

/** A call ended by cancel(): its promise is rejected with this. */
export class Cancelled extends Error {
  constructor() { super('cancelled'); this.name = 'Cancelled'; }
}

/** The worker's script: the physics' script's text and workerMain; null where the page has no
 * #bookspinPhysics (a page built before it). */
function workerSource() {
  const physics = document.getElementById('bookspinPhysics');
  if (!physics) return null;
  return `${physics.textContent}\n;(${workerMain.toString()})();\n`;
}

/** Calls into the module in a worker of its own; one call at a time (a new call while one runs
 * cancels it: the lab fits the last thing asked). `wasm`: the page's own module, used where
 * the browser makes no worker (then on the main thread, as before; `inWorker` says which). */
export class FitWorker {
  constructor(wasm) {
    this.wasm = wasm;
    this.worker = null;
    this.pending = null;
    this.nextId = 1;
    /** Calls answered by a worker, and on the main thread (the test hooks read these). */
    this.counts = { worker: 0, main: 0 };
  }

  /** The worker, made (and its module loaded) where there is none; null where the browser
   * makes none. */
  start() {
    if (this.worker) return this.worker;
    const source = typeof Worker === 'function' ? workerSource() : null;
    if (!source) return null;
    let worker;
    const url = URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
    try {
      worker = new Worker(url);
    } catch (e) {
      console.warn(`the lab's fit runs on the page's main thread: no worker (${e.message})`);
      return null;
    } finally {
      URL.revokeObjectURL(url);
    }
    worker.onmessage = (e) => this.answer(e.data);
    worker.onerror = (e) => {
      e.preventDefault();
      this.settle(this.pending, null, new Error(`the fit's worker failed: ${e.message || 'no message'}`));
      this.end();
    };
    physicsBytes().then((wasmBinary) => worker.postMessage({ load: { wasmBinary } }, wasmBinary ? [wasmBinary.buffer] : []));
    this.worker = worker;
    return worker;
  }

  /** A promise of the module's `method(...args)` (for the lab's fits, with `onProgress(stage,
   * …details)` told each stage: `progress` true). Rejected with Cancelled by cancel() or a
   * later call, with the worker's error otherwise (the module's own {error} answers resolve);
   * with loneSurrogateInArguments' line, before anything is asked, for text no UTF-8 holds. */
  call(method, args, onProgress = null) {
    // No lone surrogate reaches the module (well_formed.js): the fields name their own first.
    const problem = loneSurrogateInArguments(method, args);
    if (problem) return Promise.reject(new Error(problem));
    this.cancel();
    const worker = this.start();
    if (!worker) {
      // No worker: on the main thread, a turn of the event loop first (the page says what it does).
      return new Promise((resolve) => setTimeout(resolve, 0)).then(() => {
        this.counts.main += 1;
        return this.wasm[method](...args, ...(onProgress ? [(...p) => onProgress(...p)] : []));
      });
    }
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      this.pending = { id, resolve, reject, onProgress };
      worker.postMessage({ id, method, args, progress: Boolean(onProgress) });
    });
  }

  answer(m) {
    const p = this.pending;
    if (!p || m.id !== p.id) return;
    if (m.progress) { if (p.onProgress) p.onProgress(...m.progress); return; }
    this.counts.worker += 1;
    this.settle(p, m.result, 'error' in m ? new Error(m.error) : null);
  }

  settle(p, result, error) {
    if (!p || this.pending !== p) return;
    this.pending = null;
    if (error) p.reject(error); else p.resolve(result);
  }

  /** Whether a call is in flight. */
  get busy() { return this.pending !== null; }

  /** The call in flight ended at once (its worker terminated, its promise rejected with
   * Cancelled); the next call makes a fresh worker. Nothing where none is in flight. */
  cancel() {
    const p = this.pending;
    if (!p) return false;
    this.end();
    p.reject(new Cancelled());
    return true;
  }

  end() {
    if (this.worker) this.worker.terminate();
    this.worker = null;
    this.pending = null;
  }
}
