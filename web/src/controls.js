// The control column: the state shown in the page's inputs and read back from them. Only what
// the chosen model uses is shown: its own integrators (physics::supports, as the WebAssembly
// module lists them: state.js), normalization where it has one, damping and k for the particle
// model, lattice cells for a particle body other than the book, air drag for the exact and rigid
// models (physics::supports_drag; its rate once a law is chosen). The JavaScript engines' models
// (a page written with --engines) have neither integrator nor normalization of bookspin's.
import { AXES, DRAG_LAWS } from './state.js';

const $ = (id) => document.getElementById(id);
const NUMBERS = ['k', 'cells', 'dragRate', 'dt', 'rate', 'jiggle', 'seed', 'speed'];
const CHOICES = ['scene', 'body', 'model', 'integrator', 'drag', 'axis', 'model2', 'integrator2'];
/** The models that take air drag (physics::supports_drag). */
const DRAGGED = ['exact', 'rigid-matrix', 'rigid-quaternion'];
const BOXES = ['normalize', 'damping', 'compare', 'tiles', 'normalize2', 'showL', 'showAxes'];
/** Controls that choose the methods: a change leaves a comparison's tiles for the two chosen. */
export const METHOD_CONTROLS = ['model', 'integrator', 'normalize', 'compare', 'model2', 'integrator2', 'normalize2'];
/** Controls that change only the drawing, not the run. */
export const VIEW_CONTROLS = ['showL', 'showAxes', 'speed'];

function fillSelect(id, list) {
  $(id).innerHTML = list.map((x) => `<option value="${x}">${x}</option>`).join('');
}

/** A number as a field shows it: an integer whole, anything else to 6 significant digits
 * (1/60 as 0.0166667, not 0.016666666666666666). */
export function shownNumber(x) {
  return Number.isInteger(x) || !Number.isFinite(x) ? String(x) : String(Number(x.toPrecision(6)));
}

/** Shows `x` in field `id`, rounded; the exact value kept beside it (data-exact). */
function writeNumber(id, x) {
  const el = $(id);
  el.value = shownNumber(x);
  el.dataset.exact = String(x);
  el.dataset.shown = el.value;
}

/** The field's number: the exact value it was given while it still shows it rounded, else
 * what was typed. */
function readNumber(id) {
  const el = $(id);
  return el.value === el.dataset.shown ? Number(el.dataset.exact) : Number(el.value);
}

function show(id, visible) {
  $(id).hidden = !visible;
}

/** A canvas's 2D context that measures text as `style` (an element's computed style) lays it
 * out: its font, and its letter and word spacing, which a reader's own style may set (WCAG
 * 1.4.12: measured without them, "rigid-matrix" was cut to "rigid-matri"). */
function measurer(style) {
  const g = document.createElement('canvas').getContext('2d');
  g.font = `${style.fontStyle} ${style.fontWeight} ${style.fontSize} ${style.fontFamily}`;
  g.letterSpacing = style.letterSpacing === 'normal' ? '0px' : style.letterSpacing;
  g.wordSpacing = style.wordSpacing === 'normal' ? '0px' : style.wordSpacing;
  return g;
}

/** The menu's chosen entry shortened at a word, with "…", to what the closed menu shows (its
 * box less its padding and the arrow's 24 px), the others whole, so that no word is cut at the
 * menu's edge; the whole title is the line under the menu (#sceneTitle). Each entry's own text
 * is kept in its data-full. */
export function fitMenu(menu) {
  const style = getComputedStyle(menu);
  const g = measurer(style);
  const roomOf = () => menu.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight) - 24;
  // Where the chosen title's first word does not fit beside the menu's name (a narrow column:
  // "Dzhanibekov's" showed as "Dzhanib …"), the menu goes to the line under its name, the
  // column's whole width (index.html, .menuUnder).
  const label = menu.parentElement, chosen = menu.selectedOptions[0];
  const firstWord = chosen ? (chosen.dataset.full ?? chosen.textContent).split(' ')[0] : '';
  label.classList.remove('menuUnder');
  if (firstWord && g.measureText(`${firstWord} …`).width > roomOf()) label.classList.add('menuUnder');
  const room = roomOf();
  for (const option of menu.options) {
    if (option.dataset.full === undefined) option.dataset.full = option.textContent;
    let text = option.dataset.full;
    if (option.selected && room > 0 && g.measureText(text).width > room) {
      const words = text.split(' ');
      while (words.length > 1 && g.measureText(`${words.join(' ')} …`).width > room) words.pop();
      text = words.join(' ');
      // One word longer than the room (a name): its letters, as many as fit.
      while (text.length > 1 && g.measureText(`${text} …`).width > room) text = text.slice(0, -1);
      text = `${text} …`;
    }
    if (option.textContent !== text) option.textContent = text;
  }
}

/** Each menu of the column but the scene's as wide as the fields (140 px, at most 56 % of its
 * row) or, where its chosen entry is wider, as that entry and the menu's arrow (26 px), so that
 * no entry shows cut ("rigid-matri" at 1024×600); a menu wider than its row's room goes to the
 * line under its name (index.html). */
export function fitChoices() {
  // A number field likewise, as wide as its number and its padding and border (a toss's dt,
  // 1/240's "0.00416667", was cut at 1024×600).
  for (const menu of document.querySelectorAll('#controls select:not(#scene), #controls input[type=number]')) {
    const style = getComputedStyle(menu), option = menu.tagName === 'SELECT' ? menu.selectedOptions[0] : null;
    const g = measurer(style);
    const need = Math.ceil(menu.tagName === 'SELECT' ? (option ? g.measureText(option.textContent).width : 0) + 26
      : g.measureText(menu.value).width + 10);
    // Its chosen entry's width decides whether it fits beside its name (index.html: the row
    // wraps by the items' widths); then it grows to the fields' width where the row has room.
    const width = `min(${need}px, 100%)`, most = `min(100%, max(${need}px, min(140px, 56%)))`;
    if (menu.style.width !== width) menu.style.width = width;
    if (menu.style.maxWidth !== most) menu.style.maxWidth = most;
  }
}

export class Controls {
  /** `space`: the page's StateSpace (state.js: the physics' models, their integrators, the
   * bodies); `engines`: the JavaScript engines' adapters (web/src/engines/), loaded, offered as
   * models after bookspin's own. */
  constructor(space, scenes, engines = []) {
    this.space = space;
    this.scenes = scenes;
    this.engineModels = engines.map((e) => e.model);
    this.aboutFor = undefined;  // the scene whose description fitPanel() last unfolded
    fillSelect('scene', [''].concat(scenes.map((s) => s.name)));
    $('scene').options[0].textContent = '(custom)';
    // The menu lists the scenes by title (the value stays the scene's name, as in a link).
    scenes.forEach((s, i) => { if (s.title) $('scene').options[i + 1].textContent = s.title; });
    window.addEventListener('resize', () => { fitMenu($('scene')); fitChoices(); });
    fillSelect('body', space.bodies);
    const models = space.models.concat(this.engineModels);
    fillSelect('model', models); fillSelect('model2', models);
    fillSelect('axis', AXES);
    fillSelect('drag', DRAG_LAWS);
  }

  /** The integrators `model` accepts (an engine's model: its own, named 'euler' in the state). */
  integratorsOf(model) {
    if (this.engineModels.includes(model)) return ['euler'];
    return this.space.supports[model] || [];
  }

  /** Whether `model` has bookspin's integrators and normalization (not exact, not an engine). */
  integrated(model) {
    return model !== 'exact' && !this.engineModels.includes(model);
  }

  /** The state from the inputs; an integrator the model does not take becomes its first. */
  read(state) {
    const next = { ...state };
    for (const id of CHOICES) next[id] = $(id).value;
    for (const id of NUMBERS) next[id] = readNumber(id);
    for (const id of BOXES) next[id] = $(id).checked;
    next.w = ['wx', 'wy', 'wz'].map(readNumber);
    return this.fit(next);
  }

  /** `state` with each integrator one its model takes (else the model's first). */
  fit(state) {
    const next = { ...state };
    for (const [m, i] of [['model', 'integrator'], ['model2', 'integrator2']]) {
      const list = this.integratorsOf(next[m]);
      if (list.length && !list.includes(next[i])) next[i] = list[0];
    }
    return next;
  }

  /** Shows `state` in the inputs, hiding what its models do not use. */
  write(state) {
    fillSelect('integrator', this.integratorsOf(state.model));
    fillSelect('integrator2', this.integratorsOf(state.model2));
    for (const id of CHOICES) $(id).value = state[id];
    fitMenu($('scene'));
    for (const id of NUMBERS) writeNumber(id, state[id]);
    for (const id of BOXES) $(id).checked = state[id];
    ['wx', 'wy', 'wz'].forEach((id, i) => writeNumber(id, state.w[i]));
    const scene = this.scenes.find((x) => x.name === state.scene);
    // The scene's words are of its own body: another body keeps the scene's start and settings
    // but not its title and description (a phone is not "Dzhanibekov's T-handle").
    const own = scene ? this.space.sceneBase(this.scenes, state.scene).body : '';
    const title = scene ? scene.title || scene.name : '';
    $('sceneTitle').textContent = !scene ? '' : state.body === own ? title : `The ${state.body}, from “${title}”`;
    show('sceneAbout', Boolean(scene));  // (custom): no scene to tell of
    const key = `${state.scene}\n${state.body}`;
    const newScene = this.aboutFor !== key;
    this.aboutFor = key;
    $('sceneDescription').textContent = !scene ? '' : state.body === own ? scene.description || ''
      : `This scene's words are of its own body, the ${own}: here the ${state.body} runs from its start, spin and settings.`;
    // The time slider spans the scene's run (bookspin explore's `duration`), or 300 time units.
    $('slider').max = Math.max(scene && scene.duration > 0 ? scene.duration : 300, Math.ceil(state.t));
    // A comparison shows its every tile (the engines' replayed), or the two methods chosen.
    const tiles = scene && scene.tiles ? scene.tiles.length : 0;
    show('tilesRow', tiles > 0);
    $('tilesCount').textContent = String(tiles);
    const particle = state.model === 'particle';
    show('integratorRow', this.integrated(state.model));
    show('normalizeRow', this.integrated(state.model));
    show('dampingRow', particle);
    show('kRow', particle);
    show('cellsRow', particle && state.body !== 'book');
    show('dragRow', DRAGGED.includes(state.model));
    show('dragRateRow', DRAGGED.includes(state.model) && state.drag !== 'none');
    // A measured toss runs in the recording's seconds (docs/phone-lab.md), so its rate is per second.
    $('dragRateUnit').textContent = scene && scene.measured ? '1/s' : '1/time';
    show('custom', state.axis === 'custom');
    show('rateRow', state.axis !== 'custom');
    show('second', state.compare);
    show('integrator2Row', this.integrated(state.model2));
    show('normalize2Row', this.integrated(state.model2));
    // 'mesh' is the scene's own mesh body: offered only where the scene has one.
    const mesh = $('body').querySelector('option[value="mesh"]');
    mesh.disabled = !(scene && scene.body && scene.body.shape === 'mesh');
    mesh.textContent = mesh.disabled ? 'mesh (a mesh scene)' : `mesh (${scene.name})`;
    fitChoices();
    this.fitPanel(newScene);
  }

  /** The left panel within the screen (1366×768 and up): the scene's description folded under its title while the panel is taller than the screen; `unfold`: shown
   * first (a new scene, a new screen size), otherwise only ever folded, so that a description
   * the reader opened stays open until the panel outgrows the screen. */
  fitPanel(unfold = true) {
    const about = $('sceneAbout'), column = $('controls');
    if (unfold) about.open = true;
    if (about.open && column.scrollHeight > column.clientHeight) about.open = false;
    // The menus to the column's width now (a scroll bar that came or went changed it: the
    // scene's title was shortened for the column without one and cut in it with one).
    fitMenu($('scene'));
    fitChoices();
  }

  /** Calls `onChange(id)` when an input of the column or the transport changes. */
  /** Adds `scene` (a toss the Phone-toss lab fitted, lab.js) to the scene menu, by its title;
   * a scene of the same name keeps its entry. */
  addScene(scene) {
    const menu = $('scene');
    if (![...menu.options].some((o) => o.value === scene.name)) menu.add(new Option(scene.title || scene.name, scene.name));
  }

  listen(onChange) {
    for (const el of document.querySelectorAll('#controls input, #controls select, #speed')) {
      el.addEventListener('change', () => {
        // A menu keeps no focus once chosen: the arrow keys then step time, not the menu.
        if (el.tagName === 'SELECT') el.blur();
        onChange(el.id);
      });
    }
  }
}
