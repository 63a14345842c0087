#!/usr/bin/env python3
"""The benchmark of the explorer's taps (docs/performance.md, "Taps"): each control's
interaction duration as the browser's Event Timing API measures it (from the tap until the next
paint after its handlers: the measure behind INP, whose "good" is 200 ms), in headless Chromium
at a touch phone's 390×844 with WebGL on the CPU (SwiftShader), unthrottled and with the
DevTools protocol's CPU throttling (Emulation.setCPUThrottlingRate, 4 by default), `--runs`
runs each (a fresh page each), the median and the worst.

The controls, in the order a student meets them: the explorer's Play, its scene menu (a key
on the focused menu), its speed (a number typed, then Enter), its second method (the
comparison's tick) and "Phone-toss lab"; then in the lab Record, Stop after a real recording
(`--recording`, a phyphox Raw Data.csv, fed through the gyroscope's sensor override at its own
rate, as tests/browser/explorer_records_gyro_test.py feeds it), a recording's tick, "Fit the
ticked", Remove and Close. A tap's long animation frames (the Long Animation Frames API: its
scripts, its style and layout) are printed with `--frames`, and `--trace FILE` writes a
performance trace (Chrome's trace event format, for chrome://tracing or Perfetto) of the
throttled first run's Stop, whose busiest slices per thread it prints.

How the browser draws matters as much as the page here: by default WebGL, the compositor and
the page's raster go through SwiftShader (a software GPU, as the tests with WebGL run);
`--chromium-arg=--disable-gpu-rasterization` keeps WebGL and the compositor there but rasters
the page's tiles on the CPU (as a phone's GPU would not be a CPU's bottleneck); `--disable-gpu`
is the lab's browser tests' own set-up (browser.py's open_browser without webgl): software
compositing and raster. The CSV's `switches` column says which.

Usage: tap_bench.py EXPLORER_HTML [--recording CSV] [--runs 3] [--rate 4] [--trace FILE]
           [--frames] [--disable-gpu] [--chromium-arg=SWITCH …] [--slow-only] [--out CSV]
EXPLORER_HTML: a page written by `bookspin explore SCENE… -o OUT` from web/build.sh's shell
(make bench-explorer makes one). Writes CSV (default bench/results/taps-MACHINE.csv) and prints
the table.
"""
import argparse
import csv
import datetime
import io
import json
import os
import statistics
import sys
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "browser"))
sys.path.insert(0, str(ROOT / "bench"))
from browser import find_browser, open_browser, wait_for  # noqa: E402
from explorer_records_gyro_test import DevTools, feed, feed_at_own_rate, override  # noqa: E402
import explorer_records_gyro_test  # noqa: E402
from explorer_test import load  # noqa: E402
from explorer_bench import cpu_model, machine_slug  # noqa: E402
from taps import TAP_FLOOR_MS, interaction, key, mark, settle, tap, watch  # noqa: E402

SIZE = (390, 844)
REAL = Path("/work/shared/recordings-real/dvarkian-2022-05-03/12-13-01/Raw Data.csv")
CONTROLS = ["Play", "scene menu", "speed", "second method", "Open the lab", "Record", "Stop",
            "a tick", "Fit the ticked", "Remove", "Close"]


class TracingDevTools(DevTools):
    """The test's DevTools session, its events kept: a trace's Tracing.dataCollected."""

    def __init__(self, driver):
        self.trace = []
        self.traced = threading.Event()
        super().__init__(driver)

    def event(self, message):
        if message.get("method") == "Tracing.dataCollected":
            self.trace.extend(message["params"]["value"])
        elif message.get("method") == "Tracing.tracingComplete":
            self.traced.set()


def session(driver):
    """The tab's one DevTools session (the sensor overrides' and the trace's)."""
    sessions = explorer_records_gyro_test.DEVTOOLS
    if driver.session_id not in sessions:
        sessions[driver.session_id] = TracingDevTools(driver)
    return sessions[driver.session_id]


TRACE_CATEGORIES = ("devtools.timeline,disabled-by-default-devtools.timeline,"
                    "disabled-by-default-devtools.timeline.frame,blink,cc,gpu,viz,v8.execute,toplevel")


def busiest(trace, since_us, until_us, n=12):
    """The complete slices ('X') of the trace between the two times (µs), summed by thread and
    name, the busiest `n`: [(ms, thread, name)]."""
    names = {(e["pid"], e["tid"]): e["args"]["name"] for e in trace
             if e.get("ph") == "M" and e.get("name") == "thread_name"}
    total = {}
    for e in trace:
        if e.get("ph") != "X" or "dur" not in e or not since_us <= e["ts"] <= until_us:
            continue
        k = (names.get((e["pid"], e["tid"]), str(e["tid"])), e["name"])
        total[k] = total.get(k, 0) + e["dur"] / 1000
    return sorted(((ms, t, name) for (t, name), ms in total.items()), reverse=True)[:n]


def measure(driver, name, action, since=None):
    """`action()` done, its interaction measured: (ms, long frames)."""
    since = mark(driver) if since is None else since
    action()
    ms, entries, frames = interaction(driver, since)
    return ms, frames


def focus_and(driver, selector, action):
    def run():
        driver.execute_script("document.querySelector(arguments[0]).focus()", selector)
        action()
    return run


def one_run(driver, page, rate, recording, trace_file=None, trace_control="Stop"):
    """Every control measured once on a fresh page at CPU throttling `rate`: {control: (ms,
    long frames)}; with `trace_file`, a performance trace of `trace_control`'s tap written there
    (and its events in got["trace"])."""
    devtools = session(driver)
    got = {}

    def timed(driver, name, action, since=None):
        if not trace_file or name != trace_control:
            return measure(driver, name, action, since)
        devtools.trace.clear()
        devtools.traced.clear()
        devtools.call("Tracing.start", {"categories": TRACE_CATEGORIES, "transferMode": "ReportEvents"})
        time.sleep(0.5)
        result = measure(driver, name, action, since)
        time.sleep(1.0)
        devtools.call("Tracing.end", {})
        devtools.traced.wait(120)
        Path(trace_file).write_text(json.dumps({"traceEvents": devtools.trace}))
        got["trace"] = list(devtools.trace)
        return result

    driver.execute_cdp_cmd("Emulation.setCPUThrottlingRate", {"rate": 1})
    load(driver, page)
    driver.execute_async_script("window.explorer.labForget().then(arguments[0])")
    watch(driver)
    settle(driver, 10)
    driver.execute_cdp_cmd("Emulation.setCPUThrottlingRate", {"rate": rate})
    got["Play"] = timed(driver, "Play", lambda: tap(driver, "#play"))
    driver.execute_script("window.explorer.setPlaying(false)")
    settle(driver)
    got["scene menu"] = timed(driver, "scene menu", focus_and(driver, "#scene", lambda: key(driver, "ArrowDown")))
    settle(driver)

    def speed():
        driver.execute_script("const s = document.getElementById('speed'); s.focus(); s.select();")
        driver.execute_cdp_cmd("Input.insertText", {"text": "2"})
    speed()
    got["speed"] = timed(driver, "speed", lambda: key(driver, "Enter"))
    settle(driver)
    got["second method"] = timed(driver, "second method", lambda: tap(driver, "#compare"))
    settle(driver)
    got["Open the lab"] = timed(driver, "Open the lab", lambda: tap(driver, "#labOpen"))
    settle(driver)

    t, omega = recording
    override(driver, True)
    feed(driver, omega[0])
    got["Record"] = timed(driver, "Record", lambda: tap(driver, "#labRecord"))
    said = wait_for(driver, "return document.getElementById('labRecordState').textContent",
                    lambda s: s.startswith(("recording", "error")), 60)
    if not said.startswith("recording"):
        sys.exit(f"tap_bench: the recording did not start: {said!r}")
    feed_at_own_rate(driver, t, omega)
    driver.execute_script("window.explorer.lastShown = window.explorer.labResult();")
    got["Stop"] = timed(driver, "Stop", lambda: tap(driver, "#labRecord"))
    fitted = wait_for(driver, """const r = window.explorer.labResult();
        return [r !== window.explorer.lastShown, document.getElementById('labError').textContent]""",
                      lambda s: s[0] or s[1], 300)
    if not fitted[0]:
        sys.exit(f"tap_bench: the recording was not fitted: {fitted[1]!r}")
    settle(driver)
    row = "#labRecordList li:last-child"
    got["a tick"] = timed(driver, "a tick", lambda: tap(driver, f"{row} input[type=checkbox]"))
    tap(driver, f"{row} input[type=checkbox]")  # ticked again, for the fit
    settle(driver)
    driver.execute_script("window.explorer.lastShown = window.explorer.labResult();")
    got["Fit the ticked"] = timed(driver, "Fit the ticked", lambda: tap(driver, "#labRecordFit"))
    wait_for(driver, "return window.explorer.labRecorderPhase()", lambda s: s == "idle", 300)
    settle(driver)
    got["Remove"] = timed(driver, "Remove", lambda: tap(driver, f"{row} button"))
    settle(driver)
    got["Close"] = timed(driver, "Close", lambda: tap(driver, "#labClose"))
    driver.execute_cdp_cmd("Emulation.setCPUThrottlingRate", {"rate": 1})
    return got


def shown(ms):
    return f"<{TAP_FLOOR_MS}" if ms <= TAP_FLOOR_MS else f"{ms:.0f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("page", help="a built explorer.html")
    ap.add_argument("--recording", default=str(REAL), help="the phyphox Raw Data.csv fed while recording")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--rate", type=float, default=4.0, help="the CPU throttling of the slow runs")
    ap.add_argument("--slow-only", action="store_true", help="the slow runs alone (no table written)")
    ap.add_argument("--trace", help="a performance trace of the slow first run's Stop (or --trace-tap), written here")
    ap.add_argument("--trace-tap", default="Stop", choices=CONTROLS, help="the control whose tap --trace traces")
    ap.add_argument("--frames", action="store_true", help="print each slow tap's long animation frames")
    ap.add_argument("--chromium-arg", action="append", default=[],
                    help="a Chromium switch more (repeatable), e.g. --disable-gpu-rasterization")
    ap.add_argument("--disable-gpu", action="store_true",
                    help="Chromium's --disable-gpu, as the lab's browser tests open it (browser.py's "
                         "open_browser without webgl): software compositing and raster")
    ap.add_argument("--machine", default=os.environ.get("BOOKSPIN_MACHINE") or machine_slug())
    ap.add_argument("--out", help="CSV (default bench/results/taps-MACHINE.csv)")
    a = ap.parse_args()
    page = Path(a.page).resolve()
    if not page.is_file():
        sys.exit(f"tap_bench: no page at {a.page} (web/build.sh BUILD, then BUILD/bookspin explore SCENE -o OUT)")
    rows = list(csv.reader(io.StringIO(Path(a.recording).read_text())))[1:]
    recording = ([float(r[0]) for r in rows], [tuple(float(c) for c in r[1:4]) for r in rows])
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    machine = f"{cpu_model()}, {os.cpu_count()} cores"
    out = Path(a.out) if a.out else ROOT / "bench" / "results" / f"taps-{a.machine}.csv"

    chromium, driver_path = find_browser()
    results = {}
    renderer = ""
    with open_browser(chromium, driver_path, size=SIZE, webgl=not a.disable_gpu, exact_viewport=True,
                      script_timeout=600, extra_args=a.chromium_arg) as driver:
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
            "width": SIZE[0], "height": SIZE[1], "deviceScaleFactor": 1, "mobile": True})
        driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 5})
        for rate in (a.rate,) if a.slow_only else (1.0, a.rate):
            for run in range(a.runs):
                trace = a.trace if (a.trace and rate == a.rate and run == 0) else None
                got = one_run(driver, page.as_uri(), rate, recording, trace, a.trace_tap)
                if trace:
                    stop = got.pop("trace")
                    ts = [e["ts"] for e in stop if e.get("ph") == "X" and e.get("name") == "EventDispatch"]
                    since = min(ts) if ts else min(e["ts"] for e in stop if "ts" in e and e["ts"] > 0)
                    print(f"trace of {a.trace_tap} at {rate:g}x: {a.trace}; the busiest slices in the "
                          f"{got[a.trace_tap][0]:.0f} ms after the tap's first event:")
                    for ms, thread, name in busiest(stop, since, since + 1000 * got[a.trace_tap][0]):
                        print(f"  {ms:8.1f} ms  {thread:28} {name}")
                for control, (ms, frames) in got.items():
                    results.setdefault((rate, control), []).append(ms)
                    if a.frames and ms > 50:
                        print(f"{rate:g}x run {run + 1} {control}: {ms:.0f} ms; long frames:")
                        for f in frames:
                            scripts = ", ".join(f"{s['invoker']} {s['duration']:.0f}" for s in f["scripts"][:4])
                            print(f"   frame {f['duration']:.0f} ms (render {f['start'] + f['duration'] - f['renderStart']:.0f} ms, "
                                  f"style+layout {f['start'] + f['duration'] - f['styleAndLayoutStart']:.0f} ms): {scripts}")
                print(f"{rate:g}x run {run + 1}: " + ", ".join(f"{c} {shown(got[c][0])}" for c in CONTROLS),
                      file=sys.stderr)
        renderer = driver.execute_script("""const gl = document.createElement('canvas').getContext('webgl2');
          const ext = gl && gl.getExtension('WEBGL_debug_renderer_info');
          return ext ? gl.getParameter(ext.UNMASKED_RENDERER_WEBGL) : 'unknown';""")
        version = driver.capabilities.get("browserVersion", "")
    if a.slow_only:
        return

    table = []
    for control in CONTROLS:
        row = {"control": control}
        for rate in (1.0, a.rate):
            ms = results[(rate, control)]
            row[f"median_ms_{rate:g}x"] = shown(statistics.median(ms))
            row[f"worst_ms_{rate:g}x"] = shown(max(ms))
        switches = " ".join(["--disable-gpu"] if a.disable_gpu else ["--use-angle=swiftshader"]) + \
            "".join(f" {x}" for x in a.chromium_arg)
        row.update(runs=a.runs, switches=switches, machine=machine, chromium=version, webgl=renderer, date=date)
        table.append(row)
    out.parent.mkdir(parents=True, exist_ok=True)
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table)
    print(f"taps: {machine}, Chromium {version}, WebGL {renderer}, {date}; {SIZE[0]}x{SIZE[1]} touch, "
          f"Chromium switches {table[0]['switches']}, {a.runs} runs, Event Timing interaction duration (ms; <{TAP_FLOOR_MS}: under the API's least threshold)")
    print(f"| control | median 1× | worst 1× | median {a.rate:g}× | worst {a.rate:g}× |")
    print("|---|---:|---:|---:|---:|")
    for row in table:
        print(f"| {row['control']} | {row['median_ms_1x']} | {row['worst_ms_1x']} | "
              f"{row[f'median_ms_{a.rate:g}x']} | {row[f'worst_ms_{a.rate:g}x']} |")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
