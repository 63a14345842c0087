#!/usr/bin/env python3
"""The explorer (docs/explorer.md) used as a person uses it, at random: headless Chromium on each
screen a class uses (tests/browser/screens.py: 1024×600, 1280×720, 1366×768, 1920×1080, and a
phone upright and on its side, 390×844 and 844×390, with touch), the page `bookspin explore`
writes from every scene, and on each screen a seeded series of actions a person takes
(BOOKSPIN_PERSON_ACTIONS of them a screen, 45 by default; BOOKSPIN_PERSON_SEED, 80 by default:
the same seed takes the same actions):

  seek with the time slider (a real click on it, at a time that is no whole number of steps),
  with the → and ← keys, the Step button; Play, Pause, Reset; open the address the page wrote
  (while playing too: its t is ahead of the time shown, between two steps); change the scene,
  the body and the method (model); click the momentum sphere (a start anywhere on it, inside or
  outside a separatrix).

After each action it checks that

  - the page is never stuck: every catch-up ends (no "simulating to" left on screen, at 100 %
    or anywhere), and Play moves t on within 2 s (pressed for the check where the page was
    paused, and paused again after);
  - the flips shown are the exact motion's from the command line for the same start: the
    exact run's "flips N" and each method's "exact motion: … count M" ("never turns over", 0)
    equal the turn-overs by the page's t of `bookspin sweep` of the exact model from that start
    (body, ω0 or spin axis and rate, jiggle, seed, dt; first_flip_exact + k·flip_period_exact
    ≤ t, none where sweep's flip detector sees no turn-over over the run: a wobble), as
    Browser.ExplorerMatchesSimulate compares the page's flips with `bookspin sweep`;
  - no text is under 12 px, past its panel or the screen, or over another text
    (explorer_screen_test.py's checks, and two text nodes' boxes crossing), and no text drawn
    on a canvas runs past the canvas's edge;
  - the 3D view keeps its share of the screen (a third of its area, 200 px tall), nothing is
    drawn over a control, every plot axis has at least two labelled ticks (screens.py);
  - while Play plays (its action), no control of the transport bar moves by more than 2 px
    between two frames;
  - after a change of scene, Back returns to the scene before, Forward to the new one;
  - on the phone's touch screen, no text says "click".

Screenshots of the last state and of each failure go to BINARY_DIR/test-output/browser/person-*.png.
About 5 minutes on the 2-core machine.

Usage: explorer_person_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import contextlib
import csv
import io
import json
import math
import os
import random
import re
import time
from pathlib import Path

from browser import console_errors, explorer_of_every_scene, fail, find_browser, open_browser, require, run, test_arguments
from explorer_screen_test import CANVAS_TEXTS, check_canvas_texts, check_texts, overlaps
from explorer_test import load
from screens import (CANVAS_INK, MOVE_LIMIT_PX, SCREENS, canvas_overlap_problems, displaced_while_playing,
                     label_over_body_problems, layout_problems, screen_name, set_screen, text_problems,
                     touch_word_problems)
from screens import text_overlaps as visible_text_overlaps

# JavaScript run before the page's scripts: every fillText on a 2D canvas whose text runs past
# the canvas's left or right edge, as [text, canvas id, left, right, canvas width] in the
# canvas's pixels (its transform and textAlign applied).
CANVAS_EDGES = """
  window.__canvasCuts = [];
  const fill = CanvasRenderingContext2D.prototype.fillText;
  CanvasRenderingContext2D.prototype.fillText = function (text, x, ...rest) {
    const w = this.measureText(String(text)).width, a = this.textAlign;
    const left = a === 'center' ? x - w / 2 : a === 'right' || a === 'end' ? x - w : x;
    const m = this.getTransform();
    const l = m.a * left + m.e, r = m.a * (left + w) + m.e;
    if (String(text).trim() && (l < -1 || r > this.canvas.width + 1))
      window.__canvasCuts.push([String(text).slice(0, 60), this.canvas.id, l, r, this.canvas.width]);
    return fill.call(this, text, x, ...rest);
  };
"""

# JavaScript: the page's time, state, playing, notice, and the readout's runs as shown:
# [{flips (the run's own count shown), exact (the exact motion's count shown beside it, or
# null where none is shown), closedForm}].
SHOWN = """
  const x = window.explorer, s = x.state();
  const runs = [...document.querySelectorAll('#status .run')].map((e) => {
    const flips = /flips (\\d+)/.exec(e.querySelector('.flips').textContent);
    const ex = e.querySelector('.exact');
    let exact = null;
    if (ex) {
      const t = ex.textContent;
      const m = /count (\\d+)/.exec(t);
      exact = m ? Number(m[1]) : /never turns over/.test(t) ? 0 : /the exact motion/.test(t) ? 'self' : t;
    }
    return { flips: flips ? Number(flips[1]) : e.querySelector('.flips').textContent, exact,
             method: e.querySelector('.method').textContent };
  });
  const scene = (window.BOOKSPIN_SCENES || []).find((c) => c.name === s.scene) || null;
  return { t: s.t, state: s, playing: document.getElementById('play').textContent === 'Pause',
           notice: document.getElementById('notice').textContent,
           message: document.getElementById('message').textContent,
           settled: x.settled(), runs, closedForm: x.trails().map((r) => r.label === 'exact'),
           book: scene && scene.book && !scene.body ? scene.book : null,
           ownBody: scene && scene.body ? scene.body.shape : (scene ? 'book' : null),
           duration: scene ? scene.duration : null };
"""


def poll(driver, script, done, timeout):
    """Runs `script` in the page every 30 ms until done(result) or `timeout` seconds; returns
    the last result (browser.wait_for's, at a finer step: it runs after every action)."""
    deadline = time.monotonic() + timeout
    while True:
        result = driver.execute_script(script)
        if done(result) or time.monotonic() > deadline:
            return result
        time.sleep(0.03)


def click_at(driver, x, y):
    for kind in ("mousePressed", "mouseReleased"):
        driver.execute_cdp_cmd("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y,
                                                            "button": "left", "clickCount": 1})


def key(driver, code, key_name):
    for kind in ("keyDown", "keyUp"):
        driver.execute_cdp_cmd("Input.dispatchKeyEvent", {"type": kind, "code": code, "key": key_name,
                                                          "windowsVirtualKeyCode": {"ArrowRight": 39, "ArrowLeft": 37}[code]})


def box(driver, element_id):
    # Scrolled into view first, as a person on a phone scrolls to it.
    return driver.execute_script(
        f"const e = document.getElementById('{element_id}'); if (e.offsetParent !== null) e.scrollIntoView({{block: 'nearest'}});"
        f"const r = e.getBoundingClientRect();"
        "return r.width > 0 ? [r.left, r.top, r.width, r.height] : null;")


def choose(driver, element_id, rng, values=None):
    """Picks one of the enabled options of select `element_id` (or of `values`) as a person
    does: the value set and a change event, as the browser's menu gives it."""
    options = driver.execute_script(
        f"return [...document.getElementById('{element_id}').options].filter((o) => !o.disabled)"
        ".map((o) => o.value)")
    options = [o for o in options if values is None or o in values]
    if not options:
        return None
    value = rng.choice(options)
    driver.execute_script("""
      const s = document.getElementById(arguments[0]); s.focus(); s.value = arguments[1];
      s.dispatchEvent(new Event('change'));""", element_id, value)
    return value


class ExactFlips:
    """The exact motion's turn-overs from a start, from `bookspin sweep` of the exact model (its
    first_flip_exact and flip_period_exact, and whether its flip detector sees a turn-over at
    all), one sweep per start."""

    def __init__(self, bookspin, source, workdir):
        self.bookspin, self.source, self.workdir = bookspin, source, workdir
        self.cache = {}
        self.sweeps = 0

    def scene_text(self, shown, horizon):
        """A scene file of the page's start: its body (the scene's book size, the default book,
        a preset or the scene's mesh), ω0, jiggle, seed and dt; the exact model; `horizon`
        time units of steps."""
        s = shown["state"]
        lines = []
        if s["body"] == "book":
            lines += ["[body]", 'shape = "book"']
            if shown["book"]:
                lines += ["[book]", f"size = {json.dumps(shown['book']['size'])}",
                          f"mass = {shown['book']['mass']!r}"]
        elif s["body"] == "mesh":
            scene = (self.source / "scenes" / f"{s['scene']}.toml").read_text()
            mesh = re.search(r'^mesh\s*=\s*"([^"]+)"', scene, re.M).group(1)
            lines += ["[body]", 'shape = "mesh"',
                      f"mesh = {json.dumps(str((self.source / 'scenes' / mesh).resolve()))}"]
        else:
            lines += ["[body]", f'shape = "{s["body"]}"']
        lines += ["[model]", 'kind = "exact"', "[initial]"]
        if s["axis"] == "custom":
            lines.append(f"angular_velocity = [{', '.join(repr(float(w)) for w in s['w'])}]")
        else:
            lines += [f'spin_axis = "{s["axis"]}"', f"spin_rate = {float(s['rate'])!r}"]
        # The page's dt, or a longer step where that would be more than 200 000 steps: the
        # closed form's first flip and half period do not depend on the step, and the detector
        # still sees a turn-over's every swing.
        dt = max(float(s["dt"]), horizon / 200000)
        steps = max(1, math.ceil(horizon / dt))
        per_frame = min(steps, 100000)  # the scene's limit is 10⁶ a frame
        lines += [f"jiggle = {float(s['jiggle'])!r}", f"seed = {int(s['seed'])}", "[time]",
                  f"dt = {dt!r}", f"steps_per_frame = {per_frame}",
                  f"frames = {1 + math.ceil(steps / per_frame)}"]
        return "\n".join(lines) + "\n"

    def measures(self, shown, horizon):
        """(first_flip_exact, flip_period_exact, tumbles) of the start shown, from a sweep
        `horizon` time units long (a wobble's detector counts none however long)."""
        s = shown["state"]
        key = json.dumps([s["scene"], s["body"], s["axis"], s["rate"], s["w"], s["jiggle"], s["seed"], s["dt"],
                          shown["book"]])
        if key in self.cache and self.cache[key][0] >= horizon:
            return self.cache[key][1]
        scene = self.workdir / "start.toml"
        scene.write_text(self.scene_text(shown, horizon))
        seed = int(s["seed"])
        out = self.workdir / "sweep"
        run([self.bookspin, "sweep", str(scene), "--vary", f"initial.seed={seed}:{seed}:1",
             "--measure", "first_flip,flip_period", "-o", str(out)])
        self.sweeps += 1
        with open(out / "start-sweep.csv") as f:
            row = list(csv.DictReader(line for line in f if not line.startswith("#")))[-1]
        number = lambda k: float(row[k]) if row.get(k) not in (None, "") else None
        result = (number("first_flip_exact"), number("flip_period_exact"), number("first_flip") is not None)
        self.cache[key] = (horizon, result)
        return result

    def count(self, shown):
        """The exact motion's turn-overs by the page's time: zeros of ω about the intermediate
        axis at first_flip_exact + k·flip_period_exact ≤ t where the motion turns over, else 0."""
        t = shown["t"]
        # One sweep a start, over the slider's span (the scene's run) or twice t, whichever is
        # longer; the detector decides tumble or wobble over at least four half periods.
        horizon = max(2.0 * t, shown["duration"] or 300.0, 10.0)
        first, period, tumbles = self.measures(shown, horizon)
        if period is not None and not tumbles and horizon < t + 4.0 * period + first:
            first, period, tumbles = self.measures(shown, t + 4.0 * period + first)
        if not tumbles or first is None or t < first:
            return 0, first, period
        return 1 + int(math.floor((t - first) / period + 1e-12)), first, period


class Person:
    def __init__(self, driver, page, rng, exact, shots):
        self.driver, self.page, self.rng, self.exact, self.shots = driver, page, rng, exact, shots
        self.log = []
        self.problems = []
        self.moved = None  # what an action found wrong as it acted
        self.where = ""
        self.touch = False

    def shown(self):
        return self.driver.execute_script(SHOWN)

    # The actions.
    def slider(self):
        b = box(self.driver, "slider")
        # A click along the track, away from its ends (the thumb's half width).
        x = b[0] + 8 + self.rng.random() * (b[2] - 16)
        click_at(self.driver, x, b[1] + b[3] / 2)
        return f"slider click at x = {x:.1f}"

    def arrow(self):
        code = self.rng.choice(["ArrowRight", "ArrowRight", "ArrowLeft"])
        key(self.driver, code, code)
        return code

    def button(self, element_id):
        b = box(self.driver, element_id)
        if not b:
            return f"{element_id}: not shown"
        click_at(self.driver, b[0] + b[2] / 2, b[1] + b[3] / 2)
        return f"{element_id} clicked"

    def play(self):
        what = self.button("play")
        moved, control, t, frames = displaced_while_playing(self.driver, self.rng.choice([0.2, 0.5, 1.0]), press=False)
        if moved > MOVE_LIMIT_PX:
            self.moved = f"#{control} moved {moved:.1f} px between two frames while playing (t = {t:.2f})"
        return what

    def link(self):
        url = self.driver.current_url
        load(self.driver, url)
        return f"opened the written address {url.split('?', 1)[-1] if '?' in url else ''}"

    def scene(self):
        names = self.driver.execute_script(
            "return [...document.getElementById('scene').options].map((o) => o.value).filter((v) => v)")
        before = self.driver.execute_script("return window.explorer.state().scene")
        chosen = choose(self.driver, 'scene', self.rng, names)
        if chosen != before:
            # Back returns to the scene before, Forward to this one.
            time.sleep(0.1)
            self.driver.back()
            back = poll(self.driver, "return window.explorer.state().scene", lambda s: s == before, 10)
            self.driver.forward()
            fwd = poll(self.driver, "return window.explorer.state().scene", lambda s: s == chosen, 10)
            if back != before or fwd != chosen:
                self.moved = f"Back after the scene {chosen}: {back!r}, not {before!r}; Forward: {fwd!r}"
        return f"scene {chosen}"

    def body(self):
        return f"body {choose(self.driver, 'body', self.rng)}"

    def method(self):
        return f"model {choose(self.driver, 'model', self.rng)}"

    def sphere(self):
        b = box(self.driver, "sphere")
        size = min(b[2], b[3])
        # A point within the sphere's disc (it fills about 0.8 of the canvas's shorter side).
        r, a = 0.38 * size * math.sqrt(self.rng.random()), 2 * math.pi * self.rng.random()
        x, y = b[0] + b[2] / 2 + r * math.cos(a), b[1] + b[3] / 2 + r * math.sin(a)
        click_at(self.driver, x, y)
        return f"sphere click at ({x - b[0]:.0f}, {y - b[1]:.0f})"

    ACTIONS = (("slider", 6), ("arrow", 4), ("step", 3), ("play", 5), ("reset", 2), ("link", 4),
               ("scene", 3), ("body", 2), ("method", 2), ("sphere", 5))

    def act(self):
        names = [n for n, w in self.ACTIONS for _ in range(w)]
        name = self.rng.choice(names)
        if name == "step":
            return self.button("stepOnce")
        if name == "reset":
            return self.button("reset")
        return getattr(self, name)()

    # The checks.
    def problem(self, i, why):
        self.problems.append(f"{self.where} action {i} ({self.log[-1]}): {why}")
        if len(self.problems) <= 5:
            self.driver.save_screenshot(str(self.shots / f"person-problem-{len(self.problems)}.png"))

    def check_not_stuck(self, i):
        """Every catch-up ends; Play moves t on within 2 s. Returns the page as shown after."""
        settled = poll(self.driver, "return window.explorer.settled()", bool, timeout=60)
        shown = self.shown()
        if not settled or "simulating to" in shown["notice"]:
            self.problem(i, f"stuck catching up: notice {shown['notice']!r} at t = {shown['t']}")
            return None
        was_playing = shown["playing"]
        if not was_playing:
            self.driver.execute_script("document.getElementById('play').click()")
        t0 = shown["t"]
        moved = poll(self.driver, "return window.explorer.state().t", lambda t: t > t0, timeout=2)
        if not moved > t0:
            self.problem(i, f"Play does not move t on in 2 s (t = {t0}, notice {shown['notice']!r})")
        if not was_playing:
            self.driver.execute_script("document.getElementById('play').click()")
            poll(self.driver, "return window.explorer.settled()", bool, timeout=10)
        return self.shown()

    def check_flips(self, i, shown):
        """The flips shown against the exact motion's from the command line."""
        s = shown["state"]
        if not s["scene"] or not shown["runs"]:
            return
        count, first, period = self.exact.count(shown)
        for run, closed in zip(shown["runs"], shown["closedForm"]):
            got = run["flips"] if closed else run["exact"]
            if got is None or got == "self":
                continue
            if got != count:
                self.problem(i, f"{run['method']!r} shows {got} exact turn-overs at t = {shown['t']}; "
                                f"bookspin sweep of the exact motion from the same start: {count} "
                                f"(first {first}, half period {period}); state {s}")

    def check_text(self, i):
        where = f"action {i}"
        found = []
        scratch = []
        with contextlib.redirect_stdout(io.StringIO()):  # their counts, printed per call
            check_texts(self.driver, where, scratch)
            check_canvas_texts(self.driver, where, found)
        # At 1366×768 every text on the screen and inside its panel (explorer_screen_test.py);
        # elsewhere a panel or the page may scroll to a text (screens.py).
        found += scratch if self.where == "1366x768" else text_problems(self.driver, where)
        found += visible_text_overlaps(self.driver)
        found += canvas_overlap_problems(self.driver, where)
        found += label_over_body_problems(self.driver, where)
        if self.touch:
            found += touch_word_problems(self.driver, where)
        cuts = self.driver.execute_script("const c = window.__canvasCuts; window.__canvasCuts = [];"
                                          "window.__canvasTexts = []; return c;")
        for text, canvas, left, right, width in (cuts or [])[:3]:
            found.append(f"{text!r} on canvas {canvas!r} runs past its edge: {left:.0f} … {right:.0f} of {width}")
        found += layout_problems(self.driver, where)
        if self.moved:
            found.append(self.moved)
            self.moved = None
        for why in found[:4]:
            self.problem(i, why)


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    actions = int(os.environ.get("BOOKSPIN_PERSON_ACTIONS", "45"))
    seed = int(os.environ.get("BOOKSPIN_PERSON_SEED", "80"))
    out, shots, page = explorer_of_every_scene(bookspin, source, binary, "explorer-person")
    rng = random.Random(seed)
    exact = ExactFlips(bookspin, source, out)
    started = time.monotonic()
    with open_browser(chromium, driver_path, size=(1366, 768), webgl=True, offline=True) as driver:
        driver.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": CANVAS_TEXTS + CANVAS_EDGES + CANVAS_INK})
        person = Person(driver, page, rng, exact, shots)
        for screen in SCREENS:
            set_screen(driver, screen)
            person.where, person.touch = screen_name(screen), screen[2]
            first = rng.choice(["t-handle-dzhanibekov", "fig09-matrix-unstable-x", "exact-unstable-x"])
            load(driver, page + f"?scene={first}")
            person.log.append(f"{person.where}: opened {first}")
            for i in range(actions):
                person.log.append(person.act())
                shown = person.check_not_stuck(i)
                if shown is not None:
                    person.check_flips(i, shown)
                person.check_text(i)
                if len(person.problems) >= 20:
                    break
            driver.save_screenshot(str(shots / f"person-last-{screen[0]}x{screen[1]}.png"))
            if len(person.problems) >= 20:
                break
        errors = console_errors(driver)
        if errors:
            person.problems.append(f"console errors: {errors[:5]}")
        driver.save_screenshot(str(shots / "person-last.png"))
    took = time.monotonic() - started
    counts = {}
    for line in person.log:
        if ": opened " not in line:
            counts[line.split(" ")[0]] = counts.get(line.split(" ")[0], 0) + 1
    print(f"seed {seed}: {sum(counts.values())} actions on {len(SCREENS)} screens in {took:.0f} s "
          f"({counts}); {exact.sweeps} sweeps")
    if person.problems:
        print("the actions:\n" + "\n".join(f"{i}: {a}" for i, a in enumerate(person.log)), flush=True)
        fail(f"{len(person.problems)} problems (seed {seed}):\n" + "\n".join(person.problems[:30]))
    print("ok: on every screen never stuck, the flips shown are the exact motion's, every text "
          "readable, the view its share, the transport bar still, Back back to the scene before")


if __name__ == "__main__":
    main()
