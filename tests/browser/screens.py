"""The screens a class uses and what the explorer keeps on each of them (docs/explorer.md, "On
every screen"), shared by explorer_every_screen_test.py and explorer_person_test.py:

  SCREENS: (width, height, touch) of a netbook (1024×600), a projector (1280×720), a laptop
  (1366×768), a 1920×1080 screen, and a phone upright (390×844) and on its side (844×390),
  the phone's with touch (a coarse pointer: the page's touch words);

  set_screen(driver, screen): the page's viewport set to it (a phone: mobile, touch, 2×);

  layout_problems(driver, where): the 3D view's share (at least a third of the window's area,
  less only by what the readout's strip must show, its t, flips and first flips; never under
  200 px tall, wholly on the first screen), nothing drawn over a control (a body's
  label, a text, a canvas over a button of the transport bar or a field of the left column, each
  as far as its clipping boxes let it show), every plot axis with at least two labelled ticks
  of different values;

  displaced_while_playing(driver, seconds): the most any control of the transport bar moves
  between two frames while the page plays (the page's own animation frames);

  touch_word_problems(driver, where): on a touch screen, no visible text and no text drawn on a
  canvas since the last call says "click";

  CANVAS_INK (run before the page's scripts) and canvas_overlap_problems(driver, where): no two
  texts drawn on one canvas (in its last whole drawing) whose inked boxes meet, say the momentum
  sphere's axis names, or a chart's title and its key.
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


# JavaScript: the window, the 3D view's box, each visible control's box, and what is painted
# that could lie over a control: the bodies' labels, every visible text, every canvas (the tiles,
# the sphere's and the plots' labels are drawn on canvases, which draw nothing outside their own
# box). Each box is cut to what its clipping ancestors (overflow other than visible) let show,
# as the browser paints it: a label left unclipped over the transport bar is seen there. The
# plots' tick labels.
LAYOUT = """
  const box = (e) => { const b = e.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
  const shown = (e) => e.offsetParent !== null && !e.closest('[hidden]') && getComputedStyle(e).visibility !== 'hidden';
  const clipped = (e, b) => {
    const c = b.slice();
    for (let a = e.parentElement; a && a !== document.documentElement; a = a.parentElement) {
      const s = getComputedStyle(a), ab = box(a);
      if (s.overflowX !== 'visible') { c[0] = Math.max(c[0], ab[0]); c[2] = Math.min(c[2], ab[2]); }
      if (s.overflowY !== 'visible') { c[1] = Math.max(c[1], ab[1]); c[3] = Math.min(c[3], ab[3]); }
      if (s.position === 'fixed') break;
    }
    return c[2] > c[0] && c[3] > c[1] ? c : null;
  };
  const controlElements = [...document.querySelectorAll(
      '#transport button, #transport input, #controls button, #controls input, #controls select')].filter(shown);
  const controls = controlElements.map((e) => [e.id || e.tagName, clipped(e, box(e))]);
  const painted = [];
  const add = (what, e, b) => {
    const c = clipped(e, b);
    if (!c) return;
    const over = controlElements.filter((k) => !k.contains(e) && !e.contains(k)).map((k) => k.id || k.tagName);
    painted.push([what, c, over]);
  };
  for (const e of document.querySelectorAll('.bodyLabel')) if (shown(e)) add(`the label ${JSON.stringify(e.textContent)}`, e, box(e));
  for (const e of document.querySelectorAll('canvas')) if (shown(e)) add(`the canvas #${e.id || e.className}`, e, box(e));
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const e = n.parentElement;
    if (!n.textContent.trim() || !e || e.closest('[hidden], script, style, option, select, .bodyLabel, #lab, #judge') || !shown(e)) continue;
    if (e.closest('details:not([open])') && !e.closest('summary')) continue;
    const range = document.createRange(); range.selectNodeContents(n);
    for (const r of range.getClientRects())
      if (r.width > 0 && r.height > 0) add(`the text ${JSON.stringify(n.textContent.trim().slice(0, 40))}`, e, [r.left, r.top, r.right, r.bottom]);
  }
  const modal = ['lab', 'judge'].some((id) => !document.getElementById(id).hidden);
  // The readout's strip and what in it must be read (its clock, each run's flips and first
  // flip: the strip is never bounded under them, docs/explorer.md "What the class must read").
  const strip = document.getElementById('overlay'), sb = strip.getBoundingClientRect();
  const must = Math.max(0, ...[...strip.querySelectorAll('#clock, #status .flips, #status .first')]
    .map((e) => e.getBoundingClientRect().bottom - sb.top + strip.scrollTop));
  return { w: innerWidth, h: innerHeight, y: window.scrollY, view: box(document.getElementById('view')),
           strip: sb.height, must: must + parseFloat(getComputedStyle(strip).paddingBottom || '0'),
           controls: modal ? [] : controls.filter(([, b]) => b), painted,
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
    # Below a third only where the strip is no taller than what must be read in it needs (the
    # engines' six tiles at 1024×600: the view 534×338 px, 29 %).
    must_read = s["strip"] <= s["must"] + 2
    if vh < VIEW_MIN_PX - 0.5 or (share < 1 / 3 - 1e-3 and not must_read):
        problems.append(f"{where}: the 3D view is {vw:.0f}×{vh:.0f} px, {100 * share:.0f} % of the "
                        f"{s['w']}×{s['h']} window (at least a third, and {VIEW_MIN_PX} px tall)")
    # On the first screen: where it lies with the page scrolled to its top (a phone's page
    # scrolls to the controls below).
    if v[1] + s["y"] < -0.5 or v[3] + s["y"] > s["h"] + 0.5:
        problems.append(f"{where}: the 3D view {[round(x) for x in v]} (the page scrolled {s['y']:.0f} px) "
                        f"is not on the first screen ({s['h']} px)")
    for what, b, over in s["painted"]:
        for name, c in s["controls"]:
            if name in over and crossing(b, c):
                problems.append(f"{where}: {what} {[round(x) for x in b]} lies over "
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


# JavaScript: a function, visibleTextNodes(), giving every visible text node of the page as
# {text (its first 60 characters), e (its element), style (e's computed style), rects (each line
# box of the text node itself, a Range's, as [left, top, right, bottom])}: texts in hidden
# elements, scripts, styles, menus and closed details (but their summaries) left out.
VISIBLE_TEXT_NODES = """
  function visibleTextNodes() {
    const found = [];
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
      if (rects.length) found.push({ text: n.textContent.trim().slice(0, 60), e, style, rects });
    }
    return found;
  }
"""

# JavaScript: every visible text node as [text, font px, rects, whether a scroller clips it
# vertically (a scrolling panel, the page itself: reached by scrolling, not cut)].
TEXTS = VISIBLE_TEXT_NODES + """
  const scroller = (e) => {
    for (let a = e.parentElement; a; a = a.parentElement) {
      const o = getComputedStyle(a).overflowY;
      if ((o === 'auto' || o === 'scroll') && a.scrollHeight > a.clientHeight + 1) return a.getBoundingClientRect();
    }
    return null;
  };
  const out = visibleTextNodes().map(({ text, e, style, rects }) => {
    const s = scroller(e);
    return [text, parseFloat(style.fontSize), rects, s ? [s.left, s.top, s.right, s.bottom] : null];
  });
  const page = document.documentElement.scrollHeight > innerHeight + 1;
  return [out, innerWidth, innerHeight, page];
"""


# JavaScript: each visible field whose text does not fit it, as [id, text, the width it needs,
# the width it has]: an input's value longer than its box (its scrollWidth past its clientWidth:
# 1/60's "0.0166667" cut to "0.016666" at 1024×600), a menu's chosen entry wider than the box
# less the menu's arrow (MENU_ARROW_PX).
CUT_FIELDS = """
  const out = [];
  const g = document.createElement('canvas').getContext('2d');
  for (const e of document.querySelectorAll('input, select, textarea')) {
    if (e.offsetParent === null || e.closest('[hidden]') || getComputedStyle(e).visibility === 'hidden') continue;
    if (e.tagName === 'SELECT') {
      const s = getComputedStyle(e), o = e.selectedOptions[0];
      if (!o || !o.textContent.trim()) continue;
      g.font = `${s.fontStyle} ${s.fontWeight} ${s.fontSize} ${s.fontFamily}`;
      const room = e.clientWidth - parseFloat(s.paddingLeft) - parseFloat(s.paddingRight) - arguments[0];
      const need = g.measureText(o.textContent).width;
      if (need > room + 0.5) out.push([e.id, o.textContent, need, room]);
    } else if (!['checkbox', 'radio', 'range', 'file', 'button', 'submit', 'color'].includes(e.type) && e.value) {
      if (e.scrollWidth > e.clientWidth + 0.5) out.push([e.id, e.value, e.scrollWidth, e.clientWidth]);
    }
  }
  return out;
"""
MENU_ARROW_PX = 20  # Chromium's menu arrow and the start padding of its text


def text_problems(driver, where):
    """Text under 12 px, or cut: past the window's sides, or past its bottom or top where
    neither a scrolling panel nor the page scrolls to it (a panel that scrolls shows the rest
    when scrolled: the left column at 1024×600, the readout's strip, a phone's page), or a
    field's text cut by its box (CUT_FIELDS)."""
    texts, width, height, page_scrolls = driver.execute_script(TEXTS)
    # The page always shows words (its controls' names): none found is the check itself broken.
    problems = [] if texts else [f"{where}: no visible text found on the page (the text walk found none)"]
    for field, text, need, room in driver.execute_script(CUT_FIELDS, MENU_ARROW_PX):
        problems.append(f"{where}: #{field}'s {text!r} is cut: it needs {need:.0f} px, the field shows {room:.0f}")
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


# JavaScript run before the page's scripts: each text a 2D canvas draws, with its inked box
# (measureText's actual bounding box about the point drawn at, through the context's
# transform, in the canvas's pixels), kept on the canvas as canvas.__ink: [text, left, top,
# right, bottom]; a fillRect or clearRect over the whole canvas (a new drawing) empties it.
CANVAS_INK = """
(() => {
  const P = CanvasRenderingContext2D.prototype, fill = P.fillText, rect = P.fillRect, clear = P.clearRect;
  const whole = (g, x, y, w, h) => {
    const m = g.getTransform();
    return m.a * x + m.e <= 0.5 && m.d * y + m.f <= 0.5 && m.a * (x + w) + m.e >= g.canvas.width - 0.5 &&
      m.d * (y + h) + m.f >= g.canvas.height - 0.5;
  };
  P.fillRect = function (x, y, w, h) { if (whole(this, x, y, w, h)) this.canvas.__ink = []; return rect.call(this, x, y, w, h); };
  P.clearRect = function (x, y, w, h) { if (whole(this, x, y, w, h)) this.canvas.__ink = []; return clear.call(this, x, y, w, h); };
  P.fillText = function (text, x, y, ...rest) {
    const t = String(text);
    if (t.trim() && this.globalAlpha > 0) {
      const m = this.measureText(t), k = this.getTransform();
      const b = [x - m.actualBoundingBoxLeft, y - m.actualBoundingBoxAscent, x + m.actualBoundingBoxRight,
        y + m.actualBoundingBoxDescent];
      (this.canvas.__ink = this.canvas.__ink || []).push(
        [t.slice(0, 40), k.a * b[0] + k.c * b[1] + k.e, k.b * b[0] + k.d * b[1] + k.f, k.a * b[2] + k.c * b[3] + k.e, k.b * b[2] + k.d * b[3] + k.f]);
    }
    return fill.call(this, text, x, y, ...rest);
  };
})();
"""

# JavaScript: each visible canvas's name, its backing-store pixels per CSS pixel, and its texts.
INKED = """
  return [...document.querySelectorAll('canvas')]
    .filter((c) => c.offsetParent !== null && !c.closest('[hidden]') && c.getBoundingClientRect().width > 0)
    .map((c) => [c.id || c.className || 'canvas', c.width / c.getBoundingClientRect().width, c.__ink || []]);
"""
INK_GAP_PX = 1  # CSS px that two texts' inked boxes must keep apart


def canvas_overlap_problems(driver, where):
    """Two texts drawn on one canvas whose inked boxes come closer than INK_GAP_PX (CSS px):
    one drawn over the other (the sphere's far-side axis names over the near ones, a chart's
    title into its key)."""
    problems = []
    for canvas, scale, ink in driver.execute_script(INKED):
        boxes = []
        for text, *b in ink:
            if (text, b) not in boxes:
                boxes.append((text, b))
        gap = INK_GAP_PX * scale
        for i in range(len(boxes)):
            for j in range(i + 1, len(boxes)):
                (ta, a), (tb, b) = boxes[i], boxes[j]
                if min(a[2], b[2]) - max(a[0], b[0]) > -gap and min(a[3], b[3]) - max(a[1], b[1]) > -gap:
                    problems.append(f"{where}: on canvas #{canvas}, {ta!r} {[round(x / scale) for x in a]} "
                                    f"and {tb!r} {[round(x / scale) for x in b]} (CSS px) overlap")
    return problems


# JavaScript: for each body's label shown, how many pixels of the 3D view under its box are
# not the view's background (its corner pixel): a body drawn there, under the label. The
# labels are page elements over the canvas, so the canvas's pixels are the bodies alone.
UNDER_LABELS = """
  const v = document.getElementById('view'), vb = v.getBoundingClientRect();
  const labels = [...document.querySelectorAll('.bodyLabel')].filter((l) => !l.hidden && l.offsetParent !== null);
  if (!labels.length || !v.width || !v.height) return [];
  const c = document.createElement('canvas');
  c.width = v.width; c.height = v.height;
  const g = c.getContext('2d', { willReadFrequently: true });
  g.drawImage(v, 0, 0);
  const bg = g.getImageData(1, 1, 1, 1).data, k = v.width / vb.width;
  return labels.map((l) => {
    const b = l.getBoundingClientRect();
    const x0 = Math.max(0, Math.floor((b.left - vb.left) * k)), x1 = Math.min(v.width, Math.ceil((b.right - vb.left) * k));
    const y0 = Math.max(0, Math.floor((b.top - vb.top) * k)), y1 = Math.min(v.height, Math.ceil((b.bottom - vb.top) * k));
    if (x1 <= x0 || y1 <= y0) return [l.textContent, 0, 0, [b.left, b.top, b.right, b.bottom]];
    const d = g.getImageData(x0, y0, x1 - x0, y1 - y0).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4)
      if (Math.max(Math.abs(d[i] - bg[0]), Math.abs(d[i + 1] - bg[1]), Math.abs(d[i + 2] - bg[2])) > 30) ++n;
    return [l.textContent, n, d.length / 4, [b.left, b.top, b.right, b.bottom]];
  });
"""


def label_over_body_problems(driver, where):
    """A body's label over a body (the 3D view's pixels under the label's box not its
    background, more than 0.5 % of them: a landscape phone's tiles had their labels over the
    lower row's books)."""
    problems = []
    # A body that grows past the room framed for it (a particle lattice or a quaternion left
    # unnormalized: what compare-normalization shows) may reach a neighbour's label.
    growth = driver.execute_script("return window.explorer.bodyGrowth()")
    if growth is None or growth > 1.02:
        return problems
    for text, n, total, box in driver.execute_script(UNDER_LABELS):
        if n > max(4, 0.005 * total):
            problems.append(f"{where}: the label {text!r} {[round(x) for x in box]} lies over a body "
                            f"({n} of its {total} pixels)")
    return problems
