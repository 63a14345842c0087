#!/usr/bin/env python3
"""The conformance kit's league page (`bookspin flipcheck league`, docs/flipcheck.md) in a real
browser: headless Chromium at 1366×768, as a reader opens it.

Judges two of bookspin's methods and the exact motion in two scenarios (a turning one and a
stable spin), writes the league page and checks in Chromium that
  - the table has a row per motion and a column per scenario, a cell each,
  - no text is under 12 px and none runs past its box, and the table fits the window's width
    (docs/outputs.md, "Pictures"),
  - every number in a cell has at most the three significant digits the league prints
    (a measure without an uncertainty: its thresholds' precision, docs/flipcheck.md),
  - the page logs no console error,
  - the page says what the motions' names mean (bookspin's own models, the engines built in,
    the JavaScript engines by their npm package), and the scenarios' row stays on screen
    while the table scrolls under it, with no sliver of the rows showing above it (the pixels
    above the header's text at its top are the header's own, at 1366 and 390 px wide),
  - on a phone (390×844, mobile: the page's viewport) the page is laid out at the phone's
    width (not at 980 px shrunk to a third), its text at least 12 px, and the table scrolled
    sideways keeps its first column (the motions' names) on screen,
and saves the screenshots as build/test-output/browser/league*.png.

Usage: league_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Needs Debian's chromium, chromium-driver and python3-selenium (scripts/install-deps.sh). Where
one is missing the test is skipped (exit 77), except under CI=true, where that is a failure.
"""
import re
import shutil
import struct
import sys
import zlib

from browser import (console_errors, fail, find_browser, open_browser, run, shown_digits,
                     test_arguments, text_problems)

SCENARIOS = ["book-intermediate-0.2", "book-largest-axis"]
METHODS = "rigid-quaternion:rk4,rigid-matrix:euler"

CELLS = """
return Array.from(document.querySelectorAll('table tr')).map(r =>
  Array.from(r.children).map(c => c.textContent.trim()));
"""


def png_rows(data):
    """The RGB rows of PNG `data` (8-bit RGB or RGBA, not interlaced: Chromium's screenshots)."""
    width, height, depth, kind = struct.unpack(">IIBB", data[16:26])
    if depth != 8 or kind not in (2, 6):
        fail(f"a screenshot PNG of bit depth {depth}, colour type {kind}")
    raw, at = b"", 8
    while at < len(data):
        n, tag = struct.unpack(">I4s", data[at:at + 8])
        if tag == b"IDAT":
            raw += data[at + 8:at + 8 + n]
        at += 12 + n
    raw = zlib.decompress(raw)
    bpp = 3 if kind == 2 else 4
    stride = width * bpp
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * bpp:x * bpp + 3]) for x in range(width)])
        prev = line
    return rows


# JavaScript: the page scrolled to the table's box (no taller than the window), the box
# scrolled to its end; the header row's box, the top of its first cell's text and the box's
# top, in CSS px of the window, and how far the box scrolled.
SCROLLED_HEADER = """
  const box = document.querySelector('.league');
  window.scrollTo(0, box.getBoundingClientRect().top + window.scrollY);
  box.scrollTop = box.scrollHeight;
  const ths = [...document.querySelectorAll('thead th')].map((c) => c.getBoundingClientRect());
  const range = document.createRange(); range.selectNodeContents(document.querySelector('thead th'));
  const b = box.getBoundingClientRect();
  const right = Math.min(b.right, ...ths.map((r) => r.right));
  return [ths[0].left, ths[0].top, Math.min(b.right, Math.max(...ths.map((r) => r.right))), ths[0].bottom,
          range.getBoundingClientRect().top, box.scrollTop, b.top];
"""


def sliver(driver, where):
    """Scrolled to the table's end, the pixels of the header row's band above its text: the
    header's own (its grey, its border), no row under it showing (a pass's green, a fail's
    red, a cell's text); a list of what is wrong."""
    left, top, right, bottom, text_top, scrolled, box_top = driver.execute_script(SCROLLED_HEADER)
    if not scrolled > 0:
        return [f"{where}: the table does not scroll (the window too tall for the check)"]
    scale = driver.execute_script("return window.devicePixelRatio")
    rows = png_rows(driver.get_screenshot_as_png())
    foreign = set()
    for y in range(max(0, int(box_top * scale)), max(1, int(text_top * scale) - 1)):
        for x in range(max(0, int(left * scale)), min(len(rows[0]), int(right * scale))):
            r, g, b = rows[y][x]
            # The header's #f4f4f4, its borders' #ccc and what lies between: greys.
            if max(r, g, b) - min(r, g, b) > 6 or max(r, g, b) < 0xb0:
                foreign.add((r, g, b))
    print(f"{where}: scrolled {scrolled} px, the header row at {top:.1f}..{bottom:.1f} px, "
          f"its text from {text_top:.1f}; colours above its text not the header's: {sorted(foreign)[:5]}")
    problems = []
    if not (box_top - 0.5 <= top and bottom <= box_top + 80):
        problems.append(f"{where}: the scenarios' row scrolls away: at {top:.0f}..{bottom:.0f} px")
    if foreign:
        problems.append(f"{where}: rows show above the sticky header's text: colours {sorted(foreign)[:5]}")
    return problems


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    root = binary / "test-output" / "browser"
    out = root / "league"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    scenes = [source / "scenes" / "flipcheck" / f"{name}.toml" for name in SCENARIOS]
    run([bookspin, "flipcheck", "export", *scenes, "-o", out])
    motions = [out / f"{name}-exact.csv" for name in SCENARIOS]
    run([bookspin, "flipcheck", "league", *scenes, "--motions", *motions, "--methods", METHODS,
         "-o", out])

    errors = []
    with open_browser(chromium, driver_path, size=(1366, 768)) as driver:
        driver.get((out / "flipcheck-league.html").resolve().as_uri())
        rows = driver.execute_script(CELLS)
        print(f"{len(rows)} rows: {rows[0]}")
        if rows[0][1:] != SCENARIOS or len(rows) != 1 + 3:
            errors.append(f"expected a column per scenario {SCENARIOS} and 3 motions: {rows}")
        for row in rows[1:]:
            if len(row) != 1 + len(SCENARIOS) or not all(row[1:]):
                errors.append(f"a row without a cell per scenario: {row}")
            for cell in row[1:]:
                # Counts ("6/6") and the step counts are whole; every measured number has at
                # most 3 significant digits.
                for number in re.findall(r"(?<![\w/.])-?\d+\.\d+(?:e-?\d+)?", cell):
                    if shown_digits(number.split("e")[0]) > 3:
                        errors.append(f"{number} in {cell!r}: more digits than its precision")
        errors += text_problems(driver)
        wide = driver.execute_script(
            "return [document.documentElement.scrollWidth, document.documentElement.clientWidth]")
        if wide[0] > wide[1]:
            errors.append(f"the table is {wide[0]} px wide in a {wide[1]} px window")
        errors += [f"console: {entry['message']}" for entry in console_errors(driver)]
        # The names explained; the scenarios' row stays on screen scrolled to the last motion
        # (a window short enough to scroll: the league of make figures is 8 screens long).
        names = driver.execute_script(
            "const d = document.querySelector('dl.names'); return d ? d.textContent : ''")
        for name in ("rigid-matrix euler", "mujoco euler", "mujoco-js@0.0.7+euler", "exact"):
            if name not in names:
                errors.append(f"the page does not say what {name!r} names: {names!r}")
        driver.save_screenshot(str(root / "league.png"))
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                               {"width": 1366, "height": 120, "deviceScaleFactor": 1, "mobile": False})
        errors += sliver(driver, "1366×120")
        driver.save_screenshot(str(root / "league-scrolled.png"))
        # A phone: laid out at its width, its text readable, the first column kept.
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                               {"width": 390, "height": 844, "deviceScaleFactor": 2, "mobile": True})
        driver.get((out / "flipcheck-league.html").resolve().as_uri())
        width = driver.execute_script("return [document.documentElement.clientWidth, window.innerWidth, "
                                      "!!document.querySelector('meta[name=viewport]')]")
        print(f"390×844 phone: laid out {width[0]} px wide, window {width[1]} px, viewport meta {width[2]}")
        if width[0] != 390 or width[1] != 390:
            errors.append(f"on a 390 px phone the page is laid out {width[0]} px wide (window {width[1]}): "
                          "no viewport, text shrunk")
        # Text at least 12 px; none past the window but the table's, which scrolls sideways.
        phone_text = driver.execute_script("""
          return [...document.querySelectorAll('body *')].filter((e) =>
              [...e.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim())).map((e) =>
            [e.textContent.trim().slice(0, 40), parseFloat(getComputedStyle(e).fontSize),
             !e.closest('table') && e.getBoundingClientRect().right > document.documentElement.clientWidth + 1]);""")
        small = [t for t in phone_text if t[1] < 12]
        past = [t for t in phone_text if t[2]]
        print(f"390×844: {len(phone_text)} texts, the smallest {min(t[1] for t in phone_text)} px")
        if small or past:
            errors.append(f"390×844: text under 12 px {small[:3]}, past the window {past[:3]}")
        driver.save_screenshot(str(root / "league-390x844.png"))
        kept = driver.execute_script("""
          const box = document.querySelector('.league');
          box.scrollLeft = box.scrollWidth;
          const th = document.querySelector('tbody th').getBoundingClientRect();
          return [box.scrollLeft, th.left, th.right, box.getBoundingClientRect().left];""")
        print(f"scrolled sideways by {kept[0]} px: the motions' column at {kept[1]:.0f}..{kept[2]:.0f} px")
        if not kept[0] > 0:
            errors.append("on a 390 px phone the table does not scroll sideways in its box")
        if not (kept[3] - 0.5 <= kept[1] <= kept[3] + 1):
            errors.append(f"scrolled sideways by {kept[0]} px the motions' column goes: at {kept[1]:.0f} px")
        driver.save_screenshot(str(root / "league-390x844-sideways.png"))
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                               {"width": 390, "height": 200, "deviceScaleFactor": 2, "mobile": True})
        errors += sliver(driver, "390×200")
        print(f"screenshot {root / 'league.png'}")
    if errors:
        fail("\n  " + "\n  ".join(errors))
    print("PASS: the league page reads at 1366×768")
    return 0


if __name__ == "__main__":
    sys.exit(main())
