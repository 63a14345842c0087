#!/usr/bin/env python3
"""Screenshots of a built explorer page (docs/explorer.md) in headless Chromium, for looking at
what the page draws: one PNG per query and window size.

Usage: explorer-shots.py EXPLORER_HTML OUT_DIR [--size WxH ...] [--t T] QUERY...
  QUERY: a URL query without '?', e.g. 'scene=compare-methods-x' or
         'scene=fig09-matrix-unstable-x&compare=1'. --t advances the page to time T first
         (the time slider's way). Writes OUT_DIR/<n>-<WxH>.png and prints each path.
"""
import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests" / "browser"))
from browser import find_browser, open_browser  # noqa: E402
from explorer_test import EXPLORER_WINDOW, load, slide_to  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("page")
    ap.add_argument("out")
    ap.add_argument("queries", nargs="+")
    ap.add_argument("--size", action="append", default=None, help="WxH (default 1280x720)")
    ap.add_argument("--t", type=float, default=0.0)
    a = ap.parse_args()
    page = Path(a.page).resolve().as_uri()
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    chromium, driver_path = find_browser()
    with open_browser(chromium, driver_path, script_timeout=600, **EXPLORER_WINDOW) as driver:
        for size in a.size or ["1280x720"]:
            w, h = (int(x) for x in size.split("x"))
            driver.set_window_size(w, h)
            driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                                   {"width": w, "height": h, "deviceScaleFactor": 1,
                                    "mobile": False})
            for n, query in enumerate(a.queries):
                load(driver, f"{page}?{query}")
                if a.t > 0:
                    slide_to(driver, a.t)
                time.sleep(0.5)
                path = out / f"{n}-{size}.png"
                driver.save_screenshot(str(path))
                print(f"{path}: {query}")


if __name__ == "__main__":
    main()
