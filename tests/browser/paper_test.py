#!/usr/bin/env python3
"""The league and the gallery on paper (docs/flipcheck.md, "The league on paper"; docs/outputs.md,
"The gallery on paper"): each page printed by headless Chromium to a PDF on A4 and on US Letter
(Page.printToPDF, portrait, the default margins, no background graphics), its text read back
with pdftotext (poppler-utils).

The league of the seven scenarios of scenes/flipcheck/ with 30 motions more (the exact motion
copied under engines' names, in three of the scenarios: the others' cells "not run") and
rigid-matrix euler (cells that fail, with their reasons): 32 motions in 7 columns, more than a
page. On each paper
  - every row of the table is in the PDF's text whole, in the order the page draws it: its
    motion's name and each scenario's cell, reasons and all (on screen the table's box is the
    window's height and scrolls: printed, 5 of 37 motions were on the paper), and the scenarios'
    row (3 of 7 scenarios were);
  - the table is on more than one page;
  - no text prints pale (under print media every text dark on a light ground, WCAG's 4.5:1).
The gallery of two rendered scenes beside their plots: on each paper
  - every section's title is in the text, no player's clock ("0:00") is;
  - the PDF holds an image for every clip's still and every chart (pdfimages), the clips' stills
    (their poster frames) where their players were;
  - under print media no player is shown, each clip's still is loaded and beside its chart
    (side by side, not under it), and no text is pale.
The pages' PNGs: BINARY_DIR/test-output/browser/paper-{league,gallery}-{A4,Letter}-N.png.

Usage: paper_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Needs Debian's chromium, chromium-driver, python3-selenium and poppler-utils
(scripts/install-deps.sh); where one is missing the test is skipped (exit 77), except under
CI=true, where that is a failure.
"""
import shutil
import sys

from browser import (PAPERS, console_errors, fail, find_browser, open_browser, pale_print,
                     pdf_pages, pdf_text, pdf_to_png, print_to_pdf, require, run, serve,
                     squeezed, test_arguments, wait_for)
from gallery_test import build_gallery

COPIED = ["book-intermediate-0.2", "book-largest-axis", "symmetric-top"]

ROWS = """
return [...document.querySelectorAll('.league tr')].map((r) =>
  [...r.children].map((c) => c.textContent));
"""


def check_league(driver, league, shots):
    errors = []
    driver.get(league.resolve().as_uri())
    rows = driver.execute_script(ROWS)
    print(f"league: {len(rows) - 1} motions in {len(rows[0]) - 1} scenarios")
    if len(rows) - 1 != 32 or len(rows[0]) - 1 != 7:
        errors.append(f"expected 32 motions in 7 scenarios, the page has {len(rows) - 1} in {len(rows[0]) - 1}")
    for paper in PAPERS:
        pdf = print_to_pdf(driver, shots / f"paper-league-{paper}.pdf", paper)
        text = squeezed(pdf_text(pdf, "-raw"))
        pages = pdf_pages(pdf)
        pdf_to_png(pdf, shots / f"paper-league-{paper}")
        missing = [r[0] for r in rows if squeezed("".join(r)) not in text]
        print(f"{paper}: {pages} pages, {len(rows) - len(missing)} of {len(rows)} rows whole")
        if missing:
            errors.append(f"{paper}: {len(missing)} of the table's {len(rows)} rows not whole on the "
                          f"paper: {[squeezed(m)[:40] for m in missing[:8]]}")
        lost = [s for s in rows[0][1:] if squeezed(s) not in text]
        if lost:
            errors.append(f"{paper}: scenarios not on the paper: {lost}")
        if pages < 2:
            errors.append(f"{paper}: the league printed on {pages} page")
    pale = pale_print(driver)
    if pale:
        errors.append(f"the league prints pale text: {pale[:5]}")
    driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": ""})
    return errors


def pdf_images(pdf):
    """The images of the PDF (pdfimages -list): [(page, width, height)]."""
    pdfimages, = require("pdfimages")
    rows = run([pdfimages, "-list", str(pdf)]).splitlines()[2:]
    return [(int(r.split()[0]), int(r.split()[3]), int(r.split()[4])) for r in rows]


# JavaScript under print media: the players shown, and each clip's still, its chart, both boxes.
GALLERY_PRINT = """
  const box = (e) => { const r = e.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; };
  return {
    players: [...document.querySelectorAll('video')].filter((v) => v.checkVisibility()).length,
    clips: [...document.querySelectorAll('.media:has(> video[poster])')].map((m) => {
      const still = m.querySelector('img.still'), chart = m.querySelector('img.plot');
      return { title: m.closest('section').querySelector('h2').textContent,
               poster: m.querySelector('video').getAttribute('poster'),
               still: still && still.checkVisibility() ? [still.getAttribute('src'), still.naturalWidth, box(still)] : null,
               chart: chart ? box(chart) : null };
    }),
    titles: [...document.querySelectorAll('section h2')].map((h) => h.textContent),
    charts: document.querySelectorAll('img.plot').length };
"""


def check_gallery(driver, url, shots):
    errors = []
    driver.get(url + "index.html")
    wait_for(driver, "return document.readyState", lambda s: s == "complete")
    for paper in PAPERS:
        pdf = print_to_pdf(driver, shots / f"paper-gallery-{paper}.pdf", paper)
        text = pdf_text(pdf)
        pages = pdf_pages(pdf)
        pdf_to_png(pdf, shots / f"paper-gallery-{paper}")
        images = pdf_images(pdf)
        driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": "print"})
        shown = driver.execute_script(GALLERY_PRINT)
        driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": ""})
        need = len(shown["clips"]) + shown["charts"]
        print(f"{paper}: {pages} pages, {len(images)} images (the clips' stills and the charts: "
              f"{len(shown['clips'])} + {shown['charts']}), {shown['players']} players shown")
        for title in shown["titles"]:
            if squeezed(title) not in squeezed(text):
                errors.append(f"{paper}: the section {title!r} is not on the paper")
        if "0:00" in text:
            errors.append(f"{paper}: a player's clock is printed: {text[text.index('0:00') - 40:][:80]!r}")
        if len(images) < need:
            errors.append(f"{paper}: {len(images)} images on the paper, fewer than the "
                          f"{len(shown['clips'])} clips' stills and {shown['charts']} charts")
        if shown["players"]:
            errors.append(f"{paper}: {shown['players']} players printed (empty boxes on paper)")
        if not shown["clips"]:
            errors.append("no clip with a poster frame in the gallery")
        for clip in shown["clips"]:
            still, chart = clip["still"], clip["chart"]
            if not still or still[0] != clip["poster"] or not still[1]:
                errors.append(f"{paper}: {clip['title']!r}: its still ({clip['poster']}) not printed: {still}")
            elif chart and not (still[2][2] <= chart[0] + 1 and still[2][1] < chart[3] and chart[1] < still[2][3]):
                errors.append(f"{paper}: {clip['title']!r}: its still {still[2]} is not beside its chart {chart}")
    pale = pale_print(driver)
    if pale:
        errors.append(f"the gallery prints pale text: {pale[:5]}")
    driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": ""})
    return errors


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("pdftotext", "pdfinfo", "pdftoppm", "pdfimages")
    shots = binary / "test-output" / "browser"
    shots.mkdir(parents=True, exist_ok=True)
    for old in shots.glob("paper-*"):
        old.unlink()
    out = binary / "test-output" / "paper"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)

    scenes = sorted((source / "scenes" / "flipcheck").glob("*.toml"))
    motions = out / "motions"
    run([bookspin, "flipcheck", "export", *scenes, "-o", motions])
    for scenario in COPIED:
        exact = (motions / f"{scenario}-exact.csv").read_bytes()
        for k in range(1, 31):
            (motions / f"{scenario}-copied-engine-{k:02d}@0.{k}.0+euler.csv").write_bytes(exact)
    run([bookspin, "flipcheck", "league", *scenes, "--motions", *sorted(motions.glob("*.csv")),
         "--methods", "rigid-matrix:euler", "-o", out / "league"])
    gallery = out / "gallery"
    gallery.mkdir()
    build_gallery(bookspin, source, gallery)

    with open_browser(chromium, driver_path, size=(1366, 768)) as driver:
        errors = check_league(driver, out / "league" / "flipcheck-league.html", shots)
        with serve(gallery) as url:
            errors += check_gallery(driver, url, shots)
        errors += [f"console: {e['message']}" for e in console_errors(driver)]
    print(f"the printed pages: {shots}/paper-*.png")
    if errors:
        fail("\n  " + "\n  ".join(errors))
    print("PASS: the league and the gallery print whole, dark on white, on A4 and US Letter")
    return 0


if __name__ == "__main__":
    sys.exit(main())
