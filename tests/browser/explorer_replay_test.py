#!/usr/bin/env python3
"""A comparison in the explorer page shows every one of its methods, as its clip does
(docs/explorer.md, "Comparison"), in headless Chromium, the page opened from disk.

Builds the page's program with web/build.sh BINARY_DIR, writes the page of
scenes/compare-engines.toml, scenes/compare-methods-x.toml and scenes/exact-unstable-x.toml with
`bookspin explore`, and checks at 1366×768:
  - `?scene=compare-engines` shows its six tiles, in the scene's order, by the scene's labels:
    the exact motion stepped by the page, MuJoCo (Euler, RK4), Bullet (both) and ODE, which the
    page cannot step, each labelled "(replay of make figures' run)" in the readout and the
    plots' legend, and "· replay" after its short name under its body in the view;
  - each replay is that engine's motion: its body-frame ω at t = 300.5 (the sample of frame 300
    held) and t = 599 equals `bookspin simulate` of the tile's scene (the scene with the tile's
    model, no [[compare]]) at those frames to 1e-3 of |ω| (16-bit samples), and its flips at
    t = 599 are the count of the flip detector (docs/physics.md §14) on that run's
    cos(intermediate axis, L), frame by frame: MuJoCo, Bullet's default and ODE turn over,
    Bullet without its gyroscopic term never does (docs/engines.md); the exact motion 3 times;
  - the replay data of the scene is compact: under 100 kB of the page;
  - a start other than the scene's (`jiggle=0.002`) shows the exact motion alone and says the
    replays are of the scene's own start; `tiles=0` two methods at most (here the one the page
    steps); `?scene=compare-methods-x` steps its four tiles live;
  - no console error; a screenshot of compare-engines at t = 300.5, kept as
    BINARY_DIR/test-output/browser/replay-compare-engines-1366x768.png.

Usage: explorer_replay_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import csv
import json
import math
import re
import tomllib

from browser import console_errors, fail, find_browser, open_browser, require, run, test_arguments
from explorer_test import load

REPLAY = "(replay of make figures' run)"
MARGIN = 0.5  # analysis::FlipDetector::kMargin


def flips(values):
    """The flip detector's count (analysis::FlipDetector, docs/physics.md §14): the signal past
    the margin on the side opposite the one it was last past it on (first: its first sign)."""
    side, count = 0, 0
    for v in values:
        s = (v > 0) - (v < 0)
        if s == 0:
            continue
        if side == 0:
            side = s
        elif s == -side and abs(v) > MARGIN:
            count, side = count + 1, s
    return count


def simulated(bookspin, scene_text, tile, folder):
    """`bookspin simulate` of the scene with `tile`'s model and no [[compare]]: its rows."""
    head = scene_text.split("[[compare]]")[0]
    model = tile["model"]
    lines = [f'kind = "{model["kind"]}"'] + ([f'integrator = "{model["integrator"]}"']
                                             if "integrator" in model else [])
    path = folder / (re.sub(r"[^a-z0-9]+", "-", tile["label"].lower()) + ".toml")
    path.write_text(head + "\n[model]\n" + "\n".join(lines) + "\n")
    out = path.with_suffix(".csv")
    run([bookspin, "simulate", str(path), "--csv", str(out)])
    with open(out) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def runs(driver):
    return driver.execute_script("return window.explorer.trails()")


def check_compare_engines(driver, page, bookspin, source, folder, shots):
    scene_path = source / "scenes" / "compare-engines.toml"
    text = scene_path.read_text()
    tiles = tomllib.loads(text)["compare"]
    load(driver, page + "?scene=compare-engines")
    shown = [r["label"] for r in runs(driver)]
    want = [t["label"] if t["model"]["kind"] == "exact" else f"{t['label']} {REPLAY}" for t in tiles]
    print("compare-engines shows:", shown)
    if shown != want:
        fail(f"?scene=compare-engines shows {shown}, not the scene's six tiles {want}")
    if sum(REPLAY in s for s in shown) != 5:
        fail(f"not five replays labelled as such: {shown}")
    readout = driver.execute_script(
        "return [...document.querySelectorAll('#status .run .method')].map((e) => e.textContent)")
    if readout != want:
        fail(f"the readout names {readout}, not {want}")
    # Under each body its name, short (up to its parenthesis), "· replay" where it is one.
    short = [t["label"].split(" (")[0] + ("" if t["model"]["kind"] == "exact" else " · replay")
             for t in tiles]
    labels = driver.execute_script(
        "return [...document.querySelectorAll('.bodyLabel')].filter((e) => !e.hidden).map((e) => e.textContent)")
    if labels != short:
        fail(f"the view labels its bodies {labels}, not {short}")
    # No two names under the bodies meet, and each stays inside the view.
    boxes = driver.execute_script(
        "const v = document.querySelector('#view').getBoundingClientRect();"
        "return [v.left, v.right, [...document.querySelectorAll('.bodyLabel')].filter((e) => !e.hidden)"
        ".map((e) => { const r = e.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; })]")
    view_left, view_right, boxes = boxes
    for i, a in enumerate(boxes):
        if a[0] < view_left - 1 or a[2] > view_right + 1:
            fail(f"the name {labels[i]!r} runs out of the view: {a}, view {view_left}–{view_right}")
        for j in range(i):
            b = boxes[j]
            if a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]:
                fail(f"the names {labels[j]!r} {b} and {labels[i]!r} {a} meet")

    at = {}
    for t in (300.5, 599.0):
        at[t] = driver.execute_script(f"return window.explorer.omegaAt({t!r})")
    measures = driver.execute_script("return window.explorer.flipMeasures()")
    print("flips at t = 599:", [m["count"] for m in measures])
    if measures[0]["count"] != 3:
        fail(f"the exact motion flips {measures[0]['count']} times in 599 time units, not 3")
    for k, tile in enumerate(tiles):
        if tile["model"]["kind"] == "exact":
            continue
        rows = simulated(bookspin, text, tile, folder)
        for t, omegas in at.items():
            row = rows[int(t)]
            w = [row["omega_x"], row["omega_y"], row["omega_z"]]
            err = math.dist(omegas[k], w) / math.hypot(*w)
            print(f"{tile['label']}: ω at t = {t:g} off the simulated frame {int(t)} by {err:.2e} of |ω|")
            if not err < 1e-3:
                fail(f"{shown[k]}: ω at t = {t:g} is {omegas[k]}, the engine's run {w} (frame {int(t)})")
        want_flips = flips(row["cos_intermediate_L"] for row in rows)
        got = measures[k]["count"]
        print(f"{tile['label']}: {got} flips in the page, {want_flips} in the engine's run")
        if got != want_flips:
            fail(f"{shown[k]}: {got} flips at t = 599, the engine's run {want_flips}")
        turns = tile["model"].get("integrator") != "none"
        if turns != (got > 0):
            fail(f"{shown[k]}: {got} flips: expected {'some' if turns else 'none'} (docs/engines.md)")
    driver.execute_script("window.explorer.omegaAt(300.5)")
    driver.save_screenshot(str(shots / "replay-compare-engines-1366x768.png"))

    html = (folder / "explorer.html").read_text()
    line = next(x for x in html.splitlines() if x.startswith('{"name":"compare-engines"'))
    replays = json.dumps(json.loads(line.rstrip(","))["replays"])
    print(f"compare-engines' replays: {len(replays)} bytes of the page")
    if len(replays) > 100_000:
        fail(f"the replays take {len(replays)} bytes of the page: not compact")

    load(driver, page + "?scene=compare-engines&jiggle=0.002")
    message = driver.find_element("id", "message").text
    if [r["label"] for r in runs(driver)] != [want[0]] or "own start" not in message:
        fail(f"another start: {runs(driver)}, message {message!r}: expected the exact motion "
             "alone and the replays said to be of the scene's own start")
    load(driver, page + "?scene=compare-engines&tiles=0")
    if len(runs(driver)) != 1:
        fail(f"tiles=0: {len(runs(driver))} methods, expected the one the page steps")


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    out = binary / "test-output" / "explorer-replay"
    shots = binary / "test-output" / "browser"
    shots.mkdir(parents=True, exist_ok=True)
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    run([bookspin, "explore", *(str(source / "scenes" / f"{s}.toml") for s in
                                ("compare-engines", "compare-methods-x", "exact-unstable-x")),
         "-o", str(out)])
    page = (out / "explorer.html").resolve().as_uri()
    with open_browser(chromium, driver_path, size=(1366, 768), webgl=True, offline=True,
                      exact_viewport=True) as driver:
        check_compare_engines(driver, page, bookspin, source, out, shots)
        load(driver, page + "?scene=compare-methods-x")
        methods = [r["label"] for r in runs(driver)]
        tiles = [t["label"] for t in tomllib.loads((source / "scenes" / "compare-methods-x.toml").read_text())["compare"]]
        if methods != tiles:
            fail(f"?scene=compare-methods-x steps {methods}, not its four tiles {tiles}")
        errors = console_errors(driver)
        if errors:
            fail(f"console errors: {errors}")
    print("explorer replays: OK")


if __name__ == "__main__":
    main()
