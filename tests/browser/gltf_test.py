#!/usr/bin/env python3
"""Exported glTF and WebM clips in real tools: the Khronos glTF-Validator (node) and headless
Chromium (three.js's GLTFLoader; a <video> element).

  - `bookspin export --gltf` of the book (fig09), the T-handle and a two-colour mesh: the
    validator reports 0 errors and 0 warnings for each;
  - three.js loads each, plays its one animation to a keyframe time t and the node's
    quaternion equals the CSV's q_w, q_x, q_y, q_z of that frame (`bookspin simulate`) to 1e-6
    (up to sign: q and -q are the same rotation); the book's view is saved as
    build/test-output/browser/gltf-book.png;
  - `bookspin render --format webm` of a small clip plays in a <video>: it reaches
    HAVE_ENOUGH_DATA, its currentTime advances, and videoWidth/videoHeight are the clip's.

Usage: gltf_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Needs node and npm (the pinned tests/browser/package-lock.json is installed with `npm ci`
into BINARY_DIR/test-output/gltf-npm) and Chromium with Selenium (browser.py). A missing piece
skips (exit 77), except under CI=true, where it fails.
"""
import filecmp
import json
import shutil
import sys
from pathlib import Path

from browser import (console_errors, fail, find_browser, open_browser, require, run, serve,
                     test_arguments, wait_for)

FRAMES = 150
FPS = 30


def npm_tools(source, binary):
    """node_modules with gltf-validator and three, from the pinned lockfile."""
    node, npm = require("node", "npm")
    folder = binary / "test-output" / "gltf-npm"
    folder.mkdir(parents=True, exist_ok=True)
    here = source / "tests" / "browser"
    stale = not (folder / "node_modules").is_dir()
    for name in ("package.json", "package-lock.json", "validate_gltf.mjs", "gltf_page.html"):
        target = folder / name
        if name.startswith("package") and (not target.exists() or not filecmp.cmp(here / name, target)):
            stale = True
        shutil.copyfile(here / name, target)
    if stale:
        run([npm, "ci", "--no-audit", "--no-fund", "--prefix", str(folder)])
    return node, folder


def csv_quaternion(bookspin, scene, frame, extra=()):
    """(w, x, y, z) of `frame` in `bookspin simulate`'s CSV."""
    text = run([bookspin, "simulate", scene, "--set", f"time.frames={frame + 1}", *extra,
                "--csv", "-"])
    lines = [l for l in text.splitlines() if l and not l.startswith("bookspin:")]
    header = lines[0].split(",")
    row = lines[frame + 1].split(",")
    return [float(row[header.index(c)]) for c in ("q_w", "q_x", "q_y", "q_z")]


def write_mesh_scene(folder):
    (folder / "box.mtl").write_text("newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n")
    (folder / "box.obj").write_text(
        "mtllib box.mtl\nv 0 0 0\nv 2 0 0\nv 0 1 0\nv 2 1 0\nv 0 0 0.5\nv 2 0 0.5\nv 0 1 0.5\n"
        "v 2 1 0.5\nusemtl blue\nf 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\n"
        "usemtl red\nf 5 6 8 7\n")
    scene = folder / "box-mesh.toml"
    scene.write_text('[body]\nshape = "mesh"\nmesh = "box.obj"\nmass = 1.0\n'
                     '[model]\nkind = "rigid-quaternion"\n'
                     '[initial]\nangular_velocity = [0.0, 1.0, 0.05]\n')
    return scene


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    node, site = npm_tools(source, binary)
    shots = binary / "test-output" / "browser"
    shots.mkdir(parents=True, exist_ok=True)
    for old in site.glob("*.glb"):
        old.unlink()

    # name → (scene, keyframe checked)
    cases = {
        "fig09-matrix-unstable-x": (source / "scenes" / "fig09-matrix-unstable-x.toml", 120),
        "t-handle-dzhanibekov": (source / "scenes" / "t-handle-dzhanibekov.toml", 75),
        "box-mesh": (write_mesh_scene(site), 40),
    }
    for name, (scene, _) in cases.items():
        run([bookspin, "export", scene, "--gltf", "--frames", str(FRAMES), "-o", site])
        if not (site / f"{name}.glb").is_file():
            fail(f"bookspin export wrote no {name}.glb")

    reports = run([node, site / "validate_gltf.mjs", *sorted(site.glob("*.glb"))])
    for line in reports.splitlines():
        report = json.loads(line)
        print(f"validator: {Path(report['file']).name}: {report['errors']} errors, "
              f"{report['warnings']} warnings, {report['vertices']} vertices")
        if report["errors"] or report["warnings"] or report["animations"] != 1:
            fail(f"glTF-Validator on {report['file']}: {report}")

    clip = binary / "test-output" / "gltf-webm"
    shutil.rmtree(clip, ignore_errors=True)
    run([bookspin, "render", source / "scenes" / "fig09-matrix-unstable-x.toml", "--set",
         "render.width=320", "--set", "render.height=180", "--frames", "45", "--no-png",
         "--format", "webm", "--jobs", "2", "-o", clip])
    shutil.copyfile(clip / "fig09-matrix-unstable-x.webm", site / "clip.webm")
    (site / "video.html").write_text(
        '<!doctype html><html><head><link rel="icon" href="data:,"></head><body><video id="v" src="clip.webm" muted autoplay loop '
        'playsinline></video></body></html>')

    with serve(site) as url, open_browser(chromium, driver_path, size=(1000, 800), webgl=True,
                                          media=True) as driver:
        for name, (scene, frame) in cases.items():
            t = frame / FPS
            driver.get(f"{url}gltf_page.html?file={name}.glb&t={t!r}")
            wait_for(driver, "return window.done === true;", bool, timeout=120)
            result = driver.execute_script("return window.result;")
            if not result or "error" in result:
                fail(f"three.js could not load {name}.glb: {result}")
            x, y, z, w = result["quaternion"]
            expected = csv_quaternion(bookspin, str(scene), frame)
            sign = 1.0 if sum(a * b for a, b in zip((w, x, y, z), expected)) >= 0 else -1.0
            error = max(abs(sign * a - b) for a, b in zip((w, x, y, z), expected))
            print(f"three.js: {name} at t = {t:.4f} s: quaternion {[w, x, y, z]}, CSV "
                  f"{expected}, largest difference {error:.2e}")
            if result["clips"] != 1 or abs(result["duration"] - (FRAMES - 1) / FPS) > 1e-4:
                fail(f"{name}: expected one clip of {(FRAMES - 1) / FPS} s, got {result}")
            if error > 1e-6:
                fail(f"{name}: three.js's orientation differs from the CSV's by {error}")
            driver.save_screenshot(str(shots / f"gltf-{name}.png"))
        severe = console_errors(driver)
        if severe:
            fail(f"console errors: {severe}")

        driver.get(f"{url}video.html")
        state = wait_for(driver, """const v = document.getElementById('v');
            return {ready: v.readyState, time: v.currentTime, w: v.videoWidth, h: v.videoHeight,
                    error: v.error ? v.error.code + ' ' + v.error.message : null};""",
                         lambda s: s["error"] or (s["ready"] >= 4 and s["time"] > 0.2), timeout=60)
        print(f"webm in <video>: {state}")
        if state["error"] or state["ready"] < 4 or state["time"] <= 0.2 or \
                (state["w"], state["h"]) != (320, 180):
            fail(f"the WebM did not play in Chromium: {state}")
    print("gltf_test: validator, three.js and WebM playback all agree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
