#!/usr/bin/env python3
"""The explorer (docs/explorer.md, "On every screen") on the screens a class uses: a netbook's
1024×600, a projector's 1280×720, a laptop's 1366×768, 1920×1080, and a phone upright (390×844)
and on its side (844×390) with touch. Headless Chromium, the page `bookspin explore` writes from
every scene. At each screen, for fig09 at t = 227, the engines' comparison with its every tile
at t = 300 and the page with no scene, it checks (tests/browser/screens.py):

  - the 3D view keeps its share: at least a third of the window's area, at least 200 px tall,
    on the first screen (the readout bounded, scrolling inside its strip, never pushing the view
    out: at 1024×600 it wrapped to 214 px and left fig09's body 100 px, the tiles none);
  - nothing is drawn over a control (the tiles' labels lay over Reset and Copy link): no body's
    label, text or canvas as the browser shows it (cut by its clipping boxes) crosses one;
  - no two texts of one canvas meet (their inked boxes), the momentum sphere's axis names also
    at 12 seeded random turns of it (its far ends' names were stacked on the near ones);
  - no body's label over a body (the view's pixels under it: the tiles' labels lay over the
    lower row's books at 844×390), nor over another text;
  - no field's text cut ("0.0166667" showed as "0.016666" at 1024×600; "rigid-matri");
  - every plot axis has at least two labelled ticks (fig09 at t = 227 at 1280×720: the ω and
    energy-drift panels were labelled "0" alone);
  - no text under 12 px nor past its panel or the screen (explorer_screen_test.py's check);
  - Play pressed on fig09 at t = 100 and playing across its first flip (104.36, counted a few
    time units after), no control of the transport bar moves by more than 2 px between two frames
    (the phone's bar jumped 28 px when the first flip was counted; Play becoming Pause moved the
    buttons after it by 14 px);
  - on the touch screens no text says "click" (the sphere's caption did).

At 1366×768, once:

  - Back and Forward: a scene changed from the menu, then Back, is the scene before at its t,
    Forward the new one; the Phone-toss lab opened, then Back, is closed, Forward opens it and
    it says to drop the recording again (an address carries no files); a reload keeps the
    scene, t and the open panel (#lab);
  - the lab's toss charts at each screen: no two texts of a chart meet (its title and its
    legend met on a phone);
  - "Play beside the measurement": the sample recording fitted through the lab's file input,
    its first toss's button plays the toss (t moves on), in seconds ("t (s)" on the plots' time
    axis, "s" after the readout's t), never "time units"; then, at each screen, the toss's page
    with nothing cut (its dt of 1/240 in its field at 1024×600, the plots' legend) nor over
    another.

Screenshots: BINARY_DIR/test-output/browser/every-screen-<case>-<W>x<H>.png.

Usage: explorer_every_screen_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import contextlib
import io
import math
import random
import time

from browser import console_errors, fail, find_browser, open_browser, require, run, test_arguments, wait_for
from explorer_person_test import CANVAS_EDGES
from explorer_screen_test import CANVAS_TEXTS, check_canvas_texts
from explorer_test import load, slide_to
from screens import (CANVAS_INK, SCREENS, canvas_overlap_problems, displaced_while_playing, label_over_body_problems,
                     layout_problems, screen_name, set_screen, text_overlaps, text_problems, touch_word_problems)

SPHERE_TURNS = 12  # seeded random views of the momentum sphere at each screen
# (name, query, t)
CASES = (
    ("fig09", "?scene=fig09-matrix-unstable-x", 227),
    ("compare-engines", "?scene=compare-engines&tiles=1", 300),
    ("default", "", None),
)


def check_screen(driver, page, shots, screen, problems):
    set_screen(driver, screen)
    name = screen_name(screen)
    for case, query, t in CASES:
        where = f"{case} at {name}"
        load(driver, page + query)
        if t is not None:
            slide_to(driver, t)
        time.sleep(0.4)
        driver.save_screenshot(str(shots / f"every-screen-{case}-{screen[0]}x{screen[1]}.png"))
        problems += layout_problems(driver, where)
        problems += text_problems(driver, where)
        problems += canvas_overlap_problems(driver, where)
        problems += label_over_body_problems(driver, where)
        problems += [f"{where}: {o}" for o in text_overlaps(driver)]
        if screen[2]:
            problems += touch_word_problems(driver, where)
        with contextlib.redirect_stdout(io.StringIO()):
            check_canvas_texts(driver, where, problems)
        cuts = driver.execute_script("const c = window.__canvasCuts; window.__canvasCuts = [];"
                                     "window.__canvasTexts = []; return c;")
        for text, canvas, left, right, width in (cuts or [])[:3]:
            problems.append(f"{where}: {text!r} on canvas {canvas!r} runs past its edge: "
                            f"{left:.0f} … {right:.0f} of {width}")
    # The sphere turned as a person drags it, to seeded random views: no axis name over another.
    rng = random.Random(87)
    for k in range(SPHERE_TURNS):
        q = [rng.gauss(0, 1) for _ in range(4)]
        n = math.sqrt(sum(x * x for x in q))
        w, x, y, z = (c / n for c in q)
        rows = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
        driver.execute_script("window.explorer.turnSphere(arguments[0])", rows)
        wait_for(driver, "return window.explorer.sphereAxisLabels().length > 0", bool, 5)
        time.sleep(0.15)
        problems += canvas_overlap_problems(driver, f"the sphere turned ({k}) at {name}")
    # Across fig09's first flip (104.36): the transport bar stays where it is.
    load(driver, page + "?scene=fig09-matrix-unstable-x&speed=8")
    slide_to(driver, 100)
    moved, control, t, frames = displaced_while_playing(driver, 1.0, until_flip=True)
    flips = driver.execute_script("return window.explorer.flipMeasures()[0].count")
    print(f"{name}: playing fig09 from t = 100 ({frames} frames, to {flips} flips): the transport "
          f"moved at most {moved:.1f} px (#{control} at t = {t:.2f})")
    if flips < 1:
        problems.append(f"{name}: fig09 played from t = 100 did not reach its first flip")
    if moved > 2:
        problems.append(f"{name}: #{control} moved {moved:.1f} px between two frames while playing "
                        f"(at t = {t:.2f})")


def state(driver):
    return driver.execute_script(
        "const s = window.explorer.state(); return [s.scene, s.t, !document.getElementById('lab').hidden,"
        " document.getElementById('scene').value, location.hash]")


def check_history(driver, page, problems):
    set_screen(driver, (1366, 768, False))
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    slide_to(driver, 50)
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select

    # As a person chooses: the menu clicked (a user's gesture: Chromium's Back skips an entry a
    # page adds without one).
    Select(driver.find_element(By.ID, "scene")).select_by_value("exact-unstable-x")
    wait_for(driver, "return window.explorer.settled()", bool, 30)
    after = state(driver)
    driver.back()
    back = wait_for(driver, "return [window.explorer.state().scene, window.explorer.settled()]",
                    lambda r: r[0] == "fig09-matrix-unstable-x" and r[1], 30)
    back = state(driver)
    print(f"scene changed: {after}; Back: {back}")
    if back[0] != "fig09-matrix-unstable-x" or back[3] != back[0] or abs(back[1] - 50) > 0.01:
        problems.append(f"Back after a scene change: {back}, not fig09 at t = 50")
    driver.forward()
    fwd = wait_for(driver, "return window.explorer.state().scene", lambda s: s == "exact-unstable-x", 30)
    if fwd != "exact-unstable-x":
        problems.append(f"Forward after Back: scene {fwd}, not exact-unstable-x")
    # The lab: a history entry of its own.
    # Its entry is written after the frame that shows it open (docs/explorer.md, "Every tap
    # answered at once").
    driver.find_element(By.ID, "labOpen").click()
    wait_for(driver, "return location.hash", lambda h: h == "#lab", 10)
    opened = state(driver)
    driver.back()
    closed = wait_for(driver, "return document.getElementById('lab').hidden", bool, 10)
    print(f"lab opened: {opened}; Back: lab hidden {closed}, scene {state(driver)[0]}")
    if not opened[2] or opened[4] != "#lab":
        problems.append(f"the lab opened: {opened}, its address without #lab")
    if not closed or state(driver)[0] != "exact-unstable-x":
        problems.append(f"Back after opening the lab: lab hidden {closed}, {state(driver)}")
    driver.forward()
    again = wait_for(driver, "return !document.getElementById('lab').hidden", bool, 10)
    said = driver.execute_script("return document.getElementById('labBox').textContent")
    if not again or "drop yours here again" not in said:
        problems.append(f"Forward to the lab: shown {again}; it does not say to drop the recording again")
    # Hidden, then shown again before the dialog's close event arrives (Back, then Forward at
    # once on a busy machine): the stale close must not hide the panel shown again.
    kept = driver.execute_async_script(
        "const done = arguments[arguments.length - 1]; const lab = document.getElementById('lab');"
        " lab.hidden = true;"
        " Promise.resolve().then(() => { lab.hidden = false;"
        " setTimeout(() => done([!lab.hidden, lab.open]), 200); });")
    print(f"the lab hidden and shown again at once: shown {kept[0]}, dialog open {kept[1]}")
    if not kept[0] or not kept[1]:
        problems.append(f"the lab hidden and shown again before its close event: shown {kept}")
    # A reload (a shared link) keeps the scene, t and the open panel.
    driver.execute_script("document.getElementById('labClose').click()")
    slide_to(driver, 12.5)
    url = driver.current_url
    load(driver, url)
    reloaded = state(driver)
    print(f"reloaded {url.split('?')[-1]}: {reloaded}")
    if reloaded[0] != "exact-unstable-x" or abs(reloaded[1] - 12.5) > 0.01:
        problems.append(f"a reload of {url}: {reloaded}")


def check_play_beside(driver, page, source, problems):
    from selenium.webdriver.common.by import By

    set_screen(driver, (1366, 768, False))
    load(driver, page)
    driver.execute_script("document.getElementById('labOpen').click()")
    recording = source / "recordings" / "phone-on-book-synthetic" / "Raw Data.csv"
    driver.find_element(By.ID, "labFile").send_keys(str(recording.resolve()))
    shown = wait_for(driver, "return !document.getElementById('labResult').hidden", bool, 120)
    if not shown:
        problems.append(f"the lab fitted nothing: {driver.find_element(By.ID, 'labError').text}")
        return
    # Its toss charts on each screen (drawn again as the window changes size): no title into
    # its legend (on a phone "measured" lay over "against t (s)").
    for screen in SCREENS + ((1366, 768, False),):
        set_screen(driver, screen)
        time.sleep(0.4)
        charts = driver.execute_script(
            "return [...document.querySelectorAll('#labTosses canvas')].map((c) => [c.width, c.height,"
            " c.clientWidth * devicePixelRatio, c.clientHeight * devicePixelRatio])")
        if not charts:
            problems.append(f"the lab at {screen_name(screen)}: no toss chart shown")
        for w, h, want_w, want_h in charts:
            if abs(w - want_w) > 1 or abs(h - want_h) > 1:
                problems.append(f"the lab at {screen_name(screen)}: a toss chart drawn {w}×{h} for "
                                f"{want_w:.0f}×{want_h:.0f} pixels shown (not drawn again at this size)")
        problems += canvas_overlap_problems(driver, f"the lab at {screen_name(screen)}")
        # Its result table within the panel (it scrolls sideways inside itself, keeping the toss
        # column), the page no wider than the screen, and no number or interval broken over two
        # lines (a phone's "uncalibrated" broke mid-word).
        page_w, screen_w, panel_w, panel_shown, broken = driver.execute_script("""
          const panel = document.getElementById('labResult'), table = document.getElementById('labOutcome');
          const lines = (td) => { const r = document.createRange(); r.selectNodeContents(td);
            return new Set([...r.getClientRects()].map((b) => Math.round(b.top))).size; };
          return [document.documentElement.scrollWidth, innerWidth, panel.scrollWidth, panel.clientWidth,
            [...table.querySelectorAll('td:not(.words)')].filter((td) => lines(td) > 1).map((td) => td.textContent)]""")
        if page_w > screen_w + 1 or panel_w > panel_shown + 1:
            problems.append(f"the lab at {screen_name(screen)}: its result {panel_w} px wide in a panel of "
                            f"{panel_shown}, the page {page_w} px on a screen of {screen_w}")
        if broken:
            problems.append(f"the lab at {screen_name(screen)}: result cells broken over lines: {broken}")
    driver.execute_script("window.__canvasTexts = []")
    driver.execute_script("""[...document.querySelectorAll('#labTosses button')]
      .find((b) => b.textContent === 'Play beside the measurement').click()""")
    t0 = driver.execute_script("return window.explorer.state().t")
    moved = wait_for(driver, "return [window.explorer.state().t, document.getElementById('play').textContent]",
                     lambda r: r[0] > t0 + 0.05, 5)
    time.sleep(0.3)
    clock = driver.execute_script("return document.getElementById('clock').textContent")
    axis = driver.execute_script("return (window.__canvasTexts || []).map((c) => c[0]).filter((x) => /^t \\(/.test(x))")
    print(f"play beside the measurement: t {t0} → {moved}, clock {clock!r}, time axis {sorted(set(axis))}")
    if not moved[0] > t0 + 0.05 or moved[1] != "Pause":
        problems.append(f"Play beside the measurement does not play: t {t0} → {moved}")
    if not clock.endswith(" s") or not axis or any(a != "t (s)" for a in axis):
        problems.append(f"the toss is not shown in seconds: clock {clock!r}, time axis {sorted(set(axis))}")
    # Nor in any word shown beside it (the drag rate's unit was "1/time").
    shown = driver.execute_script("return document.body.innerText")
    for word in ("time unit", "1/time"):
        if word in shown:
            at = shown.index(word)
            problems.append(f"the toss's page says {shown[max(0, at - 30):at + 20]!r}: not seconds")
    # The toss beside its measurement on each screen: nothing cut (its dt, 1/240's "0.00416667",
    # in its field at 1024×600; the plots' "measured (the scene's measured ω)" past their edge).
    for screen in SCREENS:
        driver.execute_script("window.__canvasCuts = []")
        set_screen(driver, screen)
        time.sleep(0.5)
        where = f"the toss played at {screen_name(screen)}"
        problems += text_problems(driver, where) + layout_problems(driver, where)
        problems += canvas_overlap_problems(driver, where)
        for text, canvas, left, right, width in (driver.execute_script("return window.__canvasCuts") or [])[:3]:
            problems.append(f"{where}: {text!r} on canvas {canvas!r} runs past its edge: {left:.0f} … {right:.0f} of {width}")


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    out = binary / "test-output" / "explorer-every-screen"
    shots = binary / "test-output" / "browser"
    for d in (out, shots):
        d.mkdir(parents=True, exist_ok=True)
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    run([bookspin, "explore", *sorted(str(p) for p in (source / "scenes").glob("*.toml")), "-o", str(out)])
    page = (out / "explorer.html").resolve().as_uri()
    problems = []
    with open_browser(chromium, driver_path, size=(1366, 768), webgl=True, offline=True) as driver:
        driver.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": CANVAS_TEXTS + CANVAS_EDGES + CANVAS_INK})
        for screen in SCREENS:
            check_screen(driver, page, shots, screen, problems)
        check_history(driver, page, problems)
        check_play_beside(driver, page, source, problems)
        problems += [f"console: {e['message'][:200]}" for e in console_errors(driver)]
    if problems:
        fail(f"{len(problems)} problems:\n  " + "\n  ".join(problems[:40]))
    print("ok: on every screen the view keeps its share, nothing covers a control, every axis says "
          "its range, the transport bar stays put, Back and Forward restore the page")


if __name__ == "__main__":
    main()
