"""Taps and keys on the explorer page and what the browser measures of them: the Event Timing
API's interaction duration (from the input's time stamp until the next paint after its
handlers, the measure behind INP) and the long animation frames meanwhile (where a frame's time
went: its scripts, its style and layout). Shared by bench/tap_bench.py (the table in
docs/performance.md, "Taps") and tests/browser/explorer_first_frame_test.py.

    watch(driver)                        # after each page load
    tap(driver, "#labRecord")            # a touch through the DevTools protocol
    d = interaction(driver, mark)        # its duration in ms (TAP_FLOOR_MS where under it)
"""
# The Event Timing API reports an interaction only where it took 16 ms or more (its least
# durationThreshold); one not reported took less.
TAP_FLOOR_MS = 16

# JavaScript: every Event Timing entry of an interaction (interactionId not 0) and every long
# animation frame from now, in window.tapEntries and window.tapFrames.
WATCH = """
if (!window.tapEntries) {
  window.tapEntries = [];
  window.tapFrames = [];
  new PerformanceObserver((list) => {
    for (const e of list.getEntries()) if (e.interactionId) window.tapEntries.push({
      name: e.name, id: e.interactionId, start: e.startTime, duration: e.duration,
      processingStart: e.processingStart, processingEnd: e.processingEnd,
      target: e.target ? (e.target.id || e.target.tagName) : ''});
  }).observe({type: 'event', durationThreshold: 16, buffered: true});
  if (PerformanceObserver.supportedEntryTypes.includes('long-animation-frame'))
    new PerformanceObserver((list) => {
      for (const f of list.getEntries()) window.tapFrames.push({
        start: f.startTime, duration: f.duration, renderStart: f.renderStart,
        styleAndLayoutStart: f.styleAndLayoutStart, blocking: f.blockingDuration,
        scripts: f.scripts.map((s) => ({invoker: s.invoker, duration: s.duration,
          forcedStyleAndLayout: s.forcedStyleAndLayoutDuration,
          source: `${s.sourceFunctionName || ''}@${s.sourceCharPosition}`}))});
    }).observe({type: 'long-animation-frame', buffered: false});
}
"""


def watch(driver):
    """The page's Event Timing and long-animation-frame observers installed (once a load)."""
    driver.execute_script(WATCH)


def mark(driver):
    """performance.now() in the page: the start of what interaction() reads."""
    return driver.execute_script("return performance.now()")


def centre(driver, selector):
    """The element's centre in CSS px of the viewport (scrolled into view first)."""
    return driver.execute_script(
        "const e = document.querySelector(arguments[0]); e.scrollIntoView({block: 'center'});"
        "const r = e.getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2];",
        selector)


def tap(driver, selector):
    """A tap on the element's centre: touchStart and touchEnd through the DevTools protocol
    (the page's handlers have run when it returns)."""
    x, y = centre(driver, selector)
    point = {"x": x, "y": y}
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [point]})
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})


KEYS = {"ArrowDown": 40, "ArrowUp": 38, "Enter": 13}


def key(driver, name):
    """A key pressed and released on the focused element through the DevTools protocol."""
    code = KEYS[name]
    down = {"type": "rawKeyDown", "key": name, "code": name, "windowsVirtualKeyCode": code,
            "nativeVirtualKeyCode": code}
    if name == "Enter":
        down = {**down, "type": "keyDown", "text": "\r", "unmodifiedText": "\r"}
    driver.execute_cdp_cmd("Input.dispatchKeyEvent", down)
    driver.execute_cdp_cmd("Input.dispatchKeyEvent", {**down, "type": "keyUp", "text": "",
                                                      "unmodifiedText": ""})


def settle(driver, frames=3):
    """Returns after `frames` animation frames of the page (and a task after the last)."""
    driver.execute_async_script("""const [n, done] = arguments; let k = 0;
      const next = () => requestAnimationFrame(() => (++k >= n ? setTimeout(done, 0) : next()));
      next();""", frames)


def interaction(driver, since):
    """The duration (ms) of the first interaction that began after `since` (mark()): the
    longest of its Event Timing entries, as INP counts it; TAP_FLOOR_MS where the browser
    reported none (it took less) once a few frames passed. Returns (ms, entries, long frames
    since `since`)."""
    read = ("return [window.tapEntries.filter((e) => e.start >= arguments[0]),"
            " window.tapFrames.filter((f) => f.start + f.duration >= arguments[0])]")
    for _ in range(2):
        # An entry is queued after the interaction's paint; a few frames later it is there.
        settle(driver)
        entries, frames = driver.execute_script(read, since)
        if entries:
            break
    if not entries:
        return TAP_FLOOR_MS, [], frames
    first = min(e["id"] for e in entries)
    mine = [e for e in entries if e["id"] == first]
    return max(e["duration"] for e in mine), mine, frames
