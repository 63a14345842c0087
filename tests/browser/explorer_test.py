#!/usr/bin/env python3
"""The explorer page (web/, docs/explorer.md) in a real browser: headless Chromium driven by
Selenium, the page opened straight from disk (file://) with the network off.

Builds the page's program with web/build.sh BINARY_DIR, writes BINARY_DIR/test-output/explorer/
explorer.html with `bookspin explore` (every scene, and a mesh scene of its own), and checks:
  - the page loads with no console error and draws the body: the book's colours (its
    dark blue cover, its cream pages) fill part of the 3D view, the background the rest;
  - ω at t = 100 in the page equals `bookspin simulate` of the same settings to 1e-10
    relative, for the rigid models (matrix and quaternion, several integrators, with and
    without normalization) and the exact model, the book, the T-handle and a mesh body (the
    long box, its surface and moments carried by the page from bookspin);
  - the mesh body is drawn (its grey faces where the body is);
  - wiring: the T-handle scene with the spin axis and rate set through the page's controls
    (largest axis: no flip in 300 time units, driven through the time slider; intermediate
    axis: flips), ω at t = 300 equal to `bookspin simulate` with that spin axis and rate;
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

from browser import console_errors, fail, find_browser, open_browser, require, run, test_arguments

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


def load(driver, url=None):
    """Opens url (None: the page the driver is on, say after a click) and waits until the
    explorer is ready; fail() after 30 s."""
    if url is not None:
        driver.get(url)
    for _ in range(300):
        if driver.execute_script("return !!(window.explorer && window.explorer.ready)"):
            return
        time.sleep(0.1)
    fail(f"the page never became ready: {url or driver.current_url}\n{driver.get_log('browser')}")


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
        ]
        worst = 0.0
        for scene, settings in cases:
            expected = simulate_omega(bookspin, scene, settings)
            q = {"scene": Path(scene).stem, "dt": "0.01",
                 "model": settings["model.kind"].strip('"'),
                 "integrator": settings.get("model.integrator", '"euler"').strip('"'),
                 "normalize": "1" if settings.get("model.normalize") == "true" else "0"}
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
            driver.execute_script("""
              const s = document.getElementById('slider');
              s.max = 300; s.value = 300; s.dispatchEvent(new Event('input'));""")
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
        if flips["largest"] != 0:
            fail(f"spin about the largest axis flipped {flips['largest']} times in 300 time units")
        if flips["intermediate"] < 1:
            fail("spin about the intermediate axis did not flip in 300 time units")

        # 4. Compare mode: the second method set through its controls runs beside the first,
        #    each equal to bookspin simulate of its own method; two trails on the sphere.
        load(driver, page + "?scene=fig09-matrix-unstable-x&dt=0.01")
        base = driver.execute_script("return window.explorer.state()")
        # One method first: its trail (more than the position marker, a disc of radius 5 of
        # about 80 pixels) and nothing of the second colour.
        driver.execute_script("""
          const s = document.getElementById('slider');
          s.max = 200; s.value = 200; s.dispatchEvent(new Event('input'));""")
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
        driver.execute_script("""
          const s = document.getElementById('slider');
          s.max = 200; s.value = 200; s.dispatchEvent(new Event('input'));""")
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
        #    speed to the page's default, which the scene does not use) and read back.
        Select(driver.find_element("id", "integrator")).select_by_value("rk4")
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
        if same != ["body", "model", "scene", "w"]:
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
            expected_runs = 2 if name in ("compare-methods-x", "major-axis-rule") else 1  # [[compare]]
            if len(trails) != expected_runs:
                fail(f"{name} opened with {len(trails)} runs, not {expected_runs}")
    print("OK")


if __name__ == "__main__":
    sys.exit(main())
