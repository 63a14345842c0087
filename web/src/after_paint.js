// A tap's answer painted before its heavier work (docs/explorer.md, "Every tap answered at
// once"): the handler changes what the tap shows (a button's words, a panel), then awaits
// afterPaint() before the work the change sets off (a fit handed to the worker, a list
// drawn, a run rebuilt), so that the browser paints the answer in the first frame after the tap
// and the work runs after that frame is on the screen. Nothing else here.

/** The longest wait (ms) for the browser's word that a tap's frame is on the screen, after the
 * frame is painted: past it the work runs all the same. */
export const PRESENTED_WAIT_MS = 400;

/** Waits for a tap's frame: {at (performance.now() in the tap's handler), resolve}. */
const waiting = new Set();

/** The browser's Event Timing entries (a tap's duration until its frame was presented: the
 * entry is delivered after that frame is on the screen) settle the waits of their taps.
 * Entries of 16 ms or more only (the API's least threshold): a frame presented sooner sends
 * none, and its wait ends at PRESENTED_WAIT_MS. */
function watchPresented() {
  if (typeof PerformanceObserver === 'undefined' ||
      !(PerformanceObserver.supportedEntryTypes || []).includes('event')) return false;
  new PerformanceObserver((list) => {
    for (const entry of list.getEntries()) {
      for (const w of waiting) {
        // The entry of the event whose handlers were running when the wait began (a select's
        // change is dispatched inside the key's or the click's handling, which is reported).
        if (entry.processingStart <= w.at && w.at <= entry.processingEnd + 1) w.resolve();
      }
    }
  }).observe({ type: 'event', durationThreshold: 16 });
  return true;
}
let presentedWatched = null;

/** A promise settled after the frame that answers the tap, click or key whose handler calls
 * this is painted and, where the browser says so (Event Timing), on the screen: a requestAnimationFrame callback runs before
 * that frame's style, layout and paint, a task it queues runs after them; where the frame took
 * 16 ms or more the browser's entry for the event comes once it is presented (a software GPU
 * on a busy CPU takes hundreds of ms to composite it, and the page's work meanwhile took the
 * CPU it needed), else the wait ends PRESENTED_WAIT_MS after the paint. Called outside an
 * event's handlers (a timer's), or without Event Timing, it settles after the paint. A hidden
 * page paints no frame: there it settles after a task. */
export function afterPaint() {
  if (presentedWatched === null) presentedWatched = watchPresented();
  return new Promise((resolve) => {
    if (document.visibilityState === 'hidden') { setTimeout(resolve, 0); return; }
    // window.event: the event being dispatched, undefined outside one.
    const waitPresented = Boolean(presentedWatched && window.event);
    let w = null;
    const done = () => { if (w) waiting.delete(w); resolve(); };
    if (waitPresented) { w = { at: performance.now(), resolve: done }; waiting.add(w); }
    requestAnimationFrame(() => setTimeout(() => {
      if (!waitPresented) { done(); return; }
      setTimeout(done, PRESENTED_WAIT_MS);
    }, 0));
  });
}
