#!/usr/bin/env python3
"""Every tap answered in the first frame after it (docs/explorer.md, "Every tap answered at
once"): in headless Chromium at a touch phone's 390x844 with WebGL on the CPU (SwiftShader),
the CPU slowed 4x (the DevTools protocol's Emulation.setCPUThrottlingRate), each control of the
Phone-toss lab (Record, Stop after a real recording fed through the gyroscope's sensor override
at its own rate, a recording's tick, Fit the ticked, Remove, Close) and of the explorer (Play,
the scene menu, the speed, the second method, "Phone-toss lab") is tapped (the menu and the
speed by their keys) and what the page shows is read in the first animation frame after it.

No clock is read: a requestAnimationFrame callback, registered by the test in the capture phase
of the tap's event (before the page's own handlers run), runs at the next frame before its
style, layout and paint: what the DOM holds then is what that frame paints. Asserted there:
  - the control's visible answer is in it (the button's new words, the panel shown or gone, the
    row removed, the tick);
  - none of the work the tap sets off is in it: the heavier work (the recording's row made and
    its fit asked, the trace's canvas laid out, the runs rebuilt (window.explorer.rebuilds()),
    the readout's strip laid out (window.explorer.layouts())), the 3D view, the sphere and
    the plots drawn (window.explorer.framesDrawn(): software GL's frame is the heaviest part of
    a paint), the address written (a panel opened or closed, the speed: a new address has the
    browser draw its bar, a frame of its own) and, opening the lab, its panel under its head
    come in later frames. Where the page drew the view in that frame, or did the work
    before the frame, the paint waits for it;
  - then, settled, the page as it would be had all of it been done at once: the lab's whole
    panel shown, the address with the panel and the speed, the speed's field.
Before Record, before Stop (recording, the live trace shown) and with a result shown, the
Record/Stop button is on the screen where it is, wherever the lab is scrolled, and scrolling
it into view as WebDriver's click and the bench do scrolls nothing: on a phone a scroll's frame
just before the tap held up its answer.
After the scene menu and the second method the runs are rebuilt once, later; two changes of the
scene menu in one task (before the first's rebuild ran) end on the second's state.
bench/tap_bench.py measures the same taps' durations (docs/performance.md, "Taps").

Usage: explorer_first_frame_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, or the
real recording (../shared/recordings-real/), except under CI=true, where that is a failure.
"""
import csv
import io
from pathlib import Path

from browser import (console_errors, fail, find_browser, lab_page_under_test, missing, open_browser,
                     require, run, test_arguments, wait_for)
from explorer_records_gyro_test import feed, feed_at_own_rate, override
from explorer_test import load
from taps import key, settle, tap

SIZE = (390, 844)
REAL = "dvarkian-2022-05-03/12-13-01"
THROTTLE = 4

# JavaScript: the next frame's DOM, read by a requestAnimationFrame callback registered in the
# capture phase of the first `event` on the page from now: window.firstFrame = {answer: the
# answer's expression then, before: the work's expression at the event, after: the work's
# expression in that frame}.
ARM = """
const [event, answerSource, workSource] = arguments;
const answer = new Function(`return (${answerSource});`), work = new Function(`return JSON.stringify(${workSource});`);
window.firstFrame = null;
window.addEventListener(event, () => {
  const before = work();
  requestAnimationFrame(() => { window.firstFrame = {answer: answer(), before, after: work()}; });
}, {capture: true, once: true});
"""

# The work a lab's tap may set off, none of it in the first frame: the view drawn, the list's
# rows, the fit asked (its busy line), the live trace's canvas.
LAB_WORK = ("[window.explorer.framesDrawn(), document.querySelectorAll('#labRecordList li').length, "
            "document.getElementById('labBusy').textContent, !!document.getElementById('labRecordTrace')]")
# The work an explorer control may set off, none of it in the first frame: the view, the sphere
# and the plots drawn, the runs built again (a scene, a method: main.js, rebuild), the readout's
# strip laid out afresh (Play: main.js, layout).
PAGE_WORK = "[window.explorer.framesDrawn(), window.explorer.rebuilds(), window.explorer.layouts()]"
REBUILDS = "return window.explorer.rebuilds()"
# The address, written after the frame that shows a panel opened or closed, or a new speed (a
# new address has the browser draw its bar, a frame of its own the answer waited behind).
ADDRESS_WORK = PAGE_WORK[:-1] + ", location.search + location.hash]"
# The lab opened: its head alone in the first frame; the rest of the panel (its drop zone, the
# Record bar) laid out from the frame after, and the address after it.
OPEN_WORK = ADDRESS_WORK[:-1] + (", document.getElementById('labDrop').getClientRects().length, "
                                 "document.getElementById('labRecordRow').getClientRects().length]")
# JavaScript: the lab as it settles after opening: [the panel's parts not shown though not
# hidden (none: the head-first class gone), the drop zone's and the bar's boxes, the address's
# panel, the first focused control].
LAB_SETTLED = """const box = document.getElementById('labBox');
return [[...box.children].filter((e) => !e.hidden && e.getClientRects().length === 0).map((e) => e.id || e.className),
        document.getElementById('lab').className, document.getElementById('labDrop').getClientRects().length > 0,
        document.getElementById('labRecordRow').getClientRects().length > 0, location.hash, document.activeElement.id]"""


FAILURES = []


# JavaScript: where Record/Stop is ([top, bottom] in the viewport, the lab's scroll) after
# scrolling it into view as WebDriver's click and the bench do ({block: 'end'}, {block:
# 'center'}), the lab's scroll first set to `arguments[0]` ('top', 'bottom' or null: as it is).
STILL = """
const lab = document.getElementById('lab'), b = document.getElementById('labRecord');
if (arguments[0] === 'top') lab.scrollTop = 0;
if (arguments[0] === 'bottom') lab.scrollTop = lab.scrollHeight;
const at = () => { const r = b.getBoundingClientRect(); return [Math.round(r.top), Math.round(r.bottom), Math.round(lab.scrollTop)]; };
const before = at();
b.scrollIntoView({block: 'end', inline: 'nearest'});
const end = at();
b.scrollIntoView({block: 'center'});
return [before, end, at(), innerHeight];
"""


def no_scroll_to(driver, where, scrolled=(None,)):
    """Record/Stop on the screen without a scroll at `where` (docs/explorer.md, "Every tap
    answered at once": a scroll's frame just before a tap delayed its answer): in the viewport,
    at the same place wherever the lab is scrolled (each of `scrolled`), and scrolling it into
    view (WebDriver's click, the bench) scrolls nothing."""
    places, failed = set(), len(FAILURES)
    for how in scrolled:
        before, end, centre, height = driver.execute_script(STILL, how)
        if not (0 <= before[0] and before[1] <= height):
            FAILURES.append(f"{where} (lab scrolled {how or 'as it is'}): the button at {before[:2]} px, "
                            f"outside the {height} px screen")
        if end != before or centre != before:
            FAILURES.append(f"{where} (lab scrolled {how or 'as it is'}): scrolling the button into view "
                            f"scrolled the lab (top, bottom, scroll {before} -> {end}, {centre})")
        places.add(tuple(before[:2]))
    if len(places) > 1:
        FAILURES.append(f"{where}: the button moves as the lab scrolls: {sorted(places)}")
    if len(FAILURES) == failed:
        print(f"{where}: the button at {sorted(places)} px, no scroll to reach it")


def rebuilt_once(driver, where, before):
    """Waits until the runs were built again after a change (main.js's rebuild after its
    frame): a failure where they were not, or more than once. Returns the count now."""
    now = wait_for(driver, REBUILDS, lambda n: n > before, 60)
    settle(driver, 5)
    now = driver.execute_script(REBUILDS)
    if now != before + 1:
        FAILURES.append(f"{where}: the runs were built {now - before} times after it, not once")
    return now


def first_frame(driver, where, event, act, answer, work):
    """`act()` (a tap or a key), the first frame after its `event` read: a failure (each said,
    the test failed at its end) unless `answer` (a JavaScript expression) holds in it and `work`
    (another) is as it was at the event."""
    driver.execute_script(ARM, event, answer, work)
    act()
    seen = wait_for(driver, "return window.firstFrame", bool, 120)
    if not seen:
        fail(f"{where}: no {event} reached the page, or no frame came after it")
    if not seen["answer"]:
        FAILURES.append(f"{where}: the first frame after the tap does not show its answer ({answer}): "
                        "the answer waits behind other work")
    elif seen["before"] != seen["after"]:
        FAILURES.append(f"{where}: the first frame after the tap holds more than its answer: {work} was "
                        f"{seen['before']} at the tap and {seen['after']} in that frame (the paint waits for it)")
    else:
        print(f"{where}: answered in the first frame; the work {seen['after']} after it")
        return
    print(f"FAILED: {FAILURES[-1]}")


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    real = source.parent / "shared" / "recordings-real" / REAL / "Raw Data.csv"
    if not real.exists():
        real = Path("/work/shared/recordings-real") / REAL / "Raw Data.csv"
    if not real.exists():
        missing(f"the real recording {REAL} (../shared/recordings-real/)")
    rows = list(csv.reader(io.StringIO(real.read_text())))[1:]
    t = [float(r[0]) for r in rows]
    omega = [tuple(float(c) for c in r[1:4]) for r in rows]
    out, recordings, shots, page = lab_page_under_test(bookspin, source, binary, "explorer-first-frame")
    # Two scenes, so that the scene menu has another to choose.
    run([bookspin, "explore", str(source / "scenes" / "exact-unstable-x.toml"),
         str(source / "scenes" / "fig09-matrix-unstable-x.toml"), "-o", str(out)])

    with open_browser(chromium, driver_path, size=SIZE, webgl=True, exact_viewport=True) as driver:
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
            "width": SIZE[0], "height": SIZE[1], "deviceScaleFactor": 1, "mobile": True})
        driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 5})
        load(driver, page)
        driver.execute_async_script("window.explorer.labForget().then(arguments[0])")
        driver.execute_cdp_cmd("Emulation.setCPUThrottlingRate", {"rate": THROTTLE})
        try:
            settle(driver, 5)
            # The explorer's own controls.
            first_frame(driver, "Play", "click", lambda: tap(driver, "#play"),
                        "document.getElementById('play').textContent === 'Pause'", PAGE_WORK)
            tap(driver, "#play")
            settle(driver)
            built = driver.execute_script(REBUILDS)

            def menu():
                last = driver.execute_script("const m = document.getElementById('scene'); m.focus();"
                                             "return m.selectedIndex === m.options.length - 1")
                key(driver, "ArrowUp" if last else "ArrowDown")
            first_frame(driver, "the scene menu", "keydown", menu,
                        "document.getElementById('sceneTitle').textContent === "
                        "document.getElementById('scene').selectedOptions[0].dataset.full", PAGE_WORK)
            # The runs are built after that frame, once.
            built = rebuilt_once(driver, "the scene menu", built)
            # Two changes before the rebuild (the menu down and back up in one task): one rebuild,
            # of the second's state: the runs start as the scene's first did.
            starts = driver.execute_script("return window.explorer.startOmegas()")
            scene = driver.execute_script("return window.explorer.state().scene")
            built = driver.execute_script(REBUILDS)
            driver.execute_script("""const m = document.getElementById('scene');
              const other = m.selectedIndex === 0 ? 1 : 0, back = m.selectedIndex;
              for (const i of [other, back]) { m.selectedIndex = i; m.dispatchEvent(new Event('change')); }""")
            built = rebuilt_once(driver, "two changes of the scene menu", built)
            again = driver.execute_script("return [window.explorer.state().scene, window.explorer.startOmegas()]")
            if again != [scene, starts]:
                FAILURES.append(f"two changes of the scene menu before its rebuild: the page holds {again[0]} "
                                f"starting {again[1]}, not {scene} starting {starts} (the second change lost)")
            settle(driver)

            def speed():
                driver.execute_script("const s = document.getElementById('speed'); s.focus(); s.select();")
                driver.execute_cdp_cmd("Input.insertText", {"text": "3"})
                key(driver, "Enter")
            first_frame(driver, "the speed", "keydown", speed,
                        "window.explorer.state().speed === 3", ADDRESS_WORK)
            # Then the field written back and the address with it.
            written = wait_for(driver, """return [document.getElementById('speed').value,
                new URLSearchParams(location.search).get('speed')]""", lambda s: s[1] == "3", 30)
            if written != ["3", "3"]:
                FAILURES.append(f"the speed: after its frame the field and the address say {written}, not 3")
                print(f"FAILED: {FAILURES[-1]}")
            settle(driver)
            first_frame(driver, "the second method", "click", lambda: tap(driver, "#compare"),
                        "document.getElementById('compare').checked && "
                        "!document.getElementById('model2').closest('[hidden]')", PAGE_WORK)
            built = rebuilt_once(driver, "the second method", built)
            runs = driver.execute_script("return window.explorer.trails().length")
            if runs != 2:
                FAILURES.append(f"the second method: {runs} runs after its rebuild, not 2")
            settle(driver)
            first_frame(driver, "Phone-toss lab", "click", lambda: tap(driver, "#labOpen"),
                        "document.getElementById('lab').open && "
                        "document.getElementById('labTitle').getClientRects().length > 0 && "
                        "document.activeElement === document.getElementById('labClose')", OPEN_WORK)
            # Settled: the whole panel shown, as a panel opened all at once shows it, and the
            # address says so.
            lab = wait_for(driver, LAB_SETTLED, lambda s: s[4] == "#lab" and not s[1], 30)
            if lab[:5] != [[], "", True, True, "#lab"]:
                FAILURES.append(f"Phone-toss lab: after its first frame the panel did not settle whole "
                                f"(parts not shown {lab[0]}, class {lab[1]!r}, drop zone shown {lab[2]}, "
                                f"Record bar shown {lab[3]}, address {lab[4]!r})")
                print(f"FAILED: {FAILURES[-1]}")
            settle(driver)

            # The lab's controls, a real recording's.
            override(driver, True)
            feed(driver, omega[0])
            no_scroll_to(driver, "Record", (None, "bottom", "top"))
            first_frame(driver, "Record", "click", lambda: tap(driver, "#labRecord"),
                        "document.getElementById('labRecord').disabled && "
                        "document.getElementById('labRecordState').textContent.startsWith('asking')", LAB_WORK)
            said = wait_for(driver, "return document.getElementById('labRecordState').textContent",
                            lambda s: s.startswith(("recording", "error")), 60)
            if not said.startswith("recording"):
                fail(f"Record: the recording did not start: {said!r}")
            feed_at_own_rate(driver, t, omega)
            driver.execute_script("window.explorer.before = window.explorer.labResult();")
            no_scroll_to(driver, "Stop")
            first_frame(driver, "Stop", "click", lambda: tap(driver, "#labRecord"),
                        "document.getElementById('labRecord').textContent === 'fitting…' && "
                        "document.getElementById('labRecordState').textContent.includes('samples through')",
                        LAB_WORK)
            done = wait_for(driver, """const r = window.explorer.labResult();
                return [r !== window.explorer.before, document.getElementById('labError').textContent,
                        window.explorer.labRecorderPhase()]""", lambda s: (s[0] or s[1]) and s[2] == "idle", 300)
            if not done[0]:
                fail(f"Stop: the recording was not fitted: {done[1]!r}")
            kept = driver.execute_script("return window.explorer.labRecordings()")
            if len(kept) != 1 or not kept[0]["ticked"] or kept[0]["samples"] < 10:
                fail(f"Stop: the list holds {kept}, not the one recording, ticked")
            settle(driver)
            no_scroll_to(driver, "Record with a result shown", (None, "bottom", "top"))
            row = "#labRecordList li:last-child"
            first_frame(driver, "a tick", "click", lambda: tap(driver, f"{row} input[type=checkbox]"),
                        f"!document.querySelector('{row} input[type=checkbox]').checked", LAB_WORK)
            tap(driver, f"{row} input[type=checkbox]")
            settle(driver)
            driver.execute_script("window.explorer.before = window.explorer.labResult();")
            first_frame(driver, "Fit the ticked", "click", lambda: tap(driver, "#labRecordFit"),
                        "document.getElementById('labRecord').textContent === 'fitting…'", LAB_WORK)
            wait_for(driver, "return window.explorer.labRecorderPhase()", lambda s: s == "idle", 300)
            if driver.execute_script("return window.explorer.labResult() === window.explorer.before"):
                fail("Fit the ticked: no fit shown")
            settle(driver)
            first_frame(driver, "Remove", "click", lambda: tap(driver, f"{row} button"),
                        "document.querySelectorAll('#labRecordList li').length === 0",
                        "[window.explorer.framesDrawn(), document.getElementById('labBusy').textContent]")
            settle(driver)
            first_frame(driver, "Close", "click", lambda: tap(driver, "#labClose"),
                        "!document.getElementById('lab').open", ADDRESS_WORK)
            closed = wait_for(driver, "return location.hash", lambda h: h == "", 30)
            if closed != "":
                FAILURES.append(f"Close: the address still says {closed!r} after its frame")
                print(f"FAILED: {FAILURES[-1]}")
            settle(driver, 5)
            drawn = driver.execute_script("const n = window.explorer.framesDrawn(); return n")
            settle(driver, 3)
            if driver.execute_script("return window.explorer.framesDrawn()") <= drawn:
                FAILURES.append("Close: the 3D view is not drawn again after the lab closed")
        finally:
            driver.execute_cdp_cmd("Emulation.setCPUThrottlingRate", {"rate": 1})
        errors = [e for e in console_errors(driver) if "favicon" not in e.get("message", "")]
        if errors:
            fail(f"console errors: {errors[:3]}")
    if FAILURES:
        fail(f"{len(FAILURES)} checks failed: " + "; ".join(FAILURES))
    print("ok")


if __name__ == "__main__":
    main()
