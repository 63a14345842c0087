#!/usr/bin/env python3
"""A fitted toss opened in the explorer (docs/phone-lab.md, "A toss in the explorer"): a
synthetic gyroscope recording made here (Euler's equations integrated by RK4 in Python, a body
of moments 1 : 1.6 : 2.3 askew in the phone, 100 Hz, noise and bias, rest around one flight),
fitted by `bookspin fit --tosses`, then the command the fit prints run as printed, and the page
opened at the toss's scene in headless Chromium (1280×720). Checks:

  - the fit prints the `bookspin explore` command of the toss's scene, and it writes the page;
  - the page's state is the scene's: its name, the exact model, ω0 the scene's
    initial.angular_velocity, the fitted drag's law and rate; its time slider spans the scene's duration;
  - the page's exact motion flips where the recording does: its first flip within 0.02 s of
    the first sign change of the true ω about the intermediate axis (from RK4, here), its flip
    period within 1e-4 of the fit CSV's half_period_fitted and within 2 % of the true one;
  - its ω at five times within 0.06 rad/s of the recorded samples there (in the scene's body
    frame: the measured CSV the scene names; the noise is 0.01);
  - the measured overlay drawn: every measured sample as dots on the ω plot and as points of
    the L/|L| trail on the sphere at the scene's end (window.explorer.measuredDrawn()), those
    up to t alone at t = 0.9 s, at most the first at t = 0;
  - no NaN in the readout, no console error; screenshots in BINARY_DIR/test-output/browser/
    (explorer-toss-flight.png at 0.9 s, explorer-toss.png at the end).

Usage: explorer_toss_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
"""
import csv
import glob
import math
import random
import shlex
import sys
import tomllib

from browser import console_errors, fail, find_browser, open_browser, require, run, test_arguments
from explorer_test import EXPLORER_WINDOW, load

MOMENTS = (1.0, 1.6, 2.3)  # principal moments 1, 2, 3
OMEGA0 = (3.0, 14.0, 2.5)  # rad/s about principal axes 1, 2, 3 at release
REST, THROW, FLIGHT, CATCH = 1.5, 0.15, 1.8, 0.1  # s
RATE, NOISE, BIAS = 100.0, 0.01, (0.02, -0.015, 0.01)


def rotation(axis, angle):
    """The rotation matrix (rows) of `angle` radians about `axis` (Rodrigues)."""
    n = math.sqrt(sum(a * a for a in axis))
    x, y, z = (a / n for a in axis)
    c, s, v = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return [[c + x * x * v, x * y * v - z * s, x * z * v + y * s],
            [y * x * v + z * s, c + y * y * v, y * z * v - x * s],
            [z * x * v - y * s, z * y * v + x * s, c + z * z * v]]


AXES = rotation((1, 2, 3), math.radians(20))  # columns: principal axes 1, 2, 3, phone frame


def to_phone(w):
    return [sum(AXES[r][c] * w[c] for c in range(3)) for r in range(3)]


def euler_rate(w):
    I1, I2, I3 = MOMENTS
    return ((I2 - I3) / I1 * w[1] * w[2], (I3 - I1) / I2 * w[2] * w[0], (I1 - I2) / I3 * w[0] * w[1])


def rk4(w, h):
    k1 = euler_rate(w)
    k2 = euler_rate([w[i] + 0.5 * h * k1[i] for i in range(3)])
    k3 = euler_rate([w[i] + 0.5 * h * k2[i] for i in range(3)])
    k4 = euler_rate([w[i] + h * k3[i] for i in range(3)])
    return [w[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(3)]


def flight_truth():
    """The free flight's principal ω every 1e-4 s, and the times its ω about axis 2 changes
    sign (linear interpolation), s since the release."""
    h, w, t, track, crossings = 1e-4, list(OMEGA0), 0.0, [], []
    track.append((0.0, w))
    while t < FLIGHT + 1e-9:
        nxt = rk4(w, h)
        if (nxt[1] > 0) != (w[1] > 0):
            crossings.append(t + h * w[1] / (w[1] - nxt[1]))
        w, t = nxt, t + h
        track.append((t, w))
    return track, crossings


def write_recording(path):
    """The recording as a plain t,wx,wy,wz CSV; returns (release time, true crossings)."""
    rng = random.Random(7)
    track, crossings = flight_truth()
    release = REST + THROW
    end = release + FLIGHT + CATCH + 1.0
    rows, t = [], 0.0
    w0 = to_phone(OMEGA0)
    last = to_phone(track[-1][1])
    while t < end:
        if t < REST:
            w = [0.0, 0.0, 0.0]
        elif t < release:
            w = [c * (t - REST) / THROW for c in w0]
        elif t <= release + FLIGHT:
            w = to_phone(track[min(len(track) - 1, round((t - release) / 1e-4))][1])
        elif t < release + FLIGHT + CATCH:
            w = [c * (1 - (t - release - FLIGHT) / CATCH) for c in last]
        else:
            w = [0.0, 0.0, 0.0]
        rows.append([t] + [w[i] + BIAS[i] + rng.gauss(0, NOISE) for i in range(3)])
        t += 1 / RATE
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["t", "wx", "wy", "wz"])
        out.writerows([f"{x:.6f}" for x in row] for row in rows)
    return release, crossings


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    out = binary / "test-output" / "explorer-toss"
    out.mkdir(parents=True, exist_ok=True)
    shots = binary / "test-output" / "browser"
    shots.mkdir(parents=True, exist_ok=True)
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    release, crossings = write_recording(out / "lab.csv")
    # The flight by hand, inside the free part (the finder's own tests are the fit stage's).
    a, b = release + 0.02, release + FLIGHT - 0.02
    said = run([bookspin, "fit", str(out / "lab.csv"), "--tosses", f"{a:.3f}:{b:.3f}",
                "-o", str(out / "fit"), "--force"])
    print(said)
    command = [line for line in said.splitlines() if "bookspin explore " in line]
    if not command:
        fail(f"the fit does not say how to open the toss in the explorer:\n{said}")
    # The command names the tosses by a shell glob: expanded here as a shell would.
    words = []
    for word in shlex.split(command[0].split(": ", 1)[1].split(", then open")[0]):
        words += sorted(glob.glob(word)) if "*" in word else [word]
    if words[:2] != ["bookspin", "explore"] or str(out / "fit" / "lab-toss1.toml") not in words:
        fail(f"not the explore command of the toss's scene: {command[0]}")
    run([bookspin, *words[1:]])
    scene = tomllib.loads((out / "fit" / "lab-toss1.toml").read_text())
    with open(out / "fit" / "lab-fit.csv") as f:
        toss = next(csv.DictReader(f))
    with open(out / "fit" / "lab-toss1-measured.csv") as f:
        measured = [[float(x) for x in row] for row in list(csv.reader(f))[1:]]
    t_start = float(toss["t_start"])
    fitted = float(toss["half_period_fitted"])
    duration = scene["time"]["duration"]
    # The true flips, in the scene's time (t = 0 at the flight's first sample).
    true_first = next(c for c in crossings if c > t_start - release) - (t_start - release)
    true_half = (crossings[-1] - crossings[0]) / (len(crossings) - 1)
    print(f"truth: first sign change {true_first:.4f} s after the flight's start, half period {true_half:.4f} s; "
          f"fit: half_period_fitted {fitted:.4f} s")

    page = (out / "fit" / "explorer.html").resolve().as_uri()
    with open_browser(chromium, driver_path, **EXPLORER_WINDOW) as driver:
        load(driver, page + "?scene=lab-toss1")
        state = driver.execute_script("return window.explorer.state()")
        print(f"page state: scene {state['scene']}, model {state['model']}, w {state['w']}, "
              f"speed {state['speed']}")
        if state["scene"] != scene["scene"]["name"] or state["model"] != "exact":
            fail(f"the page is not at the toss's scene with the exact model: {state}")
        want = scene["initial"]["angular_velocity"]
        if any(abs(x - y) > 1e-12 * abs(y) + 1e-15 for x, y in zip(state["w"], want)):
            fail(f"the page's ω0 {state['w']} is not the scene's {want}")
        # The fitted air drag rides with the scene (docs/physics.md §21): the page runs the
        # damped exact motion of the scene's law and rate.
        model = scene.get("model", {})
        want_drag = (model.get("drag", "none"), model.get("drag_rate", 0.0))
        if (state["drag"], state["dragRate"]) != want_drag:
            fail(f"the page's drag {state['drag']} {state['dragRate']} is not the scene's {want_drag}")
        slider = float(driver.find_element("id", "slider").get_attribute("max"))
        frame = scene["time"]["dt"] * scene["time"]["steps_per_frame"]
        if not duration - 1e-9 <= slider <= duration + frame + 1e-9:
            fail(f"the time slider spans {slider} s, not the scene's {duration} s")
        drawn0 = driver.execute_script("return window.explorer.measuredDrawn()")
        if drawn0 != {"plot": 0, "sphere": 0} and drawn0 != {"plot": 1, "sphere": 1}:
            fail(f"at t = 0 the measured overlay already shows {drawn0}")
        # ω on the page against the recorded samples (body frame) at five times.
        worst = 0.0
        for k in range(5):
            sample = measured[(k + 1) * len(measured) // 6]
            page_w = driver.execute_script(f"return window.explorer.omegaAt({sample[0]!r})")[0]
            state_t = driver.execute_script("return window.explorer.state().t")
            # The page steps whole dt: compare at the time it reached, the samples around it
            # interpolated (|ω̈| ≤ |ω|³ makes that 0.035 rad/s at most between 10 ms samples).
            i = next(i for i, row in enumerate(measured) if row[0] >= state_t)
            (t0, *w0), (t1, *w1) = measured[i - 1], measured[i]
            f = (state_t - t0) / (t1 - t0)
            worst = max(worst, math.dist(page_w, [p + f * (q - p) for p, q in zip(w0, w1)]))
        print(f"page ω against the measured samples: at most {worst:.4f} rad/s apart")
        if worst > 0.06:
            fail(f"the page's ω is {worst:.3f} rad/s from the measured samples (noise 0.01)")
        # Halfway through the flight: the measurement drawn up to the time shown, no further.
        driver.execute_script("window.explorer.omegaAt(0.9)")
        half_t = driver.execute_script("return window.explorer.state().t")
        half = driver.execute_script("return window.explorer.measuredDrawn()")
        upto = sum(1 for row in measured if row[0] <= half_t)
        print(f"at t = {half_t:.4f}: measured drawn {half} of {len(measured)} ({upto} up to t)")
        if half != {"plot": upto, "sphere": upto}:
            fail(f"at t = {half_t} the measured overlay draws {half}, not the {upto} samples up to t")
        driver.save_screenshot(str(shots / "explorer-toss-flight.png"))
        driver.execute_script(f"window.explorer.omegaAt({duration!r})")
        exact = driver.execute_script("return window.explorer.exactFlips()")[0]
        own = driver.execute_script("return window.explorer.flipMeasures()")[0]
        drawn = driver.execute_script("return window.explorer.measuredDrawn()")
        readout = driver.find_element("id", "status").text
        print(f"at t = {duration}: exact flips {exact}, the run's {own}; measured drawn {drawn}; "
              f"readout {readout!r}")
        if exact["first"] is None or abs(exact["first"] - true_first) > 0.02:
            fail(f"the page's first flip {exact['first']} is not the recording's {true_first:.4f} ± 0.02")
        if exact["period"] is None or abs(exact["period"] - fitted) > 1e-4 * fitted:
            fail(f"the page's flip period {exact['period']} is not the fit's {fitted} (1e-4)")
        if abs(exact["period"] - true_half) > 0.02 * true_half:
            fail(f"the page's flip period {exact['period']} is not the true {true_half:.4f} within 2 %")
        if own["count"] < 3:
            fail(f"the scene shows {own['count']} flips, not at least 3")
        if drawn != {"plot": len(measured), "sphere": len(measured)}:
            fail(f"the measured overlay draws {drawn}, not every one of the {len(measured)} samples")
        if "NaN" in readout or "NaN" in driver.find_element("id", "time").text:
            fail(f"NaN on the page: {readout!r}")
        driver.save_screenshot(str(shots / "explorer-toss.png"))
        errors = console_errors(driver)
        if errors:
            fail(f"console errors: {errors}")
    print("OK")


if __name__ == "__main__":
    sys.exit(main())
