// The bookspin explorer: src/physics compiled to WebAssembly (web/bindings.cpp) stepped live,
// the body drawn with three.js, the momentum sphere and plots on 2D canvases. No physics and no
// measuring here: every number drawn comes from the WebAssembly module (docs/explorer.md).
// This file wires the parts: state and URL (state.js), runs (runs.js), 3D view (view3d.js),
// sphere (sphere.js), plots (plots.js), controls (controls.js), the work per frame (pacing.js);
// the JavaScript engines, with --engines, come as window.BOOKSPIN_ENGINES (engines/).
import { StateSpace } from './state.js';
import { Pacer, FIRST_BUDGET_MS } from './pacing.js';
import { testHooks } from './hooks.js';
import { Runs } from './runs.js';
import { View3D } from './view3d.js';
import { Sphere } from './sphere.js';
import { drawPlots } from './plots.js';
import { Controls, VIEW_CONTROLS } from './controls.js';
import { PrecessionTables } from './tables.js';

const $ = (id) => document.getElementById(id);
/** Time units of one Step (and of → and ←), at least. */
const STEP_TIME = 0.5;
/** While playing, the address is rewritten every 60 ms to 1 s, so that it keeps t. */
const URL_MIN_MS = 60, URL_MAX_MS = 1000;
/** `x` to `digits` decimals, without a "-0.00". */
const fixed = (x, digits) => (Math.abs(x) < 0.5 * 10 ** -digits ? 0 : x).toFixed(digits);

function startApp(wasm, engines) {
  const SCENES = window.BOOKSPIN_SCENES || [];  // inlined by bookspin explore
  const space = new StateSpace(wasm);  // the physics' names and defaults
  const app = {
    state: space.parse(location.search, space.sceneBase(SCENES, new URLSearchParams(location.search).get('scene') || '')),
    runs: new Runs(wasm, space, SCENES, engines),
    view: new View3D($('view'), window.BOOKSPIN_BOOK_ART || null),
    controls: new Controls(space, SCENES, engines),
    playing: false, stepDebt: 0, lastFrame: null, framesDrawn: 0, plotsDrawnAt: -Infinity,
    pacer: new Pacer((text) => { $('notice').textContent = text; }),
    tables: new PrecessionTables(wasm),
    waitingSince: null,  // performance.now() when a run began waiting for its precession table
    seen: { sphere: null, plots: null },
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

  /** The address of the state. `lead` (time units): while playing, t is written ahead of the
   * time shown by half the time until the next rewrite, so that between two rewrites the address
   * is never more than half that time off (0.45 at speed 15). */
  function writeUrl(lead = 0) {
    const q = space.format(lead ? { ...app.state, t: app.state.t + lead } : app.state, base());
    history.replaceState(null, '', q ? `?${q}` : location.pathname);
  }

  function rebuild() {
    const { state, runs } = app;
    $('message').textContent = runs.rebuild(state).join('; ');
    app.view.setRuns(runs.list, state.showL);
    const target = state.t;
    state.t = 0;
    app.pacer.stop();
    requestTables();
    catchUp(target, FIRST_BUDGET_MS);
    writeUrl();
  }

  /** Each run waiting for its exact orientation gets its precession table, built off the main
   * thread (tables.js); the page goes on meanwhile, the run held at t = 0, a notice saying so. */
  function requestTables() {
    const waiting = app.runs.list.filter((r) => r.pending);
    app.waitingSince = waiting.length ? performance.now() : null;
    waitingNotice();
    for (const run of waiting) {
      app.tables.get(run.session.moments(), run.session.startOmega()).then((table) => {
        // A run supplied already (the test hooks build its table at once) or gone: the notice
        // ends all the same once no run waits.
        const supplied = app.runs.supply(run, table);
        if (!app.runs.pending()) app.waitingSince = null;
        if (!supplied) { waitingNotice(); return; }
        waitingNotice();
        if (app.pacer.target === null && app.state.t > 0) app.pacer.target = app.state.t;
        app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
        draw();
      }, (err) => {
        $('message').textContent = `exact motion: ${err.message || err}`;
      });
    }
  }

  function waitingNotice() {
    const since = app.waitingSince;
    app.pacer.waiting = since === null ? '' :
      `computing the exact motion's orientation (its precession table) in the background: ` +
      `${((performance.now() - since) / 1000).toFixed(1)} s; the exact run waits at t = 0, the page stays live`;
    app.pacer.notice(app.state);
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

  function setPlaying(p) {
    app.playing = p;
    $('play').textContent = p ? 'Pause' : 'Play';
    app.lastFrame = null;
    if (!p) writeUrl();
  }

  /** The readout a class reads from the back: t, and for each run its flips (the method's own
   * turn-over detector, docs/physics.md §14) and its first flip beside the exact motion's. */
  function readout() {
    const { state, runs } = app;
    const t = fixed(state.t, 2);
    $('time').textContent = `t = ${t}`;
    $('clock').textContent = `t = ${t}`;
    $('slider').max = Math.max(Number($('slider').max), Math.ceil(state.t));
    $('slider').value = state.t;
    const html = runs.list.map((r) => {
      const h = r.history[r.history.length - 1];
      const own = r.session.flips();
      const exact = r.closedForm ? own : r.session.exactFlips(state.t);
      const first = own.first === null ? '—' : fixed(own.first, 2);
      const beside = r.closedForm ? '(the exact motion)' : exact.first === null
        ? 'exact motion: never turns over (a wobble)'
        : `exact motion: first flip at ${fixed(exact.first, 2)}, count ${exact.count}`;
      return `<div class="run" style="color:${r.colour}"><div class="method">${r.label}${r.diverged ? ' — ' + r.diverged : ''}</div>` +
        `<div class="counts"><span class="big flips">flips ${own.count}</span> ` +
        `<span class="big first">first flip at t = ${first}</span> <span class="exact">${beside}</span></div>` +
        // ω in numbers for one run; in compare mode the plots show it, and the books stay in view.
        (runs.list.length > 1 ? '' : `<div class="omega">ω = (${h.w.map((x) => x.toFixed(4)).join(', ')})</div>`) +
        '</div>';
    }).join('');
    if (html !== app.seen.readout) { $('status').innerHTML = html; app.seen.readout = html; }
    if (app.waitingSince !== null) waitingNotice();
  }

  /** Whether `parts` differ from what `seen[name]` held; remembers them. */
  function changed(name, parts) {
    const old = app.seen[name];
    app.seen[name] = parts;
    return !(old && old.length === parts.length && parts.every((p, i) => p === old[i]));
  }

  function draw() {
    let t0 = performance.now();
    const lap = (part) => { const t1 = performance.now(); app.costs[part] += t1 - t0; t0 = t1; };
    const list = app.runs.list;
    app.view.render(list); lap('view');
    // The 2D panels only when what they show changed; while playing, the plots (their whole
    // history rescaled each time) ten times a second, the sphere every frame.
    const s = $('sphere'), p = $('plots');
    if (changed('sphere', [s.width, s.height, measured(), ...list.flatMap((r) => [r.trail, r.trail.length])]) || sphere.redraw) {
      sphere.draw(list, measured(), app.state.t);
    }
    lap('sphere');
    if ((!app.playing || t0 - app.plotsDrawnAt >= 100) &&
        changed('plots', [p.width, p.height, measured(), ...list.flatMap((r) => [r.history, r.history.length])])) {
      const drawn = drawPlots(p, list, measured());
      app.plotSpans = drawn.spans;
      app.measuredDots = drawn.measuredDots;
      app.plotsDrawnAt = t0;
    }
    lap('plots');
    readout(); lap('readout');
    if (app.framesDrawn === 0) app.firstFrameAt = performance.now();
    app.framesDrawn += 1;
  }

  function frame(now) {
    const t0 = performance.now();
    if (app.pacer.continue(app.runs, app.state)) {
      app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
      if (app.pacer.target === null) writeUrl();
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
        // Every half time unit, as often as browsers let a page rewrite its address (about
        // 200 times in 10 s), at least once a second.
        const every = Math.min(URL_MAX_MS, Math.max(URL_MIN_MS, 500 / Math.max(app.state.speed, 1e-9)));
        if (now - (app.urlWrittenAt || 0) >= every) {
          writeUrl(0.5 * (every / 1000) * app.state.speed);
          app.urlWrittenAt = now;
        }
        app.costs.physics += performance.now() - t0;
      }
      app.lastFrame = now;
    }
    draw();
    requestAnimationFrame(frame);
  }

  /** `canvas`'s backing store at its displayed size times the screen's pixel density. */
  function fitCanvas(canvas) {
    const dpr = window.devicePixelRatio || 1;
    const box = canvas.getBoundingClientRect();
    const w = Math.max(1, Math.round(box.width * dpr)), h = Math.max(1, Math.round(box.height * dpr));
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  }

  function resize() {
    fitCanvas($('sphere'));
    fitCanvas($('plots'));
    sphere.redraw = true;
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
    }
    app.state = app.pacer.limit(app.state, base());
    app.controls.write(app.state);
    if (VIEW_CONTROLS.includes(id)) { app.view.pose(app.runs.list, app.state.showL, app.state.showAxes); writeUrl(); } else rebuild();
    draw();
  });
  $('play').addEventListener('click', () => setPlaying(!app.playing));
  /** To time `target`: forwards by catching up, backwards by starting again from t = 0. */
  function seek(target) {
    setPlaying(false);
    target = Math.max(0, target);
    if (target < app.state.t) { app.state.t = target; rebuild(); } else catchUp(target, FIRST_BUDGET_MS);
    draw(); writeUrl();
  }
  /** A step of the Step button and the arrow keys: 0.5 time units (whole steps of dt), so that
   * a class sees the book move. */
  const stepSize = () => Math.max(1, Math.round(STEP_TIME / app.state.dt)) * app.state.dt;
  function reset() { setPlaying(false); app.state.t = 0; rebuild(); draw(); }
  function toggleFullscreen() {
    if (document.fullscreenElement) document.exitFullscreen();
    else document.documentElement.requestFullscreen().catch((e) => { $('message').textContent = `full screen: ${e.message}`; });
  }
  function copyLink() {
    writeUrl();
    const done = () => { $('copyLink').textContent = 'Link copied'; setTimeout(() => { $('copyLink').textContent = 'Copy link'; }, 2000); };
    const fallback = () => {
      const box = document.createElement('textarea');
      box.value = location.href;
      document.body.appendChild(box); box.select();
      const ok = document.execCommand('copy');
      box.remove();
      if (ok) done(); else window.prompt('Copy this link:', location.href);
    };
    if (navigator.clipboard && window.isSecureContext) navigator.clipboard.writeText(location.href).then(done, fallback);
    else fallback();
  }
  $('stepOnce').addEventListener('click', () => seek(app.state.t + stepSize()));
  $('reset').addEventListener('click', reset);
  $('slider').addEventListener('input', () => seek(Number($('slider').value)));
  $('fullscreen').addEventListener('click', toggleFullscreen);
  $('copyLink').addEventListener('click', copyLink);
  $('camera').addEventListener('click', () => { app.view.resetCamera(app.runs.list, app.state.showL); draw(); });
  // Keys, except while typing in a field: space plays, → and ← step 0.5 time units (never the
  // menu under the focus), R resets, F goes full screen.
  window.addEventListener('keydown', (ev) => {
    const typing = ev.target instanceof HTMLInputElement && ev.target.type !== 'checkbox' && ev.target.type !== 'range';
    if (typing || ev.ctrlKey || ev.metaKey || ev.altKey) return;
    const act = {
      Space: () => setPlaying(!app.playing),
      ArrowRight: () => seek(app.state.t + stepSize()),
      ArrowLeft: () => seek(app.state.t - stepSize()),
      KeyR: reset,
      KeyF: toggleFullscreen,
    }[ev.code];
    if (!act) return;
    ev.preventDefault();
    ev.stopPropagation();
    if (ev.target instanceof HTMLSelectElement) ev.target.blur();
    act();
  }, true);
  window.addEventListener('resize', resize);
  document.addEventListener('fullscreenchange', resize);

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

// The JavaScript engines (bookspin explore --engines); one that fails to load is left out.
const ENGINES = (window.BOOKSPIN_ENGINES || []).map((e) => e.load().then(() => e, (err) => {
  console.warn(`${e.label}: not loaded: ${err}`);
  return null;
}));
Promise.all([BookspinPhysics(), ...ENGINES]).then(([wasm, ...engines]) => startApp(wasm, engines.filter(Boolean)));
