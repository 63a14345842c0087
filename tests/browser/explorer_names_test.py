#!/usr/bin/env python3
"""A class's recordings named in its own alphabets in the explorer's "Phone-toss lab"
(docs/phone-lab.md, "Names"): the page names them by the same rule as the command line
(src/common/file_name.cpp compiled to WebAssembly with Debian's utf8proc).

Builds the page's program with web/build.sh BINARY_DIR, writes a page with `bookspin explore`,
and fits seven one-throw recordings named 太郎, Αθηνά, Юлия, "Wurf über dem Bett" (written
decomposed, as a Mac names it), تجربة, "🎲 würfel" and "anna b", beside "anna:b" and "anna*b"
(made alike by the rule, told apart by the pool):
  - through window.explorer.fitRecordings: the pool's name, every toss's recording and every
    toss scene's name and title are `bookspin fit`'s of the same files (its -fit.csv, the
    scene files it wrote), the names in NFC;
  - through the file input (the files chosen by their paths, the browser naming each File):
    the panel's summary names the pool, each toss's heading names its recording, and Play
    chooses the toss's scene by its name in the scene menu;
  - a recording with a 240-character name: named by its first 160, its toss played, the scene's
    title wraps inside the left column (it ran past its edge).
Screenshots: BINARY_DIR/test-output/browser/explorer-lab-names-1280x720.png and
explorer-lab-long-name-title-1280x720.png.

Usage: explorer_names_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import base64
import csv
import io
import re
import subprocess
import unicodedata

from browser import (console_errors, fail, find_browser, lab_page_under_test, open_browser, require,
                     serve, test_arguments, wait_for)

# The file's stem as written on disk, and the name the rule gives it.
NAMES = [("太郎", "太郎"), ("Αθηνά", "Αθηνά"), ("Юлия", "Юлия"),
         (unicodedata.normalize("NFD", "Wurf über dem Bett"), "Wurf über dem Bett"),
         ("تجربة", "تجربة"), ("🎲 würfel", "🎲 würfel"), ("anna b", "anna b"),
         ("anna:b", "anna-b"), ("anna*b", "anna-b-2")]


def main():
    from selenium.webdriver.common.by import By

    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    out, recordings, shots, page = lab_page_under_test(bookspin, source, binary, "explorer-names")

    # One throw each: the sample recording's Raw Data.csv cut at its rests, the pieces given in
    # turn (the first three throws, then again).
    raw = (source / "recordings" / "phone-on-book-synthetic" / "Raw Data.csv").read_text().splitlines()
    cuts = [(0.0, 3.8), (3.8, 6.5), (6.6, 9.3)]
    files = []
    for k, (stem, _) in enumerate(NAMES):
        a, b = cuts[k % len(cuts)]
        rows = [r for r in raw[1:] if a <= float(r.split(",")[0]) < b]
        # A sample's noise of its own, so that no two recordings are the same samples.
        rows = [",".join([c[0], *(f"{float(x) + 1e-6 * k:.9g}" for x in c[1:])])
                for c in (r.split(",") for r in rows)]
        path = recordings / f"{stem}.csv"
        path.write_text("\n".join([raw[0], *rows]) + "\n")
        files.append(path)
    folder = out / "cli"
    r = subprocess.run([bookspin, "fit", *map(str, files), "-o", str(folder)],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        fail(f"bookspin fit: exit {r.returncode}: {r.stderr}")
    expected = sorted(name for _, name in NAMES)  # the canonical order: by name, as bytes
    pool = f"{expected[0]}-and-{len(NAMES) - 1}-more"
    cli_csv = folder / f"{pool}-fit.csv"
    if not cli_csv.exists():
        fail(f"bookspin fit wrote no {cli_csv.name}: {sorted(p.name for p in folder.iterdir())}")
    cli_rows = list(csv.DictReader(io.StringIO(cli_csv.read_text())))
    if sorted(row["recording"] for row in cli_rows) != expected:
        fail(f"bookspin fit's rows name {[row['recording'] for row in cli_rows]}, not {expected}")
    cli_scenes = {}
    for toml in folder.glob(f"{pool}-toss*.toml"):
        text = toml.read_text()
        cli_scenes[re.search(r'^name = "(.*)"$', text, re.M).group(1)] = \
            re.search(r'^title = "(.*)"$', text, re.M).group(1)

    with serve(out) as base_url, open_browser(chromium, driver_path, size=(1280, 720)) as driver:
        driver.get(base_url + "explorer.html?scene=exact-unstable-x#lab")
        if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
            fail(f"the page never became ready: {driver.get_log('browser')}")
        given = [{"name": p.name, "bytes": base64.b64encode(p.read_bytes()).decode()} for p in files]
        got = driver.execute_async_script("""
            const [given, done] = arguments;
            const files = given.map((f) => ({name: f.name,
              bytes: Uint8Array.from(atob(f.bytes), (c) => c.charCodeAt(0))}));
            window.explorer.fitRecordings(files, 'linear')
              .then((r) => done({ok: true, r}), (e) => done({ok: false, error: String(e.message)}));
        """, given)
        if not got["ok"]:
            fail(f"the page refused the recordings: {got['error']}")
        r = got["r"]
        if r["recording"] != pool:
            fail(f"the page names the pool {r['recording']!r}, bookspin fit {pool!r}")
        if r["refused"]:
            fail(f"the page refused {r['refused']}")
        page_rows = sorted(row["recording"] for row in r["tosses"])
        if page_rows != expected:
            fail(f"the page's toss rows name {page_rows}, bookspin fit's {expected}")
        page_scenes = {s["name"]: s["title"] for s in r["scenes"]}
        if page_scenes != cli_scenes:
            fail(f"the page's scenes {page_scenes} are not bookspin fit's {cli_scenes}")
        print(f"the hook: {pool}, its rows and scenes as bookspin fit names them")

        # The file input: the browser names each File from its path.
        driver.find_element(By.ID, "labFile").send_keys("\n".join(str(p.resolve()) for p in files))
        if not wait_for(driver, "return !document.getElementById('labResult').hidden", bool, 180):
            fail(f"the panel showed no fit: {driver.find_element(By.ID, 'labError').text}")
        shown = driver.find_element(By.ID, "labSummary").text
        if f"recording: {pool}" not in shown:
            fail(f"the panel does not name the pool {pool!r}: {shown!r}")
        heads = driver.execute_script(
            "return [...document.querySelectorAll('#labTosses .tossHead')].map((h) => h.textContent)")
        for name in expected:
            if not any(name in h for h in heads):
                fail(f"no toss heading names {name!r}: {heads}")
        driver.save_screenshot(str(shots / "explorer-lab-names-1280x720.png"))
        driver.execute_script("document.querySelectorAll('#labTosses button')[0].click()")
        chosen = wait_for(driver, "return document.getElementById('scene').value",
                          lambda v: v in cli_scenes, 30)
        if chosen not in cli_scenes:
            fail(f"Play chose the scene {chosen!r}, none of {sorted(cli_scenes)}")
        print(f"the panel: the pool, {len(heads)} tosses headed by their recordings, Play chose {chosen!r}")

        # A 240-character name (cut to 160 by the rule): its toss played, the scene's title in
        # the left column wraps inside it, none of it cut (it ran past the column's edge).
        long_name = "n" * 240 + ".csv"
        got = driver.execute_async_script("""
            const [name, bytes, done] = arguments;
            window.explorer.fitRecording(name, Uint8Array.from(atob(bytes), (c) => c.charCodeAt(0)), 'linear')
              .then((r) => { window.explorer.playToss(r.scenes[0]); done({ok: true, name: r.recording}); },
                    (e) => done({ok: false, error: String(e.message)}));
        """, long_name, given[0]["bytes"])
        if not got["ok"] or got["name"] != "n" * 160:
            fail(f"the 240-character name: {got}")
        title = wait_for(driver, """
            const t = document.getElementById('sceneTitle'), c = document.getElementById('controls');
            const a = t.getBoundingClientRect(), b = c.getBoundingClientRect();
            return t.textContent.startsWith('nnnn') ? {text: t.textContent, title: [a.left, a.right],
              column: [b.left + c.clientLeft, b.left + c.clientLeft + c.clientWidth],
              scroll: [t.scrollWidth, t.clientWidth, c.scrollWidth, c.clientWidth]} : null""", bool, 30)
        if not title:
            fail("the long name's toss was not played: no scene title")
        (cl, cr), (sw, cw, csw, ccw) = title["column"], title["scroll"]
        if title["title"][1] > cr + 0.5 or sw > cw + 0.5 or csw > ccw + 0.5:
            fail(f"the long name's scene title runs past the left column: title {title['title']}, "
                 f"column {title['column']}, scroll widths {title['scroll']}")
        driver.save_screenshot(str(shots / "explorer-lab-long-name-title-1280x720.png"))
        print(f"a 240-character name: {got['name'][:8]}… (160), its title wrapped in the left column")
        errors = [e for e in console_errors(driver) if "favicon" not in e.get("message", "")]
        if errors:
            fail(f"console errors: {errors}")


if __name__ == "__main__":
    main()
