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
    the screen (nothing to scroll to, "Judge a motion…" and "Phone-toss lab…" on screen), and
    the scene menu shows the scene's title whole or its first words to a "…", never cut at
    the menu's edge (the whole title is the line under it);
  - no text under 12 px (each visible text's computed font size, and each text drawn on a
    canvas: its font's size times the canvas's CSS width over its pixel width, recorded by a
    wrapper around fillText from the page's first script on) and no text past its panel
    (the controls' column, the view's column, the transport bar, the side column) nor past the
    screen;
  - at 1366×768, the Phone-toss lab with a result (the sample recording fitted) and the judge
    with one (fig09's exact motion, as `bookspin flipcheck export` writes it, judged): no text
    under 12 px nor past the panel's sides, and every number of their tables at its precision
    (web/src/precision.js): a value ± σ with σ at two significant digits and the value at σ's
    decimal place; a number alone at four significant digits at most (the flights' times to
    the millisecond);
  - the sphere's axis names, the far ends' dimmed ones too, each wholly inside the disc or
    wholly outside it, never across its outline, and none over another;
  - every tick label of the page's plots at its axis's precision: a multiple of the axis's
    round step ("1-2-5"), with no more decimals than the step has (0.02: two; 5e-4 written
    "5e-4"), and the labels of one axis all different.

Usage: explorer_screen_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
"""
import math
import time

from browser import (console_errors, exact_fig09_motion, explorer_of_every_scene, fail, find_browser,
                     open_browser, require, run, test_arguments, wait_for)
from explorer_test import load, slide_to
from screens import VISIBLE_TEXT_NODES

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
TEXTS = VISIBLE_TEXT_NODES + """
  const panels = ['controls', 'main', 'transport', 'side', 'judge', 'lab'];
  const out = visibleTextNodes().map(({ text, e, style, rects }) => {
    const panel = panels.find((id) => e.closest('#' + id));
    return [text, parseFloat(style.fontSize), panel || '', rects, !!e.closest('.bodyLabel')];
  });
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


# JavaScript run before the page's own scripts: every fillText on a 2D canvas recorded as
# [text, canvas id, the size it is shown at in CSS px].
CANVAS_TEXTS = """
  window.__canvasTexts = [];
  const fillText = CanvasRenderingContext2D.prototype.fillText;
  CanvasRenderingContext2D.prototype.fillText = function (text, ...rest) {
    const c = this.canvas, px = /([0-9.]+)px/.exec(this.font);
    // Shown at: the font's pixels, through the context's scale, at the canvas's CSS size.
    const shown = (c.getBoundingClientRect ? c.getBoundingClientRect().width / c.width : 1) * Math.hypot(this.getTransform().a, this.getTransform().b);
    if (px && String(text).trim())
      window.__canvasTexts.push([String(text).slice(0, 40), c.id || c.className, parseFloat(px[1]) * shown]);
    return fillText.call(this, text, ...rest);
  };
"""


def check_canvas_texts(driver, where, problems):
    """The texts drawn on the page's canvases since it loaded, each at least 12 px as shown."""
    drawn = driver.execute_script("return window.__canvasTexts || null")
    if drawn is None:
        problems.append(f"{where}: the canvases' texts were not recorded")
        return
    small = sorted({(text, canvas, round(px, 1)) for text, canvas, px in drawn if px < MIN_TEXT_PX - 0.01})
    print(f"{where}: {len(drawn)} canvas texts drawn, under {MIN_TEXT_PX} px: {small[:5]}")
    for text, canvas, px in small[:10]:
        problems.append(f"{where}: {text!r} drawn on canvas {canvas!r} at {px} px, under {MIN_TEXT_PX}")


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


def step_decimals(step):
    """The decimals a round step m·10^k (m = 1, 2 or 5) has: max(0, −k)."""
    return max(0, -math.floor(math.log10(step) + 1e-9))


def tick_problems(labels):
    """Each drawn tick label {axis, value, step, text} past its axis's precision, as text."""
    bad, seen = [], {}
    for t in labels:
        text, value, step, axis = t["text"], t["value"], t["step"], t["axis"]
        if step <= 0:
            continue
        try:
            shown = float(text)
        except ValueError:
            bad.append(f"{axis}: tick {text!r} is not a number")
            continue
        if abs(shown - value) > 1e-6 * step:
            bad.append(f"{axis}: tick {text!r} does not show its value {value!r}")
        if abs(value / step - round(value / step)) > 1e-6:
            bad.append(f"{axis}: tick {text!r} is not a multiple of its step {step:g}")
        if "e" in text:  # m.mmm e k: the mantissa's decimals down to the step's leading digit
            mantissa, exponent = text.split("e")
            decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
            if decimals > int(exponent) - math.floor(math.log10(step) + 1e-9):
                bad.append(f"{axis}: tick {text!r} has more digits than its step {step:g}")
        elif "." in text and len(text.split(".")[1]) > step_decimals(step):
            bad.append(f"{axis}: tick {text!r} has more decimals than its step {step:g}")
        if text in seen.setdefault(axis, set()):
            bad.append(f"{axis}: tick {text!r} twice")
        seen[axis].add(text)
    return bad


def sphere_label_problems(driver, where):
    """The sphere's axis names (each on its patch, canvas pixels) clear of the disc's outline:
    a patch wholly inside the disc or wholly outside it, never across the circle; and no two
    overlapping."""
    drawn = driver.execute_script("return window.explorer.sphereAxisLabelBoxes()")
    cx, cy, radius = drawn["disc"]["cx"], drawn["disc"]["cy"], drawn["disc"]["R"]
    problems = []
    for label in drawn["labels"]:
        x0, y0, x1, y1 = label["box"]
        near = math.hypot(max(x0 - cx, 0, cx - x1), max(y0 - cy, 0, cy - y1))
        far = math.hypot(max(abs(x0 - cx), abs(x1 - cx)), max(abs(y0 - cy), abs(y1 - cy)))
        if near < radius + 0.5 and far > radius - 0.5:
            problems.append(f"{where}: the sphere's {label['text']!r} {[round(v) for v in label['box']]} "
                            f"lies across the disc's outline (centre {cx:.0f}, {cy:.0f}, radius {radius:.0f})")
    for i, a in enumerate(drawn["labels"]):
        for b in drawn["labels"][i + 1:]:
            if overlaps(a["box"], b["box"]):
                problems.append(f"{where}: the sphere's {a['text']!r} and {b['text']!r} overlap")
    if not drawn["labels"]:
        problems.append(f"{where}: the sphere names no axis")
    return problems


def check_case(driver, page, shots, screen, case, problems):
    name, query, t = case
    where = f"{name} at {screen[0]}×{screen[1]}"
    load(driver, page + query)
    if t is not None:
        slide_to(driver, t)
    time.sleep(0.5)
    driver.save_screenshot(str(shots / f"screen-{name}-{screen[0]}x{screen[1]}.png"))
    texts = check_texts(driver, where, problems)
    check_canvas_texts(driver, where, problems)
    problems += sphere_label_problems(driver, where)
    ticks = driver.execute_script("return window.explorer.plotTickLabels()")
    if not ticks:
        problems.append(f"{where}: the plots drew no tick labels")
    for why in tick_problems(ticks):
        problems.append(f"{where}: {why}")
    body = driver.execute_script(BODY_BOX)
    if body is None:
        problems.append(f"{where}: no body drawn in the view")
        return
    covering = [(text, [round(x) for x in r]) for text, _, _, rects, label in texts if not label
                for r in rects if overlaps(r, body)]
    print(f"{where}: body box {[round(x) for x in body]}, {len(texts)} texts, covering it: {covering}")
    for text, r in covering:
        problems.append(f"{where}: {text!r} {r} covers the body {[round(x) for x in body]}")


# JavaScript: the scene menu's closed text, its width in the menu's font, the room the menu
# gives it (its box less its padding and the arrow's 24 px), and the title under the menu.
MENU_TEXT = """
  const menu = document.getElementById('scene'), style = getComputedStyle(menu);
  const g = document.createElement('canvas').getContext('2d');
  g.font = `${style.fontWeight} ${style.fontSize} ${style.fontFamily}`;
  const shown = menu.options[menu.selectedIndex].text;
  const title = menu.value ? document.getElementById('sceneTitle').textContent : shown;
  return {shown, text: g.measureText(shown).width, title,
          room: menu.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight) - 24};
"""


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
        # The scene menu's closed text whole within it (the words of the title under it, up
        # to a "…"), never cut at the menu's edge.
        menu = driver.execute_script(MENU_TEXT)
        if menu["text"] > menu["room"] + 0.5 or not menu["title"].startswith(menu["shown"].removesuffix(" …")):
            problems.append(f"{scene or '(custom)'} at {screen[0]}×{screen[1]}: the scene menu shows "
                            f"{menu['shown']!r}, {menu['text']:.0f} px in {menu['room']:.0f} px, over "
                            f"the title {menu['title']!r}")
        if sizes[0] > sizes[1] or sizes[2]:
            problems.append(f"{scene or '(custom)'} at {screen[0]}×{screen[1]}: the left panel is "
                            f"{sizes[0]} px for {sizes[1]} px of screen; off screen: {sizes[2]}")
    print(f"left panel at {screen[0]}×{screen[1]}: {len(names)} scenes looked at")


# JavaScript: the numbers of the lab's and the judge's tables that are shown past their
# precision, as [cell text, why].
DIGITS = r"""
  const digits = (t) => t.replace('-', '').replace('.', '').replace(/^0+/, '').length;
  const decimals = (t) => (t.includes('.') ? t.split('.')[1].length : 0);
  const number = /^-?\d+(\.\d+)?( × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?$/;
  const milliseconds = ['t_start', 't_end', 'half_period_measured', 'half_period_fitted',
                        'half_period_predicted'];
  const bad = [];
  for (const td of document.querySelectorAll('#labBody td, #labTosses td, #judgeTable td')) {
    const text = td.textContent.trim();
    const key = (td.parentElement.querySelector('th code') || {}).textContent || '';
    if (text.includes('±')) {
      // "v ± σ unit", "v1 ± σ1 : v2 ± σ2 : 1 (…)", "(x, y, z) ± σ°"
      for (const part of text.split(' : ').filter((p) => p.includes('±'))) {
        const m = part.match(/^\(?([-\d., ]+?)\)? ± ([\d.]+)/);
        if (!m) { bad.push([text, 'unread']); continue; }
        const values = m[1].split(', '), sigma = m[2];
        if (digits(sigma.replace(/0+$/, '')) > 2 || digits(sigma) < 2) bad.push([text, `σ ${sigma} not two digits`]);
        if (!part.includes('°') && values.some((v) => decimals(v) !== decimals(sigma)))
          bad.push([text, `value not at σ's place`]);
        if (values.some((v) => decimals(v) !== decimals(values[0]))) bad.push([text, 'components at other places']);
      }
    } else if (number.test(text)) {
      const mantissa = text.split(' × ')[0];
      if (milliseconds.includes(key) ? decimals(mantissa) > 3 : (mantissa.includes('.') && digits(mantissa) > 4))
        bad.push([text, `${key}: more digits than its precision`]);
    }
  }
  return bad;
"""


def check_panel(driver, shots, name, box_id, problems):
    """A panel with its result: screenshot, text size, text within the panel's sides, the
    numbers' digits."""
    time.sleep(0.5)
    driver.save_screenshot(str(shots / f"screen-{name}-1366x768.png"))
    texts, _, width, _ = driver.execute_script(TEXTS)
    box = driver.execute_script(f"const r = document.getElementById('{box_id}').getBoundingClientRect();"
                                "return [r.left, r.top, r.right, r.bottom];")
    shown = 0
    for text, px, panel, rects, _ in texts:
        if panel not in ("judge", "lab"):
            continue
        shown += 1
        if px < MIN_TEXT_PX:
            problems.append(f"{name}: {text!r} at {px} px, under {MIN_TEXT_PX}")
        for r in rects:
            if r[0] < box[0] - 0.5 or r[2] > box[2] + 0.5:
                problems.append(f"{name}: {text!r} runs past the panel's sides {[round(x) for x in box]}: "
                                f"{[round(x) for x in r]}")
    check_canvas_texts(driver, name, problems)
    bad = driver.execute_script(DIGITS)
    print(f"{name}: {shown} texts in the panel; numbers past their precision: {bad}")
    if not shown:
        problems.append(f"{name}: the panel shows no text")
    for text, why in bad:
        problems.append(f"{name}: {text!r}: {why}")


def check_lab_and_judge(driver, page, shots, source, motion, problems):
    load(driver, page + "#lab")
    driver.find_element("id", "labFile").send_keys(
        str((source / "recordings" / "phone-on-book-synthetic" / "Raw Data.csv").resolve()))
    if not wait_for(driver, "return !document.getElementById('labResult').hidden", bool, 240):
        problems.append(f"the lab showed no fit: {driver.find_element('id', 'labError').text}")
    else:
        check_panel(driver, shots, "lab-result", "labBox", problems)
        driver.execute_script("document.querySelector('#labTosses .toss').scrollIntoView()")
        check_panel(driver, shots, "lab-toss", "labBox", problems)
    load(driver, page + "?scene=fig09-matrix-unstable-x#judge")
    driver.find_element("id", "judgeFile").send_keys(str(motion.resolve()))
    if not wait_for(driver, "return !document.getElementById('judgeResult').hidden", bool, 240):
        problems.append(f"the judge showed no judgement: {driver.find_element('id', 'judgeError').text}")
    else:
        check_panel(driver, shots, "judge-result", "judgeBox", problems)


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    out, shots, page = explorer_of_every_scene(bookspin, source, binary, "explorer-screen")
    motion = exact_fig09_motion(bookspin, source, out)
    problems = []
    for screen in SCREENS:
        with open_browser(chromium, driver_path, size=screen, webgl=True, offline=True,
                          exact_viewport=True) as driver:
            driver.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": CANVAS_TEXTS})
            for case in CASES:
                check_case(driver, page, shots, screen, case, problems)
            check_left_panel(driver, page, screen, problems)
            if screen == SCREENS[0]:
                check_lab_and_judge(driver, page, shots, source, motion, problems)
            errors = console_errors(driver)
            if errors:
                problems.append(f"console errors at {screen[0]}×{screen[1]}: {errors}")
    print(f"screenshots: {shots}/screen-*.png")
    if problems:
        fail(f"{len(problems)} problems:\n" + "\n".join(problems[:60]))
    print("ok: no text over the body, the left panel fits, no text under 12 px or past its panel")


if __name__ == "__main__":
    main()
