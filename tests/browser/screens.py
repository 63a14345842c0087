"""The screens a class uses and what the explorer keeps on each of them (docs/explorer.md, "On
every screen"), shared by explorer_every_screen_test.py and explorer_person_test.py:

  SCREENS: (width, height, touch) of a netbook (1024×600), a projector (1280×720), a laptop
  (1366×768), a 1920×1080 screen, and a phone upright (390×844) and on its side (844×390),
  the phone's with touch (a coarse pointer: the page's touch words);

  set_screen(driver, screen): the page's viewport set to it (a phone: mobile, touch, 2×);

  layout_problems(driver, where): the 3D view's share (at least a third of the window's area,
  never under 200 px tall, wholly on the first screen), nothing drawn over a control (a body's
  label over a button of the transport bar), every plot axis with at least two labelled ticks
  of different values;

  displaced_while_playing(driver, seconds): the most any control of the transport bar moves
  between two frames while the page plays (the page's own animation frames);

  touch_word_problems(driver, where): on a touch screen, no visible text and no text drawn on a
  canvas since the last call says "click".
"""
import time

SCREENS = ((1024, 600, False), (1280, 720, False), (1366, 768, False), (1920, 1080, False),
           (390, 844, True), (844, 390, True))
VIEW_MIN_PX = 200
MOVE_LIMIT_PX = 2


def screen_name(screen):
    w, h, touch = screen
    return f"{w}x{h}" + (" touch" if touch else "")


def set_screen(driver, screen):
    w, h, touch = screen
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": w, "height": h, "deviceScaleFactor": 2 if touch else 1,
                            "mobile": touch})
    driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": touch, "maxTouchPoints": 5})
    driver.execute_script("window.dispatchEvent(new Event('resize'))")
    time.sleep(0.3)


# JavaScript: the window, the 3D view's box, each visible control's box, the bodies' labels'
# boxes as seen (cut to the view's box, which clips them), and the plots' tick labels.
LAYOUT = """
  const box = (e) => { const b = e.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
  const shown = (e) => e.offsetParent !== null && !e.closest('[hidden]') && getComputedStyle(e).visibility !== 'hidden';
  const controls = [...document.querySelectorAll(
      '#transport button, #transport input, #controls button, #controls input, #controls select')]
    .filter(shown).map((e) => [e.id || e.tagName, box(e)]);
  const clip = box(document.getElementById('viewBox'));
  const labels = [...document.querySelectorAll('.bodyLabel')].filter(shown).map((e) => {
    const b = box(e);
    return [e.textContent, [Math.max(b[0], clip[0]), Math.max(b[1], clip[1]), Math.min(b[2], clip[2]), Math.min(b[3], clip[3])]];
  }).filter(([, b]) => b[2] > b[0] && b[3] > b[1]);
  return { w: innerWidth, h: innerHeight, y: window.scrollY, view: box(document.getElementById('view')), controls, labels,
           ticks: window.explorer.plotTickLabels() };
"""


def crossing(a, b, slack=1.0):
    return a[0] + slack < b[2] and b[0] + slack < a[2] and a[1] + slack < b[3] and b[1] + slack < a[3]


def layout_problems(driver, where):
    s = driver.execute_script(LAYOUT)
    problems = []
    v = s["view"]
    vw, vh = v[2] - v[0], v[3] - v[1]
    share = vw * vh / (s["w"] * s["h"])
    if vh < VIEW_MIN_PX - 0.5 or share < 1 / 3 - 1e-3:
        problems.append(f"{where}: the 3D view is {vw:.0f}×{vh:.0f} px, {100 * share:.0f} % of the "
                        f"{s['w']}×{s['h']} window (at least a third, and {VIEW_MIN_PX} px tall)")
    # On the first screen: where it lies with the page scrolled to its top (a phone's page
    # scrolls to the controls below).
    if v[1] + s["y"] < -0.5 or v[3] + s["y"] > s["h"] + 0.5:
        problems.append(f"{where}: the 3D view {[round(x) for x in v]} (the page scrolled {s['y']:.0f} px) "
                        f"is not on the first screen ({s['h']} px)")
    for text, b in s["labels"]:
        for name, c in s["controls"]:
            if crossing(b, c):
                problems.append(f"{where}: the label {text!r} {[round(x) for x in b]} lies over "
                                f"#{name} {[round(x) for x in c]}")
    axes = {}
    for t in s["ticks"] or []:
        axes.setdefault(t["axis"], set()).add(t["value"])
    if not axes:
        problems.append(f"{where}: the plots drew no tick label")
    for axis, values in axes.items():
        if len(values) < 2:
            problems.append(f"{where}: the plot axis {axis!r} has {len(values)} labelled tick "
                            f"({sorted(values)}): its range unsaid")
    return problems


# JavaScript (async): plays for arguments[0] seconds, recording each animation frame the boxes
# of the transport bar's controls; returns the largest move of one of them between two frames,
# with its name and the times, and how many frames were seen.
PLAY_AND_WATCH = """
  const done = arguments[arguments.length - 1], seconds = arguments[0], untilFlip = arguments[1];
  let flippedAt = null;
  const ids = [...document.querySelectorAll('#transport button, #transport input')]
    .filter((e) => e.offsetParent !== null).map((e) => e.id);
  const at = () => ids.map((id) => { const b = document.getElementById(id).getBoundingClientRect(); return [b.left, b.top]; });
  let last = at(), worst = [0, '', 0, 0], frames = 0;
  const t0 = performance.now();
  if (document.getElementById('play').textContent !== 'Pause') document.getElementById('play').click();
  const watch = () => {
    const now = at();
    frames += 1;
    now.forEach((p, i) => {
      const d = Math.hypot(p[0] - last[i][0], p[1] - last[i][1]);
      if (d > worst[0]) worst = [d, ids[i], window.explorer.state().t, frames];
    });
    last = now;
    // At least `seconds`; with `untilFlip`, until the first run's first flip is counted and a
    // second after (30 s at most: a loaded machine draws few frames).
    const counted = () => window.explorer.flipMeasures()[0].count > 0;
    if (untilFlip && counted() && !flippedAt) flippedAt = performance.now();
    const wait = untilFlip ? (flippedAt ? Math.max(1000 * seconds, flippedAt - t0 + 1000) : 30000) : 1000 * seconds;
    if (performance.now() - t0 < wait) requestAnimationFrame(watch);
    else { window.explorer.setPlaying(false); done({ worst, frames }); }
  };
  requestAnimationFrame(watch);
"""


def displaced_while_playing(driver, seconds, press=True, until_flip=False):
    """(the largest move in px, the control, the page's t then, frames seen) over `seconds`
    of play from where the page is (`press`: Play pressed first and Pause after; else the page
    watched as it is, playing or not; `until_flip`: on until the first flip is counted, and a
    second more)."""
    script = PLAY_AND_WATCH if press else PLAY_AND_WATCH.replace(
        "if (document.getElementById('play').textContent !== 'Pause') document.getElementById('play').click();", "").replace(
        "window.explorer.setPlaying(false); done", "done")
    r = driver.execute_async_script(script, seconds, until_flip)
    return r["worst"][0], r["worst"][1], r["worst"][2], r["frames"]


# JavaScript: the visible texts of the page with "click" in them, and those drawn on canvases
# (window.__canvasTexts, explorer_screen_test.CANVAS_TEXTS) since the last call.
CLICK_WORDS = """
  const out = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const e = n.parentElement;
    if (!e || e.closest('[hidden], script, style') || e.offsetParent === null) continue;
    if (getComputedStyle(e).display === 'none') continue;
    if (/\\bclick/i.test(n.textContent)) out.push(n.textContent.trim().slice(0, 80));
  }
  for (const [text] of window.__canvasTexts || []) if (/\\bclick/i.test(text)) out.push(text);
  return out;
"""


def touch_word_problems(driver, where):
    return [f"{where}: on a touch screen the page says {text!r}"
            for text in driver.execute_script(CLICK_WORDS)]


# JavaScript: every visible text node as [text, font px, rects, whether a scroller clips it
# vertically (a scrolling panel, the page itself: reached by scrolling, not cut)].
TEXTS = """
  const out = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  const scroller = (e) => {
    for (let a = e.parentElement; a; a = a.parentElement) {
      const o = getComputedStyle(a).overflowY;
      if ((o === 'auto' || o === 'scroll') && a.scrollHeight > a.clientHeight + 1) return a.getBoundingClientRect();
    }
    return null;
  };
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
    const s = scroller(e);
    out.push([n.textContent.trim().slice(0, 60), parseFloat(style.fontSize), rects, s ? [s.left, s.top, s.right, s.bottom] : null]);
  }
  const page = document.documentElement.scrollHeight > innerHeight + 1;
  return [out, innerWidth, innerHeight, page];
"""


def text_problems(driver, where):
    """Text under 12 px, or cut: past the window's sides, or past its bottom or top where
    neither a scrolling panel nor the page scrolls to it (a panel that scrolls shows the rest
    when scrolled: the left column at 1024×600, the readout's strip, a phone's page)."""
    texts, width, height, page_scrolls = driver.execute_script(TEXTS)
    problems = []
    for text, px, rects, scroller in texts:
        if px < 12:
            problems.append(f"{where}: {text!r} at {px} px, under 12")
        for r in rects:
            if r[0] < -0.5 or r[2] > width + 0.5:
                problems.append(f"{where}: {text!r} runs past the window's side: {[round(x) for x in r]}")
            elif not scroller and not page_scrolls and (r[1] < -0.5 or r[3] > height + 0.5):
                problems.append(f"{where}: {text!r} cut at the window's edge: {[round(x) for x in r]}")
    return problems


def text_overlaps(driver):
    """Pairs of visible text nodes whose boxes cross (more than 2 px each way), each box cut
    to the scrolling panel it lies in (a text scrolled out of the readout's strip is not seen)."""
    texts = driver.execute_script(TEXTS)[0]
    rects = []
    for n, (text, _, rs, clip) in enumerate(texts):
        for r in rs:
            if clip:
                r = [max(r[0], clip[0]), max(r[1], clip[1]), min(r[2], clip[2]), min(r[3], clip[3])]
            if r[2] - r[0] > 0 and r[3] - r[1] > 0:
                rects.append((n, text, r))
    out = []
    for i in range(len(rects)):
        for j in range(i + 1, len(rects)):
            (na, ta, a), (nb, tb, b) = rects[i], rects[j]
            if na != nb and min(a[2], b[2]) - max(a[0], b[0]) > 2 and min(a[3], b[3]) - max(a[1], b[1]) > 2:
                out.append(f"{ta!r} {[round(x) for x in a]} and {tb!r} {[round(x) for x in b]} overlap")
    return out
