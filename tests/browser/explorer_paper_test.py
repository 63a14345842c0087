#!/usr/bin/env python3
"""The explorer's Phone-toss lab after a class's pooled fit, on paper and on a phone
(docs/explorer.md, "On paper"; docs/phone-lab.md, "Reading the result").

Builds the page's program with web/build.sh BINARY_DIR, writes a page with `bookspin explore`,
and fits five one-throw recordings named as the page's own recorder names them
(toss-YYYY-MM-DD-hh-mm-ss-gyroscope-53Hz.csv) through the lab's file input at 1280×720, "Flights
by hand" left empty. Then
  - printed by headless Chromium to a PDF on A4 and on US Letter (Page.printToPDF, portrait,
    the default margins, no background graphics) and read back with pdftotext (poppler-utils):
    every row of the outcome table whole (its cells in the order the page draws them), every
    toss's heading and every row of its own table, the summary's lines (the notes), an image
    per toss (its chart: pdfimages), the lab on more than one page and no two pages the same
    (it printed its first screen on both pages, none of its tosses), the empty field's
    placeholder not printed as if typed;
  - under print media no text of the panel is pale or on a dark ground (WCAG's 4.5:1), and no
    button, menu or file field is shown;
  - at 390×844 (a phone, mobile, touch) the outcome table does not scroll sideways (the verdict
    columns were a scroll away), each recording's name in it is on at most two lines (it broke
    over six), and each toss's verdict ("within 2σ") is on the screen's width.
The PDFs' pages as PNGs and the phone's screenshot: BINARY_DIR/test-output/browser/
paper-explorer-lab-{A4,Letter}-N.png and explorer-lab-outcome-390x844.png.

Usage: explorer_paper_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten, npm or poppler-utils is
missing, except under CI=true, where that is a failure (browser.py).
"""

from browser import (PAPERS, console_errors, fail, find_browser, lab_page_under_test, open_browser,
                     pale_print, pdf_pages, pdf_text, pdf_to_png, print_to_pdf, require, serve,
                     squeezed, test_arguments, wait_for)
from paper_test import pdf_images

STAMPS = ["2026-11-28-09-14-03", "2026-11-28-09-15-41", "2026-11-28-09-17-12",
          "2026-11-28-09-18-59", "2026-11-28-09-20-30"]

# JavaScript: what the lab shows after a fit: the outcome table's rows, each toss's heading and
# its table's rows, the summary's lines.
SHOWN = """
  const cells = (t) => [...t.querySelectorAll('tr')].map((r) => [...r.children].map((c) => c.textContent).join(''));
  return {
    outcome: cells(document.getElementById('labOutcome')),
    caption: document.querySelector('#labOutcome caption').textContent,
    tosses: [...document.querySelectorAll('#labTosses .toss')].map((t) => ({
      head: t.querySelector('.tossHead strong').textContent, rows: cells(t.querySelector('table')) })),
    body: cells(document.getElementById('labBody')),
    summary: document.getElementById('labSummary').textContent.split('\\n').filter((l) => l.trim()),
    placeholder: document.getElementById('labFlights').placeholder };
"""

# JavaScript under print media: the controls of the panel still shown.
SHOWN_CONTROLS = """
  return [...document.querySelectorAll('#lab button, #lab select, #lab input[type=file], #lab input[type=range]')]
    .filter((e) => e.checkVisibility()).map((e) => e.id || e.textContent);
"""

# JavaScript at 390 px: the outcome table's scroll, each recording's lines, each verdict's box.
PHONE = """
  const t = document.getElementById('labOutcome');
  const lines = (e) => { const r = document.createRange(); r.selectNodeContents(e);
    return new Set([...r.getClientRects()].filter((x) => x.width > 0).map((x) => Math.round(x.top))).size; };
  const rows = [...t.querySelectorAll('tr')].filter((r) => r.querySelector('td'));
  return { scroll: [t.scrollWidth, t.clientWidth], page: [document.documentElement.scrollWidth, innerWidth],
    names: rows.map((r) => [r.children[1].textContent, lines(r.children[1])]),
    verdicts: rows.map((r) => { const b = r.children[5].getBoundingClientRect(); return [r.children[5].textContent, b.left, b.right]; }) };
"""


def check_paper(driver, shots, shown):
    errors = []
    rows = [("outcome", r) for r in shown["outcome"]] + [("body", r) for r in shown["body"]]
    for toss in shown["tosses"]:
        rows += [(toss["head"], toss["head"])] + [(toss["head"], r) for r in toss["rows"]]
    for paper in PAPERS:
        pdf = print_to_pdf(driver, shots / f"paper-explorer-lab-{paper}.pdf", paper)
        raw = pdf_text(pdf, "-raw")
        text = squeezed(raw)
        pages = pdf_pages(pdf)
        pdf_to_png(pdf, shots / f"paper-explorer-lab-{paper}")
        missing = [f"{where}: {squeezed(r)[:50]}" for where, r in rows if squeezed(r) not in text]
        notes = [line for line in shown["summary"] if squeezed(line) not in text]
        charts = len(pdf_images(pdf))
        texts = [squeezed(page) for page in raw.split("\f") if page.strip()]
        print(f"{paper}: {pages} pages, {len(rows) - len(missing)} of {len(rows)} rows, "
              f"{len(shown['summary']) - len(notes)} of {len(shown['summary'])} notes, {charts} images")
        if missing:
            errors.append(f"{paper}: {len(missing)} of {len(rows)} rows not on the paper: {missing[:6]}")
        if notes:
            errors.append(f"{paper}: notes not on the paper: {notes[:4]}")
        if squeezed(shown["caption"]) not in text:
            errors.append(f"{paper}: the outcome table's caption is not on the paper")
        if charts < len(shown["tosses"]):
            errors.append(f"{paper}: {charts} images for {len(shown['tosses'])} tosses' charts")
        if pages < 2 or len(set(texts)) < len(texts):
            errors.append(f"{paper}: {pages} pages, {len(set(texts))} of them different")
        if squeezed(shown["placeholder"]) in text:
            errors.append(f"{paper}: the empty field's placeholder {shown['placeholder']!r} is printed")
    pale = pale_print(driver, "#lab")
    if pale:
        errors.append(f"the lab prints pale text: {pale[:5]}")
    controls = driver.execute_script(SHOWN_CONTROLS)
    if controls:
        errors.append(f"controls printed: {controls}")
    driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": ""})
    return errors


def check_phone(driver, shots):
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": 390, "height": 844, "deviceScaleFactor": 2, "mobile": True})
    driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 5})
    driver.execute_script("document.getElementById('labOutcome').scrollIntoView()")
    got = wait_for(driver, PHONE, lambda g: g["page"][1] == 390, 10)
    driver.save_screenshot(str(shots / "explorer-lab-outcome-390x844.png"))
    print(f"390×844: the outcome table {got['scroll'][0]} px wide in {got['scroll'][1]}, names on "
          f"{[n[1] for n in got['names']]} lines, verdicts at {[round(v[2]) for v in got['verdicts']]} px")
    errors = []
    if got["scroll"][0] > got["scroll"][1] + 1 or got["page"][0] > got["page"][1]:
        errors.append(f"390×844: the outcome table scrolls sideways: {got['scroll']}, the page {got['page']}")
    for name, lines in got["names"]:
        if lines > 2:
            errors.append(f"390×844: {name!r} on {lines} lines")
    for verdict, left, right in got["verdicts"]:
        if left < 0 or right > 390 + 0.5:
            errors.append(f"390×844: the verdict {verdict!r} at {left:.0f}..{right:.0f} px, off the screen")
    return errors


def main():
    from selenium.webdriver.common.by import By

    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm", "pdftotext", "pdfinfo", "pdftoppm", "pdfimages")
    out, recordings, shots, page = lab_page_under_test(bookspin, source, binary, "explorer-paper")
    for old in shots.glob("paper-explorer-lab-*"):
        old.unlink()

    # One throw each: the sample recording cut at its rests, a sample's noise of its own.
    raw = (source / "recordings" / "phone-on-book-synthetic" / "Raw Data.csv").read_text().splitlines()
    cuts = [(0.0, 3.8), (3.8, 6.5), (6.6, 9.3)]
    files = []
    for k, stamp in enumerate(STAMPS):
        a, b = cuts[k % len(cuts)]
        rows = [r.split(",") for r in raw[1:] if a <= float(r.split(",")[0]) < b]
        rows = [",".join([c[0], *(f"{float(x) + 1e-6 * k:.9g}" for x in c[1:])]) for c in rows]
        path = recordings / f"toss-{stamp}-gyroscope-53Hz.csv"
        path.write_text("\n".join([raw[0], *rows]) + "\n")
        files.append(path)

    with serve(out) as url, open_browser(chromium, driver_path, size=(1280, 720)) as driver:
        driver.get(url + "explorer.html?scene=exact-unstable-x#lab")
        if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
            fail(f"the page never became ready: {driver.get_log('browser')}")
        driver.find_element(By.ID, "labFile").send_keys("\n".join(str(p.resolve()) for p in files))
        if not wait_for(driver, "return !document.getElementById('labResult').hidden", bool, 180):
            fail(f"the panel showed no fit: {driver.find_element(By.ID, 'labError').text}")
        # The charts are drawn a frame after the result.
        wait_for(driver, "return new Promise((r) => requestAnimationFrame(() => r(true)))", bool, 10)
        shown = driver.execute_script(SHOWN)
        print(f"the lab: {len(shown['outcome']) - 1} tosses in the outcome table, "
              f"{len(shown['tosses'])} charted, {len(shown['summary'])} lines of notes")
        if len(shown["tosses"]) < len(files):
            fail(f"{len(shown['tosses'])} tosses fitted of {len(files)} throws")
        errors = check_paper(driver, shots, shown)
        errors += check_phone(driver, shots)
        errors += [f"console: {e['message']}" for e in console_errors(driver)
                   if "favicon" not in e.get("message", "")]
    print(f"the printed pages: {shots}/paper-explorer-lab-*.png")
    if errors:
        fail("\n  " + "\n  ".join(errors))
    print("PASS: the lab prints every toss, dark on white, and its outcome reads on a phone")


if __name__ == "__main__":
    main()
