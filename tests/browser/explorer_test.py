#!/usr/bin/env python3
"""The explorer page (web/, docs/explorer.md) in a real browser: headless Chromium driven by
Selenium, the page opened straight from disk (file://) with the network off.

Builds the page's program with web/build.sh BINARY_DIR, writes BINARY_DIR/test-output/explorer/
explorer.html with `bookspin explore` (every scene, and a mesh scene of its own), and checks:
  - the page loads with no console error and draws the body: the book's colours (its
    dark blue cover, its cream pages) fill part of the 3D view, the background the rest;
  - layout: at 1280×720 (a projector) every control a run needs, Play and the time slider
    among them, lies inside the viewport; at 760×1000 (a tablet upright) the 3D view is at
    least 700 px wide and 45% of the height; the exact model shows no integrator, damping, k
    or lattice cells, and each model's integrator list is its own;
  - a click on the momentum sphere at a known pixel sets ω0 to I⁻¹·|L|·u, u the body-frame
    point under it (the sphere's rotation inverted, the book's moments in closed form), to
    1e-6 in direction, at the start's |L|; a touch tap does the same and a touch drag turns
    the sphere without picking; the URL restores the picked ω0;
  - the page's flips (analysis::FlipDetector in WebAssembly) equal `bookspin sweep --measure
    first_flip,flip_period`'s for three scenes: the first flip and the period to 1e-6, and the
    count that those imply over the run;
  - ω at t = 100 in the page equals `bookspin simulate` of the same settings to 1e-10
    relative, for the rigid models (matrix and quaternion, several integrators, with and
    without normalization) and the exact model, the book, the T-handle and a mesh body (the
    long box, its surface and moments carried by the page from bookspin), and under air drag
    set by the link (drag, dragRate: each law, the exact and both rigid models);
  - the mesh body is drawn (its grey faces where the body is);
  - wiring: the T-handle scene with the spin axis and rate set through the page's controls
    (driven through the time slider; about the intermediate axis it flips), ω at t = 300
    equal to `bookspin simulate` with that spin axis and rate;
  - compare mode (its checkbox, the second method through its selects): each run's ω equals
    `bookspin simulate` of its own method, and both trails are drawn on the momentum sphere;
  - the page's URL, with every control set away from the scene's value, opened anew, restores
    the same state and the same ω;
  - the gallery written beside the page links every entry to the explorer on its own scene,
    and four of those links (a book figure, the T-handle, a comparison, the mesh scene) open
    it on that scene without an error.
Screenshots go to BINARY_DIR/test-output/browser/explorer-*.png.

Usage: explorer_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import json
import sys
import time
from pathlib import Path

from browser import (console_errors, fail, find_browser, open_browser, require, run, test_arguments,
                     wait_for)

# The page's window, for this test, scripts/explorer-shots.py and bench/explorer_bench.py:
# WebGL on the CPU, the network off (a proxy on a closed port), the viewport exactly the
# projector's 1280×720 (the window size includes no chrome in headless mode, but fix it to
# be sure).
EXPLORER_WINDOW = dict(size=(1280, 720), webgl=True, offline=True, exact_viewport=True)

TOL = 1e-10

MESH_SCENE = """[scene]
title = "Long box (mesh) about its {axis} axis"
[body]
shape = "mesh"
mesh = {mesh}
mass = 2.0
[initial]
spin_axis = "{axis}"
spin_rate = 2.0
jiggle = 0.001
seed = 5
"""


def load(driver, url=None, timeout=30):
    """Opens url (None: the page the driver is on, say after a click) and waits until the
    explorer is ready; fail() after `timeout` seconds."""
    if url is not None:
        driver.get(url)
    for _ in range(10 * timeout):
        if driver.execute_script("return !!(window.explorer && window.explorer.ready)"):
            return
        time.sleep(0.1)
    fail(f"the page never became ready: {url or driver.current_url}\n{driver.get_log('browser')}")


def slide_to(driver, t):
    """Drags the time slider to t and waits until the page has caught up to it (it steps in
    pieces, one per animation frame: web/src/pacing.js)."""
    driver.execute_script(f"""
      const s = document.getElementById('slider');
      s.max = {t!r}; s.value = {t!r}; s.dispatchEvent(new Event('input'));""")
    wait_for(driver, "return window.explorer.settled()", bool, timeout=240)


def simulate_omega(bookspin, scene, settings, t=100.0, dt=0.01):
    """ω (body) at time t from `bookspin simulate`: steps of dt, one row at t = 0 and one at t."""
    sets = []
    for key, value in settings.items():
        sets += ["--set", f"{key}={value}"]
    steps = round(t / dt)
    out = run([bookspin, "simulate", scene, *sets, "--set", f"time.dt={dt!r}",
               "--set", f"time.steps_per_frame={steps}", "--set", "time.frames=2"])
    rows = [r for r in out.strip().splitlines() if r and r[0].isdigit()]
    last = rows[-1].split(",")
    if abs(float(last[1]) - t) > 1e-9 * max(1.0, t):
        fail(f"bookspin simulate ended at t = {last[1]}, not {t}")
    return [float(x) for x in last[2:5]]


def relative(got, expected):
    return max(abs(a - b) for a, b in zip(got, expected)) / max(abs(x) for x in expected)


# JavaScript: `d`, the RGBA bytes of the 3D view (the WebGL canvas drawn into a 2D one).
VIEW_PIXELS = """
      const v = document.getElementById('view');
      const c = document.createElement('canvas'); c.width = v.width; c.height = v.height;
      const g = c.getContext('2d'); g.drawImage(v, 0, 0);
      const d = g.getImageData(0, 0, c.width, c.height).data;
"""


def view_pixels(driver):
    """Counts in the 3D view: background, dark blue (cover), cream (pages), other."""
    return driver.execute_script(VIEW_PIXELS + """
      let bg = 0, blue = 0, cream = 0, other = 0;
      for (let i = 0; i < d.length; i += 4) {
        const r = d[i], gg = d[i+1], b = d[i+2];
        if (Math.abs(r - 0x20) < 6 && Math.abs(gg - 0x24) < 6 && Math.abs(b - 0x2c) < 6) bg++;
        else if (b > r + 12 && b >= gg && b > 35) blue++;
        else if (r > 150 && gg > 140 && b > 110 && r >= b) cream++;
        else other++;
      }
      return {bg, blue, cream, other, total: d.length / 4};
    """)


def body_label_reach(driver, reach=50):
    """For each body label of compare mode (HTML over the 3D view): its text and the count of
    the view's drawn (not background) pixels within `reach` CSS px of its box."""
    return driver.execute_script(VIEW_PIXELS + f"""
      const box = v.getBoundingClientRect(), sx = v.width / box.width, sy = v.height / box.height;
      return [...document.querySelectorAll('.bodyLabel')].filter((l) => !l.hidden).map((l) => {{
        const r = l.getBoundingClientRect();
        const x0 = Math.max(0, Math.floor((r.left - box.left - {reach}) * sx));
        const x1 = Math.min(v.width, Math.ceil((r.right - box.left + {reach}) * sx));
        const y0 = Math.max(0, Math.floor((r.top - box.top - {reach}) * sy));
        const y1 = Math.min(v.height, Math.ceil((r.bottom - box.top + {reach}) * sy));
        let n = 0;
        for (let y = y0; y < y1; ++y) for (let x = x0; x < x1; ++x) {{
          const i = 4 * (y * v.width + x);
          if (Math.abs(d[i] - 0x20) + Math.abs(d[i + 1] - 0x24) + Math.abs(d[i + 2] - 0x2c) > 30) n++;
        }}
        return [l.textContent, n];
      }});""")


def grey_pixels(driver):
    """Pixels of the 3D view in the lit greys of a mesh's default colour (not background)."""
    return driver.execute_script(VIEW_PIXELS + """
      let n = 0;
      for (let i = 0; i < d.length; i += 4) {
        const r = d[i], gg = d[i+1], b = d[i+2];
        if (Math.max(r, gg, b) - Math.min(r, gg, b) < 12 && r > 70) n++;
      }
      return n;
    """)


def sphere_colours(driver):
    return driver.execute_script("""
      const v = document.getElementById('sphere');
      const d = v.getContext('2d').getImageData(0, 0, v.width, v.height).data;
      const near = (i, r, g, b) => Math.abs(d[i]-r) + Math.abs(d[i+1]-g) + Math.abs(d[i+2]-b) < 30;
      let first = 0, second = 0;
      for (let i = 0; i < d.length; i += 4) {
        if (near(i, 0xe8, 0xb0, 0x0b)) first++;
        if (near(i, 0x35, 0xc0, 0xf0)) second++;
      }
      return [first, second];
    """)


def set_viewport(driver, width, height):
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
    driver.execute_script("window.dispatchEvent(new Event('resize'))")
    time.sleep(0.3)


def rect(driver, element_id):
    return driver.execute_script(f"""
      const e = document.getElementById('{element_id}');
      const r = e.getBoundingClientRect();
      return {{left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width,
               height: r.height, shown: e.offsetParent !== null}};""")


# The controls a run needs (issue: scene, body, model, integrator, dt, spin, Play, Step,
# Reset, speed, the time slider); the spin is its axis and either its rate or ω0's components.
RUN_CONTROLS = ("scene", "body", "model", "integrator", "dt", "axis", "play", "stepOnce",
                "reset", "speed", "slider")
SPIN_RATE, SPIN_OMEGA = ("rate",), ("wx", "wy", "wz")


def check_layout(driver, shots):
    """At 1280×720 every control of a run inside the viewport; at 760×1000 the view ≥ 700 px
    wide and ≥ 45% of the height; what the exact model ignores hidden."""
    spin = SPIN_RATE if rect(driver, "rate")["shown"] else SPIN_OMEGA
    for element_id in RUN_CONTROLS + spin:
        r = rect(driver, element_id)
        if not (r["shown"] and r["left"] >= 0 and r["top"] >= 0 and r["right"] <= 1280
                and r["bottom"] <= 720 and r["width"] > 0 and r["height"] > 0):
            fail(f"#{element_id} is not inside the 1280×720 viewport: {r}")
    driver.save_screenshot(str(shots / "explorer-1280x720.png"))
    set_viewport(driver, 760, 1000)
    view = rect(driver, "view")
    canvas = driver.execute_script("const v = document.getElementById('view'); return [v.width, v.height];")
    driver.save_screenshot(str(shots / "explorer-760x1000.png"))
    print(f"760×1000: view {view}, canvas {canvas}")
    if view["width"] < 700 or canvas[0] < 700 or view["height"] < 450:
        fail(f"at 760×1000 the 3D view is not ≥ 700 px wide and ≥ 45% high: {view}, canvas {canvas}")
    set_viewport(driver, 1280, 720)


def check_model_controls(driver, page):
    load(driver, page + "?scene=exact-unstable-x")
    hidden = driver.execute_script("""
      return ['integratorRow', 'normalizeRow', 'dampingRow', 'kRow', 'cellsRow']
        .filter((id) => document.getElementById(id).offsetParent === null);""")
    if sorted(hidden) != sorted(["integratorRow", "normalizeRow", "dampingRow", "kRow", "cellsRow"]):
        fail(f"the exact model leaves controls it does not use shown: hidden are only {hidden}")
    from selenium.webdriver.support.ui import Select
    expected = {"particle": ["euler", "symplectic-euler", "velocity-verlet"],
                "rigid-quaternion": ["euler", "rk4", "implicit-midpoint", "splitting", "splitting4",
                                     "rescaled-euler"]}
    for model, integrators in expected.items():
        Select(driver.find_element("id", "model")).select_by_value(model)
        offered = driver.execute_script(
            "return [...document.getElementById('integrator').options].map((o) => o.value)")
        if offered != integrators:
            fail(f"the {model} model offers the integrators {offered}, not {integrators}")
        k_shown = driver.execute_script("return document.getElementById('kRow').offsetParent !== null")
        if k_shown != (model == "particle"):
            fail(f"the {model} model {'hides' if model == 'particle' else 'shows'} the spring constant k")


# The book of the fig09 scene (size a, b, c and mass m): principal moments about x, y, z in
# closed form, m(b² + c²)/12, m(a² + c²)/12, m(a² + b²)/12 (docs/physics.md §1).
BOOK_SIZE, BOOK_MASS = (1.878, 2.9085, 0.5), 8.0
BOOK_MOMENTS = tuple(BOOK_MASS * (BOOK_SIZE[(d + 1) % 3] ** 2 + BOOK_SIZE[(d + 2) % 3] ** 2) / 12
                     for d in range(3))


def solve3(m, p):
    """x with m·x = p (Cramer's rule), m 3×3 row-major."""
    def det(a):
        return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
                - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    d = det(m)
    out = []
    for c in range(3):
        mc = [[p[r] if k == c else m[r][k] for k in range(3)] for r in range(3)]
        out.append(det(mc) / d)
    return out


def pick_expectation(driver, px, py):
    """ω0 that a pick at canvas pixel (px, py) should give: the view point (X, Y, √(1−X²−Y²)),
    X = (px − W/2)/R, Y = (0.53·H − py)/R, R = 0.36·min(W, H) (the disc a little below the
    middle, under the sphere's title), back through the sphere's rotation M (body → view) to the
    body frame, u = M⁻¹·p, then ω = |L|·u/|u| / I componentwise."""
    w, h = driver.execute_script("const c = document.getElementById('sphere'); return [c.width, c.height];")
    radius = 0.36 * min(w, h)
    x, y = (px - w / 2) / radius, (0.53 * h - py) / radius
    view_point = [x, y, (1 - x * x - y * y) ** 0.5]
    u = solve3(driver.execute_script("return window.explorer.sphereRotation()"), view_point)
    norm = sum(c * c for c in u) ** 0.5
    return [c / norm for c in u]


def direction_error(a, b):
    na, nb = sum(c * c for c in a) ** 0.5, sum(c * c for c in b) ** 0.5
    return max(abs(x / na - y / nb) for x, y in zip(a, b))


def momentum(w):
    return sum((i * c) ** 2 for i, c in zip(BOOK_MOMENTS, w)) ** 0.5


def click_sphere(driver, px, py, touch=False):
    """A click (or a touch tap) at canvas pixel (px, py) of the sphere, as the browser's input."""
    r = rect(driver, "sphere")
    w = driver.execute_script("return document.getElementById('sphere').width")
    scale = r["width"] / w
    x, y = r["left"] + px * scale, r["top"] + py * scale
    if touch:
        for kind, points in (("touchStart", [{"x": x, "y": y}]), ("touchEnd", [])):
            driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": kind, "touchPoints": points})
    else:
        for kind in ("mousePressed", "mouseReleased"):
            driver.execute_cdp_cmd("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y,
                                                                "button": "left", "clickCount": 1})
    time.sleep(0.2)


def check_sphere_pick(driver, page):
    """A click, a tap and a touch drag on the sphere; the URL restores the picked ω0."""
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    start = driver.execute_script("return window.explorer.state()")
    L0 = momentum(start["w"])
    for touch, (px, py) in ((False, (210, 133)), (True, (120, 200))):
        u = pick_expectation(driver, px, py)
        expected = [L0 * c / i for c, i in zip(u, BOOK_MOMENTS)]
        click_sphere(driver, px, py, touch)
        state = driver.execute_script("return window.explorer.state()")
        err = direction_error(state["w"], expected)
        print(f"sphere {'tap' if touch else 'click'} at ({px}, {py}): ω0 {state['w']}, expected "
              f"{expected}, direction error {err:.1e}, |L| {momentum(state['w'])} (start {L0})")
        if state["axis"] != "custom" or not err <= 1e-6:
            fail(f"the sphere pick at ({px}, {py}) set ω0 {state['w']} (axis {state['axis']}), "
                 f"not the direction of {expected}")
        if abs(momentum(state["w"]) / L0 - 1) > 1e-9:
            fail(f"the sphere pick changed |L|: {momentum(state['w'])}, not {L0}")
        # The fields show ω0 to 6 significant digits and carry it exactly (data-exact).
        shown = [float(driver.find_element("id", f).get_attribute("value")) for f in ("wx", "wy", "wz")]
        exact = [float(driver.find_element("id", f).get_attribute("data-exact")) for f in ("wx", "wy", "wz")]
        if exact != state["w"] or any(abs(a - b) > 5e-6 * abs(b) for a, b in zip(shown, state["w"])):
            fail(f"the ω0 fields show {shown} (exactly {exact}), not the picked {state['w']}")
    picked = state["w"]
    # A touch drag turns the sphere and picks nothing.
    before = driver.execute_script("return window.explorer.sphereRotation()")
    r = rect(driver, "sphere")
    x, y = r["left"] + 170, r["top"] + 160
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [{"x": x, "y": y}]})
    for k in range(1, 6):
        driver.execute_cdp_cmd("Input.dispatchTouchEvent",
                               {"type": "touchMove", "touchPoints": [{"x": x + 12 * k, "y": y + 5 * k}]})
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
    time.sleep(0.2)
    after = driver.execute_script("return window.explorer.sphereRotation()")
    if after == before or driver.execute_script("return window.explorer.state().w") != picked:
        fail(f"a touch drag on the sphere did not turn it alone: rotation {before} → {after}")
    url = driver.current_url
    if "w=" not in url:
        fail(f"the picked ω0 is not in the URL: {url}")
    load(driver, url)
    restored = driver.execute_script("return window.explorer.state()")
    if restored["w"] != picked or restored["axis"] != "custom":
        fail(f"the URL {url} restores ω0 {restored['w']}, not the picked {picked}")
    print(f"the URL restores the picked ω0: {url.split('?', 1)[1]}")


def sweep_flips(bookspin, scene, workdir):
    """first_flip and flip_period of `bookspin sweep` of the scene as it stands (a one-point
    grid: the seed at its own value)."""
    seed = next(line.split("=")[1].split("#")[0].strip() for line in Path(scene).read_text().splitlines()
                if line.startswith("seed"))
    run([bookspin, "sweep", scene, "--vary", f"initial.seed={seed}:{seed}:1",
         "--measure", "first_flip,flip_period", "-o", str(workdir)])
    csv = workdir / f"{Path(scene).stem}-sweep.csv"
    header, row = [line.split(",") for line in csv.read_text().strip().splitlines()[-2:]]
    values = dict(zip(header, row))
    return float(values["first_flip"]), float(values["flip_period"])


def check_flips_against_sweep(driver, page, bookspin, source, workdir):
    """The page's flip detector over each scene's whole run against bookspin sweep's."""
    for name in ("exact-unstable-x", "t-handle-dzhanibekov", "fig09-matrix-unstable-x"):
        scene = source / "scenes" / f"{name}.toml"
        first, period = sweep_flips(bookspin, str(scene), workdir)
        load(driver, page + f"?scene={name}")
        dt = driver.execute_script("return window.explorer.state().dt")
        text = scene.read_text()
        frames = int(text.split("frames = ")[1].split()[0])
        steps = int(text.split("steps_per_frame = ")[1].split()[0])
        t_end = (frames - 1) * steps * dt
        driver.execute_script(f"window.explorer.omegaAt({t_end!r})")
        got = driver.execute_script("return window.explorer.flipMeasures()")[0]
        # Flips come every `period` from `first`: those within the run.
        count = 1 + int((t_end - first) // period)
        print(f"{name}: page flips {got}, sweep first {first} period {period} → {count} flips "
              f"by t = {t_end}")
        if got["count"] != count or abs(got["first"] / first - 1) > 1e-6 or abs(got["period"] / period - 1) > 1e-6:
            fail(f"{name}: the page's flips {got} are not bookspin sweep's (first {first}, "
                 f"period {period}, {count} flips by t = {t_end})")



def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")

    out = binary / "test-output" / "explorer"
    shots = binary / "test-output" / "browser"
    shots.mkdir(parents=True, exist_ok=True)
    out.mkdir(parents=True, exist_ok=True)
    # Mesh bodies of the test's own: the long box about its intermediate and its largest axis.
    mesh_scenes = {}
    for axis in ("intermediate", "largest"):
        mesh_scenes[axis] = out / f"mesh-{axis}.toml"
        mesh_scenes[axis].write_text(MESH_SCENE.format(
            axis=axis, mesh=json.dumps(str(source / "scenes" / "long-box.obj"))))
    mesh_scene = mesh_scenes["intermediate"]
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    run([bookspin, "explore", *sorted(str(p) for p in (source / "scenes").glob("*.toml")),
         *map(str, mesh_scenes.values()), "-o", str(out)])
    page = (out / "explorer.html").resolve().as_uri()
    book_scene = str(source / "scenes" / "fig09-matrix-unstable-x.toml")
    t_handle = str(source / "scenes" / "t-handle-dzhanibekov.toml")

    with open_browser(chromium, driver_path, **EXPLORER_WINDOW) as driver:
        # 1. Opens from disk, no console error, draws the book.
        load(driver, page + "?scene=fig09-matrix-unstable-x")
        time.sleep(1.0)
        errors = console_errors(driver)
        if errors:
            fail(f"console errors on load: {errors}")
        px = view_pixels(driver)
        driver.save_screenshot(str(shots / "explorer-book.png"))
        if px["bg"] < 0.5 * px["total"]:
            fail(f"the view is not mostly background: {px}")
        if px["blue"] + px["cream"] < 0.01 * px["total"] or px["blue"] == 0 or px["cream"] == 0:
            fail(f"the book's colours (blue cover, cream pages) are not drawn: {px}")
        print(f"view pixels: {px}")

        # 1b. Layout at a projector's 1280×720 and a tablet's 760×1000; the model's controls.
        check_layout(driver, shots)
        check_model_controls(driver, page)

        # 1c. Picking the start on the sphere; 1d. flips against bookspin sweep.
        check_sphere_pick(driver, page)
        check_flips_against_sweep(driver, page, bookspin, source, out)

        # 2. ω at t = 100 against bookspin simulate.
        cases = [
            (book_scene, {"model.kind": '"rigid-matrix"', "model.integrator": '"euler"', "model.normalize": "true"}),
            (book_scene, {"model.kind": '"rigid-matrix"', "model.integrator": '"rk4"', "model.normalize": "false"}),
            (book_scene, {"model.kind": '"rigid-matrix"', "model.integrator": '"implicit-midpoint"', "model.normalize": "false"}),
            (book_scene, {"model.kind": '"rigid-quaternion"', "model.integrator": '"euler"', "model.normalize": "true"}),
            (book_scene, {"model.kind": '"rigid-quaternion"', "model.integrator": '"splitting"', "model.normalize": "false"}),
            (book_scene, {"model.kind": '"rigid-quaternion"', "model.integrator": '"splitting4"', "model.normalize": "true"}),
            (book_scene, {"model.kind": '"exact"'}),
            (t_handle, {"model.kind": '"exact"'}),
            (t_handle, {"model.kind": '"rigid-quaternion"', "model.integrator": '"rk4"', "model.normalize": "true"}),
            # The mesh: the exact motion through the flips; the integrators about the stable
            # largest axis. Through 100 time units of flips of the long box, a one-ulp change
            # of the jiggle moves RK4's ω(100) by 8e-9 relative (measured with bookspin
            # simulate): there the math libraries' last bits alone exceed 1e-10.
            (str(mesh_scene), {"model.kind": '"exact"'}),
            (str(mesh_scenes["largest"]), {"model.kind": '"exact"'}),
            (str(mesh_scenes["largest"]), {"model.kind": '"rigid-quaternion"', "model.integrator": '"rk4"', "model.normalize": "true"}),
            (str(mesh_scenes["largest"]), {"model.kind": '"rigid-matrix"', "model.integrator": '"implicit-midpoint"', "model.normalize": "false"}),
            # Air drag (docs/physics.md §21) through the link: the damped closed form and the
            # rigid models' Strang-split drag, each law (ω(100) falls to e^-1 or 1/3 of ω0).
            (book_scene, {"model.kind": '"exact"', "model.drag": '"linear"', "model.drag_rate": "0.01"}),
            (book_scene, {"model.kind": '"rigid-quaternion"', "model.integrator": '"rk4"', "model.normalize": "true",
                          "model.drag": '"quadratic"', "model.drag_rate": "0.02"}),
            (book_scene, {"model.kind": '"rigid-matrix"', "model.integrator": '"splitting"', "model.normalize": "false",
                          "model.drag": '"linear"', "model.drag_rate": "0.01"}),
        ]
        worst = 0.0
        for scene, settings in cases:
            expected = simulate_omega(bookspin, scene, settings)
            q = {"scene": Path(scene).stem, "dt": "0.01",
                 "model": settings["model.kind"].strip('"'),
                 "integrator": settings.get("model.integrator", '"euler"').strip('"'),
                 "normalize": "1" if settings.get("model.normalize") == "true" else "0"}
            if "model.drag" in settings:
                q.update(drag=settings["model.drag"].strip('"'), dragRate=settings["model.drag_rate"])
            url = page + "?" + "&".join(f"{k}={v}" for k, v in q.items())
            load(driver, url)
            got = driver.execute_script("return window.explorer.omegaAt(100)")[0]
            rel = relative(got, expected)
            worst = max(worst, rel)
            print(f"{Path(scene).stem} {settings}: page {got} simulate {expected} rel {rel:.2e}")
            if not rel <= TOL:
                fail(f"ω at t = 100 differs by {rel:.3e} relative (> {TOL}) for {scene} {settings}: "
                     f"page {got}, bookspin simulate {expected}")
        print(f"ω agreement: worst {worst:.2e} relative over {len(cases)} cases")

        # 2b. The mesh body is drawn: the long box's default grey faces in the view.
        load(driver, page + "?scene=mesh-intermediate")
        time.sleep(0.5)
        body = driver.execute_script("return window.explorer.state().body")
        grey = grey_pixels(driver)
        driver.save_screenshot(str(shots / "explorer-mesh.png"))
        print(f"mesh scene: body {body}, grey pixels {grey}")
        if body != "mesh":
            fail(f"the mesh scene opened with body {body!r}, not its mesh")
        if grey < 0.01 * px["total"]:
            fail(f"the mesh body is not drawn: {grey} grey pixels")

        # 3. Wiring through the controls: largest axis, no flip; intermediate, flips; and ω at
        #    t = 300 is bookspin simulate's for that spin axis and rate (the scene spins at 2
        #    about the intermediate axis: the page must take both from the controls).
        from selenium.webdriver.support.ui import Select
        load(driver, page + "?scene=t-handle-dzhanibekov")
        flips = {}
        for axis in ("largest", "intermediate"):
            Select(driver.find_element("id", "axis")).select_by_value(axis)
            driver.find_element("id", "rate").clear()
            driver.find_element("id", "rate").send_keys("1.5\n")
            slide_to(driver, 300)
            state = driver.execute_script("return window.explorer.state()")
            if state["axis"] != axis or state["rate"] != 1.5 or abs(state["t"] - 300) > 1e-6:
                fail(f"the controls did not set axis {axis}, rate 1.5 and t = 300: {state}")
            flips[axis] = driver.execute_script("return window.explorer.flips()")[0]
            text = driver.find_element("id", "status").text
            if f"flips {flips[axis]}" not in text:
                fail(f"the readout does not show the flips: {text!r}")
            driver.save_screenshot(str(shots / f"explorer-t-handle-{axis}.png"))
            got = driver.execute_script("return window.explorer.omegaAt(300)")[0]
            expected = simulate_omega(bookspin, t_handle, {"initial.spin_axis": f'"{axis}"',
                                                           "initial.spin_rate": "1.5"},
                                      t=300.0, dt=state["dt"])
            rel = relative(got, expected)
            print(f"t-handle about the {axis} axis at 1.5: page {got} simulate {expected} rel {rel:.2e}")
            if not rel <= TOL:
                fail(f"ω at t = 300 spun about the {axis} axis through the controls differs by "
                     f"{rel:.3e} relative from bookspin simulate: page {got}, simulate {expected}")
        print(f"flips in 300 time units: {flips}")
        if flips["intermediate"] < 1:
            fail("spin about the intermediate axis did not flip in 300 time units")
        if flips["largest"] != 0:
            fail(f"the wobble about the largest axis counted {flips['largest']} flips, not 0 "
                 "(a flip is a turn-over, docs/physics.md §14)")

        # 4. Compare mode: the second method set through its controls runs beside the first,
        #    each equal to bookspin simulate of its own method; two trails on the sphere.
        load(driver, page + "?scene=fig09-matrix-unstable-x&dt=0.01")
        base = driver.execute_script("return window.explorer.state()")
        # One method first: its trail (more than the position marker, a disc of radius 5 of
        # about 80 pixels) and nothing of the second colour.
        slide_to(driver, 200)
        colours = sphere_colours(driver)
        print(f"one method: sphere pixels of each colour {colours}")
        if colours[0] < 300 or colours[1] > 0:
            fail(f"the sphere does not show the one run's trail alone: pixels {colours}")
        driver.find_element("id", "compare").click()
        Select(driver.find_element("id", "model2")).select_by_value("rigid-quaternion")
        Select(driver.find_element("id", "integrator2")).select_by_value("splitting")
        driver.find_element("id", "normalize2").click()
        omegas = driver.execute_script("return window.explorer.omegaAt(100)")
        if len(omegas) != 2:
            fail(f"compare mode does not run two methods: ω {omegas}")
        first = simulate_omega(bookspin, book_scene, {})
        second = simulate_omega(bookspin, book_scene, {
            "model.kind": '"rigid-quaternion"', "model.integrator": '"splitting"',
            "model.normalize": "true"})
        if relative(first, second) < 1e-8:
            fail(f"the two methods of the compare check agree too closely to tell apart: {first}")
        print(f"compare at t = 100: page {omegas}, simulate {first} and {second}")
        if not (relative(omegas[0], first) <= TOL and relative(omegas[1], second) <= TOL):
            fail(f"compare mode's runs are not the two methods: page {omegas}, bookspin simulate "
                 f"{first} (first method) and {second} (rigid-quaternion splitting, normalized)")
        slide_to(driver, 200)
        trails = driver.execute_script("return window.explorer.trails()")
        colours = sphere_colours(driver)
        driver.save_screenshot(str(shots / "explorer-compare.png"))
        print(f"compare: trails {trails}, sphere pixels of each colour {colours}")
        if len(trails) != 2 or min(t["points"] for t in trails) < 100:
            fail(f"compare mode does not run two methods: {trails}")
        # The second trail, drawn over the first (which it nearly follows), is more than its
        # marker; of the first, at least its marker shows.
        if colours[0] < 30 or colours[1] < 300:
            fail(f"the sphere does not show both trails: pixels {colours}")

        # 5. The URL restores the state: every control set away from the scene's value (the
        #    speed to the page's default, which the scene does not use) and read back. The
        #    particle model on the T-handle, so that k, damping and the lattice cells are shown;
        #    the air drag set first, while the model is a rigid one that takes it (the particle
        #    model hides it).
        Select(driver.find_element("id", "drag")).select_by_value("linear")
        driver.find_element("id", "dragRate").clear()
        driver.find_element("id", "dragRate").send_keys("0.05\n")
        Select(driver.find_element("id", "model")).select_by_value("particle")
        if driver.find_element("id", "dragRow").is_displayed():
            fail("the particle model shows the air drag, which it does not take")
        Select(driver.find_element("id", "body")).select_by_value("t-handle")
        Select(driver.find_element("id", "integrator")).select_by_value("velocity-verlet")
        Select(driver.find_element("id", "axis")).select_by_value("largest")
        for field, value in (("rate", "0.3"), ("dt", "0.02"), ("k", "3"), ("cells", "5"),
                             ("jiggle", "0.002"), ("seed", "11"), ("speed", "5")):
            driver.find_element("id", field).clear()
            driver.find_element("id", field).send_keys(value + "\n")
        for box in ("normalize", "damping", "showL", "showAxes"):
            driver.find_element("id", box).click()
        url = driver.current_url
        before = driver.execute_script("return window.explorer.state()")
        same = sorted(k for k in before if k != "t" and before[k] == base[k])
        # `tiles` (every method of a comparison) is off for a scene of one method, which does not
        # offer it; its URL is checked by tests/browser/explorer_replay_test.py.
        if same != ["scene", "tiles", "w"]:
            fail(f"the URL check leaves fields at the scene's values: {same}")
        omega = driver.execute_script("return window.explorer.omegaAt(50)")
        load(driver, url)
        after = driver.execute_script("return window.explorer.state()")
        if json.dumps(before, sort_keys=True) != json.dumps(after, sort_keys=True):
            fail(f"the shared URL did not restore the state:\n{before}\n{after}")
        if driver.execute_script("return window.explorer.omegaAt(50)") != omega:
            fail("the shared URL does not reproduce the run")
        errors = console_errors(driver)
        if errors:
            fail(f"console errors: {errors}")
        print(f"shared URL restores the state: {url.split('?', 1)[1]}")

        # 6. The gallery beside the page links every entry to the explorer on its own scene;
        #    four of them opened: a book figure, the T-handle, a comparison, the mesh scene.
        scene_files = sorted((source / "scenes").glob("*.toml"))
        run([bookspin, "gallery", str(out), *map(str, scene_files)])
        driver.get((out / "index.html").resolve().as_uri())
        links = driver.execute_script("""
          return [...document.querySelectorAll('section.clip')].map((s) => {
            const a = [...s.querySelectorAll('a')].find((x) => x.textContent === 'open in the explorer');
            return [s.id, a ? a.getAttribute('href') : null];
          });""")
        if sorted(name for name, _ in links) != sorted(p.stem for p in scene_files):
            fail(f"the gallery's entries are not the scenes: {links}")
        for name, href in links:
            if href != f"explorer.html?scene={name}":
                fail(f"gallery entry {name} links {href!r}, not the explorer on its scene")
        for name in ("fig05-particle-unstable-x", "t-handle-dzhanibekov", "compare-methods-x",
                     "major-axis-rule"):
            driver.get((out / "index.html").resolve().as_uri())
            driver.execute_script(f"document.querySelector('#{name} a[href^=\"explorer.html\"]').click()")
            load(driver)
            state = driver.execute_script("return window.explorer.state()")
            message = driver.find_element("id", "message").text
            trails = driver.execute_script("return window.explorer.trails()")
            driver.save_screenshot(str(shots / f"explorer-from-gallery-{name}.png"))
            print(f"gallery → {name}: body {state['body']}, model {state['model']}, "
                  f"compare {state['compare']}, runs {len(trails)}")
            errors = console_errors(driver)
            if state["scene"] != name or message or errors:
                fail(f"the gallery's link did not open {name} cleanly: scene {state['scene']!r}, "
                     f"message {message!r}, console {errors}")
            # A comparison opens with every one of its [[compare]] tiles (docs/explorer.md,
            # "Comparison"): 4 and 2; a scene of one method with one run.
            expected_runs = {"compare-methods-x": 4, "major-axis-rule": 2}.get(name, 1)
            if len(trails) != expected_runs:
                fail(f"{name} opened with {len(trails)} runs, not {expected_runs}")
    print("OK")


if __name__ == "__main__":
    sys.exit(main())
