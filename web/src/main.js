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
import { ClassLink } from './class_join.js';
import { loadProgram } from './packed.js';
import { Address } from './address.js';
import { afterPaint } from './after_paint.js';

const $ = (id) => document.getElementById(id);
/** The 3D view's least height (CSS px) on any screen. */
const VIEW_MIN_PX = 200;
/** index.html's small landscape screen (800×600): the sphere and the plots beside the view. */
const SMALL_LANDSCAPE = '(min-width: 700px) and (max-width: 899px) and (orientation: landscape) and (min-height: 500px)';

function startApp(wasm, engines) {
  const SCENES = window.BOOKSPIN_SCENES || [];  // inlined by bookspin explore
  const space = new StateSpace(wasm);  // the physics' names and defaults
  const app = {
    state: space.parse(location.search, space.sceneBase(SCENES, new URLSearchParams(location.search).get('scene') || '')),
    runs: new Runs(wasm, space, SCENES, engines),
    view: new View3D($('view'), window.BOOKSPIN_BOOK_ART || null),
    controls: new Controls(space, SCENES, engines),
    playing: false, stepDebt: 0, lastFrame: null, framesDrawn: 0, quiet: false, uncovered: false, asleep: false,
    // How many times the runs were built and the strip laid out (the first-frame test's counts).
    rebuilds: 0, layouts: 0,
    pacer: new Pacer((text) => { $('notice').textContent = text; }),
    readout: new Readout(),
    // Milliseconds spent in each part of the frames so far (the benchmark's breakdown).
    costs: { physics: 0, view: 0, sphere: 0, plots: 0, readout: 0 },
  };
  const base = () => space.sceneBase(SCENES, app.state.scene);
  /** The scene's measured ω ({t, w, ut, u}, bookspin explore), or null. */
  const measured = () => (SCENES.find((s) => s.name === app.state.scene) || {}).measured || null;
  /** The scene's time unit: a measured toss's is the recording's second (its ω in rad/s, its
   * flight in seconds: docs/phone-lab.md); a scene of the paper's runs in time units. */
  const timeUnit = () => (measured() ? 's' : 'time units');
  /** The scene's title as the 3D view's name says it. */
  const sceneName = () => {
    const scene = SCENES.find((s) => s.name === app.state.scene);
    return scene ? `scene: ${scene.title || scene.name}` : 'no scene (the controls\' settings)';
  };

  /** Steps towards time `target` (for at most `ms`, the rest a piece per frame). */
  function catchUp(target, ms) {
    app.pacer.catchUp(app.runs, app.state, target, ms);
    app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
  }

  const address = new Address(space, () => app.state, base);

  function rebuild() {
    rebuildAsked = false;
    app.rebuilds += 1;
    const { state, runs } = app;
    $('message').textContent = runs.rebuild(state).join('; ');
    app.view.setRuns(runs.list, state.showL);
    $('overlay').style.minHeight = '';
    const target = state.t;
    state.t = 0;
    app.pacer.stop();
    catchUp(target, FIRST_BUDGET_MS);
    address.write();
  }

  /** A control's change rebuilds the runs after the frame that shows it (afterPaint; docs/
   * explorer.md, "Every tap answered at once"): the menu's new value, the tick, the scene's
   * title first. Changes made before it ran are rebuilt once, from the state the last one
   * left; anything that reads the runs first (a seek, the test hooks) rebuilds them then. */
  let rebuildAsked = false;
  function rebuildAfterPaint() {
    rebuildAsked = true;
    afterPaint().then(rebuildIfAsked);
  }
  /** The rebuild asked for, where it has not run yet, and the readout's words of it. */
  function rebuildIfAsked() {
    if (!rebuildAsked) return;
    rebuild();
    readout();
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
  app.panels = new Panels($('sphere'), $('plots'), sphere, measured, timeUnit, () => Number($('slider').max));

  /** Plays or pauses; `answerFirst` (a tap on Play, Space): the button's new word painted
   * first, the strip laid out afresh after that frame (afterPaint). */
  function setPlaying(p, answerFirst = false) {
    app.playing = p;
    $('play').textContent = p ? 'Pause' : 'Play';
    app.lastFrame = null;
    if (!p) address.write();
    if (!answerFirst) layout(true);
    else afterPaint().then(() => { if (app.playing === p) layout(true); });
  }

  /** The readout's words (t, each run's flips) as the state now has them; true where its strip
   * grew past its bound and was laid out afresh. */
  function readout() {
    const grew = app.readout.draw(app.runs.list, app.state.t, timeUnit(), sceneName());
    if (grew) fitStrip();
    if (app.playing) { const strip = $('overlay'); strip.style.minHeight = `${strip.offsetHeight}px`; }
  }

  function draw() {
    let t0 = performance.now();
    const lap = (part) => { const t1 = performance.now(); app.costs[part] += t1 - t0; t0 = t1; };
    const list = app.runs.list;
    // The readout first: its strip's height sets the view's (index.html), under whose bottom
    // the bodies' labels are placed; placed before it grew, a label ran past the view.
    readout();
    lap('readout');
    app.view.render(list); lap('view');
    app.panels.draw(list, app.state.t, app.playing, t0, lap);
    if (app.framesDrawn === 0) app.firstFrameAt = performance.now();
    app.framesDrawn += 1;
  }

  /** The frame loop started again where it stopped (frame(): the lab covered the page). */
  function wake() {
    if (!app.asleep) return;
    app.asleep = false;
    requestAnimationFrame(frame);
  }
  /** Whether the Phone-toss lab covers the page (its dialog open over the whole window). */
  const labCovers = () => !$('lab').hidden;
  function frame(now) {
    // The lab records, or covers the page: nothing drawn (docs/explorer.md, "Every tap
    // answered at once"), the run behind it held where it is; the first frame after it closes
    // (or after any tap, click or key) paints that alone, the view drawn from the next.
    // The loop itself stops there (a frame asked for is a frame the page's thread and the
    // compositor work on): wake() starts it again when the lab closes or stops recording.
    if (app.quiet || labCovers()) { app.lastFrame = null; app.uncovered = true; app.asleep = true; return; }
    if (app.uncovered) { app.uncovered = false; requestAnimationFrame(frame); return; }
    // A control changed and its runs are not rebuilt yet: the runs before it are not drawn.
    if (rebuildAsked) { requestAnimationFrame(frame); return; }
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

  /** The readout's strip bounded so that the 3D view keeps its share of the screen: at least
   * a third of the window's area and never under VIEW_MIN_PX tall (docs/explorer.md, "On every
   * screen"); what the strip cannot show scrolls inside it. While playing it only grows (a
   * line that wraps anew grows it once; none shrinks it), so that nothing under it moves under
   * the pointer; a new run, a new size or a pause sets it afresh (`fresh`). */
  function layout(fresh) {
    app.layouts += 1;
    const strip = $('overlay'), box = $('viewBox'), main = $('main');
    // index.html's small landscape screen: the readout over the view, as on a projector, in
    // #main of the screen's height less the transport bar under it.
    const small = matchMedia(SMALL_LANDSCAPE).matches;
    main.style.height = small ? `${innerHeight - $('transport').offsetHeight}px` : '';
    const stacked = !small && matchMedia('(max-width: 899px)').matches;  // index.html's stacked layout
    if (fresh) strip.style.minHeight = '';
    const need = mustReadHeight(strip, stacked);
    box.style.height = '';
    if (!stacked) {
      const share = 1 + Math.max(VIEW_MIN_PX, innerWidth * innerHeight / 3 / Math.max(1, main.clientWidth));
      const cap = Math.max(48, main.clientHeight - share);
      strip.style.maxHeight = `${offLines(strip, Math.max(cap, Math.min(need, main.clientHeight - VIEW_MIN_PX)), need)}px`;
    } else {
      // Stacked (a phone): the view its own height (index.html); the strip as tall as a
      // phone's screen leaves beside the view and the transport bar.
      // index.html: beside the view on a phone on its side; under it on a short one (a zoomed
      // projector's 427×267).
      const beside = getComputedStyle(main).flexDirection === 'row';
      const cap = beside ? box.offsetHeight : Math.max(96, innerHeight - box.offsetHeight - $('transport').offsetHeight);
      strip.style.maxHeight = `${offLines(strip, Math.max(cap, need), need)}px`;
      // Under the strip, the view ends on the first screen: a tall strip (a comparison's six
      // tiles on a phone) takes from its height, never below VIEW_MIN_PX.
      const room = Math.floor(innerHeight - strip.offsetHeight);
      if (!beside && room < box.offsetHeight) box.style.height = `${Math.max(VIEW_MIN_PX, room)}px`;
    }
    stripNeed = need;
    stripStacked = stacked;
  }
  /** The readout's height down to the last of what a class must read (docs/explorer.md, "What
   * the class must read"): the clock, and each run's flips and first flip (a comparison's every
   * tile's) and the exact motion's first flip beside it (at 960×540 it lay under the strip's
   * edge); stacked (a phone, a zoomed projector) each run's label too. Beside the view a
   * comparison's last labels may lie a scroll down, so that the view keeps its third of the
   * window. The strip is never bounded under it, whatever the view's share. */
  function mustReadHeight(strip, stacked) {
    const top = strip.getBoundingClientRect().top - strip.scrollTop;
    let bottom = 0;
    const what = '#clock, #status .flips, #status .first, #status .exact' + (stacked ? ', #status .method' : '');
    for (const e of strip.querySelectorAll(what))
      bottom = Math.max(bottom, e.getBoundingClientRect().bottom - top);
    return Math.ceil(bottom + parseFloat(getComputedStyle(strip).paddingBottom || '0'));
  }
  /** The strip's bound `max` moved up off a line of text it would cut through (the line then
   * scrolls whole, never shown sliced), down to no less than what must be read (`need`). */
  function offLines(strip, max, need) {
    const top = strip.getBoundingClientRect().top - strip.scrollTop;
    const least = need - parseFloat(getComputedStyle(strip).paddingBottom || '0') - 1;
    const range = document.createRange();
    const walker = document.createTreeWalker(strip, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      range.selectNodeContents(n);
      for (const r of range.getClientRects()) {
        const a = r.top - top, b = r.bottom - top;
        if (a < max && b > max && a >= least) max = Math.ceil(a);
      }
    }
    return max;
  }
  let stripNeed = 0, stripStacked = false;
  /** After the readout changed: bounded afresh where its must-read rows grew past the bound. */
  function fitStrip() {
    if (mustReadHeight($('overlay'), stripStacked) > stripNeed) layout(false);
  }

  /** The view, the plots and the left panel fitted to the window (`unfold`: the scene's
   * description shown again where it fits). */
  function resize(unfold = true) {
    app.controls.fitPanel(Boolean(unfold));
    layout(true);
    app.panels.resize();
    app.view.resize(app.runs.list, app.state.showL);
    if (app.runs.list.length) app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
  }

  app.controls.listen((id) => {
    if (id === 'scene') {
      app.state = space.sceneBase(SCENES, $('scene').value);
      address.push();  // Back returns to the scene before
    } else {
      const t = app.state.t;
      app.state = app.controls.read(app.state);
      app.state.t = VIEW_CONTROLS.includes(id) ? t : 0;
      if (METHOD_CONTROLS.includes(id)) app.state.tiles = false;  // the two methods chosen
    }
    app.state = app.pacer.limit(app.state, base());
    if (id === 'speed') {
      // The speed: the field shows it as typed and the frame loop plays at it from the next
      // frame; the fields written back (a refused value undone), the readout and the address
      // after the frame that shows it (docs/explorer.md, "Every tap answered at once").
      afterPaint().then(() => { app.controls.write(app.state); address.write(); readout(); });
      return;
    }
    app.controls.write(app.state);
    // The controls now; the runs and the readout's words after the frame that paints them, the
    // view, the sphere and the plots by the frame loop from the frame after (docs/explorer.md,
    // "Every tap answered at once").
    if (VIEW_CONTROLS.includes(id)) {
      app.view.pose(app.runs.list, app.state.showL, app.state.showAxes);
      address.write();
      readout();
    } else {
      // The address at once (a new scene is a new history entry): Back tapped before the
      // rebuild returns to the scene before, not out of the page.
      address.write();
      rebuildAfterPaint();
    }
  });
  /** To time `target`: forwards by catching up, backwards by starting again from t = 0. */
  function seek(target) {
    rebuildIfAsked();
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
  // A tap, a click or a key: the next frame paints its answer (a button's words, a panel) alone,
  // the view drawn from the frame after (frame(); docs/explorer.md, "Every tap answered at once").
  for (const type of ['click', 'change', 'keydown']) window.addEventListener(type, () => { app.uncovered = true; }, { capture: true });
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
  // "Play beside the measurement": the toss chosen as a scene, and played.
  const playToss = LabPanel.playAsScene(SCENES, app.controls);
  // While the lab records, the page does nothing else: the run pauses and no frame is drawn,
  // so that a slow phone's main thread takes every reading (docs/phone-lab.md).
  app.lab = new LabPanel(wasm, (scene) => { playToss(scene); setPlaying(true); }, (recording) => {
    if (recording && app.playing) setPlaying(false);
    app.quiet = recording;
    if (!recording) wake();
  });
  // In a class (the address's ?class=CODE): joined, every toss kept goes to the class's server.
  app.classLink = new ClassLink(app.lab.recorder, (name) => wasm.nameProblem(name));
  // A panel opened or closed (its button, Close, Escape, a link's #lab or #judge): a history
  // entry of its own, so that Back closes it again, and Forward opens it. Written after the
  // frame that shows the panel open or closed (afterPaint): a new address has the browser draw
  // its bar, a frame of its own that the panel's waited behind (docs/explorer.md, "Every tap
  // answered at once"); Back or Forward before it (popstate) leaves it unwritten.
  let restoring = false, panelWrites = 0;
  for (const id of ['lab', 'judge']) {
    new MutationObserver(() => {
      wake();
      if (restoring) return;
      address.push();
      const mine = ++panelWrites;
      afterPaint().then(() => { if (mine === panelWrites) address.write(); });
    }).observe($(id), { attributes: true, attributeFilter: ['hidden'] });
  }
  /** Where the address names scene `name` that the page does not hold (a toss fitted in the
   * lab, loaded again: a reload, a phone's discarded tab, a shared link, Back or Forward), the
   * message says why and offers the lab, whose list holds the recordings it keeps. */
  function notInPage(name) {
    if (!name || SCENES.some((s) => s.name === name)) return;
    const message = $('message');
    message.textContent = `scene ${name} is not in this page: a toss fitted in the Phone-toss lab is not kept in ` +
      'the address (a reload or a link shows the controls\' own motion); fit its recording in the lab again ';
    const open = document.createElement('button');
    open.id = 'messageLab';
    open.textContent = 'Open the Phone-toss lab';
    open.addEventListener('click', () => app.lab.open());
    message.append(open);
  }
  /** The lab opened from an address (a link, a reload, Back or Forward) holds no recording:
   * an address cannot carry the files, so the panel says to drop them again. */
  function labFromAddress() {
    if (!$('lab').hidden && $('labResult').hidden && !$('labBusy').textContent)
      $('labBusy').textContent = 'the address does not carry recordings: drop yours here again to see the fit';
  }
  // Not on a first visit by a link (the gallery's lab link: nothing was dropped before), only
  // where the page comes back to an address it had (a reload, Back or Forward).
  const nav = (performance.getEntriesByType('navigation')[0] || {}).type;
  if (location.hash === '#lab' && (nav === 'reload' || nav === 'back_forward')) queueMicrotask(() => queueMicrotask(labFromAddress));
  // Back and Forward: the state the address holds, its panels as its hash says.
  window.addEventListener('popstate', () => {
    restoring = true;
    panelWrites += 1;
    address.forgetPush();
    // The address's state and panels first: Pause writes the page's state into the address.
    const name = new URLSearchParams(location.search).get('scene') || '';
    app.state = app.pacer.limit(app.controls.fit(space.parse(location.search, space.sceneBase(SCENES, name))), base());
    $('lab').hidden = location.hash !== '#lab';
    if (location.hash === '#judge') app.judge.open(app.state.scene); else app.judge.close();
    setPlaying(false);
    app.controls.write(app.state);
    rebuild();
    labFromAddress();
    draw();
    // The mutation records of the panels' changes are delivered after this task: let them pass.
    setTimeout(() => { restoring = false; }, 0);
    notInPage(name);
  });
  // Test and benchmark hooks (tests/browser/explorer_test.py, bench/explorer_bench.py).
  window.explorer = testHooks(app, sphere, { rebuild, advance, draw, setPlaying, pickStart });
  // A hook reads the runs as the controls now say: a rebuild still waiting for its frame runs
  // first (not for the counts the first-frame test reads inside that frame).
  for (const [name, hook] of Object.entries(window.explorer)) {
    if (typeof hook === 'function' && !['framesDrawn', 'rebuilds', 'layouts'].includes(name))
      window.explorer[name] = (...args) => { rebuildIfAsked(); return hook(...args); };
  }
  app.state = app.pacer.limit(app.controls.fit(app.state), base());
  app.controls.write(app.state);
  resize();
  rebuild();
  notInPage(new URLSearchParams(location.search).get('scene') || '');
  draw();
  window.explorer.ready = true;
  requestAnimationFrame(frame);
  // What the page does as it opens (a link's #judge choosing a scenario) rewrites its entry;
  // from the first frame on, a scene or a panel is a new one.
  requestAnimationFrame(() => { address.live = true; });
}

// The physics and, with bookspin explore --engines, the JavaScript engines, unpacked (packed.js).
loadProgram().then(([wasm, engines]) => startApp(wasm, engines));
