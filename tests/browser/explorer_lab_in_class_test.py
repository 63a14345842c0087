#!/usr/bin/env python3
"""The lab's "Record a toss" as a class uses it (web/src/gyro_recorder.js, docs/phone-lab.md,
"Recording in the page", "The lab in a class"): headless Chromium at a phone's size (390x844,
touch: every button tapped through the DevTools protocol's touch events), the gyroscope fed
through the sensor override (explorer_records_gyro_test's DevTools session), real recordings
of ../shared/recordings-real/dvarkian-2022-05-03 fed sample by sample at their own rate (a
failure under CI=true where that folder is absent, a skip elsewhere), in a time zone far from
UTC (Pacific/Auckland, through Emulation.setTimezoneOverride).

No toss lost:
  - a double tap on Stop (the second 80 ms after the first) stops once: the recording is kept
    and fitted, and 1.5 s after the fit no new recording has started, the fit shown is that
    recording's;
  - its file's name is the phone's local time at the Stop (not UTC), within a minute;
  - Record then a double tap on Stop at once (80 ms apart): "record for longer", the earlier
    result and the list untouched, and the second tap, on a button enabled again (no fit
    follows), starts nothing: the AFTER_STOP_MS guard alone holds it;
  - a second real recording with "fit with the ticked recordings below": the pooled fit names
    both, in order, and each keeps its own download (the text of each fetched: its own rows);
  - the first unticked, "Fit the ticked": the second alone; Remove takes the first out;
  - the lab closed during a recording (Close), and Back during one: the recording stops, is
    kept in the list unticked, the page says so, the result shown stays the one before.
A slow phone: the run left playing behind the lab, the same recording fed unslowed and with the
CPU slowed 4x (Emulation.setCPUThrottlingRate): no frame of the page drawn while recording (the
run paused), at least 80 % of the samples the unslowed feed keeps, its flights found (no
"busy" note unslowed); a page kept busy by the test (a 60 ms task every 70 ms) named busy, not the sensor.
A fitted toss's address loaded (?scene=original-toss1): the message says its scene is not in the
page and offers the lab, which the offer opens.
A screen reader: the lab's live region (aria-live polite, inside its dialog) says "recording
through …", "fitting …", the result's first line and an error (flights by hand "2:1"), and the
focus stays on the control it was on.
Kept across a reload (IndexedDB): the list and each download the same after a reload; a page
refused IndexedDB says the list is not kept across a reload. A reload in the middle of a
recording: the samples so far kept by the next page, unticked, and said (once). A corrupt or
foreign row in the store skipped and named, the others listed; a store at a later version (a
newer page's) named so, not blamed on the browser.
The smaller ones: "stops after (s)" given 1 is held to its minimum of 2; on a landscape phone
(844x390) Stop and the live trace are in view while recording; Back after "Play beside the
measurement" returns to the lab, its result as it was.
The fit in a worker (web/src/fit_worker.js), the CPU slowed 6x (a school Chromebook): three real
recordings chosen in the file input and fitted as one body; no gap over 1 s between two frames
(requestAnimationFrame's timestamps) during the fit, Escape closes the lab during it, each stage
said in the live region, the answer equal as JSON to the main thread's fit of the same bytes
(window.explorer.fitOnMainThread); a second fit cancelled (Cancel the fit): the result, summary
and list as they were, and a fit after it answers.

Usage: explorer_lab_in_class_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import datetime
import os
import shutil
import time
import zoneinfo

from browser import (console_errors, fail, find_browser, lab_page_under_test, open_browser,
                     require, test_arguments, wait_for)
from explorer_records_gyro_test import (devtools, feed, feed_at_own_rate, fresh_page, readings,
                                        real_recording, state_line, tap)

SIZE = (390, 844)
FOLDER = "dvarkian-2022-05-03"
FIRST, SECOND = "12-13-01", "12-13-51"
ZONE = "Pacific/Auckland"


def start_recording(driver, where, first):
    """Taps Record with a first reading given; fail() unless it says it records. (A tap within
    AFTER_STOP_MS, 600 ms, of a Stop starts nothing: the tap waits that long.)"""
    time.sleep(0.7)
    feed(driver, first)
    tap(driver, "labRecord")
    said = wait_for(driver, "return document.getElementById('labRecordState').textContent",
                    lambda s: s.startswith(("recording", "error")), 30)
    if not said.startswith("recording"):
        button = driver.execute_script("""const b = document.getElementById('labRecord');
            return [b.textContent, b.disabled, window.explorer.labRecorderPhase(), window.taps]""")
        fail(f"{where}: the recording did not start: {said!r}; the button {button}")


def touch_at(driver, point):
    """A tap at `point` through the test's own DevTools session (a fraction of a ms each)."""
    devtools(driver).call("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [point]})
    devtools(driver).call("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})


def double_tap(driver, element_id, gap):
    """Two taps on the element's centre, the second `gap` s after the first began."""
    box = driver.execute_script(
        "const e = document.getElementById(arguments[0]); e.scrollIntoView({block: 'center'});"
        "const r = e.getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2];", element_id)
    point = {"x": box[0], "y": box[1]}
    began = time.monotonic()
    touch_at(driver, point)
    time.sleep(max(0.0, gap - (time.monotonic() - began)))
    touch_at(driver, point)


def mark_result(driver):
    driver.execute_script("window.explorer.before = window.explorer.labResult();")


def result_unchanged(driver):
    return driver.execute_script("return window.explorer.labResult() === window.explorer.before")


def wait_fit(driver, where):
    """The next fit shown after mark_result(): fail() on none."""
    done = wait_for(driver, """const r = window.explorer.labResult();
        return [r !== window.explorer.before, document.getElementById('labError').textContent,
                window.explorer.labRecorderPhase()]""", lambda s: (s[0] or s[1]) and s[2] == "idle", 300)
    if not done[0]:
        fail(f"{where}: no fit: {done[1]!r}; the state {state_line(driver)!r}")
    return driver.execute_script("return window.explorer.labResult()")


def kept(driver):
    return driver.execute_script("return window.explorer.labRecordings()")


def downloads(driver):
    """Each row of the list: [name on its row, its download's file name, the text it serves]."""
    return driver.execute_async_script("""const done = arguments[0];
        Promise.all([...document.querySelectorAll('#labRecordList li')].map((li) => {
          const a = li.querySelector('a[download]');
          return fetch(a.href).then((r) => r.text()).then((text) => [li.dataset.name, a.download, text]);
        })).then(done);""")


def data_rows(text):
    return [l for l in text.splitlines() if l and not l.startswith("#")][1:]  # the header left out


def fresh(driver, page):
    """fresh_page, and the recordings earlier pages of this test kept forgotten."""
    fresh_page(driver, page)
    driver.execute_async_script("""const done = arguments[0];
        (window.explorer.labForget ? window.explorer.labForget() : Promise.resolve()).then(() => done(true));""")


def check_no_toss_lost(driver, page, first, second):
    t1, w1 = first
    t2, w2 = second
    fresh(driver, page)
    mark_result(driver)
    driver.execute_script("""window.taps = []; for (const k of ['touchstart', 'touchend', 'click'])
        document.addEventListener(k, (e) => window.taps.push([k, e.target.id, Math.round(e.timeStamp), Math.round(performance.now())]), true);""")
    start_recording(driver, "double tap", w1[0])
    feed_at_own_rate(driver, t1, w1)
    stopped_at = datetime.datetime.now(zoneinfo.ZoneInfo(ZONE))
    double_tap(driver, "labRecord", 0.08)
    result = wait_fit(driver, "double tap")
    time.sleep(1.5)
    phase = driver.execute_script("return window.explorer.labRecorderPhase()")
    listed = kept(driver)
    if phase != "idle" or len(listed) != 1:
        fail(f"double tap on Stop: the phase {phase!r}, {len(listed)} recordings kept ({listed}), the state "
             f"{state_line(driver)!r}: the second tap started a recording")
    mark_result(driver)
    name = listed[0]["name"]
    if result.get("recording") != name.removesuffix(".csv") or not result["tosses"]:
        fail(f"double tap on Stop: the fit shown is of {result.get('recording')!r} with {len(result['tosses'])} "
             f"tosses, not of the toss recorded, {name}")
    print(f"double tap on Stop: one recording, {name}, {listed[0]['samples']} samples, fitted "
          f"({len(result['tosses'])} tosses)")
    # The name in the phone's local time (the page's zone, Pacific/Auckland), at the Stop.
    stamp = name.split("-gyroscope")[0].removeprefix("toss-")[:19]
    named = datetime.datetime.strptime(stamp, "%Y-%m-%d-%H-%M-%S").replace(tzinfo=zoneinfo.ZoneInfo(ZONE))
    if abs((named - stopped_at).total_seconds()) > 60:
        fail(f"the recording's name {name} is not the local time at the Stop in {ZONE} "
             f"({stopped_at:%Y-%m-%d %H:%M:%S}): UTC was {datetime.datetime.now(datetime.timezone.utc):%H:%M:%S}")

    # Record, then Stop at once with a nervous double tap (80 ms apart): too short; the result
    # and the list as they were, and the second tap starts nothing. No fit follows this Stop, so
    # the button is enabled again at once: only the AFTER_STOP_MS guard holds the second tap.
    start_recording(driver, "too short", w1[0])
    feed(driver, w1[1])
    double_tap(driver, "labRecord", 0.08)
    said = wait_for(driver, "return document.getElementById('labRecordState').textContent",
                    lambda s: "record for longer" in s, 10)
    time.sleep(1)
    phase = driver.execute_script("return window.explorer.labRecorderPhase()")
    if "record for longer" not in said or not result_unchanged(driver) or len(kept(driver)) != 1 or phase != "idle":
        fail(f"Record then a double tap on Stop at once: the page says {said!r} (now {state_line(driver)!r}), "
             f"the phase {phase!r}, the earlier result {'kept' if result_unchanged(driver) else 'replaced'}, "
             f"{len(kept(driver))} recordings")
    print(f"too short, a double tap on Stop: {said}; the second tap started nothing")

    # A second toss pooled with the ticked one.
    tap(driver, "labRecordPool")
    start_recording(driver, "pooled", w2[0])
    feed_at_own_rate(driver, t2, w2)
    tap(driver, "labRecord")
    result = wait_fit(driver, "pooled")
    listed = kept(driver)
    names = [k["name"] for k in listed]
    summary = driver.execute_script("return document.getElementById('labSummary').textContent")
    if len(listed) != 2 or result.get("fitted") != names or f"fitted as one body: {', '.join(names)}" not in summary:
        fail(f"pooled: the page fitted {result.get('fitted')} of the recordings {names}; its summary {summary[:300]!r}")
    rows = downloads(driver)
    for (row_name, file_name, text), k in zip(rows, listed):
        if row_name != k["name"] or file_name != k["name"] or len(data_rows(text)) != k["samples"]:
            fail(f"the download of {k['name']}: named {file_name!r} on the row of {row_name!r}, "
                 f"{len(data_rows(text))} rows for {k['samples']} samples")
    if rows[0][2] == rows[1][2]:
        fail("the two recordings' downloads serve the same text")
    print(f"pooled: {names}, each with its own download")

    # The first unticked, "Fit the ticked": the second alone; then the first removed.
    mark_result(driver)
    driver.execute_script("document.querySelector('#labRecordList li input[type=checkbox]').scrollIntoView({block: 'center'})")
    first_tick = driver.execute_script("""const r = document.querySelector('#labRecordList li input[type=checkbox]')
        .getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2];""")
    touch_at(driver, {"x": first_tick[0], "y": first_tick[1]})
    tap(driver, "labRecordFit")
    result = wait_fit(driver, "fit the ticked")
    if result.get("recording") != names[1].removesuffix(".csv") or result.get("fitted") not in (None, [names[1]]):
        fail(f"the first unticked, Fit the ticked fitted {result.get('recording')!r} ({result.get('fitted')})")
    driver.execute_script("document.querySelector('#labRecordList li button').click()")
    if [k["name"] for k in kept(driver)] != names[1:]:
        fail(f"Remove of the first left {kept(driver)}")
    print("fit the ticked, remove: as asked")

    # The lab closed during a recording, then Back during one: stopped, kept unticked, said.
    for how in ("Close", "Back"):
        mark_result(driver)
        before = len(kept(driver))
        start_recording(driver, how, w1[0])
        feed_at_own_rate(driver, t1[:150], w1[:150])
        if how == "Close":
            tap(driver, "labClose")
        else:
            driver.back()
        wait_for(driver, "return document.getElementById('lab').hidden", bool, 10)
        said = state_line(driver)
        listed = kept(driver)
        phase = driver.execute_script("return window.explorer.labRecorderPhase()")
        if (phase != "idle" or len(listed) != before + 1 or listed[-1]["ticked"]
                or "recording stopped: the lab was closed" not in said or listed[-1]["name"] not in said
                or not result_unchanged(driver)):
            fail(f"{how} during a recording: the phase {phase!r}, the list {listed}, the page says {said!r}, "
                 f"the result {'kept' if result_unchanged(driver) else 'replaced'}")
        print(f"{how} during a recording: {said}")
        tap(driver, "labOpen")


def record_behind_a_run(driver, page, where, t, w, throttle):
    """A fresh page whose run plays behind the open lab, the CPU slowed `throttle` times, the
    readings (t, w) recorded: (samples kept, frames the page drew while recording, the state
    line, the fit or None with the error)."""
    fresh(driver, page)
    driver.execute_script("window.explorer.setPlaying(true);")
    devtools(driver).call("Emulation.setCPUThrottlingRate", {"rate": throttle})
    try:
        mark_result(driver)
        start_recording(driver, where, w[0])
        frames = driver.execute_script("return window.explorer.framesDrawn()")
        feed_at_own_rate(driver, t, w)
        frames = driver.execute_script("return window.explorer.framesDrawn()") - frames
        playing = driver.execute_script("return document.getElementById('play').textContent") == "Pause"
        tap(driver, "labRecord")
        done = wait_for(driver, """const r = window.explorer.labResult();
            return [r !== window.explorer.before, document.getElementById('labError').textContent,
                    window.explorer.labRecorderPhase()]""", lambda s: (s[0] or s[1]) and s[2] == "idle", 300)
    finally:
        devtools(driver).call("Emulation.setCPUThrottlingRate", {"rate": 1})
    samples = kept(driver)[-1]["samples"]
    result = driver.execute_script("return window.explorer.labResult()") if done[0] else None
    return samples, frames, playing, state_line(driver), result, done[1]


def check_slow_phone(driver, page, first):
    """While recording the page does nothing else, and a 4x slowed phone keeps >= 80 % of the
    readings the same feed keeps unslowed, and finds the flights; a busy page is named so."""
    t1, w1 = first
    counts = {}
    for throttle in (1, 4):
        where = f"CPU slowed {throttle}x, the run playing behind the lab"
        samples, frames, playing, said, result, error = record_behind_a_run(driver, page, where, t1, w1, throttle)
        print(f"{where}: {samples} samples of {len(t1)} fed, {frames} frames drawn while recording; {said}")
        if frames or playing:
            fail(f"{where}: the page drew {frames} frames while recording (playing: {playing}): the run behind "
                 "the lab did not pause")
        if result is None or not result["tosses"]:
            fail(f"{where}: no flight found: {error!r}; the state {said!r}")
        if throttle == 1 and "busy" in said:
            fail(f"{where}: the page says {said!r}: a busy page where the page kept {samples} samples")
        counts[throttle] = samples
    if counts[4] < 0.8 * counts[1]:
        fail(f"CPU slowed 4x: {counts[4]} samples kept where the same feed unslowed keeps {counts[1]} "
             f"({counts[4] / counts[1]:.0%}, under 80 %)")
    print(f"CPU slowed 4x: {counts[4]} of {counts[1]} samples ({counts[4] / counts[1]:.0%})")

    # A page kept busy by a steady task (60 ms every 70 ms, planted by the test) takes every
    # reading about 70 ms apart, so the stamps alone look like a slow sensor: the page's own clock
    # (PageLag) names it busy, not the sensor slow nor the throw too fast.
    fresh(driver, page)
    start_recording(driver, "busy page", w1[0])
    driver.execute_script("""window.busy = setInterval(() => { const t = performance.now();
        while (performance.now() - t < 60) {} }, 70);""")
    feed_at_own_rate(driver, t1[:300], w1[:300])
    driver.execute_script("clearInterval(window.busy);")
    tap(driver, "labRecord")
    said = wait_for(driver, "return document.getElementById('labRecordState').textContent",
                    lambda s: "samples through" in s, 30)
    if "the page was busy" not in said or "throw it spinning slower" in said:
        fail(f"a busy page: the page says {said!r}, not that the page was busy")
    print(f"busy page: {said}")


def check_fitted_toss_address(driver, page):
    """A fitted toss's address loaded (a reload, a discarded tab, a shared link) says why its
    scene is not in the page and offers the lab; the offer opens it."""
    driver.get(page + "?scene=original-toss1&t=1.5")
    if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
        fail("the page with a fitted toss's address never became ready")
    said = driver.execute_script("return document.getElementById('message').textContent")
    offer = driver.execute_script("const b = document.getElementById('messageLab'); return b && b.offsetWidth > 0")
    if "scene original-toss1 is not in this page" not in said or "lab" not in said or not offer:
        fail(f"a fitted toss's address loaded: the page says {said!r}, offers the lab: {bool(offer)}")
    tap(driver, "messageLab")
    if not wait_for(driver, "return !document.getElementById('lab').hidden", bool, 10):
        fail("a fitted toss's address loaded: its offer did not open the lab")
    print(f"a fitted toss's address loaded: {said}")


def check_announced(driver, page, first):
    """A live region inside the lab (aria-live, not hidden from a reader) says "recording",
    "fitting…", the result's first line and an error, and focus stays where it was."""
    t1, w1 = first
    fresh(driver, page)
    region = driver.execute_script("""const r = document.getElementById('labSpoken');
        if (!r) return null;
        const s = getComputedStyle(r);
        return [r.getAttribute('aria-live'), r.closest('dialog') === document.getElementById('lab'),
                s.display !== 'none' && s.visibility !== 'hidden' && !r.closest('[aria-hidden=true]')];""")
    if region != ["polite", True, True]:
        fail(f"the lab's live region: {region} (aria-live, inside the lab's dialog, not hidden from a reader)")
    driver.execute_script("""window.said = [];
        new MutationObserver(() => window.said.push(document.getElementById('labSpoken').textContent))
          .observe(document.getElementById('labSpoken'), {childList: true, characterData: true, subtree: true});""")
    mark_result(driver)
    start_recording(driver, "announced", w1[0])
    focused = driver.execute_script("return document.activeElement.id")
    feed_at_own_rate(driver, t1, w1)
    tap(driver, "labRecord")
    wait_fit(driver, "announced")
    # An error: flights by hand that are no range, which fit the recording again.
    driver.execute_script("""const f = document.getElementById('labFlights'); f.value = '2:1';
        f.dispatchEvent(new Event('change'));""")
    wait_for(driver, "return document.getElementById('labError').textContent", bool, 60)
    said = driver.execute_script("return window.said")
    error = driver.execute_script("return document.getElementById('labError').textContent")
    now = driver.execute_script("return document.activeElement.id")
    wanted = {"recording": lambda s: s.startswith("recording through"), "fitting…": lambda s: s.startswith("fitting "),
              "the result's first line": lambda s: s.startswith("fitted ") and "I1 : I2 : I3" in s,
              "the error": lambda s: s == error}
    missed = [name for name, ok in wanted.items() if not any(ok(s) for s in said)]
    if missed or now != focused:
        fail(f"the live region said {said}: not {missed}; focus on {focused!r} before, {now!r} after")
    print(f"announced: {said}")


def check_kept_across_reload(driver, page, first):
    """The list survives a reload where the browser gives the page storage (IndexedDB), says
    so; and where it gives none, says that it is not kept."""
    t1, w1 = first
    fresh(driver, page)
    driver.execute_script("for (const b of document.querySelectorAll('#labRecordList li button')) b.click();")
    start_recording(driver, "kept", w1[0])
    feed_at_own_rate(driver, t1[:200], w1[:200])
    tap(driver, "labClose")  # kept, not fitted
    before = kept(driver)
    texts = downloads(driver)
    note = driver.execute_script("return document.getElementById('labRecordKept').textContent")
    if len(before) != 1 or "kept in this browser across reloads" not in note:
        fail(f"before the reload: {before}, the note {note!r}")
    driver.refresh()
    if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
        fail("the reloaded page never became ready")
    tap(driver, "labOpen")
    after = wait_for(driver, "return window.explorer.labRecordings()", bool, 10)
    if after != before or downloads(driver) != texts:
        fail(f"after a reload the list is {after}, before it {before} (or its downloads differ)")
    print(f"kept across a reload: {[k['name'] for k in after]}; {note}")
    # A browser that gives no storage (IndexedDB refused, as a private window may): said so.
    script = driver.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": """
        Object.defineProperty(window, 'indexedDB', {get() { throw new DOMException('storage refused', 'SecurityError'); }});"""})
    try:
        fresh(driver, page)
        start_recording(driver, "no storage", w1[0])
        feed_at_own_rate(driver, t1[:200], w1[:200])
        tap(driver, "labClose")
        note = driver.execute_script("return document.getElementById('labRecordKept').textContent")
        listed = kept(driver)
        if len(listed) != 1 or not note.startswith("not kept across a reload"):
            fail(f"no storage: the list {listed}, the note {note!r}")
        print(f"no storage: {note}")
    finally:
        driver.execute_cdp_cmd("Page.removeScriptToEvaluateOnNewDocument", {"identifier": script["identifier"]})


def store_rows(driver):
    """Every row of the lab's IndexedDB store, as the page's store gives them."""
    return driver.execute_async_script("""const done = arguments[0];
        const r = indexedDB.open('bookspin-lab');
        r.onsuccess = () => { const db = r.result;
          const q = db.transaction('recordings').objectStore('recordings').getAll();
          q.onsuccess = () => { db.close(); done(q.result); }; };
        r.onerror = () => done(null);""")


def reloaded(driver):
    """The page reloaded, ready, the lab open, the sensor overridden again."""
    driver.refresh()
    if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
        fail("the reloaded page never became ready")
    tap(driver, "labOpen")


def check_reload_while_recording(driver, page, first):
    """A reload in the middle of a recording (or a phone that reloads the tab it put in the
    background): the samples recorded are kept by the next page, unticked and not fitted, and
    it says so; nothing was lost without a word."""
    t1, w1 = first
    fresh(driver, page)
    start_recording(driver, "reload", w1[0])
    feed_at_own_rate(driver, t1[:300], w1[:300])
    time.sleep(1.2)  # at least one write of the recording in progress after the last reading
    reloaded(driver)
    listed = wait_for(driver, "return window.explorer.labRecordings()", bool, 10)
    said = state_line(driver)
    # All but the last write's worth (LIVE_MS, 1 s) of what was recorded: the readings fed and
    # the wait after them, at the rate the page measured.
    recorded = t1[299] - t1[0] + 1.2
    if len(listed) != 1 or listed[0]["ticked"] or \
            listed[0]["samples"] < listed[0]["rate"] * (recorded - 1.5):
        fail(f"after a reload mid-recording the list is {listed} ({recorded:.1f} s recorded)")
    if "cut short before this page loaded" not in said or listed[0]["name"] not in said:
        fail(f"after a reload mid-recording the page said {said!r}")
    # Said once: the next page lists it without saying it again, and no row in progress is left.
    reloaded(driver)
    if kept(driver) != listed or "cut short" in state_line(driver):
        fail(f"a second reload: {kept(driver)}, {state_line(driver)!r}")
    if any(r["id"] == 0 or "cut" in r for r in store_rows(driver)):
        fail(f"the store after the recording was said: {store_rows(driver)}")
    print(f"reload while recording: {listed[0]['name']} ({listed[0]['samples']} samples); {said}")


def check_corrupt_rows(driver, page, first):
    """A corrupt or foreign row in the store (an older page's, a write cut by a crash) is skipped
    and named, the others listed; a store at a later version (a newer page's) is named so, not
    blamed on the browser."""
    t1, w1 = first
    fresh(driver, page)
    start_recording(driver, "corrupt", w1[0])
    feed_at_own_rate(driver, t1[:200], w1[:200])
    tap(driver, "labClose")
    good = kept(driver)
    # Two bad rows beside the good one: an older page's (its time not an ISO time) and a write
    # cut short (a name alone).
    driver.execute_async_script("""const done = arguments[0];
        const r = indexedDB.open('bookspin-lab', 1);
        r.onsuccess = () => { const db = r.result; const tx = db.transaction('recordings', 'readwrite');
          const s = tx.objectStore('recordings');
          s.put({id: 90, name: 'older.csv', when: 'yesterday', samples: 5, rate: 50, text: 't,wx\\n', ticked: false});
          s.put({id: 91, name: 'cut.csv'});
          tx.oncomplete = () => { db.close(); done(true); }; };""")
    reloaded(driver)
    listed = wait_for(driver, "return window.explorer.labRecordings()", bool, 10)
    note = driver.execute_script("return document.getElementById('labRecordKept').textContent")
    if listed != good:
        fail(f"with two bad rows in the store the list is {listed}, expected {good}")
    if not note.startswith("kept in this browser") or "skipped 2 rows" not in note or \
            "id 90 (its time is not a time)" not in note or "id 91 (no text" not in note:
        fail(f"with two bad rows in the store the note is {note!r}")
    print(f"corrupt rows: {note}")
    # A newer page's store (version 2): named so.
    driver.execute_async_script("""const done = arguments[0];
        const r = indexedDB.open('bookspin-lab', 2);
        r.onupgradeneeded = () => {};
        r.onsuccess = () => { r.result.close(); done(true); };
        r.onerror = () => done(false);""")
    reloaded(driver)
    note = wait_for(driver, "return document.getElementById('labRecordKept').textContent", bool, 10)
    if "store at version 2" not in note or "newer copy of this page" not in note or "no storage" in note:
        fail(f"a store at version 2: {note!r}")
    print(f"a newer store: {note}")
    driver.execute_async_script("""const done = arguments[0];
        const r = indexedDB.deleteDatabase('bookspin-lab'); r.onsuccess = r.onerror = r.onblocked = () => done(true);""")


POOL = ("12-13-01", "12-13-51", "12-22-44")
#: The CPU slowed as a school Chromebook is (issue: no frame for 7-15 s during a pooled fit).
CHROMEBOOK = 6
#: The longest gap between two frames allowed during the fit (ms): the page keeps drawing.
FRAME_GAP_MS = 1000


def frames_watched(driver):
    """Starts window.frameGaps: every requestAnimationFrame timestamp's gap from the one before
    (ms), kept until frames_stopped()."""
    driver.execute_script("""const w = window.frameWatch = {gaps: [], last: null, on: true};
        const step = (t) => { if (!w.on) return; if (w.last !== null) w.gaps.push(t - w.last); w.last = t;
          requestAnimationFrame(step); };
        requestAnimationFrame(step);""")


def frames_stopped(driver):
    """[frames drawn, the longest gap (ms)] since frames_watched()."""
    return driver.execute_script("""const w = window.frameWatch; w.on = false;
        return [w.gaps.length, Math.max(0, ...w.gaps)];""")


def choose_files(driver, paths):
    """The files `paths` chosen in the lab's file input, as a student picks them."""
    from selenium.webdriver.common.by import By
    driver.find_element(By.ID, "labFile").send_keys("\n".join(str(p) for p in paths))


def busy(driver):
    return driver.execute_script("return document.getElementById('labBusy').textContent")


def check_fit_in_worker(driver, page, folder, out):
    """The fit off the page's main thread (fit_worker.js): three real recordings chosen in the
    lab's file input and fitted as one body with the CPU slowed 6x: the page draws through the
    fit (no frame gap over FRAME_GAP_MS), Escape closes the lab during it, its progress is said
    (each recording read, the flights, the fit), and its answer equals the main thread's fit of
    the same bytes to the last digit (the whole value as JSON); then a second fit cancelled:
    the result, the summary and the list before it as they were."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.keys import Keys
    pool = out / "pool"
    pool.mkdir(exist_ok=True)
    paths = []
    for name in POOL:
        path = pool / f"{name}.csv"
        shutil.copyfile(folder / name / "Raw Data.csv", path)
        paths.append(path)
    fresh(driver, page)
    driver.execute_script("""window.said = [];
        new MutationObserver(() => window.said.push(document.getElementById('labSpoken').textContent))
          .observe(document.getElementById('labSpoken'), {childList: true, characterData: true, subtree: true});""")
    mark_result(driver)
    devtools(driver).call("Emulation.setCPUThrottlingRate", {"rate": CHROMEBOOK})
    try:
        frames_watched(driver)
        choose_files(driver, paths)
        # A stage of the fit shown (or, with the fit on the main thread, its end: nothing could
        # be read before it).
        wait_for(driver, """return [document.getElementById('labBusy').textContent,
            window.explorer.labResult() !== window.explorer.before]""",
                 lambda s: "finding the flights" in s[0] or "fitting the body" in s[0] or s[1], 120)
        ActionChains(driver).send_keys(Keys.ESCAPE).perform()
        closed = driver.execute_script("return [document.getElementById('lab').hidden, window.explorer.labFitBusy()]")
        if closed[0]:
            tap(driver, "labOpen")
        wait_fit(driver, "the pooled fit in the worker")
        frames, gap = frames_stopped(driver)
    finally:
        devtools(driver).call("Emulation.setCPUThrottlingRate", {"rate": 1})
    counts = driver.execute_script("return window.explorer.labFitCounts()")
    print(f"a pooled fit of {', '.join(POOL)} at {CHROMEBOOK}x slowed: {frames} frames, the longest gap "
          f"{gap:.0f} ms; fits in the worker and on the main thread {counts}")
    if gap > FRAME_GAP_MS or counts["main"] or not counts["worker"]:
        fail(f"a pooled fit at {CHROMEBOOK}x slowed: a frame gap of {gap:.0f} ms (over {FRAME_GAP_MS} ms: "
             f"the page froze), {frames} frames; fits {counts}")
    if closed != [True, True]:
        fail(f"Escape during the fit: the lab hidden {closed[0]}, the fit still running {closed[1]}: "
             "Escape waited for the fit")
    print("Escape closed the lab during the fit")
    said = driver.execute_script("return window.said")
    wanted = [f"reading {POOL[0]}.csv (1 of 3)", f"reading {POOL[2]}.csv (3 of 3)", "finding the flights",
              "fitting the body and each toss", "toss 1: its chart and scene"]
    missed = [w for w in wanted if w not in said]
    if missed:
        fail(f"the fit's progress: the live region said {said}, not {missed}")
    print(f"progress said: {said[:8]}")
    # The main thread's fit of the same bytes (the page's own module, as the lab fitted before
    # its worker): the same value to the last digit.
    same = driver.execute_script("""const texts = arguments[0];
        const files = texts.map(([name, text]) => ({name, bytes: new TextEncoder().encode(text), meta: []}));
        const reference = window.explorer.fitOnMainThread(files, document.getElementById('labDrag').value, '');
        const shown = window.explorer.labResult();
        return [JSON.stringify(reference) === JSON.stringify(shown), reference.error || '',
                (reference.tosses || []).length, shown.tosses.length];""", [[p.name, p.read_text()] for p in paths])
    if not same[0]:
        fail(f"the worker's fit differs from the main thread's: {same}")
    print(f"the worker's answer equals the main thread's to the last digit ({same[3]} tosses)")

    # Cancel during a second fit: the result, its summary and the list as they were.
    before = driver.execute_script("""return [document.getElementById('labSummary').textContent,
        document.getElementById('labResult').hidden, document.getElementById('labError').textContent]""")
    listed = kept(driver)
    mark_result(driver)
    devtools(driver).call("Emulation.setCPUThrottlingRate", {"rate": CHROMEBOOK})
    try:
        # The pool again (two recordings took the warm worker under a second: gone before a tap).
        choose_files(driver, paths)
        running = wait_for(driver, """return !document.getElementById('labCancel').hidden
            && window.explorer.labFitBusy()""", bool, 30)
        if not running:
            fail(f"a second fit: no Cancel offered while it runs; the busy line {busy(driver)!r}")
        tap(driver, "labCancel")
        said = wait_for(driver, "return document.getElementById('labBusy').textContent",
                        lambda s: s.startswith("fit cancelled"), 10)
    finally:
        devtools(driver).call("Emulation.setCPUThrottlingRate", {"rate": 1})
    after = driver.execute_script("""return [document.getElementById('labSummary').textContent,
        document.getElementById('labResult').hidden, document.getElementById('labError').textContent]""")
    running = driver.execute_script("return window.explorer.labFitBusy()")
    if not said.startswith("fit cancelled") or running or after != before or not result_unchanged(driver) \
            or kept(driver) != listed:
        fail(f"Cancel during a fit: the page says {said!r}, a fit still running {running}, the result "
             f"{'kept' if result_unchanged(driver) else 'replaced'}, the summary/hidden/error {after[1:]} "
             f"for {before[1:]}, the list {kept(driver)} for {listed}")
    # Fitted again after the Cancel: a fresh worker answers.
    choose_files(driver, paths[:1])
    wait_fit(driver, "a fit after the Cancel")
    print(f"Cancel during a fit: {said}; the result before it kept; a fit after it answers")


def check_back_after_play(driver, page, folder, out):
    """Back after "Play beside the measurement" returns to the lab, its result as it was (not a
    rewind of the toss played)."""
    path = out / f"{FIRST}.csv"
    shutil.copyfile(folder / FIRST / "Raw Data.csv", path)
    fresh(driver, page)
    mark_result(driver)
    choose_files(driver, [path])
    result = wait_fit(driver, "back after play")
    before = driver.execute_script("return [window.explorer.state().scene, location.search]")
    box = driver.execute_script("""const b = document.querySelector('#labTosses .tossHead button');
        b.scrollIntoView({block: 'center'}); const r = b.getBoundingClientRect();
        return [b.textContent, r.left + r.width / 2, r.top + r.height / 2];""")
    if box[0] != "Play beside the measurement":
        fail(f"back after play: the toss's button says {box[0]!r}")
    touch_at(driver, {"x": box[1], "y": box[2]})
    toss = result["scenes"][0]["name"]
    playing = wait_for(driver, """return [document.getElementById('lab').hidden, window.explorer.state().scene,
        document.getElementById('play').textContent]""", lambda s: s[0] and s[1] == toss, 20)
    if playing[:2] != [True, toss]:
        fail(f"Play beside the measurement: the lab hidden {playing[0]}, the scene {playing[1]!r}, not {toss!r}")
    time.sleep(1)  # the toss plays a moment
    mark_result(driver)
    driver.back()
    back = wait_for(driver, """return [document.getElementById('lab').hidden, window.explorer.state().scene,
        location.search, document.getElementById('labResult').hidden]""", lambda s: not s[0], 10)
    if back[0] or back[3] or not result_unchanged(driver) or back[1] != before[0]:
        fail(f"Back after Play beside the measurement: the lab hidden {back[0]}, the scene {back[1]!r} "
             f"(before Play {before[0]!r}), the result {'hidden' if back[3] else 'shown'} and "
             f"{'kept' if result_unchanged(driver) else 'replaced'}: not back in the lab")
    print(f"Back after Play beside the measurement: the lab again, its result as it was, the scene {back[1]!r}")


def check_smaller(driver, page, first):
    """"stops after (s)" held to its minimum of 2; on a landscape phone (844x390) the Stop button
    and the live trace in view while recording."""
    t1, w1 = first
    fresh(driver, page)
    driver.execute_script("document.getElementById('labRecordSeconds').value = '1';")
    start_recording(driver, "stops after 1 s", w1[0])
    said = state_line(driver)
    field = driver.execute_script("return document.getElementById('labRecordSeconds').value")
    if "stops after 2 s" not in said or field != "2":
        fail(f"stops after 1 s: the page says {said!r}, the field {field!r}: not held to its minimum of 2")
    feed_at_own_rate(driver, t1[:300], w1[:300])
    wait_for(driver, "return window.explorer.labRecorderPhase()", lambda p: p == "idle", 60)
    print(f"stops after 1 s: {said}")
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
        "width": SIZE[1], "height": SIZE[0], "deviceScaleFactor": 1, "mobile": True})
    try:
        fresh(driver, page)
        start_recording(driver, "landscape", w1[0])
        feed_at_own_rate(driver, t1[:30], w1[:30])
        seen = driver.execute_script("""const inside = (e) => { const r = e.getBoundingClientRect();
            return r.top >= 0 && r.bottom <= innerHeight && r.height > 0; };
            return [inside(document.getElementById('labRecord')), inside(document.getElementById('labRecordTrace'))];""")
        tap(driver, "labRecord")
        if seen != [True, True]:
            fail(f"landscape 844x390 while recording: Stop in view {seen[0]}, the live trace in view {seen[1]}")
        print("landscape: Stop and the live trace in view while recording")
    finally:
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
            "width": SIZE[0], "height": SIZE[1], "deviceScaleFactor": 1, "mobile": True})


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    folder = real_recording(source, f"{FOLDER}/{FIRST}").parent.parent
    first = readings(folder / FIRST / "Raw Data.csv")
    second = readings(real_recording(source, f"{FOLDER}/{SECOND}"))

    out, _, _, page = lab_page_under_test(bookspin, source, binary, "explorer-lab-in-class")

    with open_browser(chromium, driver_path, size=SIZE, exact_viewport=True) as driver:
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
            "width": SIZE[0], "height": SIZE[1], "deviceScaleFactor": 1, "mobile": True})
        driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 5})
        driver.execute_cdp_cmd("Emulation.setTimezoneOverride", {"timezoneId": ZONE})
        # CHECKS (comma-separated names) runs only those: a planted fault's check alone.
        chosen = [c for c in os.environ.get("CHECKS", "").split(",") if c]
        checks = {"lost": lambda: check_no_toss_lost(driver, page, first, second),
                  "slow": lambda: check_slow_phone(driver, page, first),
                  "address": lambda: check_fitted_toss_address(driver, page),
                  "announced": lambda: check_announced(driver, page, first),
                  "kept": lambda: check_kept_across_reload(driver, page, first),
                  "reload": lambda: check_reload_while_recording(driver, page, first),
                  "corrupt": lambda: check_corrupt_rows(driver, page, first),
                  "smaller": lambda: check_smaller(driver, page, first),
                  "worker": lambda: check_fit_in_worker(driver, page, folder, out),
                  "back": lambda: check_back_after_play(driver, page, folder, out)}
        for name, check in checks.items():
            if not chosen or name in chosen:
                check()
        errors = [e for e in console_errors(driver) if "favicon" not in e.get("message", "")]
        if errors:
            fail(f"console errors: {errors[:3]}")
    print("ok")


if __name__ == "__main__":
    main()
