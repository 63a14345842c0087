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
    while the table scrolls under it,
and saves the screenshot as build/test-output/browser/league.png.

Usage: league_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Needs Debian's chromium, chromium-driver and python3-selenium (scripts/install-deps.sh). Where
one is missing the test is skipped (exit 77), except under CI=true, where that is a failure.
"""
import re
import shutil
import sys

from browser import (console_errors, fail, find_browser, open_browser, run, shown_digits,
                     test_arguments, text_problems)

SCENARIOS = ["book-intermediate-0.2", "book-largest-axis"]
METHODS = "rigid-quaternion:rk4,rigid-matrix:euler"

CELLS = """
return Array.from(document.querySelectorAll('table tr')).map(r =>
  Array.from(r.children).map(c => c.textContent.trim()));
"""


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
        driver.set_window_size(1366, 300)
        header = driver.execute_script("""
          window.scrollTo(0, document.documentElement.scrollHeight);
          const r = document.querySelector('table tr th').getBoundingClientRect();
          return [r.top, r.bottom, window.scrollY];""")
        print(f"scrolled by {header[2]} px: the header row at {header[0]:.0f}..{header[1]:.0f} px")
        if not header[2] > 0 or not (-0.5 <= header[0] and header[1] <= 80):
            errors.append(f"the scenarios' row scrolls away: at {header[0]:.0f}..{header[1]:.0f} px "
                          f"scrolled by {header[2]} px")
        driver.save_screenshot(str(root / "league-scrolled.png"))
        print(f"screenshot {root / 'league.png'}")
    if errors:
        fail("\n  " + "\n  ".join(errors))
    print("PASS: the league page reads at 1366×768")
    return 0


if __name__ == "__main__":
    sys.exit(main())
