#!/usr/bin/env python3
"""The explorer for every person (docs/explorer.md, "For every person"): a class reading a
zoomed projector, a person on a keyboard, a person with a screen reader, a small phone. Headless
Chromium at six sizes: a phone of 320×640 and one of 360×640 (touch), a tablet upright (768×1024,
touch), 800×600, 1024×768, and a 1920×1080 screen at 200 % zoom (960×540 CSS px, two device
pixels a CSS pixel), on the page `bookspin explore` writes from every scene. At each size:

  - what the class must read is shown whole, without scrolling: the readout's t, each run's
    flips and first flip (fig09 at t = 227; the engines' comparison with its every tile at
    t = 599, each tile's), inside the readout's strip as it shows (not scrolled) and inside the
    window;
  - no number, interval or version broken inside itself: each number of the readout and of the
    judge's and the lab's tables (a judgement and a fit shown) on one line (a phone showed
    "0.484" over "3");
  - each panel a modal dialog: its button (focused, Enter) opens it with focus inside it; Tab
    never leaves it (the panel's every control and back to the first); Space on the lab's "air
    drag" menu and on its Close neither plays nor steps the page behind it; Escape closes it
    and focus is back on its button, shown (:focus-visible, an outline of at least 2 px); with
    the judge open no Tab reaches the lab's button;
  - the time axis of fig09 opened at t = 0 spans the scene's run (ticks of whole time units,
    not "0 2e-10 4e-10");
  - the book (the 3D view) on the first screen, whole; on a screen wider than tall the sphere
    and the plots with it (at 320×640 the six engines' view ran 17 px past the screen; at
    800×600 the sphere and the plots were under the controls);
  - the canvases named (role img, an aria-label; the sphere, which the keyboard operates, role
    application): the 3D view's name says the scene, t and each run's flips as the readout
    shows them; a flip counted is said in a live region (aria-live, #spoken);
  - the sphere by keyboard: Tab reaches it, shown focused; its name says the keys; the arrow
    keys turn it under the cross at its centre without stepping t; Enter starts L there;
  - the gallery's link to the lab (explorer.html#lab) opened afresh does not ask to drop a
    recording "again" (a reload does: the address carries none);
  - axe-core (npm, pinned in tests/browser/package-lock.json, installed with `npm ci` into
    BINARY_DIR/test-output/every-person-npm) finds no serious or critical violation on the
    explorer (fig09, the lab open with a fit, the judge open with a judgement), on a gallery
    page (`bookspin gallery` of one short clip and its plot) and on a league page (`bookspin
    flipcheck league`), nor any violation of its landmark rules (region, landmark-*: every part
    of the page in a landmark, one main); each run's summary is printed.

Screenshots: BINARY_DIR/test-output/browser/every-person-<case>-<W>x<H>.png (the sphere focused
by Tab: every-person-sphere-keys-<W>x<H>.png).
BOOKSPIN_EVERY_PERSON_SIZES=320x640,960x540 (say) checks those sizes alone (a planted fault's run).

Usage: explorer_every_person_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten, node or npm is missing,
except under CI=true, where that is a failure (browser.py).
"""
import filecmp
import json
import os
import shutil
import time

from browser import (console_errors, exact_fig09_motion, explorer_of_every_scene, fail, find_browser, open_browser,
                     require, run, test_arguments, wait_for)
from explorer_test import load, slide_to

# (width, height, device pixels a CSS pixel, a phone or tablet: mobile viewport and touch)
SIZES = ((320, 640, 2, True), (360, 640, 3, True), (768, 1024, 2, True), (800, 600, 1, False),
         (1024, 768, 1, False), (960, 540, 2, False))
# (case, query, t, runs shown)
READOUT_CASES = (("fig09", "?scene=fig09-matrix-unstable-x", 227, 1),
                 ("compare-engines", "?scene=compare-engines&tiles=1", 599, 6))
FOCUS_OUTLINE_PX = 2
SERIOUS = ("serious", "critical")


def is_landmark_rule(rule):
    """axe-core's rules of landmarks (moderate: content outside them, no main or two): failed
    too, on every page (the gallery's and the league's content once lay outside any)."""
    return rule == "region" or rule.startswith("landmark-")
# Violations of a page bookspin's C++ writes, awaiting a change there (docs/explorer.md, "For
# every person"): printed, not failed. (page, rule) → what is to change.
WRITTEN_BY_CPP = {}


def size_name(size):
    w, h, dpr, touch = size
    return f"{w}x{h}" + (f" at {dpr * 100} %" if dpr > 1 and not touch else "") + (" touch" if touch else "")


def set_size(driver, size):
    w, h, dpr, touch = size
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": w, "height": h, "deviceScaleFactor": dpr, "mobile": touch})
    driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": touch, "maxTouchPoints": 5})
    driver.execute_script("window.dispatchEvent(new Event('resize'))")
    time.sleep(0.3)


def npm_tools(source, binary):
    """The folder of node_modules from tests/browser's pinned lockfile (axe-core among them)."""
    _, npm = require("node", "npm")
    folder = binary / "test-output" / "every-person-npm"
    folder.mkdir(parents=True, exist_ok=True)
    here = source / "tests" / "browser"
    stale = not (folder / "node_modules" / "axe-core" / "axe.min.js").is_file()
    for name in ("package.json", "package-lock.json"):
        target = folder / name
        if not target.exists() or not filecmp.cmp(here / name, target):
            stale = True
        shutil.copyfile(here / name, target)
    if stale:
        run([npm, "ci", "--no-audit", "--no-fund", "--prefix", str(folder)])
    return folder / "node_modules" / "axe-core"


# JavaScript: the readout's strip as it shows (its box less its scroll bar, how far it is
# scrolled), the window, and what the class must read: the clock, each run's flips and first.
READOUT = """
  const strip = document.getElementById('overlay'), s = strip.getBoundingClientRect();
  const top = s.top + strip.clientTop;
  const must = [document.getElementById('clock'), ...document.querySelectorAll('#status .flips, #status .first')];
  return { scrolled: strip.scrollTop, w: innerWidth, h: innerHeight,
           strip: [s.left, top, s.right, top + strip.clientHeight], runs: document.querySelectorAll('#status .run').length,
           items: must.map((e) => { const r = e.getBoundingClientRect(); return [e.textContent.trim(), [r.left, r.top, r.right, r.bottom]]; }) };
"""

# JavaScript: each number (a version, "m × 10ⁿ", "v ± σ", a range) in the text of `arguments[0]`'s
# elements whose characters lie on more than one line: [the number, the text around it].
BROKEN_NUMBERS = r"""
  const NUM = arguments[1] ? new RegExp(arguments[1], 'gu') :
    /(?<![\p{L}\d.])(?:\d+\.\d+\.\d+|-?\d+(?:\.\d+)?(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?(?:–-?\d+(?:\.\d+)?)?(?: ± \d+(?:\.\d+)?(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?)?)/gu;
  const out = [];
  let seen = 0;
  for (const root of document.querySelectorAll(arguments[0])) {
    if (root.closest('[hidden]') || root.getClientRects().length === 0) continue;
    const walker = document.createTreeWalker(root, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      if (n.parentElement.closest('.digest, [hidden]')) continue;
      for (const m of n.textContent.matchAll(NUM)) {
        const r = document.createRange();
        r.setStart(n, m.index); r.setEnd(n, m.index + m[0].length);
        const tops = new Set([...r.getClientRects()].filter((b) => b.width > 0).map((b) => Math.round(b.bottom)));
        seen += 1;
        if (tops.size > 1) out.push([m[0], n.textContent.trim().slice(0, 80)]);
      }
    }
  }
  return [seen, out];
"""
NUMBER_PLACES = "#overlay, #judgeTable, #judgeStamp, #judgeFailures, #labBody, #labTosses, #labSummary"
# The judge's words whole too: "SHA-256" and each formula's token (no space inside: "ω0|/|ω0|",
# "2E·I2/L²"); a phone showed "SHA-" over "256" and "|ω(0) − ω0|/|" over "ω0|".
NAME_PLACES = "#judgeTable th, #judgeStamp"
NAMES = r"SHA-256|[^\s]*[|/][^\s]*"

# JavaScript: where the keyboard's focus is: [its id or tag, inside #lab, inside #judge, whether
# it shows as focused (:focus-visible) and its outline's style and width].
FOCUS = """
  const a = document.activeElement, s = getComputedStyle(a);
  return [a.id || a.tagName, !!a.closest('#lab'), !!a.closest('#judge'), a.matches(':focus-visible'),
          s.outlineStyle, parseFloat(s.outlineWidth) || 0];
"""
PAGE = ("const x = window.explorer; return [x.state().t, document.getElementById('play').textContent,"
        " !document.getElementById('lab').hidden, !document.getElementById('judge').hidden]")
# JavaScript: how many controls of a panel Tab reaches.
CONTROLS = """
  return [...document.getElementById(arguments[0]).querySelectorAll('button, input, select, summary, [href]')]
    .filter((e) => !e.disabled && !e.closest('[hidden]') && e.getClientRects().length > 0).length;
"""
# JavaScript: every canvas shown and its accessible name: [id or class, role, aria-label]; one the
# keyboard operates (the sphere, in the tab order) is an application, any other an image.
CANVASES = """
  return [...document.querySelectorAll('canvas')].filter((c) => !c.closest('[hidden]') && c.getClientRects().length > 0)
    .map((c) => [c.id || c.className, c.getAttribute('role'), c.getAttribute('aria-label') || '', c.tabIndex >= 0]);
"""


# JavaScript: the window and the boxes of the 3D view, the sphere and the plots.
ON_SCREEN = """
  const box = (id) => { const r = document.getElementById(id).getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; };
  return [innerWidth, innerHeight, { viewBox: box('viewBox'), sphere: box('sphere'), plots: box('plots') }];
"""


def press(driver, key):
    from selenium.webdriver.common.action_chains import ActionChains
    ActionChains(driver).send_keys(key).perform()
    time.sleep(0.15)


def check_readout(driver, page, shots, size, where, problems):
    for case, query, t, runs in READOUT_CASES:
        load(driver, page + query)
        slide_to(driver, t)
        time.sleep(0.3)
        driver.save_screenshot(str(shots / f"every-person-{case}-{size[0]}x{size[1]}.png"))
        r = driver.execute_script(READOUT)
        at = f"{case} at {where}"
        if r["runs"] != runs or len(r["items"]) != 1 + 2 * runs:
            problems.append(f"{at}: the readout shows {r['runs']} runs, {len(r['items'])} of t, flips and "
                            f"first flips; want {runs} runs")
        if r["scrolled"] > 0.5:
            problems.append(f"{at}: the readout's strip opened scrolled by {r['scrolled']} px")
        left, top, right, bottom = r["strip"]
        cut = [(text, [round(v) for v in b]) for text, b in r["items"]
               if b[1] < max(0, top) - 0.5 or b[3] > min(r["h"], bottom) + 0.5 or b[0] < -0.5 or b[2] > r["w"] + 0.5]
        lowest = max(b[3] for _, b in r["items"])
        print(f"{at}: the readout's strip {[round(v) for v in r['strip']]}, what must be read down to "
              f"{lowest:.0f} px: {'whole' if not cut else f'{len(cut)} cut'}")
        for text, b in cut:
            problems.append(f"{at}: {text!r} {b} is not whole in the readout's strip as shown "
                            f"{[round(v) for v in r['strip']]} (window {r['w']}×{r['h']})")
        check_numbers(driver, at, problems)
        check_on_screen(driver, at, problems)
        # The 3D view's name: the scene, t and each run's flips as the readout shows them.
        name = driver.execute_script("return document.getElementById('view').getAttribute('aria-label') || ''")
        clock = driver.execute_script("return document.getElementById('clock').textContent")
        flips = driver.execute_script(
            "return [...document.querySelectorAll('#status .flips')].map((e) => e.textContent.trim())")
        title = driver.execute_script(
            "const s = (window.BOOKSPIN_SCENES || []).find((c) => c.name === window.explorer.state().scene);"
            "return s ? s.title || s.name : ''")
        missing = [w for w in [clock, title, *flips] if w not in name]
        if missing:
            problems.append(f"{at}: the 3D view's name {name[:200]!r} does not say {missing}")
        spoken = driver.execute_script(
            "const e = document.getElementById('spoken'); return e ? [e.getAttribute('aria-live'), e.textContent] : null")
        if not spoken or spoken[0] not in ("polite", "assertive") or "flip" not in spoken[1]:
            problems.append(f"{at}: the flips counted on the way to t = {t} were said in no live region: {spoken}")


def check_on_screen(driver, at, problems):
    """The book on the first screen, whole (the page not scrolled); on a screen wider than tall,
    the sphere and the plots with it (800x600 once had them under the controls)."""
    w, h, boxes = driver.execute_script(ON_SCREEN)
    must = ["viewBox"] + (["sphere", "plots"] if w > h else [])
    for name in must:
        left, top, right, bottom = boxes[name]
        if left < -0.5 or top < -0.5 or right > w + 0.5 or bottom > h + 0.5:
            problems.append(f"{at}: #{name} {[round(v) for v in boxes[name]]} is not on the first screen "
                            f"({w}×{h})")


def check_sphere_keys(driver, page, shots, size, problems):
    """The sphere by keyboard: Tab from the last button before it reaches it, shown focused; its
    name says how; the arrow keys turn it (and never step the page's time); Enter starts L at the
    cross, its centre: the direction the sphere's view puts there."""
    at = f"the sphere by keyboard at {size_name(size)}"
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    driver.execute_script("document.getElementById('labOpen').focus()")
    press(driver, "\ue004")  # Tab
    focus = driver.execute_script(FOCUS)
    if focus[0] != "sphere":
        problems.append(f"{at}: Tab from #labOpen reached #{focus[0]}, not the sphere")
        return
    if not focus[3] or focus[4] == "none" or focus[5] < FOCUS_OUTLINE_PX:
        problems.append(f"{at}: the focused sphere does not show it: :focus-visible {focus[3]}, outline "
                        f"{focus[4]} {focus[5]} px")
    role, name, said = driver.execute_script(
        "const c = document.getElementById('sphere'), d = document.getElementById(c.getAttribute('aria-describedby'));"
        "return [c.getAttribute('role'), c.getAttribute('aria-label') || '', d ? d.textContent : ''];")
    if role != "application" or "arrow" not in name or "Enter" not in name or "L/|L| = (" not in said:
        problems.append(f"{at}: the sphere is not told as a control (role {role!r}, name {name!r}, "
                        f"described {said!r})")
    before = driver.execute_script("const x = window.explorer; return [x.state(), x.sphereRotation()]")
    driver.execute_script("document.getElementById('sphere').scrollIntoView({ block: 'nearest' })")
    time.sleep(0.3)
    driver.save_screenshot(str(shots / f"every-person-sphere-keys-{size[0]}x{size[1]}.png"))
    for key in ("\ue014", "\ue014", "\ue015"):  # →, →, ↓
        press(driver, key)
    turned = driver.execute_script("const x = window.explorer; return [x.state(), x.sphereRotation()]")
    if turned[0]["t"] != before[0]["t"] or turned[1] == before[1]:
        problems.append(f"{at}: the arrow keys moved t {before[0]['t']} → {turned[0]['t']}, turned the sphere "
                        f"{turned[1] != before[1]}")
    press(driver, "\ue007")  # Enter
    time.sleep(0.3)
    state, dots = driver.execute_script("const x = window.explorer; return [x.state(), x.sphereDots()]")
    cross = turned[1][2]  # the view's z axis in the body frame: the centre of the disc
    u = dots[0]["u"] if dots else [0, 0, 0]
    if state["axis"] != "custom" or state["w"] == before[0]["w"] or max(abs(a - b) for a, b in zip(u, cross)) > 0.02:
        problems.append(f"{at}: Enter started axis {state['axis']!r}, ω0 {state['w']} (was {before[0]['w']}), "
                        f"L along {u}, not the cross's {cross}")
    print(f"{at}: Tab reached it, shown focused; the arrows turned it, Enter started L along {[round(v, 3) for v in u]}")


def check_numbers(driver, at, problems):
    seen, broken = driver.execute_script(BROKEN_NUMBERS, NUMBER_PLACES, None)
    if not seen:
        problems.append(f"{at}: no number found to check (the check itself broken)")
    for number, text in broken:
        problems.append(f"{at}: the number {number!r} is broken over two lines in {text!r}")
    if driver.execute_script("return !document.getElementById('judge').hidden"):
        names, broken = driver.execute_script(BROKEN_NUMBERS, NAME_PLACES, NAMES)
        if not names:
            problems.append(f"{at}: no name or formula of the judge's found to check (the check itself broken)")
        for name, text in broken:
            problems.append(f"{at}: {name!r} is broken over two lines in {text!r}")
    return seen


def check_canvases(driver, at, problems):
    for name, role, label, keys in driver.execute_script(CANVASES):
        if role != ("application" if keys else "img") or len(label) < 10:
            problems.append(f"{at}: the canvas {name!r} is not named for a screen reader (role {role!r}, "
                            f"aria-label {label!r}, in the tab order {keys})")


def check_panel_keys(driver, page, where, problems):
    """Each panel by keyboard: opened by its button, focus kept in it, the page's keys inert
    behind it, Escape back to the button."""
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    # The time axis of a scene just opened (t = 0) spans the scene's run: its ticks whole time
    # units, not "0 2e-10 4e-10".
    ticks = driver.execute_script(
        "return window.explorer.plotTickLabels().filter((t) => t.axis === 't').map((t) => [t.value, t.text])")
    if len(ticks) < 2 or max(v for v, _ in ticks) < 1:
        problems.append(f"fig09 at t = 0 at {where}: the time axis reads {[t for _, t in ticks]}, not the scene's span")
    before = driver.execute_script(PAGE)
    for panel, opener in (("lab", "labOpen"), ("judge", "judgeOpen")):
        at = f"the {panel} panel at {where}"
        driver.execute_script(f"document.getElementById('{opener}').focus()")
        press(driver, "\ue007")  # Enter
        focus = driver.execute_script(FOCUS)
        opened = driver.execute_script(PAGE)
        inside = focus[1] if panel == "lab" else focus[2]
        if not (opened[2] if panel == "lab" else opened[3]):
            problems.append(f"{at}: Enter on its button did not open it")
            continue
        if not inside:
            problems.append(f"{at}: opened, the focus is on #{focus[0]}, not in the panel")
        # Tab through every control and round again: never out of the panel.
        n = driver.execute_script(CONTROLS, panel)
        reached, out = [], []
        for _ in range(n + 3):
            press(driver, "\ue004")  # Tab
            f = driver.execute_script(FOCUS)
            reached.append(f[0])
            if not (f[1] if panel == "lab" else f[2]):
                out.append(f[0])
        if out:
            problems.append(f"{at}: Tab left the panel for {sorted(set(out))}")
        if len(set(reached)) < min(n, 3):
            problems.append(f"{at}: Tab reached only {sorted(set(reached))} of its {n} controls")
        if panel == "lab":
            # Space on the air drag menu, then on Close: the page behind neither plays nor steps.
            driver.execute_script("document.getElementById('labDrag').focus()")
            press(driver, " ")
            driver.execute_script("document.getElementById('labClose').focus()")
            press(driver, " ")
            after = driver.execute_script(PAGE)
            focus = driver.execute_script(FOCUS)
            if after[0] != before[0] or after[1] != before[1]:
                problems.append(f"{at}: Space in the panel reached the page behind it: t {before[0]} → "
                                f"{after[0]}, {before[1]!r} → {after[1]!r}")
            if after[2] or focus[0] != opener:
                problems.append(f"{at}: Space on Close left the panel open {after[2]}, focus on #{focus[0]}")
            driver.execute_script(f"document.getElementById('{opener}').focus()")
            press(driver, "\ue007")
        press(driver, "\ue00c")  # Escape
        closed = driver.execute_script(PAGE)
        focus = driver.execute_script(FOCUS)
        if closed[2] or closed[3]:
            problems.append(f"{at}: Escape did not close it: {closed}")
        if focus[0] != opener:
            problems.append(f"{at}: after Escape the focus is on #{focus[0]}, not on #{opener}, its button")
        elif not focus[3] or focus[4] == "none" or focus[5] < FOCUS_OUTLINE_PX:
            problems.append(f"{at}: #{opener} focused by the keyboard does not show it: :focus-visible "
                            f"{focus[3]}, outline {focus[4]} {focus[5]} px")
        print(f"{at}: opened with the focus in it, Tab kept in it over {n + 3} presses ({len(set(reached))} "
              f"controls reached), Escape back to #{focus[0]}")
    after = driver.execute_script(PAGE)
    if after[0] != before[0] or after[1] != before[1]:
        problems.append(f"the panels at {where}: the page behind moved: {before} → {after}")


def check_first_visit(driver, page, problems):
    """The gallery's link to the lab opened afresh: the lab open, not asking to drop a recording
    "again" (nothing was dropped before); a reload of it does."""
    driver.get("about:blank")
    load(driver, page + "#lab")
    time.sleep(0.3)
    said = driver.execute_script("return [!document.getElementById('lab').hidden, document.getElementById('labBusy').textContent]")
    driver.refresh()
    load(driver)
    time.sleep(0.3)
    again = driver.execute_script("return document.getElementById('labBusy').textContent")
    print(f"the lab by a link: shown {said[0]}, saying {said[1]!r}; reloaded: {again!r}")
    if not said[0] or "again" in said[1]:
        problems.append(f"the lab opened afresh by a link: shown {said[0]}, saying {said[1]!r}")
    if "again" not in again:
        problems.append(f"the lab reloaded does not say to drop the recording again: {again!r}")


def axe_check(driver, axe_source, what, problems, page="explorer"):
    """axe-core on the page as it is now: its summary printed; a serious or critical violation a
    problem, and so is any of its landmark rules (but those of WRITTEN_BY_CPP, named as such)."""
    driver.execute_script(axe_source)
    result = driver.execute_async_script("""
      const done = arguments[arguments.length - 1];
      axe.run(document, { resultTypes: ['violations'] }).then((r) => done({
        version: r.testEngine.version, passes: r.passes.length, incomplete: r.incomplete.length,
        violations: r.violations.map((v) => ({ id: v.id, impact: v.impact, help: v.help, nodes: v.nodes.length,
          targets: v.nodes.slice(0, 3).map((n) => n.target.join(' ')) })) }), (e) => done({ error: String(e) }));""")
    if "error" in result:
        problems.append(f"{what}: axe-core failed: {result['error']}")
        return
    bad = [v for v in result["violations"] if v["impact"] in SERIOUS or is_landmark_rule(v["id"])]
    print(f"axe-core {result['version']} on {what}: {len(result['violations'])} violations "
          f"({len(bad)} serious or critical), {result['passes']} rules passed, {result['incomplete']} to review"
          + "".join(f"\n    {v['impact']}: {v['id']} ({v['nodes']} nodes, {v['targets']}): {v['help']}"
                    for v in result["violations"]))
    for v in bad:
        if (page, v["id"]) in WRITTEN_BY_CPP:
            print(f"    not failed: {v['id']} is in the page the C++ writes: {WRITTEN_BY_CPP[(page, v['id'])]}")
            continue
        problems.append(f"{what}: axe-core: {v['impact']} {v['id']}: {v['help']} at {v['targets']}")


def open_lab_with_fit(driver, page, source, problems, where):
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    driver.execute_script("document.getElementById('labOpen').click()")
    driver.find_element("id", "labFile").send_keys(
        str((source / "recordings" / "phone-on-book-synthetic" / "Raw Data.csv").resolve()))
    if not wait_for(driver, "return !document.getElementById('labResult').hidden", bool, 240):
        problems.append(f"the lab at {where} showed no fit: {driver.find_element('id', 'labError').text}")
        return False
    time.sleep(0.3)
    return True


def open_judge_with_result(driver, page, motion, problems, where):
    load(driver, page + "?scene=fig09-matrix-unstable-x#judge")
    driver.find_element("id", "judgeFile").send_keys(str(motion.resolve()))
    if not wait_for(driver, "return !document.getElementById('judgeResult').hidden", bool, 240):
        problems.append(f"the judge at {where} showed no judgement: {driver.find_element('id', 'judgeError').text}")
        return False
    time.sleep(0.3)
    return True


def build_gallery_and_league(bookspin, source, out):
    """A gallery of one short clip and its plot; a league of two methods and the exact motion in
    two scenarios. Their folders."""
    gallery = out / "gallery"
    league = out / "league"
    for folder in (gallery, league):
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
    scene = source / "scenes" / "fig09-matrix-unstable-x.toml"
    run([bookspin, "render", scene, "--set", "render.width=160", "--set", "render.height=96",
         "--set", 'render.preset="ultrafast"', "--frames", "30", "--jobs", "2", "-o", gallery])
    run([bookspin, "plot", scene, "--set", "time.frames=30", "-o", gallery])
    run([bookspin, "gallery", gallery, scene])
    scenarios = [source / "scenes" / "flipcheck" / f"{n}.toml" for n in ("book-intermediate-0.2", "book-largest-axis")]
    run([bookspin, "flipcheck", "export", *scenarios, "-o", league])
    run([bookspin, "flipcheck", "league", *scenarios, "--motions",
         *(league / f"{s.stem}-exact.csv" for s in scenarios),
         "--methods", "rigid-quaternion:rk4,rigid-matrix:euler", "-o", league])
    return gallery, league


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    axe = npm_tools(source, binary)
    axe_source = (axe / "axe.min.js").read_text()
    out, shots, page = explorer_of_every_scene(bookspin, source, binary, "explorer-every-person")
    motion = exact_fig09_motion(bookspin, source, out)
    gallery, league = build_gallery_and_league(bookspin, source, out)
    version = json.loads((axe / "package.json").read_text())["version"]
    print(f"axe-core {version} from {axe}")
    problems = []
    only = [w for w in os.environ.get("BOOKSPIN_EVERY_PERSON_SIZES", "").split(",") if w]
    sizes = [s for s in SIZES if not only or f"{s[0]}x{s[1]}" in only]
    if not sizes:
        fail(f"BOOKSPIN_EVERY_PERSON_SIZES={','.join(only)} names none of {[f'{s[0]}x{s[1]}' for s in SIZES]}")
    with open_browser(chromium, driver_path, webgl=True, offline=True) as driver:
        for size in sizes:
            where = size_name(size)
            set_size(driver, size)
            check_readout(driver, page, shots, size, where, problems)
            check_canvases(driver, f"fig09 at {where}", problems)
            axe_check(driver, axe_source, f"the explorer (compare-engines) at {where}", problems)
            check_panel_keys(driver, page, where, problems)
            check_sphere_keys(driver, page, shots, size, problems)
            if size == sizes[0]:
                check_first_visit(driver, page, problems)
            if open_lab_with_fit(driver, page, source, problems, where):
                driver.save_screenshot(str(shots / f"every-person-lab-{size[0]}x{size[1]}.png"))
                seen = check_numbers(driver, f"the lab at {where}", problems)
                check_canvases(driver, f"the lab at {where}", problems)
                axe_check(driver, axe_source, f"the explorer, the lab open with a fit, at {where}", problems)
                print(f"the lab at {where}: {seen} numbers looked at")
            if open_judge_with_result(driver, page, motion, problems, where):
                driver.save_screenshot(str(shots / f"every-person-judge-{size[0]}x{size[1]}.png"))
                seen = check_numbers(driver, f"the judge at {where}", problems)
                check_canvases(driver, f"the judge at {where}", problems)
                axe_check(driver, axe_source, f"the explorer, the judge open with a judgement, at {where}", problems)
                print(f"the judge at {where}: {seen} numbers looked at")
            driver.get((gallery / "index.html").resolve().as_uri())
            time.sleep(0.5)
            driver.save_screenshot(str(shots / f"every-person-gallery-{size[0]}x{size[1]}.png"))
            axe_check(driver, axe_source, f"the gallery at {where}", problems, "gallery")
            driver.get((league / "flipcheck-league.html").resolve().as_uri())
            time.sleep(0.3)
            driver.save_screenshot(str(shots / f"every-person-league-{size[0]}x{size[1]}.png"))
            axe_check(driver, axe_source, f"the league at {where}", problems, "league")
        errors = console_errors(driver)
        if errors:
            problems.append(f"console errors: {errors}")
    print(f"screenshots: {shots}/every-person-*.png")
    if problems:
        fail(f"{len(problems)} problems:\n" + "\n".join(problems[:80]))
    print("ok: the readout whole, numbers whole, the book (and on a wide screen the sphere and the plots) "
          "on the first screen, the panels modal by keyboard, the sphere by keyboard, the canvases named, "
          "no serious or critical axe-core violation nor any of its landmark rules, at every size")


if __name__ == "__main__":
    main()
