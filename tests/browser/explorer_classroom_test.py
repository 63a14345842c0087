#!/usr/bin/env python3
"""The explorer (docs/explorer.md) as a class sees it: headless Chromium at 1280×720, the page
written by `bookspin explore` from every scene. Checks:

  - `?scene=exact-unstable-x`: the exact run waits for nothing (its precession is a closed
    form, docs/physics.md §8): `window.explorer.waiting()` is false from the first frame on
    (within WAIT_AFTER_FIRST_MS of it, a few animation frames; a precession table built after
    the first frame kept it true for 5-17 s), no notice speaks of a table, and played, the
    exact book turns at once. The times from navigation are printed, not judged: a cold
    page's first frame is a timing of a shared machine (docs/explorer.md, "Speed", has them); Reset, compare on, a change of the second method and a scrub back each hand the
    page back within 1 s (the scrub 2 s), measured around the handler in the page;
  - the readout's t, flips and first flip at a computed font size of at least 32 px;
  - fig09 (rigid matrix) shows its first flip at 104.4 ± 0.01, the exact motion's first flip
    from the same start beside it, both on the page: the number is the closed form's
    (docs/physics.md §14: zeros of ω about the intermediate axis), independent of the method;
  - a start picked near the largest axis wobbles: 0 flips at t = 210, by the method's
    detector and the exact motion alike (the wobble's cosine stays under the margin).

Usage: explorer_classroom_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
"""
import math
import sys
import time
import tomllib

from browser import console_errors, fail, find_browser, open_browser, require, run, test_arguments, wait_for
from explorer_test import EXPLORER_WINDOW, body_label_reach, load

WAIT_AFTER_FIRST_MS = 250
CONTROL_BACK_MS = 1000
SCRUB_BACK_MS = 2000
BIG_PX = 32
FIG09_FIRST_FLIP = 104.4


def handler_ms(driver, action):
    """Milliseconds the page spends in `action` (JavaScript run in the page): the time until it
    answers again, the handlers being synchronous."""
    return driver.execute_script(f"const t0 = performance.now(); {action}; return performance.now() - t0;")


def notice(driver):
    return driver.execute_script("""
      const n = document.getElementById('notice');
      return n.offsetParent !== null && n.getBoundingClientRect().height > 0 ? n.textContent : '';""")


def font_px(driver, selector):
    return driver.execute_script(f"""
      return [...document.querySelectorAll('{selector}')].map((e) => parseFloat(getComputedStyle(e).fontSize));""")


def check_exact_scene(driver, page):
    # A watcher from the document's start: each animation frame it asks waiting() and keeps the
    # time (since navigation) of the first frame it reads false.
    watcher = driver.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": """
      (() => {
        const look = () => {
          if (window.explorer && window.explorer.ready && !window.explorer.waiting()) window.notWaitingAt = performance.now();
          else requestAnimationFrame(look);
        };
        requestAnimationFrame(look);
      })();"""})
    driver.get(page + "?scene=exact-unstable-x")
    wait_for(driver, "return !!(window.explorer && window.explorer.ready && window.explorer.firstFrameAt())",
             bool, timeout=60)
    first = driver.execute_script("return window.explorer.firstFrameAt()")
    wait_for(driver, "return window.notWaitingAt !== undefined", bool, timeout=120)
    not_waiting = driver.execute_script("return window.notWaitingAt")
    driver.execute_cdp_cmd("Page.removeScriptToEvaluateOnNewDocument", {"identifier": watcher["identifier"]})
    text = notice(driver)
    print(f"exact-unstable-x: first frame {first:.0f} ms after navigation; waiting() false at "
          f"{not_waiting:.0f} ms; notice {text!r}")
    if not_waiting - first > WAIT_AFTER_FIRST_MS:
        fail(f"window.explorer.waiting() still true {not_waiting - first:.0f} ms after the first "
             f"frame, more than {WAIT_AFTER_FIRST_MS}: the exact run waits for something")
    if "precession" in text or "table" in text:
        fail(f"the notice speaks of a table to wait for: {text!r}")
    # Played for 0.5 s at the scene's speed, the exact run has moved: t advanced, and its L
    # direction in the body frame (the sphere's trail, from R(t)) has new points.
    before = driver.execute_script("return [window.explorer.state().t, window.explorer.trails()[0].points]")
    driver.execute_script("window.explorer.setPlaying(true)")
    time.sleep(0.5)
    after = driver.execute_script("return [window.explorer.state().t, window.explorer.trails()[0].points]")
    driver.execute_script("window.explorer.setPlaying(false)")
    print(f"  played 0.5 s: t {before[0]} → {after[0]}, trail points {before[1]} → {after[1]}")
    if not (after[0] > before[0] and after[1] > before[1]):
        fail(f"the exact run did not play at once: t {before[0]} → {after[0]}, trail {before[1]} → {after[1]}")
    timings = {
        "Reset": handler_ms(driver, "document.getElementById('reset').click()"),
        "compare on": handler_ms(driver, """
          const c = document.getElementById('compare'); c.checked = true;
          c.dispatchEvent(new Event('change'))"""),
        "second method": handler_ms(driver, """
          const m = document.getElementById('model2');
          m.value = [...m.options].map((o) => o.value).find((v) => v !== m.value && v !== 'exact');
          m.dispatchEvent(new Event('change'))"""),
    }
    for name, ms in timings.items():
        print(f"  {name}: control back after {ms:.0f} ms; notice {notice(driver)!r}")
        if ms > CONTROL_BACK_MS:
            fail(f"{name} held the page {ms:.0f} ms, more than {CONTROL_BACK_MS}")
    driver.execute_script("""
      const s = document.getElementById('slider');
      s.max = 60; s.value = 60; s.dispatchEvent(new Event('input'));""")
    wait_for(driver, "return window.explorer.settled()", bool, timeout=120)
    scrub = handler_ms(driver, """
      const s = document.getElementById('slider');
      s.value = 48; s.dispatchEvent(new Event('input'))""")
    print(f"  scrub back 60 → 48: {scrub:.0f} ms")
    if scrub > SCRUB_BACK_MS:
        fail(f"a scrub back held the page {scrub:.0f} ms, more than {SCRUB_BACK_MS}")


def check_compare_labels(driver, page):
    """Compare mode: each book labelled with its method within 50 px of it."""
    load(driver, page + "?scene=fig09-matrix-unstable-x&compare=1&model2=rigid-quaternion&integrator2=rk4")
    driver.execute_script("window.explorer.omegaAt(30)")
    time.sleep(0.3)
    reach = body_label_reach(driver)
    print(f"compare: body labels and the drawn pixels within 50 px: {reach}")
    if [label for label, _ in reach] != ["rigid-matrix, euler, normalized", "rigid-quaternion, rk4"] or \
            any(n < 200 for _, n in reach):
        fail(f"the compared books are not each labelled within 50 px: {reach}")


def check_readout(driver, page):
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    # The detector counts a turn-over once the cosine is past the margin on the other side
    # (docs/physics.md §14), a few time units after the crossing it dates it by.
    driver.execute_script("window.explorer.omegaAt(130)")
    sizes = {s: font_px(driver, s) for s in ("#clock", "#status .flips", "#status .first")}
    print(f"fig09: readout font sizes {sizes}")
    for selector, px in sizes.items():
        if not px or min(px) < BIG_PX:
            fail(f"{selector} at {px} px, not at least {BIG_PX}")
    own = driver.execute_script("return window.explorer.flipMeasures()")[0]
    exact = driver.execute_script("return window.explorer.exactFlips()")[0]
    shown = driver.find_element("id", "status").text
    print(f"  method {own}, exact {exact}; shown {shown!r}")
    # The exact motion from fig09's start turns over at 104.400; fig09's method (Euler with
    # normalization, dt = 1/60) dates its first at 104.364, 0.036 early (the sweep's number,
    # explorer_test.py checks the page against it): both shown, side by side.
    if exact["first"] is None or abs(exact["first"] - FIG09_FIRST_FLIP) > 0.01:
        fail(f"the exact motion's first flip {exact['first']}, not {FIG09_FIRST_FLIP} ± 0.01")
    if own["first"] is None or abs(own["first"] - FIG09_FIRST_FLIP) > 0.1:
        fail(f"the method's first flip {own['first']}, not within 0.1 of the exact {FIG09_FIRST_FLIP}")
    if (f"first flip at t = {own['first']:.2f}" not in shown
            or f"exact motion: first flip at {exact['first']:.2f}" not in shown):
        fail(f"the page does not show the method's first flip beside the exact one: {shown!r}")
    # A start near the largest axis (body z for the book), 5° off it: a wobble, no flip.
    tilt = 5 / 180 * 3.141592653589793
    driver.execute_script(f"window.explorer.pick([Math.sin({tilt}), 0, Math.cos({tilt})])")
    driver.execute_script("window.explorer.omegaAt(210)")
    own = driver.execute_script("return window.explorer.flipMeasures()")[0]
    exact = driver.execute_script("return window.explorer.exactFlips()")[0]
    shown = driver.find_element("id", "status").text
    print(f"  picked near the largest axis, t = 210: method {own}, exact {exact}")
    if own["count"] != 0 or exact["count"] != 0 or "flips 0" not in shown:
        fail(f"a wobble about the largest axis counted as flips: {own}, exact {exact}, shown {shown!r}")


# The book of the scenes (a, b, c; mass 8): principal moments m(b² + c²)/12, m(a² + c²)/12,
# m(a² + b²)/12, so y smallest, x intermediate, z largest.
BOOK = (1.878, 2.9085, 0.5)
BOOK_MOMENTS = [8 * (BOOK[1] ** 2 + BOOK[2] ** 2) / 12, 8 * (BOOK[0] ** 2 + BOOK[2] ** 2) / 12,
                8 * (BOOK[0] ** 2 + BOOK[1] ** 2) / 12]
AXIS_NAMES = {"x": "intermediate", "y": "smallest", "z": "largest"}


def angle_deg(a, b):
    dot = sum(x * y for x, y in zip(a, b))
    na, nb = sum(x * x for x in a) ** 0.5, sum(x * x for x in b) ** 0.5
    return math.degrees(math.acos(max(-1.0, min(1.0, dot / (na * nb)))))


def momentum_direction(w):
    return [i * x for i, x in zip(BOOK_MOMENTS, w)]


def canvas_mouse(driver, points):
    """A press at the first of `points` (CSS pixels of the page), moves, a release at the last."""
    kinds = ["mousePressed"] + ["mouseMoved"] * (len(points) - 2) + ["mouseReleased"]
    for kind, (x, y) in zip(kinds, points):
        driver.execute_cdp_cmd("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": "left",
                                                            "buttons": 1, "clickCount": 1})
        time.sleep(0.05)
    time.sleep(0.2)


def check_sphere(driver, page):
    """The axes named by moment; a click on the drawn L dot, turned to the far side, picks the L
    it marks."""
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    driver.execute_script("window.explorer.omegaAt(40)")
    labels = driver.execute_script("return window.explorer.sphereAxisLabels()")
    print(f"sphere axis labels: {labels}")
    # Each axis's near end named by its moment (its far end named too where its name fits by
    # its point, sphere.js); no name other than these six.
    view = driver.execute_script("return window.explorer.sphereRotation()")
    names = {f"{sign}{axis} {name}" for axis, name in AXIS_NAMES.items() for sign in ("+", "−")}
    for axis, name in AXIS_NAMES.items():
        near = "+" if view[2]["xyz".index(axis)] >= 0 else "−"
        if f"{near}{axis} {name}" not in labels:
            fail(f"the sphere does not name the near end {near}{axis} '{name}': {labels}")
    if not set(labels) <= names or len(set(labels)) != len(labels):
        fail(f"the sphere's axis names {labels} are not among {sorted(names)}, each once")
    box = driver.execute_script("return document.getElementById('sphere').getBoundingClientRect().toJSON()")
    # fig09's L starts near +x, which the sphere's first view shows on its far side.
    dots = driver.execute_script("return window.explorer.sphereDots()")
    w_before = driver.execute_script("return window.explorer.omegaNow()")[0]
    marked = momentum_direction(w_before)
    dot = dots[0]
    rotation = driver.execute_script("return window.explorer.sphereRotation()")
    depth = sum(rotation[2][i] * dot["u"][i] for i in range(3))
    if depth >= 0:
        fail(f"the L dot is not on the sphere's far side (view z {depth:.2f}): not the case to check")
    scale = box["width"] / driver.execute_script("return document.getElementById('sphere').width")
    x, y = box["left"] + dot["x"] * scale, box["top"] + dot["y"] * scale
    canvas_mouse(driver, [(x, y), (x, y)])
    state = driver.execute_script("return window.explorer.state()")
    err = angle_deg(momentum_direction(state["w"]), marked)
    print(f"  L dot on the far side (view z {depth:.2f}) at ({dot['x']:.0f}, {dot['y']:.0f}) marks L ∝ {marked}; the click picked ω0 {state['w']}: "
          f"{err:.2f}° off")
    if state["axis"] != "custom" or err > 5:
        fail(f"a click on the drawn L dot picked a start {err:.1f}° from the L it marks")


def check_canvases(driver, page, shots):
    """Each canvas's backing store at its displayed size × devicePixelRatio, within 1 %; the
    phone's scene menu within its first screen and its touch hint shown."""
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    for width, height, dpr, mobile in ((1280, 720, 1, False), (1920, 1080, 1, False), (390, 844, 3, True)):
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                               {"width": width, "height": height, "deviceScaleFactor": dpr, "mobile": mobile})
        driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": mobile, "maxTouchPoints": 5})
        driver.execute_cdp_cmd("Emulation.setEmitTouchEventsForMouse", {"enabled": mobile})
        driver.execute_script("window.dispatchEvent(new Event('resize'))")
        time.sleep(0.6)
        sizes = driver.execute_script("""
          return [...document.querySelectorAll('canvas')].map((c) => {
            const r = c.getBoundingClientRect();
            return [c.id, c.width, c.height, r.width * devicePixelRatio, r.height * devicePixelRatio]; });""")
        driver.save_screenshot(str(shots / f"explorer-class-{width}x{height}.png"))
        print(f"{width}×{height} at {dpr}×: canvases {sizes}")
        for name, w, h, want_w, want_h in sizes:
            if abs(w - want_w) > 0.01 * want_w or abs(h - want_h) > 0.01 * want_h:
                fail(f"#{name} at {width}×{height}×{dpr}: backing store {w}×{h}, displayed "
                     f"{want_w:.0f}×{want_h:.0f} device pixels")
        if mobile:
            top = driver.execute_script("return document.getElementById('scene').getBoundingClientRect().top")
            touch = driver.execute_script("""
              const h = document.querySelector('.touchHint'), k = document.querySelector('.keyHint');
              return [getComputedStyle(h).display !== 'none', getComputedStyle(k).display !== 'none'];""")
            print(f"  phone: scene menu top {top:.0f} px; touch hint shown {touch[0]}, key hint {touch[1]}")
            if top > height:
                fail(f"the scene menu starts at {top:.0f} px, below the phone's first screen ({height})")
            if not touch[0] or touch[1]:
                fail("a touch screen shows the keyboard's hint, not the touch one")
    driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": False})
    driver.execute_cdp_cmd("Emulation.setEmitTouchEventsForMouse", {"enabled": False})
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": 1280, "height": 720, "deviceScaleFactor": 1, "mobile": False})
    driver.execute_script("window.dispatchEvent(new Event('resize'))")
    time.sleep(0.3)


def check_teacher(driver, page, source):
    """The scene's title shown; every label, field and button at least 16 px; F full screen, R reset;
    → steps 0.5 time units and keeps the scene; the address keeps t while playing."""
    from selenium.webdriver.common.action_chains import ActionChains
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    title = tomllib.loads((source / "scenes" / "fig09-matrix-unstable-x.toml").read_text())["scene"]["title"]
    shown = driver.execute_script("""
      const e = document.getElementById('sceneTitle'); const r = e.getBoundingClientRect();
      return [e.textContent, r.top >= 0 && r.bottom <= innerHeight && r.width > 0];""")
    print(f"scene title shown: {shown}")
    if shown != [title, True]:
        fail(f"the scene's title {title!r} is not shown at 1280×720: {shown}")
    small = driver.execute_script("""
      return [...document.querySelectorAll('label, input, select, button, legend, #hint span, #sceneDescription')]
        .filter((e) => e.offsetParent !== null && getComputedStyle(e).display !== 'none')
        .filter((e) => !(e.type === 'checkbox' || e.type === 'range'))  // no text to read
        .map((e) => [e.id || e.tagName, parseFloat(getComputedStyle(e).fontSize)])
        .filter(([, px]) => px < 16);""")
    if small:
        fail(f"text under 16 px: {small}")
    body = driver.find_element("tag name", "body")
    driver.execute_script("document.getElementById('scene').focus()")
    ActionChains(driver).send_keys("\ue014").perform()  # → with the scene menu focused
    time.sleep(0.3)
    state = driver.execute_script("return window.explorer.state()")
    print(f"  → with the menu focused: scene {state['scene']}, t = {state['t']}")
    if state["scene"] != "fig09-matrix-unstable-x" or not 0.499 <= state["t"] <= 0.52:
        fail(f"→ did not step 0.5 time units in the same scene: {state['scene']}, t = {state['t']}")
    ActionChains(driver).move_to_element(body).send_keys("f").perform()
    time.sleep(0.5)
    full = driver.execute_script("return document.fullscreenElement !== null")
    print(f"  F: document.fullscreenElement set: {full}")
    if not full:
        fail("F did not set document.fullscreenElement")
    driver.execute_script("document.exitFullscreen()")
    time.sleep(0.3)
    # At fig09's own speed, 15 time units a second: the address is rewritten every 60 ms at
    # most (browsers refuse more), 0.9 time units apart.
    driver.execute_script("""const s = document.getElementById('speed'); s.value = 15;
      s.dispatchEvent(new Event('change')); document.getElementById('play').click();""")
    worst = 0.0
    for _ in range(20):  # the address may be up to a rewrite's interval behind without a lead
        time.sleep(0.2)
        search, shown_t = driver.execute_script(
            "return [location.search, document.getElementById('time').textContent]")
        url_t = float(dict(p.split("=", 1) for p in search[1:].split("&")).get("t", "0"))
        t = float(shown_t.split("=")[1])
        worst = max(worst, abs(url_t - t))
    driver.find_element("id", "play").click()
    print(f"  playing at speed 15: the address's t at most {worst:.2f} from the time shown")
    if worst > 1 or t < 1:
        fail(f"the address does not keep t while playing: {worst:.2f} off (t = {t})")
    ActionChains(driver).move_to_element(body).send_keys("r").perform()
    time.sleep(0.3)
    state = driver.execute_script("return window.explorer.state()")
    if state["t"] != 0 or state["scene"] != "fig09-matrix-unstable-x":
        fail(f"R did not reset the run: t = {state['t']}, scene {state['scene']}")


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    out = binary / "test-output" / "explorer-classroom"
    out.mkdir(parents=True, exist_ok=True)
    shots = binary / "test-output" / "browser"
    shots.mkdir(parents=True, exist_ok=True)
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    run([bookspin, "explore", *sorted(str(p) for p in (source / "scenes").glob("*.toml")), "-o", str(out)])
    page = (out / "explorer.html").resolve().as_uri()
    with open_browser(chromium, driver_path, **EXPLORER_WINDOW) as driver:
        check_exact_scene(driver, page)
        check_readout(driver, page)
        check_compare_labels(driver, page)
        check_sphere(driver, page)
        check_canvases(driver, page, shots)
        check_teacher(driver, page, source)
        errors = console_errors(driver)
        if errors:
            fail(f"console errors: {errors}")
    print("OK")


if __name__ == "__main__":
    sys.exit(main())
