// The panels over the page (the Phone-toss lab, Judge a motion) as modal dialogs
// (docs/explorer.md, "By keyboard"): each a <dialog> shown with showModal(), so that the page
// behind it is inert (no click, no focus, not read by a screen reader); focus moved into it
// when it opens, Tab and Shift+Tab cycling within it, Escape closing it and focus returned to
// the button that opened it. A panel is open while its `hidden` attribute is off: the state
// the address's #lab and #judge set and the panels' own open() and close() write.

const FOCUSABLE = 'button, [href], input, select, textarea, summary, [tabindex]:not([tabindex="-1"])';

/** The controls of `root` that Tab reaches, in order: shown, enabled. */
function focusables(root) {
  return [...root.querySelectorAll(FOCUSABLE)].filter((e) => !e.disabled && !e.closest('[hidden]') &&
    e.getClientRects().length > 0 && getComputedStyle(e).visibility !== 'hidden');
}

/** Makes `dialog` modal, shown while not hidden; `opener`: its button (where focus goes back
 * when nothing else opened it: a link's #lab); `close()`: the panel's own close, which hides
 * it (called when the dialog closes by Escape). */
export function modalPanel(dialog, opener, close) {
  let returnTo = null;
  const sync = () => {
    if (!dialog.hidden && !dialog.open) {
      const active = document.activeElement;
      returnTo = active && active !== document.body && !dialog.contains(active) ? active : null;
      dialog.showModal();
      const first = focusables(dialog)[0];
      if (first) first.focus();
    } else if (dialog.hidden && dialog.open) {
      dialog.close();
    }
  };
  new MutationObserver(sync).observe(dialog, { attributes: true, attributeFilter: ['hidden'] });
  // Escape: the panel's own close at once (hidden, so the dialog closes with it), not a task
  // later in the close event, when a key or a script may already have read the page.
  dialog.addEventListener('cancel', (e) => {
    e.preventDefault();
    close();
  });
  dialog.addEventListener('close', () => {
    // A close event comes a task after dialog.close(): where the panel was shown again in
    // between (Back, then Forward at once), it is stale and must not hide it.
    if (dialog.open) return;
    if (!dialog.hidden) close();
    // Focus back on what opened the panel (Escape left it on the page's body).
    if (document.querySelector('dialog[open]')) return;
    const back = returnTo && returnTo.isConnected && focusables(document.body).includes(returnTo) ? returnTo : opener;
    returnTo = null;
    if (back && !back.hidden) back.focus();
  });
  // Tab from the last control to the first, Shift+Tab from the first to the last: never out to
  // the browser's own bar and back onto the page.
  dialog.addEventListener('keydown', (e) => {
    if (e.key !== 'Tab' || e.altKey || e.ctrlKey || e.metaKey) return;
    const items = focusables(dialog);
    if (!items.length) return;
    const first = items[0], last = items[items.length - 1], at = document.activeElement;
    if (e.shiftKey && (at === first || !dialog.contains(at))) { last.focus(); e.preventDefault(); }
    else if (!e.shiftKey && (at === last || !dialog.contains(at))) { first.focus(); e.preventDefault(); }
  });
  sync();
}

/** Whether a panel is open over the page (the page's own keys then do nothing). */
export function panelOpen() {
  return document.querySelector('dialog[open]') !== null;
}

/** A question asked before a step that cannot be undone (docs/phone-lab.md, "In a class":
 * Remove on a toss the class holds), in the page's <dialog id="question"> over everything,
 * a panel included (the top layer): `question` its first line, `detail` what follows from each
 * answer, `yes` and `no` its two buttons' words. Focus on `no` (a stray tap on the first button
 * removes nothing); Escape answers no, as does a second question while one is open. A promise of
 * true (yes) or false. */
export function askFirst({ question, detail, yes, no }) {
  const dialog = document.getElementById('question');
  // A question already asked (a second tap behind the first's dialog): this one is no.
  if (dialog.open) return Promise.resolve(false);
  document.getElementById('questionText').textContent = question;
  document.getElementById('questionDetail').textContent = detail;
  const yesButton = document.getElementById('questionYes'), noButton = document.getElementById('questionNo');
  yesButton.textContent = yes;
  noButton.textContent = no;
  const back = document.activeElement;
  return new Promise((resolve) => {
    const answer = (value) => {
      yesButton.onclick = noButton.onclick = dialog.oncancel = null;
      dialog.close();
      if (back && back.isConnected) back.focus();
      resolve(value);
    };
    yesButton.onclick = () => answer(true);
    noButton.onclick = () => answer(false);
    dialog.oncancel = (e) => { e.preventDefault(); answer(false); };
    dialog.showModal();
    noButton.focus();
  });
}
