#!/usr/bin/env python3
"""The explorer (docs/explorer.md) as a person sees it on a laptop's 1366×768 screen and on a
1920×1080 one: headless Chromium, the page `bookspin explore` writes from every scene, and
screenshots kept as the test's artefacts (BINARY_DIR/test-output/browser/screen-*.png). Checks:

  - no text covers the body: the bodies' box, found from the 3D view's drawn pixels (what is
    not the view's background), is crossed by no visible text's box (each text node's own
    rectangles, not its element's), for the default page, fig05 at t = 377, compare-engines at
    t = 754 and a comparison of two bodies (compare-normalization at t = 60); a body's own
    label (compare mode, under its body by design) is left out;
  - the left panel fits: for every scene of the page, the controls' column is no taller than
    the screen (nothing to scroll to, "Judge a motion…" and "Phone-toss lab…" on screen);
  - no text under 12 px (each visible text's computed font size) and no text past its panel
    (the controls' column, the view's column, the transport bar, the side column) nor past the
    screen.

Usage: explorer_screen_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
"""
import time

from browser import console_errors, fail, find_browser, open_browser, require, run, test_arguments
from explorer_test import load, slide_to

SCREENS = ((1366, 768), (1920, 1080))
MIN_TEXT_PX = 12
# (name, query, t): the pages a person meets (the cases).
CASES = (
    ("default", "", None),
    ("fig05-playing", "?scene=fig05-particle-unstable-x", 377),
    ("compare-engines", "?scene=compare-engines", 754),
    ("compare-two-bodies", "?scene=compare-normalization", 60),
)

# JavaScript: every visible text of the page as [text, font px, panel id, rects], each rect
# [left, top, right, bottom] of the text node itself (a Range), and the panels' boxes.
TEXTS = """
  const panels = ['controls', 'main', 'transport', 'side', 'judge', 'lab'];
  const out = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const e = n.parentElement;
    if (!n.textContent.trim() || !e || e.closest('[hidden], script, style, option, select')) continue;
    if (e.closest('details:not([open])') && !e.closest('summary')) continue;
    const style = getComputedStyle(e);
    if (style.visibility === 'hidden' || style.display === 'none' || e.offsetParent === null) continue;
    const range = document.createRange(); range.selectNodeContents(n);
    const rects = [...range.getClientRects()].filter((r) => r.width > 0 && r.height > 0)
      .map((r) => [r.left, r.top, r.right, r.bottom]);
    if (!rects.length) continue;
    const panel = panels.find((id) => e.closest('#' + id));
    out.push([n.textContent.trim().slice(0, 60), parseFloat(style.fontSize), panel || '',
              rects, !!e.closest('.bodyLabel')]);
  }
  const boxes = {};
  for (const id of panels) {
    const p = document.getElementById(id);
    if (!p || p.offsetParent === null) continue;
    const r = p.getBoundingClientRect();
    boxes[id] = [r.left, r.top, r.right, r.bottom];
  }
  return [out, boxes, innerWidth, innerHeight];
"""

# JavaScript: the box [left, top, right, bottom] (page CSS px) of the 3D view's pixels that
# are not its background (#20242c), or null where none is drawn.
BODY_BOX = """
  const v = document.getElementById('view');
  const c = document.createElement('canvas'); c.width = v.width; c.height = v.height;
  const g = c.getContext('2d'); g.drawImage(v, 0, 0);
  const d = g.getImageData(0, 0, c.width, c.height).data;
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let y = 0; y < c.height; ++y) for (let x = 0; x < c.width; ++x) {
    const i = 4 * (y * c.width + x);
    if (Math.abs(d[i] - 0x20) + Math.abs(d[i + 1] - 0x24) + Math.abs(d[i + 2] - 0x2c) > 30) {
      x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
    }
  }
  if (x1 < 0) return null;
  const box = v.getBoundingClientRect(), sx = box.width / v.width, sy = box.height / v.height;
  return [box.left + x0 * sx, box.top + y0 * sy, box.left + (x1 + 1) * sx, box.top + (y1 + 1) * sy];
"""


def overlaps(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def inside(r, box, slack=0.5):
    return r[0] >= box[0] - slack and r[1] >= box[1] - slack and r[2] <= box[2] + slack and r[3] <= box[3] + slack


def check_texts(driver, where, problems):
    """Text size, text inside its panel and the screen; returns the texts (for the overlap)."""
    texts, boxes, width, height = driver.execute_script(TEXTS)
    screen = [0, 0, width, height]
    for text, px, panel, rects, _ in texts:
        if px < MIN_TEXT_PX:
            problems.append(f"{where}: {text!r} at {px} px, under {MIN_TEXT_PX}")
        for r in rects:
            if not inside(r, screen):
                problems.append(f"{where}: {text!r} runs past the screen: {[round(x) for x in r]}")
            elif panel in boxes and not inside(r, boxes[panel]):
                problems.append(f"{where}: {text!r} runs past #{panel} "
                                f"{[round(x) for x in boxes[panel]]}: {[round(x) for x in r]}")
    return texts


def check_case(driver, page, shots, screen, case, problems):
    name, query, t = case
    where = f"{name} at {screen[0]}×{screen[1]}"
    load(driver, page + query)
    if t is not None:
        slide_to(driver, t)
    time.sleep(0.5)
    driver.save_screenshot(str(shots / f"screen-{name}-{screen[0]}x{screen[1]}.png"))
    texts = check_texts(driver, where, problems)
    body = driver.execute_script(BODY_BOX)
    if body is None:
        problems.append(f"{where}: no body drawn in the view")
        return
    covering = [(text, [round(x) for x in r]) for text, _, _, rects, label in texts if not label
                for r in rects if overlaps(r, body)]
    print(f"{where}: body box {[round(x) for x in body]}, {len(texts)} texts, covering it: {covering}")
    for text, r in covering:
        problems.append(f"{where}: {text!r} {r} covers the body {[round(x) for x in body]}")


def check_left_panel(driver, page, screen, problems):
    """Every scene: the controls' column no taller than the screen."""
    load(driver, page)
    names = driver.execute_script(
        "return [...document.getElementById('scene').options].map((o) => o.value)")
    for scene in names:
        driver.execute_script("""
          const s = document.getElementById('scene'); s.value = arguments[0];
          s.dispatchEvent(new Event('change'));""", scene)
        time.sleep(0.1)
        sizes = driver.execute_script("""
          const c = document.getElementById('controls');
          const off = ['judgeOpen', 'labOpen'].map((id) => document.getElementById(id))
            .filter((b) => b.offsetParent !== null)
            .filter((b) => { const r = b.getBoundingClientRect();
                             return r.top < 0 || r.bottom > innerHeight || r.left < 0 || r.right > innerWidth; })
            .map((b) => b.id);
          return [c.scrollHeight, c.clientHeight, off];""")
        if sizes[0] > sizes[1] or sizes[2]:
            problems.append(f"{scene or '(custom)'} at {screen[0]}×{screen[1]}: the left panel is "
                            f"{sizes[0]} px for {sizes[1]} px of screen; off screen: {sizes[2]}")
    print(f"left panel at {screen[0]}×{screen[1]}: {len(names)} scenes looked at")


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    out = binary / "test-output" / "explorer-screen"
    shots = binary / "test-output" / "browser"
    shots.mkdir(parents=True, exist_ok=True)
    out.mkdir(parents=True, exist_ok=True)
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    run([bookspin, "explore", *sorted(str(p) for p in (source / "scenes").glob("*.toml")), "-o", str(out)])
    page = (out / "explorer.html").resolve().as_uri()
    problems = []
    for screen in SCREENS:
        with open_browser(chromium, driver_path, size=screen, webgl=True, offline=True,
                          exact_viewport=True) as driver:
            for case in CASES:
                check_case(driver, page, shots, screen, case, problems)
            check_left_panel(driver, page, screen, problems)
            errors = console_errors(driver)
            if errors:
                problems.append(f"console errors at {screen[0]}×{screen[1]}: {errors}")
    print(f"screenshots: {shots}/screen-*.png")
    if problems:
        fail(f"{len(problems)} problems:\n" + "\n".join(problems[:60]))
    print("ok: no text over the body, the left panel fits, no text under 12 px or past its panel")


if __name__ == "__main__":
    main()
