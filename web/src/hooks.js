// The page's hooks for its tests and benchmark (tests/browser/explorer_test.py,
// tests/browser/explorer_engines_test.py, tests/browser/explorer_judge_test.py,
// bench/explorer_bench.py): window.explorer.
import { Runs } from './runs.js';

/** The hooks over `app` (main.js) and its sphere; `fns`: main.js's rebuild, advance, draw,
 * setPlaying. */
export function testHooks(app, sphere, { rebuild, advance, draw, setPlaying, pickStart }) {
  return {
    ready: false,
    /** performance.now() (ms after navigation began) when the first frame was drawn. */
    firstFrameAt: () => app.firstFrameAt,
    /** A pick on the sphere of body-frame direction `u`, as a click there makes it. */
    pick: (u) => pickStart(u),
    state: () => structuredClone(app.state),
    /** Whether the page has caught up with its time (no piece of a catch-up left). */
    settled: () => app.pacer.target === null,
    url: () => location.search,
    setPlaying,
    framesDrawn: () => app.framesDrawn,
    /** How many times the runs were built (main.js, rebuild) and the readout's strip laid out
     * (main.js, layout). */
    rebuilds: () => app.rebuilds,
    layouts: () => app.layouts,
    /** Milliseconds spent so far in the frames' physics, 3D view, sphere, plots and readout. */
    frameCosts: () => ({ ...app.costs }),
    /** ω (body frame) of each run at time t (steps round(t/dt) from the start), in one go. */
    omegaAt(t) {
      app.state.t = 0; rebuild();
      advance(t); app.pacer.stop(); app.pacer.notice(app.state); draw();
      return app.runs.list.map((r) => Array.from(r.session.diagnostics().omega_body));
    },
    flips: () => app.runs.flips(),
    /** Each run's start: body-frame ω0' = I⁻¹·L0, L0 with the jiggle (Session.startOmega). */
    startOmegas: () => app.runs.list.map((r) => Array.from(r.session.startOmega())),
    /** The sphere's L dots as drawn: {x, y (canvas pixels), u}; the axis names drawn. */
    sphereDots: () => sphere.dots.map((d) => ({ x: d.x, y: d.y, u: d.u })),
    sphereAxisLabels: () => sphere.axisLabels.slice(),
    /** The axis names' patches as drawn ({text, box: [left, top, right, bottom]}, canvas
     * pixels) and the disc's outline ({cx, cy, R}, canvas pixels). */
    sphereAxisLabelBoxes: () => ({ labels: sphere.axisLabelBoxes.slice(), disc: sphere.geometry() }),
    /** ω (body frame) of each run now. */
    omegaNow: () => app.runs.list.map((r) => Array.from(r.session.diagnostics().omega_body)),
    /** Each plotted line's drawn height in CSS pixels: {panel, run, component, px}. */
    plotSpans: () => app.panels.spans,
    /** The plots' tick labels as drawn: {axis (a panel's title, or 't'), value, step, text}. */
    plotTickLabels: () => app.panels.tickLabels,
    /** The scene's measured ω as drawn now: {plot: samples drawn as dots on the ω panel,
     * sphere: L/|L| points of the measured trail on the sphere} (0, 0 without one). */
    measuredDrawn: () => ({ plot: app.panels.measuredDots, sphere: sphere.measuredPoints }),
    /** Each run's flip detector: {count, first, period} (analysis::FlipDetector; the exact
     * model's closed form), and the exact motion's from the same start at the page's t. */
    flipMeasures: () => app.runs.list.map((r) => r.session.flips()),
    exactFlips: () => app.runs.list.map((r) => r.session.exactFlips(app.state.t)),
    /** Whether the page still waits before it plays: until its first frame is drawn (every
     * model, the exact one included, starts at once: its orientation is a closed form,
     * docs/physics.md §8). */
    waiting: () => app.framesDrawn === 0,
    trails: () => app.runs.list.map((r) => ({ colour: r.colour, points: r.trail.length, label: r.label })),
    /** The sphere's view rotation (body → view), row-major 3×3. */
    sphereRotation: () => { const e = sphere.rotation.elements; return [0, 1, 2].map((i) => [e[i], e[i + 3], e[i + 6]]); },
    /** Turns the sphere as a drag does: to the view rotation `rows` (body → view, row-major
     * 3×3, a rotation), drawn at the next frame. */
    /** view3d.js's growth(): the bodies' reach now in sweep radii framed (over 1: one grew). */
    bodyGrowth: () => app.view.growth(app.runs.list),
    turnSphere: (rows) => { sphere.rotation.set(...rows.flat()); sphere.redraw = true; },
    /** Wall-clock ns per step of a fresh run of `model`/`integrator` (benchmark). */
    /** `bookspin flipcheck judge SCENARIO FILE` in the page (judge.js): a promise of the
     * judgement of the motion CSV `csvText`, named `file`, against the exact motion of the page's
     * scene `scenario`, keyed by the judgement CSV's columns (analysis::judgement_table: text
     * as text, an empty cell null, the rest numbers); rejected with the command line's one
     * line (without "bookspin: error: ") for a bad file. */
    judgeMotion: (scenario, csvText, file = 'motion.csv') => app.judge.judge(scenario, csvText, file).then((j) => j.row),
    /** {json, csv}: `bookspin flipcheck export`'s two files for `scenario`, as the panel
     * downloads them, or {error}. */
    judgeExport: (scenario) => app.judge.files(scenario),
    /** The scenes the panel offers as scenarios. */
    judgeScenarios: () => app.judge.scenes.map((s) => s.name),
    /** `bookspin fit FILE --drag DRAG` in the page (lab.js): a promise of the fit of the
     * recording `text` (a string, or the file's bytes as a Uint8Array: a zip must be bytes),
     * named `fileName`, as {recording, body: the -fit-body.csv row keyed by its columns,
     * tosses: the -fit.csv rows keyed likewise (an empty cell null, a number a number, text as
     * text), summary: the lines the command prints, charts: each toss's {t, measured, fitted}
     * ω, scenes: each toss as the page's scene data}; `tosses` the flights by hand
     * (`bookspin fit --tosses`' "START:END,…" s; blank: found); rejected with the command
     * line's one line (without "bookspin: error: ") for a bad file or range (naming the
     * field "flights by hand" where the command line names --tosses). */
    fitRecording: (fileName, text, drag = 'linear', tosses = '') => app.lab.fit(fileName, text, drag, tosses),
    /** `bookspin fit FILE1 FILE2 … --drag DRAG` in the page: `files` [{name, bytes}]; a promise
     * of fitRecording's value plus fitted and refused ([{file, error}]) (lab.js fitMany). */
    fitRecordings: (files, drag = 'linear', tosses = '') => app.lab.fitMany(files, drag, tosses),
    /** fitRecordings' value computed on the page's main thread, by the page's own module (as
     * the lab fitted before its worker, fit_worker.js): the reference the worker's answers
     * must equal to the last digit; {error} for a bad one. */
    fitOnMainThread: (files, drag = 'linear', tosses = '') => app.lab.wasm.fitRecordings(files, drag, tosses, undefined),
    /** The lab's calls answered by its worker and on the main thread (fit_worker.js). */
    labFitCounts: () => ({ ...app.lab.worker.counts }),
    /** Whether a fit of the lab's is in flight (in its worker). */
    labFitBusy: () => app.lab.worker.busy,
    /** Plays `scene` (one of fitRecording's scenes) as the lab's Play button does. */
    playToss: (scene) => app.lab.play(scene),
    /** The lab's last fit shown (lab.js show: fitRecording's value), null before one. */
    labResult: () => app.lab.result,
    /** The lab's recordings kept (gyro_recorder.js): [{name, when (ISO, UTC), samples, rate,
     * ticked}], newest last; and the recorder's phase (idle, asking, recording, fitting). */
    labRecordings: () => app.lab.recorder.kept.map((k) => ({
      name: k.name, when: k.when.toISOString(), samples: k.samples, rate: k.rate, ticked: k.ticked })),
    labRecorderPhase: () => app.lab.recorder.phase,
    /** The class's outbox (class_outbox.js): each toss this phone gave a class, in the order
     * kept, [{toss, code, name, state, reason, recording}], and each kept recording's toss id
     * by its name. */
    classOutbox: () => app.classLink.outbox.list().map(({ toss, code, name, state, reason, recording }) => ({ toss, code, name, state, reason, recording })),
    labTossIds: () => Object.fromEntries(app.lab.recorder.kept.map((k) => [k.name, k.toss])),
    /** A promise settled once every toss the class holds was posted again under its id (a lost
     * answer's resend, for a test: the server must store none twice): [[toss, status]]. */
    classResendHeld: () => Promise.all(app.classLink.outbox.list().filter((i) => i.state === 'held').map((i) => {
      const kept = app.lab.recorder.kept.find((k) => k.toss === i.toss);
      return app.classLink.send({ ...i, csv: kept ? kept.text : '' }).then((a) => [i.toss, a.status]);
    })),
    /** A promise settled once the lab's kept recordings were read from the browser's storage
     * and every one removed (a test's fresh start). */
    labForget: () => app.lab.recorder.store.then(() => { for (const k of [...app.lab.recorder.kept]) app.lab.recorder.remove(k); }),
    /** The lab's "Record a toss" reads DeviceMotionEvent.rotationRate where `yes`, even where
     * the browser has a Gyroscope (gyro_recorder.js): the fallback tested in Chromium. */
    recordThroughMotion: (yes) => { app.lab.recorder.source.preferMotion = Boolean(yes); },
    /** ns per step of a run of `steps` steps (make bench-explorer); the exact model, which the
     * page evaluates once per call whatever the steps (its closed form), ns per evaluation:
     * `steps` calls of one step. */
    nsPerStep(model, integrator, normalize, steps) {
      const run = app.runs.startRun(app.state, model, integrator, normalize);
      const t0 = performance.now();
      if (model === 'exact') for (let i = 0; i < steps; ++i) Runs.step(run, app.state.dt, 1);
      else Runs.step(run, app.state.dt, steps);
      const ns = (performance.now() - t0) * 1e6 / steps;
      if (run.engine) run.engine.dispose();
      run.session.delete();
      return ns;
    },
  };
}
