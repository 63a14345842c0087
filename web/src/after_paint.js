// A tap's answer painted before its heavier work (docs/explorer.md, "Every tap answered at
// once"): the handler changes what the tap shows (a button's words, a panel), then awaits
// afterPaint() before the work the change sets off (a fit handed to the worker, a list drawn, a
// run rebuilt), so that the browser paints the answer in the first frame after the tap and
// the work runs in the frames after it. Nothing else here.

/** A promise settled after the next frame is painted: a requestAnimationFrame callback runs
 * before that frame's style, layout and paint, and a task it queues runs after them. A hidden
 * page paints no frame: there it settles after a task. */
export function afterPaint() {
  return new Promise((resolve) => {
    if (document.visibilityState === 'hidden') { setTimeout(resolve, 0); return; }
    requestAnimationFrame(() => setTimeout(resolve, 0));
  });
}
