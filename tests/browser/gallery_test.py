#!/usr/bin/env python3
"""The gallery page in a real browser: headless Chromium driven by Selenium.

Renders two tiny scenes, plots them, writes the gallery, serves the folder over a local HTTP
server (file:// pages may not play media) and checks in Chromium that
  - the page lists the scenes in paper order under a header saying how it was made,
  - the page logs no console error (no SEVERE browser log entry),
  - every <video> reaches readyState >= 1 (HAVE_METADATA) with duration > 0 and the clip's
    width and height (from ffprobe),
  - every image loads (naturalWidth > 0) and every linked file (MP4, CSV, PNG, poster)
    answers HTTP 200,
  - at 1366×768 (docs/outputs.md, "Pictures"): the page keeps its height while its lazy images
    load, every chart (a plot, a sweep's heat maps and line plots, an accuracy report's charts,
    at their default sizes) is shown at the size its text was drawn for (no smaller), a sweep's
    picture and the accuracy charts are whole on the screen (no taller than 768 px), no text is
    under 12 px and none runs past its box,
  - its contents link every section in the page's order, and the intro names the figures
    first (no league, no fit here),
  - on a phone (390×844, mobile, touch) the page is laid out at the phone's width, no text is
    under 12 px and none runs past the window's side,
and saves a full-page screenshot as build/test-output/browser/gallery.png (the phone's first
screen as gallery-390x844.png).

Usage: gallery_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Needs Debian's chromium, chromium-driver and python3-selenium (scripts/install-deps.sh). Where
one is missing the test is skipped (exit 77), except under CI=true, where that is a failure.
"""
import base64
import json
import shutil
import sys
import time
import urllib.request

from browser import (console_errors, fail, find_browser, open_browser, run, serve,
                     test_arguments, text_problems, wait_for)

CLIP_W, CLIP_H = 160, 96  # even sizes: H.264 4:2:0 needs them
SCREEN = (1366, 768)  # the window's size (docs/outputs.md, "Pictures")
BARS = 120  # a browser's title, tab and address bars and a taskbar on that screen, about
FRAMES = 8


def build_gallery(bookspin, source, out):
    scenes = [source / "scenes" / "fig09-matrix-unstable-x.toml",
              source / "scenes" / "compare-normalization.toml"]
    size = ["--set", f"render.width={CLIP_W}", "--set", f"render.height={CLIP_H}",
            "--set", 'render.preset="ultrafast"']
    for scene in scenes:
        run([bookspin, "render", scene, *size, "--frames", str(FRAMES), "--jobs", "2",
             "-o", out])
        # The plot at its default size, as make figures draws it.
        run([bookspin, "plot", scene, "--set", f"time.frames={FRAMES}", "-o", out])
    # A two-key sweep (heat maps), small and short.
    sweep = source / "sweeps" / "when-to-normalize-matrix-euler.toml"
    run([bookspin, "sweep", sweep, "--set", "time.duration=2", "--vary", "time.dt=0.01:0.02:2",
         "--vary", "model.normalize_every=1:10:2", "--measure", "orientation_error,diverged_at",
         "-o", out])
    # A one-key sweep of four measures (two rows of two plots) and an accuracy report of the
    # engines' sweep (its five charts), small and short, as make figures draws them.
    flips = source / "sweeps" / "flip-time-vs-perturbation.toml"
    run([bookspin, "sweep", flips, "--set", "time.frames=4", "--vary",
         "initial.angular_velocity[1]=1e-6:1e-2:3:log", "--measure",
         "first_flip,flip_period,energy_drift,orientation_error", "-o", out])
    engines = source / "sweeps" / "engines-energy-vs-dt.toml"
    run([bookspin, "accuracy", engines, "--flips", "1", "--methods", "rigid-quaternion:rk4",
         "--dt", "0.03333333333333333", "0.016666666666666666", "-o", out])
    # Given comparison first: the page puts the paper's figure first all the same.
    run([bookspin, "gallery", out, *reversed(scenes), sweep, flips, engines])
    return [s.stem for s in scenes], [engines.stem, flips.stem, sweep.stem]


def clip_size(mp4):
    """(width, height) of the first video stream, from ffprobe."""
    text = run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
                "stream=width,height", "-of", "json", mp4])
    stream = json.loads(text)["streams"][0]
    return stream["width"], stream["height"]


VIDEO_STATE = """
return Array.from(document.querySelectorAll('video')).map(v => ({
  src: v.getAttribute('src'), poster: v.getAttribute('poster'), readyState: v.readyState,
  duration: v.duration, width: v.videoWidth, height: v.videoHeight,
  error: v.error ? v.error.code + ' ' + v.error.message : null}));
"""

IMAGE_STATE = """
return Array.from(document.querySelectorAll('img')).map(i => ({
  src: i.getAttribute('src'), complete: i.complete, naturalWidth: i.naturalWidth}));
"""


CHART_STATE = """
return Array.from(document.querySelectorAll('img.plot, video')).map(i => i.tagName === 'VIDEO' ? ({
  src: i.getAttribute('src'), naturalWidth: i.videoWidth, naturalHeight: i.videoHeight,
  shown: i.getBoundingClientRect().width, shownHeight: i.getBoundingClientRect().height,
  attr: [i.getAttribute('width'), i.getAttribute('height')]}) : ({
  src: i.getAttribute('src'), alt: i.getAttribute('alt'),
  naturalWidth: i.naturalWidth, naturalHeight: i.naturalHeight,
  shown: i.getBoundingClientRect().width - 2, shownHeight: i.getBoundingClientRect().height - 2,
  attr: [i.getAttribute('width'), i.getAttribute('height')]}));
"""


def check_typography(driver, height_before):
    """The page at 1366×768 once every lazy image has loaded (docs/outputs.md, "Pictures")."""
    errors = []
    height_after = driver.execute_script("return document.documentElement.scrollHeight")
    print(f"page height {height_before} px before its images loaded, {height_after} after")
    if abs(height_after - height_before) > 2:
        errors.append(f"the page grows from {height_before} to {height_after} px as its images "
                      "load (an image without its size)")
    charts = driver.execute_script(CHART_STATE)
    if len(charts) < 3:
        errors.append(f"expected the plots and the sweep's picture, found {charts}")
    reports = [c for c in charts if (c.get("alt") or "").startswith("accuracy report of")]
    sweeps = [c for c in charts if (c.get("alt") or "").startswith("parameter sweep of")]
    if len(reports) != 5 or len(sweeps) != 2:
        errors.append(f"expected the two sweeps' pictures and five accuracy charts, found "
                      f"{len(sweeps)} and {len(reports)}")
    for c in charts:
        print(f"chart {c['src']}: {c['naturalWidth']}×{c['naturalHeight']}, shown "
              f"{c['shown']:.1f}×{c['shownHeight']:.1f}")
        if c["src"].endswith(".png") and c["attr"] != [str(c["naturalWidth"]),
                                                       str(c["naturalHeight"])]:
            errors.append(f"chart {c['src']}: width and height {c['attr']}, not its size")
        # A sweep's picture and the accuracy report's charts are seen whole on the screen:
        # with their border, no taller than the 768 px screen less a browser's bars, nor wider.
        sweep_chart = (c.get("alt") or "").startswith(("parameter sweep of",
                                                       "accuracy report of"))
        if sweep_chart and (c["shownHeight"] + 2 > SCREEN[1] - BARS or c["shown"] + 2 > SCREEN[0]):
            errors.append(f"chart {c['src']}: shown {c['shown']:.0f}×{c['shownHeight']:.0f} px, "
                          f"not whole on a {SCREEN[0]}×{SCREEN[1]} screen under {BARS} px of bars")
        if c["shown"] < c["naturalWidth"] - 0.5 or c["shownHeight"] < c["naturalHeight"] - 0.5:
            errors.append(f"chart {c['src']}: shown {c['shown']:.1f} px wide of its "
                          f"{c['naturalWidth']}: its text smaller than drawn")
    return errors + text_problems(driver)


def check_page(driver, url, out, scenes, sweeps, screenshot):
    errors = []
    driver.get(url + "index.html")
    wait_for(driver, "return document.readyState", lambda s: s == "complete")
    height_before = driver.execute_script("return document.documentElement.scrollHeight")
    # Lazy images load when near the viewport: scroll through the page once.
    height = driver.execute_script("return document.body.scrollHeight")
    for y in range(0, height + 1000, 500):
        driver.execute_script(f"window.scrollTo(0, {y})")
        time.sleep(0.05)
    driver.execute_script("window.scrollTo(0, 0)")

    sections = driver.execute_script(
        "return Array.from(document.querySelectorAll('section.clip')).map(s => s.id)")
    names = scenes + sweeps
    if sections != names:
        errors.append(f"sections in the order {sections}, expected {names} (paper order)")
    made = driver.execute_script(
        "const p = document.querySelector('p.made'); return p ? p.textContent : ''")
    if "bookspin" not in made or "UTC" not in made:
        errors.append(f"no header saying how the page was made: {made!r}")
    print(f"header: {made}")

    videos = wait_for(driver, VIDEO_STATE,
                      lambda vs: all(v["readyState"] >= 1 or v["error"] for v in vs))
    clips = len(scenes)  # the sweeps have no clip
    if len(videos) != clips:
        errors.append(f"{len(videos)} <video> elements, expected {clips}: {videos}")
    for v in videos:
        expected = clip_size(out / v["src"])
        if v["error"]:
            errors.append(f"video {v['src']}: MediaError {v['error']}")
        if v["readyState"] < 1:
            errors.append(f"video {v['src']}: readyState {v['readyState']} (no metadata)")
        if not (v["duration"] and v["duration"] > 0):
            errors.append(f"video {v['src']}: duration {v['duration']}")
        if (v["width"], v["height"]) != expected or expected != (CLIP_W, CLIP_H):
            errors.append(f"video {v['src']}: {v['width']}×{v['height']} in the browser, "
                          f"{expected[0]}×{expected[1]} in the file, {CLIP_W}×{CLIP_H} rendered")
        print(f"video {v['src']}: readyState {v['readyState']}, {v['duration']:.3f} s, "
              f"{v['width']}×{v['height']}")

    images = wait_for(driver, IMAGE_STATE,
                      lambda im: all(i["complete"] for i in im), timeout=30)
    if not images:
        errors.append("no <img> on the page (plots expected)")
    for i in images:
        if not i["naturalWidth"]:
            errors.append(f"image {i['src']} did not load (naturalWidth 0)")
    print(f"{len(images)} images checked")
    errors += check_typography(driver, height_before)

    links = driver.execute_script(
        "return Array.from(document.querySelectorAll('a[href]')).map(a => a.getAttribute('href'))"
        ".concat(Array.from(document.querySelectorAll('video[poster]'))"
        ".map(v => v.getAttribute('poster')))")
    links = [h for h in links if not h.startswith(("#", "data:", "http:", "https:"))]
    csvs = [h for h in links if h.endswith(".csv")]
    if len(csvs) < clips:
        errors.append(f"expected a diagnostics CSV link per scene, found {csvs}")
    for href in links:
        try:
            with urllib.request.urlopen(url + href, timeout=10) as response:
                if response.status != 200 or not response.read(1):
                    errors.append(f"link {href}: HTTP {response.status}, empty")
        except Exception as e:  # urllib raises HTTPError on 404
            errors.append(f"link {href}: {e}")
    print(f"{len(links)} links checked ({len(csvs)} CSV)")

    # A full-page screenshot through the DevTools protocol.
    metrics = driver.execute_cdp_cmd("Page.getLayoutMetrics", {})
    size = metrics["cssContentSize"]
    shot = driver.execute_cdp_cmd("Page.captureScreenshot", {
        "format": "png", "captureBeyondViewport": True,
        "clip": {"x": 0, "y": 0, "width": size["width"], "height": size["height"], "scale": 1}})
    screenshot.write_bytes(base64.b64decode(shot["data"]))
    print(f"screenshot {screenshot}")

    errors += [f"console: {entry['message']}" for entry in console_errors(driver)]
    errors += check_contents(driver)
    return errors


def check_contents(driver):
    """The contents: a link to each section (and nothing else), in the page's order."""
    got = driver.execute_script("""
      const links = [...document.querySelectorAll('nav.contents a')].map((a) => a.getAttribute('href').slice(1));
      const order = [...document.querySelectorAll('main > section')].map((s) => s.id);
      return [links, order, document.querySelector('p.about').textContent];""")
    links, order, about = got
    print(f"contents: {len(links)} links; sections {len(order)}")
    errors = []
    if links != order:
        errors.append(f"the contents {links} are not the sections in page order {order}")
    if "first the paper's figures 3–12" not in about:
        errors.append(f"the intro does not state the page's order (figures first): {about!r}")
    return errors


def check_phone(driver, url, screenshot):
    """At 390×844 (mobile, touch): laid out at 390 px, text at least 12 px, none past the side."""
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": 390, "height": 844, "deviceScaleFactor": 2, "mobile": True})
    driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 5})
    driver.get(url + "index.html")
    wait_for(driver, "return document.readyState", lambda s: s == "complete")
    width = driver.execute_script("return [document.documentElement.clientWidth, window.innerWidth]")
    errors = [] if width == [390, 390] else [f"on a 390 px phone the gallery is laid out {width} px wide"]
    errors += [f"390×844: {p}" for p in text_problems(driver)]
    driver.save_screenshot(str(screenshot))
    return errors


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    root = binary / "test-output" / "browser"
    shutil.rmtree(root, ignore_errors=True)
    out = root / "gallery"
    out.mkdir(parents=True)
    scenes, sweeps = build_gallery(bookspin, source, out)

    with serve(out) as url, open_browser(chromium, driver_path, size=SCREEN,
                                         media=True) as driver:
        errors = check_page(driver, url, out, scenes, sweeps, root / "gallery.png")
        errors += check_phone(driver, url, root / "gallery-390x844.png")
    if errors:
        fail("\n  " + "\n  ".join(errors))
    print("PASS: the gallery opens in Chromium; videos, images and links all load")
    return 0


if __name__ == "__main__":
    sys.exit(main())
