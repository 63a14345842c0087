#!/usr/bin/env python3
"""The explorer page's JavaScript engines and its bounded work (web/src/engines/, web/src/pacing.js,
docs/explorer.md) in headless Chromium, the page opened from disk with the network off.

Builds the page's program with web/build.sh BINARY_DIR, writes the page of every scene twice with
`bookspin explore`, with and without `--engines`, and checks:
  - without --engines the page holds no engine (no window.BOOKSPIN_ENGINES, no model of theirs
    in the selects) and is smaller than the page with them by at least the engines' bundle;
  - each JavaScript engine in the page (cannon-es, Rapier, Jolt without and with
    mApplyGyroscopicForce, Havok), two at a time in compare mode, gives the same body-frame ω at t = 20
    as the same npm package run under node on the same body and step (tests/browser/
    engines_node.mjs, written apart from the page's adapters, the book's principal moments in
    closed form m(b² + c²)/12…), to 1e-12 relative; each run draws its trail and shows its flips;
    once more at dt = 1/120 (not Rapier's default 1/60) from a jiggled start, node starting from
    the page's own start ω0', so an engine stepped at its default step or started without the
    jiggle fails;
  - links with extreme values keep the tab responsive: t = 1e9, dt = 1e-9 and speed = 1e9 are
    refused with a visible notice; a long catch-up (t = 1e5, six million steps) goes on in pieces
    with its progress shown and stops on Reset; playing faster than the machine steps says so;
    every script run in the page meanwhile answers within 2 s.
Screenshots go to BINARY_DIR/test-output/browser/explorer-engines-*.png.

Usage: explorer_engines_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten, node or npm is missing,
except under CI=true, where that is a failure (browser.py).
"""
import json
import time

from browser import console_errors, fail, find_browser, open_browser, require, run, test_arguments
from explorer_test import body_label_reach, load as load_page

WINDOW = dict(size=(1280, 720), webgl=True, offline=True, exact_viewport=True)
TOL = 1e-12
ENGINES = ("cannon-es", "rapier", "jolt", "jolt-gyroscopic", "havok")
# The book of scenes/exact-unstable-x.toml near its intermediate axis x, no jiggle, so that node
# starts from the same ω0: the page's ω0 is L0/I with L0 = I·w (docs/physics.md §5).
BOOK = dict(size=(1.878, 2.9085, 0.5), mass=8.0)
W0 = (5.0, 0.01, 0.02)
T_END = 20.0
RESPONSIVE_S = 2.0


def load(driver, url):
    """explorer_test.load with more time: the engines' WebAssembly compiles as the page opens."""
    load_page(driver, url, timeout=60)


def answered(driver, script, what):
    """Runs `script` in the page; fail() when it takes longer than RESPONSIVE_S."""
    t0 = time.monotonic()
    result = driver.execute_script(script)
    took = time.monotonic() - t0
    if took > RESPONSIVE_S:
        fail(f"{what}: the page took {took:.1f} s to answer a script (limit {RESPONSIVE_S} s)")
    return result


def node_omega(node, modules, tests, engine, dt, steps, omega0=None):
    """ω (body frame) after `steps` of `dt` under node from body-frame `omega0` (default W0)."""
    a, b, c = BOOK["size"]
    m = BOOK["mass"]
    moments = [m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12]
    start = omega0 or [(i * w) / i for i, w in zip(moments, W0)]
    spec = dict(mass=m, moments=moments, size=list(BOOK["size"]), omega0=start, dt=dt,
                steps=steps)
    out = run([node, str(tests / "engines_node.mjs"), str(modules), engine, json.dumps(spec)])
    return json.loads(out.strip().splitlines()[-1])["omega_body"]


def check_size(plain, with_engines, bundle):
    text = plain.read_text()
    if ("BOOKSPIN_ENGINES=" in text or "BOOKSPIN_ENGINES_PACKED=" in text
            or "<!--BOOKSPIN_ENGINES-->" in text):
        fail("the page written without --engines carries the engines (or their marker)")
    # The page a student opens from disk stays small: with every scene, at most 4.5 MB without
    # the engines and 8 MB with them (2.65 and 6.51 MB measured 2026-11-25, the physics'
    # WebAssembly and the engines packed: web/src/packed.js).
    if plain.stat().st_size > 4.5e6:
        fail(f"the page without the engines is {plain.stat().st_size} bytes, over 4.5 MB")
    if with_engines.stat().st_size > 8e6:
        fail(f"the page with the engines is {with_engines.stat().st_size} bytes, over 8 MB")
    grown = with_engines.stat().st_size - plain.stat().st_size
    if grown < bundle.stat().st_size:
        fail(f"the page with --engines is only {grown} bytes larger than without; the engines' "
             f"bundle is {bundle.stat().st_size}")
    print(f"pages: {plain.stat().st_size} bytes without the engines, "
          f"{with_engines.stat().st_size} with them")


# Each pair of engines in compare mode and its link's step and start. The last pair runs at
# dt = 1/120, not Rapier's default 1/60, with a jiggled start: node starts from the page's own
# start ω0' (window.explorer.startOmegas, the jiggle in it), so an engine stepped at its own
# default step or started without the jiggle does not match.
PAIRS = (("cannon-es", "rapier", "&jiggle=0"), ("jolt", "jolt-gyroscopic", "&jiggle=0"),
         ("rapier", "jolt-gyroscopic", "&jiggle=0.001&seed=7&dt=0.008333333333333333"),
         ("havok", "jolt", "&jiggle=0.001&seed=7&dt=0.008333333333333333"))


def check_engines(driver, page, node, modules, tests, shots):
    for first, second, start in PAIRS:
        w = ",".join(map(repr, W0))
        load(driver, f"{page}?scene=exact-unstable-x&axis=custom&w={w}{start}&model={first}"
                     f"&compare=1&model2={second}")
        options = driver.execute_script(
            "return [...document.getElementById('model2').options].map((o) => o.value)")
        if not set(ENGINES) <= set(options):
            fail(f"the compare select does not offer every engine: {options}")
        dt = driver.execute_script("return window.explorer.state().dt")
        steps = round(T_END / dt)
        got = driver.execute_script(f"return window.explorer.omegaAt({T_END!r})")
        starts = driver.execute_script("return window.explorer.startOmegas()")
        if starts[0] != starts[1]:
            fail(f"the two runs of {first} and {second} start apart: {starts}")
        jiggled = max(abs(x - y) for x, y in zip(starts[0], W0)) > 1e-6
        if jiggled != ("jiggle=0&" not in start + "&"):
            fail(f"{first} and {second} start at {starts[0]}: the link's {start} not applied")
        for engine, omega, omega0 in zip((first, second), got, starts):
            expected = node_omega(node, modules, tests, engine, dt, steps, omega0)
            err = max(abs(x - y) for x, y in zip(omega, expected)) / max(abs(x) for x in expected)
            print(f"{engine}: page ω({T_END}) = {omega}, node {expected}: {err:.1e} relative")
            if not err <= TOL:
                fail(f"{engine}: ω at t = {T_END} in the page {omega} is not node's {expected} "
                     f"({err:.2e} relative, limit {TOL})")
        trails = driver.execute_script("return window.explorer.trails()")
        if len(trails) != 2 or min(t["points"] for t in trails) < 100:
            fail(f"compare mode of {first} and {second} did not draw both trails: {trails}")
        status = driver.find_element("id", "status").text
        flips = driver.execute_script("return window.explorer.flips()")
        if status.count("flips ") != 2 or any(f"flips {n}" not in status for n in flips):
            fail(f"the readout does not show both runs' flips {flips}: {status!r}")
        # Legible: each book labelled by its method within 50 px of it, the engines without
        # the gyroscopic term said to be; cannon-es's energy (round-off, 1e-16) drawn flat,
        # Rapier's rise (9e-4 of E0 by t = 20) drawn as one.
        reach = body_label_reach(driver)
        print(f"body labels and the drawn pixels within 50 px: {reach}")
        if len(reach) != 2 or any(n < 200 for _, n in reach):
            fail(f"a book of {first} and {second} has no label within 50 px: {reach}")
        labels = [label for label, _ in reach]
        for label in labels:
            without = label.startswith(("cannon-es", "Jolt 1.1", "Havok")) and "mApplyGyroscopicForce" not in label
            if without != ("no gyroscopic term" in label):
                fail(f"the label {label!r} says the gyroscopic term wrongly")
        spans = {s["run"]: s["px"] for s in driver.execute_script("return window.explorer.plotSpans()")
                 if s["panel"].startswith("energy drift")}
        print(f"energy lines drawn (px tall): {spans}")
        for label, px in spans.items():
            if label.startswith("cannon-es") and px > 1:
                fail(f"cannon-es's energy, constant to round-off, is drawn {px:.1f} px tall")
            if label.startswith("Rapier") and px < 10:
                fail(f"Rapier's energy rise is drawn only {px:.1f} px tall")
        driver.save_screenshot(str(shots / f"explorer-engines-{first}-{second}.png"))
        errors = console_errors(driver)
        if errors:
            fail(f"console errors with {first} and {second}: {errors}")


def check_flat_energy(driver, page, shots):
    """cannon-es alone: its energy, constant to round-off (1e-16 of E0), drawn as a flat line,
    not stretched to fill its panel."""
    w = ",".join(map(repr, W0))
    load(driver, f"{page}?scene=exact-unstable-x&axis=custom&w={w}&jiggle=0&model=cannon-es")
    driver.execute_script(f"window.explorer.omegaAt({T_END!r})")
    time.sleep(0.3)
    spans = [s for s in driver.execute_script("return window.explorer.plotSpans()")
             if s["panel"].startswith("energy drift")]
    print(f"cannon-es alone: energy line drawn {spans[0]['px'] if spans else None} px tall")
    driver.save_screenshot(str(shots / "explorer-engines-cannon-es.png"))
    if len(spans) != 1 or spans[0]["px"] > 1:
        fail(f"cannon-es's energy, constant to round-off, is not drawn flat: {spans}")
    # An engine switch hands the page back within 1 s (timed in the page around the handler).
    for model in ("rapier", "jolt-gyroscopic", "exact"):
        ms = driver.execute_script(f"""
          const t0 = performance.now(), m = document.getElementById('model');
          m.value = '{model}'; m.dispatchEvent(new Event('change'));
          return performance.now() - t0;""")
        print(f"switch to {model}: control back after {ms:.0f} ms")
        if ms > 1000:
            fail(f"switching to {model} held the page {ms:.0f} ms, more than 1000")


def check_extreme_links(driver, page, shots):
    notice = "return document.getElementById('notice').textContent"
    for query, key in (("t=1e9", "t = 1000000000 refused"), ("dt=1e-9", "dt = 1e-9 refused"),
                       ("speed=1e9", "speed = 1000000000 refused"),
                       ("model=particle&k=-10", "k = -10 refused"),
                       ("compare=1&model2=particle&k=-1", "k = -1 refused"),
                       ("axis=intermediate&rate=1e308", "rate = 1e+308 refused"),
                       ("axis=custom&w=1e308,0,0", "w = 1e+308,0,0 refused"),
                       ("jiggle=-1", "jiggle = -1 refused"),
                       ("t=1e308", "t = 1e+308 refused"),
                       ("model=exact&axis=custom&w=1e308,0,0", "w = 1e+308,0,0 refused")):
        load(driver, f"{page}?scene=fig09-matrix-unstable-x&{query}")
        text = answered(driver, notice, query)
        if key not in text:
            fail(f"?{query}: no visible refusal ({key!r}) but {text!r}")
        state = answered(driver, "return window.explorer.state()", query)
        if not (state["t"] == 0 and state["dt"] < 1 and state["speed"] <= 1e4 and state["k"] > 0
                and abs(state["rate"]) <= 1e6 and all(abs(x) <= 1e6 for x in state["w"])
                and state["jiggle"] >= 0):
            fail(f"?{query}: the refused value is still in the state: {state}")
        page_text = answered(driver, "return document.body.innerText", query)
        if "NaN" in page_text or "Infinity" in page_text:
            fail(f"?{query}: the page shows NaN or Infinity: {page_text[:400]!r}")
        print(f"?{query}: {text}")
    # A long but allowed catch-up: six million steps, in pieces, with its progress.
    load(driver, f"{page}?scene=fig09-matrix-unstable-x&t=100000")
    first = answered(driver, "return window.explorer.state().t", "t=1e5")
    time.sleep(1.0)
    later = answered(driver, "return [window.explorer.state().t, window.explorer.settled()]", "t=1e5")
    text = answered(driver, notice, "t=1e5")
    driver.save_screenshot(str(shots / "explorer-engines-catch-up.png"))
    if later[1] or not (0 <= first < later[0] < 100000) or "simulating to t = 100000" not in text:
        fail(f"?t=1e5: no catch-up in pieces with its progress: t {first} then {later}, {text!r}")
    print(f"?t=1e5: t = {first} at ready, {later[0]} a second later: {text}")
    driver.find_element("id", "reset").click()
    after = answered(driver, "return [window.explorer.state().t, window.explorer.settled()]", "reset")
    if after != [0, True] or answered(driver, notice, "reset"):
        fail(f"Reset did not stop the catch-up: {after}")
    # Playing faster than the machine steps: a frame's budget, and a notice.
    load(driver, f"{page}?scene=fig09-matrix-unstable-x&dt=1e-6&speed=10000")
    answered(driver, "window.explorer.setPlaying(true)", "play")
    time.sleep(1.5)
    text = answered(driver, notice, "play")
    frames = answered(driver, "return window.explorer.framesDrawn()", "play")
    if "playing slower" not in text:
        fail(f"playing 1e10 steps a second: no notice that it plays slower: {text!r}")
    print(f"dt=1e-6 speed=1e4: {text} ({frames} frames drawn)")


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    node = require("node")[0]
    out = binary / "test-output" / "explorer-engines"
    shots = binary / "test-output" / "browser"
    shots.mkdir(parents=True, exist_ok=True)
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    scenes = sorted(str(p) for p in (source / "scenes").glob("*.toml"))
    run([bookspin, "explore", *scenes, "-o", str(out / "plain")])
    run([bookspin, "explore", *scenes, "--engines", "-o", str(out / "engines")])
    check_size(out / "plain" / "explorer.html", out / "engines" / "explorer.html",
               binary / "web" / "explorer-engines.js")
    modules = source / "web" / "node_modules"
    with open_browser(chromium, driver_path, **WINDOW) as driver:
        check_engines(driver, (out / "engines" / "explorer.html").resolve().as_uri(), node,
                      modules, source / "tests" / "browser", shots)
        check_flat_energy(driver, (out / "engines" / "explorer.html").resolve().as_uri(), shots)
        check_extreme_links(driver, (out / "plain" / "explorer.html").resolve().as_uri(), shots)
    print("explorer engines: OK")


if __name__ == "__main__":
    main()
