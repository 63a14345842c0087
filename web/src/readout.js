// The readout a class reads from the back: t, and for each run its flips (the method's own
// turn-over detector, docs/physics.md §14) and its first flip beside the exact motion's. Every
// number comes from the WebAssembly sessions (runs.js); this module only writes them out.

import { significant } from './precision.js';

const $ = (id) => document.getElementById(id);
/** `x` to `digits` decimals, without a "-0.00". */
const fixed = (x, digits) => (Math.abs(x) < 0.5 * 10 ** -digits ? 0 : x).toFixed(digits);

/** A component of ω as the readout shows it: four decimals, as a class reads a spin; from 10⁴ on
 * (a run running away before it diverges) by the page's number rule, four significant digits
 * and a power of ten ("6.265 × 10⁵⁰", not toFixed's "6.264803277982017e+50" over two lines). */
export function omegaText(x) {
  return Math.abs(x) < 1e4 - 5e-5 ? fixed(x, 4) : significant(x, 4);
}

/** The readout's HTML for more than two runs (a comparison's every tile): a cell a run, its
 * flips and the time of its first, then its method (in the run's colour, as its body's label),
 * up to three to a row, so that the view keeps its height and every count is in the strip's
 * first lines (docs/explorer.md, "What the class must read"). */
function manyRunsHtml(runs) {
  return '<div class="many">' + runs.map((r) => {
    const own = r.session.flips();
    const first = own.first === null ? '—' : fixed(own.first, 2);
    return `<div class="run" style="color:${r.colour}">` +
      `<div class="counts"><span class="flips">flips <span class="count">${own.count}</span></span> · <span class="first">first <span class="num">${first}</span></span></div>` +
      `<div class="method">${r.label}${r.diverged ? ' — ' + r.diverged : ''}</div></div>`;
  }).join('') + '</div>';
}

/** The readout's HTML for `runs` (Runs.list) at time `t`. */
function runsHtml(runs, t) {
  if (runs.length > 2) return manyRunsHtml(runs);
  return runs.map((r) => {
    const h = r.history[r.history.length - 1];
    const own = r.session.flips();
    const exact = r.closedForm ? own : r.session.exactFlips(t);
    const first = own.first === null ? '—' : fixed(own.first, 2);
    const beside = r.closedForm ? '(the exact motion)' : exact.first === null
      ? 'exact motion: never turns over (a wobble)'
      : `exact motion: first flip at ${fixed(exact.first, 2)}, count ${exact.count}`;
    return `<div class="run" style="color:${r.colour}"><div class="method">${r.label}${r.diverged ? ' — ' + r.diverged : ''}</div>` +
      `<div class="counts"><span class="big flips">flips <span class="count">${own.count}</span></span> ` +
      `<span class="big first">first flip at <span class="nb">t = <span class="num">${first}</span></span></span> <span class="exact">${beside}</span></div>` +
      // ω in numbers for one run; in compare mode the plots show it, and the books stay in view.
      (runs.length > 1 ? '' : `<div class="omega">ω = (${h.w.map(omegaText).join(', ')})</div>`) +
      '</div>';
  }).join('');
}

/** The 3D view's name for a screen reader: what it shows, the scene, t and each run's flips
 * (docs/explorer.md, "For every person"). */
export function viewDescription(runs, t, scene, clock) {
  const flips = runs.map((r) => {
    const own = r.session.flips();
    return `${r.label}: flips ${own.count}` + (own.first === null ? '' : `, the first at t = ${fixed(own.first, 2)}`);
  });
  const bodies = runs.length === 1 ? 'the body' : `${runs.length} bodies, one a method`;
  return `3D view of ${bodies}, ${scene}; ${clock}` + (flips.length ? `; ${flips.join('; ')}` : '');
}

export class Readout {
  constructor() {
    this.shown = null;  // the runs' HTML last written
    this.counts = [];   // each run's [label, flips] last drawn: a new flip is said (#spoken)
    this.described = '';
  }

  /** Says each run's flips counted since the last draw in the live region #spoken (a screen
   * reader reads it out); a new run (its count lower, or another label) says nothing. */
  announce(runs, t) {
    const counts = runs.map((r) => [r.label, r.session.flips().count]);
    const said = counts.filter(([label, n], k) => this.counts[k] && this.counts[k][0] === label && n > this.counts[k][1])
      .map(([label, n]) => `${label}: flip ${n} counted, at t = ${fixed(t, 2)}`);
    this.counts = counts;
    if (said.length) $('spoken').textContent = said.join('; ');
  }

  /** Writes t (the clock, the time line and the slider; `unit` the scene's time unit) and the
   * runs' lines, the latter only when they changed; whether they did. `scene`: the scene's
   * title, for the 3D view's name. */
  draw(runs, t, unit = 'time units', scene = 'no scene') {
    // A measured toss's time in seconds, said; the paper's time units are left unnamed.
    const text = `t = ${fixed(t, 2)}${unit === 's' ? ' s' : ''}`;
    // Written only where changed: the same words written again are laid out and painted again,
    // every frame of a paused page (docs/explorer.md, "Every tap answered at once").
    if (text !== this.clockText) {
      $('time').textContent = text;
      $('clock').textContent = text;
      this.clockText = text;
    }
    const max = Math.max(Number($('slider').max), Math.ceil(t));
    if (Number($('slider').max) !== max) $('slider').max = max;
    if (Number($('slider').value) !== t) $('slider').value = t;
    this.announce(runs, t);
    const described = viewDescription(runs, t, scene, text);
    if (described !== this.described) { $('view').setAttribute('aria-label', described); this.described = described; }
    const html = runsHtml(runs, t);
    if (html === this.shown) return false;
    $('status').innerHTML = html;
    this.shown = html;
    return true;
  }
}
