// The buttons under the view and the keyboard: Play, Step, Reset, the time slider, full screen,
// Copy link and the camera; space plays, → and ← step 0.5 time units, R resets, F goes full
// screen (never while typing in a field, never the menu under the focus).

import { panelOpen } from './modal.js';

const $ = (id) => document.getElementById(id);
/** Time units of one Step (and of → and ←), at least. */
const STEP_TIME = 0.5;

function toggleFullscreen() {
  if (document.fullscreenElement) document.exitFullscreen();
  else document.documentElement.requestFullscreen().catch((e) => { $('message').textContent = `full screen: ${e.message}`; });
}

/** The address bar's link to the clipboard (a selected text area where the clipboard API is
 * not allowed, a prompt where neither works); the button says so for 2 s. */
function copyLink() {
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

/** Wires the buttons and keys to main.js's `actions`: {playing(), setPlaying(p), time(), dt(),
 * seek(t), reset(), writeUrl(), resetCamera()}. */
export function listenKeys(actions) {
  const { setPlaying, seek, reset } = actions;
  /** A step of the Step button and the arrow keys: 0.5 time units (whole steps of dt), so that
   * a class sees the book move. */
  const stepSize = () => Math.max(1, Math.round(STEP_TIME / actions.dt())) * actions.dt();
  $('play').addEventListener('click', () => setPlaying(!actions.playing(), true));
  $('stepOnce').addEventListener('click', () => seek(actions.time() + stepSize()));
  $('reset').addEventListener('click', reset);
  $('slider').addEventListener('input', () => seek(Number($('slider').value)));
  $('fullscreen').addEventListener('click', toggleFullscreen);
  $('copyLink').addEventListener('click', () => { actions.writeUrl(); copyLink(); });
  $('camera').addEventListener('click', actions.resetCamera);
  window.addEventListener('keydown', (ev) => {
    const typing = ev.target instanceof HTMLInputElement && ev.target.type !== 'checkbox' && ev.target.type !== 'range';
    if (typing || ev.ctrlKey || ev.metaKey || ev.altKey) return;
    // A panel over the page (modal.js: the lab, the judge) takes the keys while it is open.
    if (panelOpen()) return;
    // A control that takes keys of its own (data-keys: the sphere's arrows, Enter and Space)
    // keeps them while it has the focus.
    const own = ev.target instanceof HTMLElement ? ev.target.dataset.keys : undefined;
    if (own && own.split(' ').includes(ev.code)) return;
    const act = {
      Space: () => setPlaying(!actions.playing(), true),
      ArrowRight: () => seek(actions.time() + stepSize()),
      ArrowLeft: () => seek(actions.time() - stepSize()),
      KeyR: reset,
      KeyF: toggleFullscreen,
    }[ev.code];
    if (!act) return;
    ev.preventDefault();
    ev.stopPropagation();
    if (ev.target instanceof HTMLSelectElement) ev.target.blur();
    act();
  }, true);
}
