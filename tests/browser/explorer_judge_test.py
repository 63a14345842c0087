#!/usr/bin/env python3
"""The explorer page's "Judge a motion" panel (docs/explorer.md, docs/flipcheck.md) against the
command line: `bookspin flipcheck judge` in headless Chromium, the same C++ compiled to
WebAssembly (web/judge_bindings.cpp).

Builds the page's program with web/build.sh BINARY_DIR, writes the page with `bookspin explore
scenes/flipcheck/*.toml`, and checks:
  - the panel offers every scenario of scenes/flipcheck/ and no other scene (the page holds two
    more, which flipcheck would take);
  - for every scenario and several motions (the exact motion of `bookspin flipcheck export`;
    `bookspin simulate` of rigid-matrix euler; and perturbed copies of the exact motion that
    fail: ω scaled by 1 + 1e-3, the last half of the rows cut, the orientation turned away
    about world z by 0.21·t/t_end rad (no row on the 0.1 rad limit, where the page's
    quad-precision long double and the native x87 one may round either way), ω given in the
    world frame only), the page's judgement
    through window.explorer.judgeMotion equals `bookspin flipcheck judge`'s CSV in every
    column: text equal, an empty cell null, numbers to 1e-9 relative (ABS_FLOOR absolute for
    the round-off-sized measures of a motion that is the exact one: see below);
  - once through the panel itself: the file input given a path (send_keys), the verdict, the
    failures in words and every number of the table equal to the command line's, and the
    replay drawing both bodies (at least 2 % of its canvas);
  - the scenario JSON and exact-motion CSV the panel downloads are `flipcheck export`'s bytes
    (the JSON) and numbers (the CSV, to 1e-9);
  - a bad motion file: the hook rejects with the command line's one line and the panel shows
    it;
  - a link to the panel, explorer.html#judge (the gallery's kit section), opens it on the
    page's scenario, and where the page's scene is no scenario the page goes to one;
  - a measure the judge bounds shows its limit beside it, in the values' form (1 × 10⁻⁶, not
    0.000001), a value over it marked (the turned motion's orientation error).
  - at 1366×768 the scenario menu shows each scenario's name whole (not cut at the menu's
    edge), its title whole on the line under it.
Screenshots: BINARY_DIR/test-output/browser/explorer-judge-{1280x720,1366x768,390x844}.png.

Usage: explorer_judge_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import csv
import io
import json
import math
import re
import subprocess
import time
import tomllib
from pathlib import Path

from browser import (console_errors, fail, find_browser, open_browser, require, run, serve,
                     shown_digits, shown_number, test_arguments, wait_for)

TOL = 1e-9
# The exact motion judged against itself measures round-off: its orientation error is ~1e-16
# rad, its drifts ~1e-15, computed natively with x87's 80-bit long double in the exact motion
# and in the page with WebAssembly's 128-bit one (docs/explorer.md, "Speed"). Below this floor
# two numbers agree whatever their ratio. The orientation error is the largest over every row:
# over book-intermediate-0.002's 37,500 rows the page's exact motion (WebAssembly's libm) and
# the native one written to the motion file differ by up to 1.4e-13 rad, 10^12 times below
# the judge's 0.1 rad.
ABS_FLOOR = 1e-12
TEXT_COLUMNS = {"scenario", "motion", "verdict", "failures", "version", "scenario_sha256"}


def read_csv(path):
    rows = list(csv.reader(io.StringIO(Path(path).read_text())))
    return rows[0], rows[1:]


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)


def quat_mul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return [aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw]


def perturbed(exact_csv, folder, name):
    """The exact motion's CSV turned into motions that fail: {file name: path}."""
    header, rows = read_csv(exact_csv)
    col = {c: i for i, c in enumerate(header)}
    out = {}

    def emit(tag, hdr, body):
        path = folder / f"{name}-{tag}.csv"
        write_csv(path, hdr, body)
        out[path.name] = path

    scaled = [list(r) for r in rows]
    for r in scaled:
        for c in ("wx", "wy", "wz"):
            r[col[c]] = repr(float(r[col[c]]) * 1.001)
    emit("omega-scaled", header, scaled)
    emit("cut", header, rows[: len(rows) // 2])
    t_end = float(rows[-1][col["t"]])
    turned = []
    for r in rows:
        # 0.21, not 0.2: with 0.2 the middle row's error is the limit itself, and "past it from
        # step" then rests on the last bit (50000 on the page, 50001 natively).
        angle = 0.21 * float(r[col["t"]]) / t_end
        q = [float(r[col[c]]) for c in ("qw", "qx", "qy", "qz")]
        q = quat_mul([math.cos(angle / 2), 0.0, 0.0, math.sin(angle / 2)], q)
        turned.append([r[col["t"]], *map(repr, q), r[col["wx"]], r[col["wy"]], r[col["wz"]]])
    emit("turned", ["t", "qw", "qx", "qy", "qz", "wx", "wy", "wz"], turned)
    # The middle third of the rows turned by 5° about world z (up to 5.05° at its end, so that
    # one row is the largest turn, where the page and the command line both find it), ω (body
    # frame) as it was: L turns by 0.0873 rad there and back.
    middle = []
    third = len(rows) // 3
    for k, r in enumerate(rows):
        q = [float(r[col[c]]) for c in ("qw", "qx", "qy", "qz")]
        if third <= k < 2 * third:
            angle = math.radians(5.0 * (1.0 + 0.01 * (k - third) / third))
            q = quat_mul([math.cos(angle / 2), 0.0, 0.0, math.sin(angle / 2)], q)
        middle.append([r[col["t"]], *map(repr, q), r[col["wx"]], r[col["wy"]], r[col["wz"]]])
    emit("middle-turned", ["t", "qw", "qx", "qy", "qz", "wx", "wy", "wz"], middle)
    keep = ["t", "qw", "qx", "qy", "qz", "wx_world", "wy_world", "wz_world"]
    emit("world", keep, [[r[col[c]] for c in keep] for r in rows])
    return out


# Each of the judge's failure lines (analysis::judge_motion) and the column it is about, the
# line's start (the turn-overs' count: "N turn-overs, exact M").
FAILURE_COLUMNS = (("ends at step", "last_step"), ("starts ", "start_error"),
                   ("energy drift", "energy_drift"), ("|L| drift", "L_drift"),
                   ("L turned", "L_direction_error"), ("first turn-over", "first_flip"),
                   ("orientation error", "orientation_error"), ("tumbles at", "tumble_time"),
                   ("r = 2E", "separatrix_approach"))


def failure_marks(driver, failures, where):
    """Every failure line's measure marked in the panel's table (the row's class "over", red),
    its limit beside it as the line gives it: the number after "limit" equal, or the line's own
    words where the measure has no bound of its own."""
    from selenium.webdriver.common.by import By

    rows = {}
    for tr in driver.find_elements(By.CSS_SELECTOR, "#judgeTable tr"):
        key = (tr.find_elements(By.CSS_SELECTOR, "th code") or [tr.find_element(By.TAG_NAME, "th")])[0].text
        cells = tr.find_elements(By.TAG_NAME, "td")
        colour = tr.find_element(By.TAG_NAME, "td").value_of_css_property("color")
        rows[key] = ("over" in (tr.get_attribute("class") or "").split(), cells[1].text if len(cells) > 1 else "", colour)
    # The CSV's failures are joined by "; ", which a line's own "(limit 0.01; past it from step
    # 36)" also holds: split only outside the parentheses.
    for line in [f for f in re.split(r"; (?![^()]*\))", failures) if f]:
        column = next((c for start, c in FAILURE_COLUMNS if line.startswith(start)), None)
        if column is None and re.match(r"\d+ turn-overs?, exact", line):
            column = "flips"
        if column is None:
            fail(f"{where}: a failure line the test does not know: {line!r}")
        marked, limit, colour = rows.get(column, (False, "", ""))
        said = re.search(r"\(limit ([-0-9.e+]+)", line)
        if said:
            shown = re.search(r"limit (.+?)(,|$)", limit)
            ok = shown is not None and math.isclose(shown_number(shown.group(1)), float(said.group(1)), rel_tol=1e-3)
        else:
            ok = line in limit
        print(f"{where}: {line!r}: {column} marked {marked} ({colour}), beside it {limit!r}")
        if not marked or not ok or colour != "rgba(255, 112, 112, 1)":
            fail(f"{where}: the failure {line!r}: its row {column} marked {marked} in {colour}, "
                 f"beside it {limit!r}")


def same_number(got, expected):
    return abs(got - expected) <= TOL * max(abs(got), abs(expected)) or \
        abs(got - expected) <= ABS_FLOOR


def compare_row(where, page, header, cli):
    """fail() unless the page's judgement (a dict) equals the command line's CSV row."""
    if sorted(page) != sorted(header):
        fail(f"{where}: the page's keys {sorted(page)} are not the judgement CSV's {sorted(header)}")
    cells = dict(zip(header, cli))
    for column, cell in zip(header, cli):
        got = page[column]
        # The row of a largest error is the error's: where both errors are round-off (under
        # ABS_FLOOR), their rows are round-off's too, and any row is the same answer.
        measure = column[:-len("_step")] if column.endswith("_step") else None
        if measure in cells and cells[measure] != "" and page.get(measure) is not None and \
                abs(float(cells[measure])) <= ABS_FLOOR and abs(float(page[measure])) <= ABS_FLOOR:
            continue
        if column in TEXT_COLUMNS:
            ok = got == cell
        elif cell == "":
            ok = got is None
        else:
            ok = isinstance(got, (int, float)) and same_number(float(got), float(cell))
        if not ok:
            fail(f"{where}: column {column}: page {got!r}, bookspin flipcheck judge {cell!r}")


def judge_in_page(driver, base_url, scenario, file_name):
    """window.explorer.judgeMotion of the served file `file_name`: {ok, row} or {error}."""
    return driver.execute_async_script("""
        const [url, scenario, name, done] = arguments;
        fetch(url).then((r) => r.text())
          .then((text) => window.explorer.judgeMotion(scenario, text, name))
          .then((row) => done({ok: true, row}), (e) => done({ok: false, error: String(e.message)}));
    """, base_url + "motions/" + file_name, scenario, file_name)


# JavaScript: the scenario menu's chosen text, its width in the menu's font, the room the menu
# gives it (its box less its padding and the arrow's 24 px), and the title line under it.
MENU_FITS = """
  const menu = document.getElementById('judgeScenario'), style = getComputedStyle(menu);
  const g = document.createElement('canvas').getContext('2d');
  g.font = `${style.fontWeight} ${style.fontSize} ${style.fontFamily}`;
  const shown = menu.options[menu.selectedIndex].text;
  const title = document.getElementById('judgeScenarioTitle');
  return {shown, text: g.measureText(shown).width,
          room: menu.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight) - 24,
          title: title.textContent,
          titleRight: title.getBoundingClientRect().right,
          boxRight: document.getElementById('judgeBox').getBoundingClientRect().right};
"""


def main():
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select

    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")

    out = binary / "test-output" / "explorer-judge"
    motions = out / "motions"
    shots = binary / "test-output" / "browser"
    for d in (out, motions, shots):
        d.mkdir(parents=True, exist_ok=True)
    scenes = sorted((source / "scenes" / "flipcheck").glob("*.toml"))
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    # Two scenes flipcheck would take that are not the kit's: the panel offers the kit's alone.
    others = [source / "scenes" / f"{n}.toml" for n in ("fig09-matrix-unstable-x", "t-handle-dzhanibekov")]
    run([bookspin, "explore", *map(str, scenes + others), "-o", str(out)])
    run([bookspin, "flipcheck", "export", *map(str, scenes), "-o", str(motions)])

    # Every scenario's motions, and the command line's judgement of them, one CSV a scenario.
    cases = {}
    for scene in scenes:
        name = scene.stem
        exact = motions / f"{name}-exact.csv"
        files = {exact.name: exact}
        simulated = motions / f"{name}-rigid-matrix-euler.csv"
        # stdout alone: a method that diverges says so on stderr (its rows end there).
        sim = subprocess.run([bookspin, "simulate", str(scene), "--set", 'model.kind="rigid-matrix"',
                              "--set", 'model.integrator="euler"'],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if sim.returncode != 0:
            fail(f"bookspin simulate {scene.name} exited {sim.returncode}: {sim.stderr}")
        simulated.write_text(sim.stdout)
        files[simulated.name] = simulated
        files.update(perturbed(exact, motions, name))
        judged = out / "cli"
        # Exit 3: perturbed motions among them fail (docs/flipcheck.md, "In a CI job").
        r = subprocess.run([bookspin, "flipcheck", "judge", str(scene), *sorted(files), "-o",
                            str(judged), "--force"], cwd=motions, capture_output=True, text=True)
        if r.returncode not in (0, 3):
            fail(f"bookspin flipcheck judge {scene.name} exited {r.returncode}: {r.stderr}")
        header, rows = read_csv(judged / f"{name}-judge.csv")
        cases[name] = (header, {r[header.index("motion")]: r for r in rows})
    bad = motions / "bad.csv"
    bad.write_text("t,qw,qx,qy,qz,wx,wy,wz\n0,1,0,0,0,1,2,3\n0.01,1,0,0,0,1,nan,3\n")
    r = subprocess.run([bookspin, "flipcheck", "judge", str(source / "scenes" / "flipcheck" /
                        "mujoco-test-box.toml"), "bad.csv", "-o", str(out / "bad")],
                       cwd=motions, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    cli_line = r.stderr.strip()
    if r.returncode != 2 or not cli_line.startswith("bookspin: error: bad.csv:3: wy:"):
        fail(f"bookspin flipcheck judge of bad.csv: exit {r.returncode}, {cli_line!r}")
    # A quote left open in a column the judge does not read (tests/bad_motions: the command
    # line's line there, for mujoco-test-box too): named at its row and column, never blamed on t.
    quotes = {}
    for case in ("quote-left-open-in-a-quoted-column", "quote-left-open-at-the-end"):
        catalogue = source / "tests" / "bad_motions"
        (motions / f"{case}.csv").write_bytes((catalogue / f"{case}.csv").read_bytes())
        quotes[f"{case}.csv"] = (catalogue / f"{case}.expected").read_text().strip().replace(
            "{FILE}", f"{case}.csv")

    # The page and the motion files served from one origin (a page opened from disk may not
    # fetch), the files fetched by the page itself rather than sent through the driver.
    with serve(out) as base_url, \
            open_browser(chromium, driver_path, size=(1280, 720),
                         exact_viewport=True) as driver:
        driver.get(base_url + "explorer.html?scene=mujoco-test-box")
        if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
            fail(f"the page never became ready: {driver.get_log('browser')}")
        offered = driver.execute_script("return window.explorer.judgeScenarios()")
        if sorted(offered) != sorted(cases):
            fail(f"the panel offers {offered}, not every scenario of scenes/flipcheck: {sorted(cases)}")

        # 1. Through the hook: every scenario, every motion, every column.
        checked = 0
        for name, (header, cli_rows) in cases.items():
            t0 = time.monotonic()
            for file_name, cli in cli_rows.items():
                got = judge_in_page(driver, base_url, name, file_name)
                if not got["ok"]:
                    fail(f"{name} {file_name}: the page refused it: {got['error']}")
                compare_row(f"{name} {file_name}", got["row"], header, cli)
                checked += 1
            verdicts = {f: c[header.index("verdict")] for f, c in cli_rows.items()}
            print(f"{name}: {len(cli_rows)} motions equal ({time.monotonic() - t0:.1f} s): {verdicts}")
            if "fail" not in verdicts.values() or verdicts[f"{name}-exact.csv"] != "pass":
                fail(f"{name}: the exact motion must pass and the perturbed ones fail: {verdicts}")
        print(f"hook: {checked} judgements equal to bookspin flipcheck judge's")

        # 2. A bad file: the command line's one line.
        got = judge_in_page(driver, base_url, "mujoco-test-box", "bad.csv")
        if got.get("ok") or "bookspin: error: " + got["error"] != cli_line:
            fail(f"bad.csv: the page said {got}, the command line {cli_line!r}")
        for file_name, line in quotes.items():
            got = judge_in_page(driver, base_url, "mujoco-test-box", file_name)
            if got.get("ok") or got["error"] != line:
                fail(f"{file_name}: the page said {got}, the command line {line!r}")

        # 2b. A link to the panel (the gallery's kit section): explorer.html#judge opens it on
        #     the page's scene.
        # A page on a scene that is no scenario (the gallery's link names none; this page's
        # own default, no scene) goes to a scenario, the one the panel shows.
        driver.get(base_url + "explorer.html#judge")
        if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
            fail(f"the page at #judge never became ready: {driver.get_log('browser')}")
        opened = wait_for(driver, "return [!document.getElementById('judge').hidden, "
                          "document.getElementById('judgeScenario').value, window.explorer.state().scene]",
                          lambda o: o[0] and o[2], 10)
        if not opened[0] or opened[1] != opened[2] or opened[2] not in cases:
            fail(f"explorer.html#judge with no scene opened the panel on {opened[1]!r} over the "
                 f"page's scene {opened[2]!r}, not a scenario's")
        driver.get(base_url + "explorer.html?scene=book-intermediate-0.05#judge")
        if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
            fail(f"the page at #judge never became ready: {driver.get_log('browser')}")
        opened = driver.execute_script(
            "return [!document.getElementById('judge').hidden, document.getElementById('judgeScenario').value]")
        if opened != [True, "book-intermediate-0.05"]:
            fail(f"explorer.html#judge did not open the panel on the page's scenario: {opened}")
        driver.execute_script("document.getElementById('judgeClose').click()")

        # 3. Through the panel: the file input, the verdict, the failures, the table.
        driver.execute_script("document.getElementById('judgeOpen').click()")
        name = "book-intermediate-0.2"
        Select(driver.find_element(By.ID, "judgeScenario")).select_by_value(name)
        header, cli_rows = cases[name]
        file_name = f"{name}-turned.csv"
        driver.find_element(By.ID, "judgeFile").send_keys(str((motions / file_name).resolve()))
        shown = wait_for(driver, "return !document.getElementById('judgeResult').hidden", bool, 120)
        if not shown:
            fail(f"the panel showed no judgement: {driver.find_element(By.ID, 'judgeError').text}")
        cli = dict(zip(header, cli_rows[file_name]))
        verdict = driver.find_element(By.ID, "judgeVerdict").text
        if not verdict.startswith("FAIL" if cli["verdict"] == "fail" else "PASS") or file_name not in verdict:
            fail(f"the panel's verdict {verdict!r}, the command line's {cli['verdict']}")
        failures = [li.text for li in driver.find_elements(By.CSS_SELECTOR, "#judgeFailures li")]
        if "; ".join(failures) != cli["failures"]:
            fail(f"the panel's failures {failures}, the command line's {cli['failures']!r}")
        # What judged it (docs/flipcheck.md, "Versions"): the page's version is the program's.
        stamp = driver.find_element(By.ID, "judgeStamp").text
        if cli["version"] not in stamp or cli["scenario_sha256"] not in stamp:
            fail(f"the panel says {stamp!r}: not judged by {cli['version']}, {cli['scenario_sha256']}")
        if driver.find_element(By.ID, "version").text != cli["version"]:
            fail(f"the page's version {driver.find_element(By.ID, 'version').text!r}, the "
                 f"command line's {cli['version']!r}")
        # Each row: its readable label, its CSV key (code), its number at four significant
        # digits (a count whole) and, in the cell's title, every digit the CSV holds.
        table = {}
        for tr in driver.find_elements(By.CSS_SELECTOR, "#judgeTable tr"):
            keys = tr.find_elements(By.CSS_SELECTOR, "th code")
            td = tr.find_element(By.TAG_NAME, "td")
            key = keys[0].text if keys else tr.find_element(By.TAG_NAME, "th").text
            table[key] = (td.text, td.get_attribute("title"))
        for column, cell in cli.items():
            if column in TEXT_COLUMNS:
                continue
            shown_cell, full = table.get(column, (None, None))
            if shown_cell is None or (cell == "" and shown_cell != "—"):
                fail(f"the panel's {column}: {shown_cell!r}, the command line's {cell!r}")
            if cell == "":
                continue
            if not same_number(float(full), float(cell)):
                fail(f"the panel's {column} holds {full!r}, the command line's {cell!r}")
            # Shown: the page's own value (the title) to four significant digits; a count whole.
            whole = float(full).is_integer() and "." not in full and "e" not in full.lower()
            if (not whole and shown_digits(shown_cell) > 4) or \
                    not math.isclose(shown_number(shown_cell), float(full), rel_tol=5e-4, abs_tol=1e-300):
                fail(f"the panel shows {column} as {shown_cell!r}: not {full!r} to 4 significant digits")
        # A measure the judge bounds shows its limit (analysis::judge_rules, from the module);
        # over it, the row reads as a failure: the turned motion's orientation error among them.
        over = []
        for tr in driver.find_elements(By.CSS_SELECTOR, "#judgeTable tr"):
            cells = tr.find_elements(By.TAG_NAME, "td")
            key = (tr.find_elements(By.CSS_SELECTOR, "th code") or [tr.find_element(By.TAG_NAME, "th")])[0].text
            limit = cells[1].text if len(cells) > 1 else ""
            if not limit or limit.startswith("failed: "):  # a failure line's own words: below
                continue
            value, bound = float(cells[0].get_attribute("title")), shown_number(limit.split("limit ", 1)[1])
            # The limit in the form of the values beside it (web/src/precision.js): under 10⁻⁴
            # as m × 10ⁿ, never a run of zeros to count ("limit 0.000001").
            if re.search(r"\.0000", limit) or (bound < 1e-4 and " × 10" not in limit):
                fail(f"the panel's {key}: limit shown as {limit!r}, not in the values' form")
            marked = "over" in (tr.get_attribute("class") or "")
            if marked != (value > bound) or marked != limit.startswith("over its limit"):
                fail(f"the panel's {key}: {value} against {limit!r}, marked {'over' if marked else 'within'}")
            if marked:
                over.append(key)
        print(f"the panel's limits: over them {over}; the command line's failures {cli['failures']!r}")
        if "orientation_error" not in over:
            fail(f"the turned motion's orientation error is not shown over its limit: {over}")
        words = {"start_error": "start", "energy_drift": "energy drift", "L_drift": "|L| drift",
                 "L_direction_error": "L turned", "orientation_error": "orientation error",
                 "separatrix_approach": "separatrix"}
        wrong = [k for k in over if words.get(k, k) not in cli["failures"]]
        if wrong:
            fail(f"the panel marks {wrong} over a limit, which the command line does not fail: "
                 f"{cli['failures']!r}")
        failure_marks(driver, cli["failures"], f"{name} {file_name}")
        # The motion turned 5° in its middle third: it fails on L's turn alone, marked in the
        # table as in its failure line (the row had neither limit nor mark).
        middle_name = f"{name}-middle-turned.csv"
        driver.find_element(By.ID, "judgeFile").send_keys(str((motions / middle_name).resolve()))
        wait_for(driver, "return document.getElementById('judgeVerdict').textContent", lambda v: middle_name in v, 120)
        middle_cli = dict(zip(header, cli_rows[middle_name]))
        if "L turned" not in middle_cli["failures"]:
            fail(f"{middle_name}: the command line does not fail it on L's turn: {middle_cli['failures']!r}")
        failure_marks(driver, middle_cli["failures"], f"{name} {middle_name}")
        driver.save_screenshot(str(shots / "explorer-judge-marks-1280x720.png"))
        driver.find_element(By.ID, "judgeFile").send_keys(str((motions / file_name).resolve()))
        wait_for(driver, "return document.getElementById('judgeVerdict').textContent",
                 lambda v: v.endswith(file_name + " on " + name), 120)
        drawn = wait_for(driver, """
            const c = document.getElementById('judgeReplay');
            if (c.hidden || !c.width) return 0;
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0;
            for (let i = 3; i < d.length; i += 4) n += d[i] > 0;
            return n / (c.width * c.height);""", lambda f: f > 0.02, 30)
        if not drawn > 0.02:
            fail(f"the replay draws no body beside the exact one: {drawn} of its pixels")
        print(f"panel: {file_name} through the file input: {verdict}; replay draws "
              f"{100 * drawn:.0f} % of its canvas")
        time.sleep(1.0)
        driver.save_screenshot(str(shots / "explorer-judge-1280x720.png"))

        # 4. The downloads: flipcheck export's files.
        files = driver.execute_script("return window.explorer.judgeExport(arguments[0])", name)
        if files.get("json") != (motions / f"{name}.json").read_text():
            fail(f"{name}: the page's scenario JSON is not flipcheck export's")
        page_header, page_rows = list(csv.reader(io.StringIO(files["csv"])))[0], \
            list(csv.reader(io.StringIO(files["csv"])))[1:]
        cli_header, cli_exact = read_csv(motions / f"{name}-exact.csv")
        if page_header != cli_header or len(page_rows) != len(cli_exact):
            fail(f"{name}: the page's exact CSV has {page_header}, {len(page_rows)} rows")
        for a, b in zip(page_rows, cli_exact):
            if not all(same_number(float(x), float(y)) for x, y in zip(a, b)):
                fail(f"{name}: exact CSV row {a} against flipcheck export's {b}")
        print(f"downloads: {name}.json equal byte for byte, {name}-exact.csv to 1e-9")

        # 5. The bad file through the panel.
        Select(driver.find_element(By.ID, "judgeScenario")).select_by_value("mujoco-test-box")
        driver.find_element(By.ID, "judgeFile").send_keys(str(bad.resolve()))
        error = wait_for(driver, "return document.getElementById('judgeError').textContent",
                         lambda t: t.startswith("error:"), 60)
        if "bookspin: " + error != cli_line:
            fail(f"the panel shows {error!r} for bad.csv, the command line {cli_line!r}")

        # 6. A laptop's screen, 1366×768: every scenario's name whole in the menu (its text no
        # wider than the menu's box less its arrow) and its title whole on the line under it.
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                               {"width": 1366, "height": 768, "deviceScaleFactor": 1, "mobile": False})
        for scenario in offered:
            Select(driver.find_element(By.ID, "judgeScenario")).select_by_value(scenario)
            fits = driver.execute_script(MENU_FITS)
            if fits["text"] > fits["room"]:
                fail(f"at 1366×768 the scenario menu shows {fits['shown']!r} {fits['text']:.0f} px "
                     f"wide in {fits['room']:.0f} px: cut")
            expected = tomllib.loads((source / "scenes" / "flipcheck" / f"{scenario}.toml")
                                     .read_text())["scene"]["title"]
            if fits["title"] != expected or fits["titleRight"] > fits["boxRight"] + 0.5:
                fail(f"at 1366×768 the scenario's title under the menu reads {fits['title']!r} "
                     f"(expected {expected!r}), ending at {fits['titleRight']:.0f} px "
                     f"in a box ending at {fits['boxRight']:.0f}")
        print(f"1366×768: the menu shows each of {len(offered)} scenarios whole, its title under it")
        driver.save_screenshot(str(shots / "explorer-judge-1366x768.png"))

        # 7. A phone.
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                               {"width": 390, "height": 844, "deviceScaleFactor": 1, "mobile": True})
        Select(driver.find_element(By.ID, "judgeScenario")).select_by_value(name)
        driver.find_element(By.ID, "judgeFile").send_keys(str((motions / file_name).resolve()))
        wait_for(driver, "return !document.getElementById('judgeResult').hidden", bool, 120)
        time.sleep(1.0)
        edges = driver.execute_script(
            "return ['judgeBox', 'judgeTable', 'judgeReplay'].map((id) =>"
            " document.getElementById(id).getBoundingClientRect().right)")
        if max(edges) > 390:
            fail(f"the panel is wider than the phone: box, table, replay end at {edges} px")
        driver.save_screenshot(str(shots / "explorer-judge-390x844.png"))
        errors = [e for e in console_errors(driver) if "favicon" not in e.get("message", "")]
        if errors:
            fail(f"console errors: {errors}")
    print("explorer judge: the page judges as bookspin flipcheck judge does")


if __name__ == "__main__":
    main()
