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
and saves a full-page screenshot as build/test-output/browser/gallery.png.

Usage: gallery_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Needs Debian's chromium, chromium-driver and python3-selenium (scripts/install-deps.sh). Where
one is missing the test is skipped (exit 77), except under CI=true, where that is a failure.
"""
import functools
import http.server
import json
import os
import shutil
import subprocess
import sys
import threading
import time
import urllib.request
from pathlib import Path

SKIP = 77
CLIP_W, CLIP_H = 160, 96  # even sizes: H.264 4:2:0 needs them
FRAMES = 8


def fail(message):
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def missing(what):
    """A missing browser piece: a failure under CI, a skip elsewhere."""
    if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
        fail(f"{what} (CI=true: the browser test must run; install with scripts/install-deps.sh)")
    print(f"SKIPPED: {what}; install chromium, chromium-driver and python3-selenium "
          "(scripts/install-deps.sh) to run the browser test")
    sys.exit(SKIP)


def find_browser():
    try:
        import selenium  # noqa: F401
    except ImportError:
        missing(f"python module selenium not found by {sys.executable}")
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver") or (
        "/usr/bin/chromedriver" if os.path.exists("/usr/bin/chromedriver") else None)
    if not chromium:
        missing("chromium not found on PATH")
    if not driver:
        missing("chromedriver not found (Debian package chromium-driver)")
    return chromium, driver


def run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        fail(f"{' '.join(map(str, cmd))} exited {r.returncode}:\n{r.stdout}")
    return r.stdout


def build_gallery(bookspin, source, out):
    scenes = [source / "scenes" / "fig09-matrix-unstable-x.toml",
              source / "scenes" / "compare-normalization.toml"]
    size = ["--set", f"render.width={CLIP_W}", "--set", f"render.height={CLIP_H}",
            "--set", 'render.preset="ultrafast"']
    for scene in scenes:
        run([bookspin, "render", scene, *size, "--frames", str(FRAMES), "--jobs", "2",
             "-o", out])
        run([bookspin, "plot", scene, "--set", f"time.frames={FRAMES}", "--width", "640",
             "--height", "400", "-o", out])
    # Given comparison first: the page puts the paper's figure first all the same.
    run([bookspin, "gallery", out, *reversed(scenes)])
    return [s.stem for s in scenes]


def clip_size(mp4):
    """(width, height) of the first video stream, from ffprobe."""
    text = run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
                "stream=width,height", "-of", "json", mp4])
    stream = json.loads(text)["streams"][0]
    return stream["width"], stream["height"]


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(folder):
    handler = functools.partial(QuietHandler, directory=str(folder))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/"


def open_browser(chromium, driver_path, profile):
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--no-first-run", "--mute-audio", "--window-size=1280,1000",
                "--autoplay-policy=no-user-gesture-required", f"--user-data-dir={profile}"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(executable_path=driver_path), options=options)


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


def wait_for(driver, script, done, timeout=60):
    """Runs `script` until done(result) or the timeout; returns the last result."""
    deadline = time.monotonic() + timeout
    while True:
        result = driver.execute_script(script)
        if done(result) or time.monotonic() > deadline:
            return result
        time.sleep(0.25)


def check_page(driver, url, out, names, screenshot):
    errors = []
    driver.get(url + "index.html")
    # Lazy images load when near the viewport: scroll through the page once.
    height = driver.execute_script("return document.body.scrollHeight")
    for y in range(0, height + 1000, 500):
        driver.execute_script(f"window.scrollTo(0, {y})")
        time.sleep(0.05)
    driver.execute_script("window.scrollTo(0, 0)")

    sections = driver.execute_script(
        "return Array.from(document.querySelectorAll('section.clip')).map(s => s.id)")
    if sections != names:
        errors.append(f"sections in the order {sections}, expected {names} (paper order)")
    made = driver.execute_script(
        "const p = document.querySelector('p.made'); return p ? p.textContent : ''")
    if "bookspin" not in made or "UTC" not in made:
        errors.append(f"no header saying how the page was made: {made!r}")
    print(f"header: {made}")

    videos = wait_for(driver, VIDEO_STATE,
                      lambda vs: all(v["readyState"] >= 1 or v["error"] for v in vs))
    if len(videos) != len(names):
        errors.append(f"{len(videos)} <video> elements, expected {len(names)}: {videos}")
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

    links = driver.execute_script(
        "return Array.from(document.querySelectorAll('a[href]')).map(a => a.getAttribute('href'))"
        ".concat(Array.from(document.querySelectorAll('video[poster]'))"
        ".map(v => v.getAttribute('poster')))")
    links = [h for h in links if not h.startswith(("#", "data:", "http:", "https:"))]
    csvs = [h for h in links if h.endswith(".csv")]
    if len(csvs) < len(names):
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
    import base64
    screenshot.write_bytes(base64.b64decode(shot["data"]))
    print(f"screenshot {screenshot}")

    for entry in driver.get_log("browser"):
        if entry["level"] == "SEVERE":
            errors.append(f"console: {entry['message']}")
    return errors


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    bookspin, source, binary = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    chromium, driver_path = find_browser()
    root = binary / "test-output" / "browser"
    shutil.rmtree(root, ignore_errors=True)
    out = root / "gallery"
    out.mkdir(parents=True)
    names = build_gallery(bookspin, source, out)

    server, url = serve(out)
    driver = open_browser(chromium, driver_path, root / "profile")
    try:
        errors = check_page(driver, url, out, names, root / "gallery.png")
    finally:
        driver.quit()
        server.shutdown()
    if errors:
        fail("\n  " + "\n  ".join(errors))
    print("PASS: the gallery opens in Chromium; videos, images and links all load")
    return 0


if __name__ == "__main__":
    sys.exit(main())
