#!/usr/bin/env python3
"""The explorer's readout at a projector's zoom (docs/explorer.md, "What the class must read";
WCAG 1.4.10, reflow at 320 CSS px): a 1280×800 screen at 300 % and 400 % zoom (427×267 and
320×200 CSS px, 3 and 4 device pixels a CSS pixel) and a 1920×1080 screen at 200 % (960×540).

On the page `bookspin explore` writes from fig09 (one run beside the exact motion) and
compare-engines (six tiles), at t = 227 and 599, at each size: every text of the readout a class
reads (the clock, each run's flips, its first flip, the run's label, and the exact motion's
line) lies inside the readout's strip as it shows, unscrolled (at 200 % the comparison's six
labels may lie a scroll down, the view keeping its 200 px), every line of it (the text's
own boxes, not its element's: a line that runs past its box is caught), wrapped where it must
be, never cut; the strip does not scroll sideways and neither does the page; where the page
scrolls, its scroll bar is dark (it was white on the dark page).

At 1280×720 with WCAG 1.4.12's text spacing put on fig09's page after it loaded (the W3C's
style: line height 1.5, letters 0.12 em, words 0.16 em, paragraphs 2 em apart), every menu of
the left column shows its chosen entry whole (the model menu read "rigid-matri"): the entry
laid out in a span of the menu's font and spacing fits the menu less its arrow.

Screenshots: BINARY_DIR/test-output/browser/zoom-<case>-<W>x<H>.png and text-spacing-1280x720.png.

Usage: explorer_zoom_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import base64
import time

from browser import fail, find_browser, open_browser, require, run, test_arguments, wait_for
from explorer_test import load, slide_to
from league_test import png_rows

# (width, height, device pixels a CSS pixel): 1280×800 at 300 % and 400 %, 1920×1080 at 200 %.
SIZES = ((427, 267, 3), (320, 200, 4), (960, 540, 2))
CASES = (("fig09", "?scene=fig09-matrix-unstable-x", 227, 1),
         ("compare-engines", "?scene=compare-engines&tiles=1", 599, 6))

# JavaScript: the strip as it shows (its box less its scroll bars), how far it scrolls each way,
# the page's width against the window's, and every line box of the text a class reads.
READ = """
  const strip = document.getElementById('overlay'), s = strip.getBoundingClientRect();
  const left = s.left + strip.clientLeft, top = s.top + strip.clientTop;
  const lines = [];
  for (const e of document.querySelectorAll('#clock, #status .flips, #status .first, #status .method, #status .exact')) {
    const walker = document.createTreeWalker(e, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      if (!n.textContent.trim()) continue;
      const range = document.createRange();
      range.selectNodeContents(n);
      for (const r of range.getClientRects())
        if (r.width > 0) lines.push([e.className || e.id, n.textContent.trim(), [r.left, r.top, r.right, r.bottom]]);
    }
  }
  return { strip: [left, top, left + strip.clientWidth, top + strip.clientHeight],
           scroll: [strip.scrollLeft, strip.scrollTop, strip.scrollWidth - strip.clientWidth],
           page: [document.documentElement.scrollWidth, innerWidth],
           runs: document.querySelectorAll('#status .run').length,
           methods: document.querySelectorAll('#status .method').length, lines };
"""


# WCAG 1.4.12's text spacing, as a reader's own style sets it (the W3C's bookmarklet): line
# height 1.5, letters 0.12 em apart, words 0.16 em, paragraphs 2 em.
TEXT_SPACING = """
  const s = document.createElement('style');
  s.textContent = '* { line-height: 1.5 !important; letter-spacing: 0.12em !important; ' +
    'word-spacing: 0.16em !important; } p { margin-bottom: 2em !important; }';
  document.head.appendChild(s);
"""

# JavaScript: each menu of the left column but the scene's (which shortens its title with "…"):
# its chosen entry's width as laid out in a span of the menu's own font and spacing, and the
# room the menu gives its text (its inner width less its arrow's 16 px).
MENU_TEXT = """
  return [...document.querySelectorAll('#controls select:not(#scene)')].filter((m) => m.checkVisibility()).map((m) => {
    const style = getComputedStyle(m), span = document.createElement('span');
    for (const k of ['fontFamily', 'fontSize', 'fontWeight', 'fontStyle', 'letterSpacing', 'wordSpacing'])
      span.style[k] = style[k];
    span.style.whiteSpace = 'pre';
    span.style.position = 'absolute';
    span.textContent = m.selectedOptions[0].textContent;
    document.body.appendChild(span);
    const width = span.getBoundingClientRect().width;
    span.remove();
    return [m.id, m.selectedOptions[0].textContent, width,
            m.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight) - 16];
  });
"""


def text_spacing(driver, page, shots):
    """At 1280×720 with WCAG 1.4.12's text spacing put on the page after it has loaded: every
    menu of the left column shows its chosen entry whole ("rigid-matri" was cut); a list of
    what is wrong."""
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": 1280, "height": 720, "deviceScaleFactor": 1, "mobile": False})
    load(driver, page + "?scene=fig09-matrix-unstable-x")
    driver.execute_script(TEXT_SPACING)
    wait_for(driver, "return new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(true))))",
             bool, 10)
    menus = driver.execute_script(MENU_TEXT)
    driver.save_screenshot(str(shots / "text-spacing-1280x720.png"))
    print("text spacing at 1280x720: " + ", ".join(f"{m} {t!r} {w:.0f} px in {room:.0f}"
                                                     for m, t, w, room in menus))
    problems = [f"text spacing at 1280x720: the menu {m} cuts {t!r}: {w:.0f} px of text in {room:.0f} px"
                for m, t, w, room in menus if w > room + 0.5]
    if not any(t == "rigid-matrix" for _, t, _, _ in menus):
        problems.append(f"text spacing at 1280x720: no menu shows rigid-matrix: {menus}")
    return problems


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    out = binary / "test-output" / "explorer-zoom"
    shots = binary / "test-output" / "browser"
    for d in (out, shots):
        d.mkdir(parents=True, exist_ok=True)
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    run([bookspin, "explore", str(source / "scenes" / "fig09-matrix-unstable-x.toml"),
         str(source / "scenes" / "compare-engines.toml"), "-o", str(out)])
    page = (out / "explorer.html").resolve().as_uri()
    problems = []
    with open_browser(chromium, driver_path, size=(1280, 800)) as driver:
        for w, h, dpr in SIZES:
            driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                                   {"width": w, "height": h, "deviceScaleFactor": dpr, "mobile": False})
            for case, query, t, runs in CASES:
                at = f"{case} at {w}x{h} ({dpr * 100} %)"
                load(driver, page + query)
                slide_to(driver, t)
                time.sleep(0.3)
                driver.save_screenshot(str(shots / f"zoom-{case}-{w}x{h}.png"))
                r = driver.execute_script(READ)
                if r["runs"] != runs or r["methods"] != runs:
                    problems.append(f"{at}: {r['runs']} runs and {r['methods']} labels shown, want {runs}")
                left, top, right, bottom = r["strip"]
                # At 200 % a comparison's six labels may lie a scroll down (the view keeps its
                # 200 px of 426); never cut sideways.
                def whole(kind, b):
                    sideways = b[0] >= left - 0.5 and b[2] <= right + 0.5
                    if dpr == 2 and runs > 1 and kind == "method":
                        return sideways
                    return sideways and b[1] >= top - 0.5 and b[3] <= bottom + 0.5
                cut = [(kind, text, [round(v) for v in b]) for kind, text, b in r["lines"] if not whole(kind, b)]
                kinds = sorted({kind for kind, _, _ in r["lines"]})
                print(f"{at}: strip {[round(v) for v in r['strip']]}, {len(r['lines'])} lines of {kinds}: "
                      f"{'all whole' if not cut else f'{len(cut)} cut'}; scroll {r['scroll']}, page {r['page']}")
                for kind, text, b in cut:
                    problems.append(f"{at}: {kind} {text!r} {b} is not inside the readout's strip as shown "
                                    f"{[round(v) for v in r['strip']]}")
                if not any("exact" in kind for kind, _, _ in r["lines"]) and case == "fig09":
                    problems.append(f"{at}: the exact motion's line is not shown")
                scroll_left, scroll_top, sideways = r["scroll"]
                if sideways > 0.5 or scroll_left > 0.5:
                    problems.append(f"{at}: the readout's strip scrolls sideways by {sideways} px")
                if scroll_top > 0.5:
                    problems.append(f"{at}: the readout's strip opened scrolled down by {scroll_top} px")
                if r["page"][0] > r["page"][1] + 0.5:
                    problems.append(f"{at}: the page is {r['page'][0]} px wide in a {r['page'][1]} px window")
                # The page's scroll bar (the page scrolls down to the readout here) dark on the
                # dark page: its mean brightness under a half (it was white, 241 of 255).
                bar = driver.execute_script("return [document.documentElement.clientWidth, innerWidth]")
                if bar[1] - bar[0] >= 8:
                    shot = driver.execute_cdp_cmd("Page.captureScreenshot", {"format": "png", "clip": {
                        "x": bar[0] + 2, "y": 40, "width": bar[1] - bar[0] - 4, "height": 60, "scale": 1}})
                    pixels = [p for row in png_rows(base64.b64decode(shot["data"])) for p in row]
                    brightness = sum(sum(p) for p in pixels) / (3 * len(pixels))
                    if brightness > 127:
                        problems.append(f"{at}: the page's scroll bar is light ({brightness:.0f} of 255) "
                                        f"on the dark page")
        problems += text_spacing(driver, page, shots)
    if problems:
        fail("the readout at zoom:\n  " + "\n  ".join(problems))
    print("the readout at 300 % and 400 % of 1280x800 and 200 % of 1920x1080: every line whole")


if __name__ == "__main__":
    main()
