// The bookspin explorer: src/physics compiled to WebAssembly (web/bindings.cpp) stepped live,
// the body drawn with three.js, the momentum sphere and plots on 2D canvases. No physics and no
// measuring here: every number drawn comes from the WebAssembly module (docs/explorer.md).
// This file only wires the parts: state (state.js) and address (address.js), runs (runs.js), 3D
// view (view3d.js), sphere (sphere.js), plots (plots.js) and the measured toss over both
// (panels.js), readout (readout.js), controls (controls.js), keys (keys.js), the work per frame
// (pacing.js), and the panels, each its own module: "Judge a motion" (judge.js), "Phone-toss
// lab" (lab.js), the JavaScript engines (engines/, with --engines); all packed (packed.js).
import { StateSpace } from './state.js';
import { Pacer, FIRST_BUDGET_MS } from './pacing.js';
import { testHooks } from './hooks.js';
import { Runs } from './runs.js';
import { View3D } from './view3d.js';
import { Sphere } from './sphere.js';
import { Panels } from './panels.js';
import { Readout } from './readout.js';
import { listenKeys } from './keys.js';
import { Controls, VIEW_CONTROLS, METHOD_CONTROLS } from './controls.js';
import { JudgePanel } from './judge.js';
import { LabPanel } from './lab.js';
import { loadProgram } from './packed.js';
import { Address } from './address.js';

const $ = (id) => document.getElementById(id);

function startApp(wasm, engines) {
  const SCENES = window.BOOKSPIN_SCENES || [];  // inlined by bookspin explore
  const space = new StateSpace(wasm);  // the physics' names and defaults
  const app = {
    state: space.parse(location.search, space.sceneBase(SCENES, new URLSearchParams(location.search).get('scene') || '')),
    runs: new Runs(wasm, space, SCENES, engines),
    view: new View3D($('view'), window.BOOKSPIN_BOOK_ART || null),
    controls: new Controls(space, SCENES, engines),
    playing: false, stepDebt: 0, lastFrame: null, framesDrawn: 0,
    pacer: new Pacer((text) => { $('notice').textContent = text; }),
    readout: new Readout(),
    // Milliseconds spent in each part of the frames so far (the benchmark's breakdown).
    costs: { physics: 0, view: 0, sphere: 0, plots: 0, readout: 0 },
  };
  const base = () => space.sceneBase(SCENES, app.state.scene);
  /** The scene's measured ω ({t, w, ut, u}, bookspin explore), or null. */
  const measured = () => (SCENES.find((s) => s.name === app.state.scene) || {}).measured || null;

  /** Steps towards time `target` (for at most `ms`, the rest a piece per frame). */
  function catchUp(target, ms) {
    app.pacer.catchUp(app.runs, app.state, target, ms);
    app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
  }

  const address = new Address(space, () => app.state, base);

  function rebuild() {
    const { state, runs } = app;
    $('message').textContent = runs.rebuild(state).join('; ');
    app.view.setRuns(runs.list, state.showL);
    const target = state.t;
    state.t = 0;
    app.pacer.stop();
    catchUp(target, FIRST_BUDGET_MS);
    address.write();
  }

  function advance(t) {
    app.state.t = app.runs.advanceTo(t, app.state.dt);
    app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
  }

  /** A click on the sphere: L starts along body-frame `u` at the current start's |L|. */
  function pickStart(u) {
    const first = app.runs.list[0];
    if (!first) return;
    const w0 = Runs.omega0(first.session, app.state);
    let L = first.session.momentumMagnitude(w0[0], w0[1], w0[2]);
    if (!(L > 0)) L = first.session.momentumMagnitude(app.state.rate, 0, 0);
    app.state = { ...app.state, axis: 'custom', w: Array.from(first.session.omegaForMomentum(u[0], u[1], u[2], L)), t: 0 };
    setPlaying(false);
    app.controls.write(app.state);
    rebuild();
    draw();
  }
  const sphere = new Sphere($('sphere'), wasm, pickStart);
  app.panels = new Panels($('sphere'), $('plots'), sphere, measured);

  function setPlaying(p) {
    app.playing = p;
    $('play').textContent = p ? 'Pause' : 'Play';
    app.lastFrame = null;
    if (!p) address.write();
  }

  function draw() {
    let t0 = performance.now();
    const lap = (part) => { const t1 = performance.now(); app.costs[part] += t1 - t0; t0 = t1; };
    const list = app.runs.list;
    // The readout first: its strip's height sets the view's (index.html), under whose bottom
    // the bodies' labels are placed; placed before it grew, a label ran past the view.
    app.readout.draw(list, app.state.t); lap('readout');
    app.view.render(list); lap('view');
    app.panels.draw(list, app.state.t, app.playing, t0, lap);
    if (app.framesDrawn === 0) app.firstFrameAt = performance.now();
    app.framesDrawn += 1;
  }

  function frame(now) {
    const t0 = performance.now();
    if (app.pacer.continue(app.runs, app.state)) {
      app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
      if (app.pacer.target === null) address.write();
      app.costs.physics += performance.now() - t0;
    } else if (app.playing && app.runs.list.length) {
      if (app.lastFrame !== null) {
        const dtWall = Math.min(0.1, (now - app.lastFrame) / 1000);
        app.stepDebt += dtWall * app.state.speed / app.state.dt;
        const n = Math.floor(app.stepDebt);
        app.stepDebt -= n;
        if (n > 0) {
          app.pacer.play(app.runs, app.state, n, t0);
          app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
        }
        address.whilePlaying(now);
        app.costs.physics += performance.now() - t0;
      }
      app.lastFrame = now;
    }
    draw();
    requestAnimationFrame(frame);
  }

  /** The view, the plots and the left panel fitted to the window (`unfold`: the scene's
   * description shown again where it fits). */
  function resize(unfold = true) {
    app.controls.fitPanel(Boolean(unfold));
    app.panels.resize();
    app.view.resize(app.runs.list, app.state.showL);
    if (app.runs.list.length) app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
  }

  app.controls.listen((id) => {
    if (id === 'scene') {
      app.state = space.sceneBase(SCENES, $('scene').value);
    } else {
      const t = app.state.t;
      app.state = app.controls.read(app.state);
      app.state.t = VIEW_CONTROLS.includes(id) ? t : 0;
      if (METHOD_CONTROLS.includes(id)) app.state.tiles = false;  // the two methods chosen
    }
    app.state = app.pacer.limit(app.state, base());
    app.controls.write(app.state);
    if (VIEW_CONTROLS.includes(id)) { app.view.pose(app.runs.list, app.state.showL, app.state.showAxes); address.write(); } else rebuild();
    draw();
  });
  /** To time `target`: forwards by catching up, backwards by starting again from t = 0. */
  function seek(target) {
    setPlaying(false);
    target = Math.max(0, target);
    if (target < app.state.t) { app.state.t = target; rebuild(); } else catchUp(target, FIRST_BUDGET_MS);
    draw(); address.write();
  }
  function reset() { setPlaying(false); app.state.t = 0; rebuild(); draw(); }
  listenKeys({
    playing: () => app.playing, setPlaying, time: () => app.state.t, dt: () => app.state.dt, seek, reset, writeUrl: (lead) => address.write(lead),
    resetCamera: () => { app.view.resetCamera(app.runs.list, app.state.showL); draw(); },
  });
  window.addEventListener('resize', resize);
  // The view is what the readout's strip leaves (index.html): when the strip grows or shrinks
  // (a second method, a notice), the view is resized and the bodies framed in it again.
  let resizing = false;
  new ResizeObserver(() => {
    if (resizing) return;
    resizing = true;
    requestAnimationFrame(() => { resizing = false; resize(false); });
  }).observe($('view'));
  document.addEventListener('fullscreenchange', resize);

  $('version').textContent = wasm.version();  // bookspin's one version (VERSION)
  app.judge = new JudgePanel(wasm, SCENES, () => app.state.scene);
  app.lab = new LabPanel(wasm, LabPanel.playAsScene(SCENES, app.controls));
  // Test and benchmark hooks (tests/browser/explorer_test.py, bench/explorer_bench.py).
  window.explorer = testHooks(app, sphere, { rebuild, advance, draw, setPlaying, pickStart });
  app.state = app.pacer.limit(app.controls.fit(app.state), base());
  app.controls.write(app.state);
  resize();
  rebuild();
  draw();
  window.explorer.ready = true;
  requestAnimationFrame(frame);
}

// The physics and, with bookspin explore --engines, the JavaScript engines, unpacked (packed.js).
loadProgram().then(([wasm, engines]) => startApp(wasm, engines));
