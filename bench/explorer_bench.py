#!/usr/bin/env python3
"""The benchmark of the explorer page (docs/explorer.md): ns per step of each of the page's
methods in WebAssembly (headless Chromium, the page's `explorer.nsPerStep` hook) against the
native build on the same machine in the same run (`bookspin-bench --only explorer`, the same
loop, scene, body, initial state, dt and step count), the page's frames per second while
playing at 1280×720, and the Phone-toss lab's fit of a long recording (`--fit-minutes` of the
sample recording's tosses at its 100 Hz, tiled; window.explorer.fitRecording) against
`bookspin fit` of the same file (the program beside BOOKSPIN_BENCH), each the best of two.

The native and the WebAssembly timings are taken in alternation, `--rounds` times, each side
keeping its best (a shared machine disturbs both alike). Both are wall time. The frames per
second count `explorer.framesDrawn()` over `--seconds` of wall time after a second of warm-up;
the WebGL renderer the page got (SwiftShader on the CPU, or a GPU) is read from the page and
written beside it.

Usage: explorer_bench.py EXPLORER_HTML BOOKSPIN_BENCH [--scene SCENE.toml] [--out CSV]
Writes CSV (default bench/results/explorer-MACHINE.csv) and prints a table.
"""
import argparse
import csv
import datetime
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "browser"))
from browser import find_browser, open_browser  # noqa: E402
from explorer_test import EXPLORER_WINDOW, load  # noqa: E402

# The most the page may cost against the native build, per step (docs/explorer.md, "Speed"):
# the rigid models 1.3×, the particle model 2×. The exact model has none: its long double is
# emulated in software in WebAssembly (docs/explorer.md), and the page evaluates it once a frame.
RATIO_LIMIT = {"rigid-matrix": 1.3, "rigid-quaternion": 1.3, "particle": 2.0}


def cpu_model():
    for line in Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("model name"):
            return line.split(":", 1)[1].strip()
    return "unknown CPU"


def machine_slug():
    words = re.sub(r"\(.*?\)|processor|cpu|@.*", "", cpu_model(), flags=re.I).split()
    return f"{os.cpu_count()}core-" + "-".join(w.lower() for w in words[:3])


def native_times(bench, scene, steps, repetitions):
    """{(model, integrator): ns/step} from `bookspin-bench --only explorer`."""
    with tempfile.TemporaryDirectory(prefix="bookspin-explorer-bench-") as out:
        r = subprocess.run([bench, str(scene), "--only", "explorer", "--explorer-steps", str(steps),
                            "--rounds", str(repetitions), "-o", out],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if r.returncode != 0:
            sys.exit(f"explorer_bench: {bench} exited {r.returncode}:\n{r.stdout}")
        times = {}
        with open(Path(out) / "bench.csv", newline="") as f:
            for row in csv.DictReader(f):
                if row["section"] != "explorer":
                    continue
                model, _, integrator = row["metric"].partition(" ")
                times[(model, integrator or "euler")] = float(row["value"])
        return times


def page_times(driver, methods, steps, repetitions):
    times = {}
    for model, integrator in methods:
        times[(model, integrator)] = min(
            driver.execute_script("return window.explorer.nsPerStep(arguments[0], arguments[1], "
                                  "arguments[2], arguments[3])",
                                  model, integrator, model != "exact", steps)
            for _ in range(repetitions))
    return times


def browser_cpu_seconds(profile):
    """CPU seconds (user + system) used so far by the browser's processes: those started with
    this profile (the browser, its renderer and its GPU process, where SwiftShader draws)."""
    total = 0.0
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            cmdline = Path(f"/proc/{pid}/cmdline").read_bytes()
            if f"--user-data-dir={profile}".encode() not in cmdline:
                continue
            fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
            total += (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
        except OSError:
            continue
    return total


def frames_per_second(driver, page, scene_name, seconds, profile):
    load(driver, f"{page}?scene={scene_name}")
    info = driver.execute_script("""
      const v = document.getElementById('view');
      const gl = document.createElement('canvas').getContext('webgl2');
      const ext = gl && gl.getExtension('WEBGL_debug_renderer_info');
      return {width: v.width, height: v.height,
              inner: [window.innerWidth, window.innerHeight],
              renderer: ext ? gl.getParameter(ext.UNMASKED_RENDERER_WEBGL) : 'unknown',
              model: window.explorer.state().model, integrator: window.explorer.state().integrator};
    """)
    driver.execute_script("window.explorer.setPlaying(true)")
    time.sleep(1.0)
    cpu0 = browser_cpu_seconds(profile)
    f0, t0, c0 = driver.execute_script(
        "return [window.explorer.framesDrawn(), performance.now(), window.explorer.frameCosts()]")
    time.sleep(seconds)
    f1, t1, c1, t = driver.execute_script(
        "return [window.explorer.framesDrawn(), performance.now(), window.explorer.frameCosts(), "
        "window.explorer.state().t]")
    cpu1 = browser_cpu_seconds(profile)
    driver.execute_script("window.explorer.setPlaying(false)")
    frames = max(1, f1 - f0)
    info.update(frames=f1 - f0, seconds=(t1 - t0) / 1000, fps=(f1 - f0) / ((t1 - t0) / 1000),
                t=t, costs={k: (c1[k] - c0[k]) / frames for k in c1},
                cpu_ms=1000 * (cpu1 - cpu0) / frames, load=os.getloadavg()[0])
    return info


def long_recording(minutes, folder):
    """The sample recording's samples (recordings/phone-on-book-synthetic, 100 Hz) repeated,
    each copy after the last, until `minutes` of recording: a phyphox Raw Data.csv in `folder`
    (its pause left out). Returns its path."""
    lines = (ROOT / "recordings" / "phone-on-book-synthetic" / "Raw Data.csv").read_text().splitlines()
    header, rows = lines[0], [line.split(",") for line in lines[1:] if line.strip()]
    span = float(rows[-1][0]) - float(rows[0][0]) + 0.01
    out, offset = [header], 0.0
    while offset < 60 * minutes:
        for r in rows:
            t = float(r[0]) + offset
            if t >= 60 * minutes:
                break
            out.append(",".join([repr(t)] + r[1:]))
        offset += span
    path = Path(folder) / "long-recording" / "Raw Data.csv"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(out) + "\n")
    return path


def fit_times(driver, bookspin, path):
    """Seconds of wall time of `bookspin fit` of `path` and of the page's fit of the same bytes,
    each the best of two; and the tosses each found."""
    import base64
    native, wasm, tosses = [], [], None
    data = base64.b64encode(path.read_bytes()).decode()
    name = f"{path.parent.name}/{path.name}"
    for _ in range(2):
        with tempfile.TemporaryDirectory() as out:
            t0 = time.monotonic()
            subprocess.run([bookspin, "fit", str(path), "-o", out, "--force"], check=True,
                           stdout=subprocess.DEVNULL)
            native.append(time.monotonic() - t0)
        r = driver.execute_async_script("""
            const [name, data, done] = arguments;
            const bytes = Uint8Array.from(atob(data), (c) => c.charCodeAt(0));
            const t0 = performance.now();
            window.explorer.fitRecording(name, bytes).then(
              (r) => done({s: (performance.now() - t0) / 1000, tosses: r.tosses.length}),
              (e) => done({error: String(e.message)}));""", name, data)
        if "error" in r:
            sys.exit(f"explorer_bench: the page's fit failed: {r['error']}")
        wasm.append(r["s"])
        tosses = r["tosses"]
    return min(native), min(wasm), tosses


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("page", help="a built explorer.html")
    ap.add_argument("bench", help="the bookspin-bench program")
    ap.add_argument("--scene", default=str(ROOT / "scenes" / "fig09-matrix-unstable-x.toml"),
                    help="scene file whose settings both sides run (the page: ?scene=its stem)")
    ap.add_argument("--steps", type=int, default=100000, help="steps of each timing")
    ap.add_argument("--rounds", type=int, default=3, help="native/page alternations")
    ap.add_argument("--repetitions", type=int, default=3, help="timings per side per round")
    ap.add_argument("--seconds", type=float, default=5.0, help="wall time of the fps count")
    ap.add_argument("--fit-minutes", type=float, default=5.0,
                    help="minutes of the long recording the fit timing fits (0: none)")
    ap.add_argument("--fps-only", action="store_true",
                    help="only the frames per second (printed; no CSV written)")
    ap.add_argument("--machine", default=os.environ.get("BOOKSPIN_MACHINE") or machine_slug())
    ap.add_argument("--out", help="CSV (default bench/results/explorer-MACHINE.csv)")
    a = ap.parse_args()
    page = Path(a.page).resolve()
    if not page.is_file():
        sys.exit(f"explorer_bench: no page at {a.page} (make bench-explorer makes it: web/build.sh BUILD, then BUILD/bookspin explore SCENE... -o OUT)")
    scene = Path(a.scene).resolve()
    scene_name = scene.stem
    out = Path(a.out) if a.out else ROOT / "bench" / "results" / f"explorer-{a.machine}.csv"
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    machine = f"{cpu_model()}, {os.cpu_count()} cores"

    chromium, driver_path = find_browser()
    profile = tempfile.mkdtemp(prefix="bookspin-explorer-bench-")
    try:
        with open_browser(chromium, driver_path, profile=profile, script_timeout=600,
                          **EXPLORER_WINDOW) as driver:
            load(driver, f"{page.as_uri()}?scene={scene_name}")
            if driver.execute_script("return window.explorer.state().scene") != scene_name:
                sys.exit(f"explorer_bench: the page has no scene {scene_name}")
            native, wasm = {}, {}
            for r in range(0 if a.fps_only else a.rounds):
                n = native_times(a.bench, scene, a.steps, a.repetitions)
                w = page_times(driver, list(n), a.steps, a.repetitions)
                for k in n:
                    native[k] = min(native.get(k, n[k]), n[k])
                    wasm[k] = min(wasm.get(k, w[k]), w[k])
                print(f"round {r + 1}/{a.rounds} done", file=sys.stderr)
            fit = None
            if a.fit_minutes > 0 and not a.fps_only:
                bookspin = str(Path(a.bench).resolve().parent / "bookspin")
                recording = long_recording(a.fit_minutes, profile)
                fit = fit_times(driver, bookspin, recording)
            fps = frames_per_second(driver, page.as_uri(), scene_name, a.seconds, profile)
    finally:
        shutil.rmtree(profile, ignore_errors=True)

    software = "SwiftShader" in fps["renderer"]
    if a.fps_only:
        print(f"{fps['fps']:.1f} frames/s ({fps['frames']} in {fps['seconds']:.1f} s), view "
              f"{fps['width']}x{fps['height']}, {fps['renderer']}; browser CPU "
              f"{fps['cpu_ms']:.0f} ms per frame, load average {fps['load']:.1f}; main-thread ms "
              "per frame: " + ", ".join(f"{k} {v:.2f}" for k, v in fps["costs"].items()))
        return
    rows = []
    for (model, integrator), ns in native.items():
        rows.append({"model": model, "integrator": "" if model == "exact" else integrator,
                     "steps": a.steps, "wasm_ns_per_step": f"{wasm[(model, integrator)]:.1f}",
                     "native_ns_per_step": f"{ns:.1f}",
                     "ratio": f"{wasm[(model, integrator)] / ns:.2f}", "frames_per_second": "",
                     "note": f"scene {scene_name}, normalized" if model != "exact" else
                             f"scene {scene_name}, ns per evaluation of the closed form"})
    rows.append({"model": fps["model"], "integrator": fps["integrator"], "steps": "",
                 "wasm_ns_per_step": "", "native_ns_per_step": "", "ratio": "",
                 "frames_per_second": f"{fps['fps']:.1f}",
                 "note": f"playing {scene_name}, view canvas {fps['width']}x{fps['height']} in a "
                         f"{fps['inner'][0]}x{fps['inner'][1]} window, {fps['frames']} frames in "
                         f"{fps['seconds']:.1f} s, browser CPU {fps['cpu_ms']:.0f} ms per frame, "
                         f"load average {fps['load']:.1f}, WebGL: {fps['renderer']}"})
    if fit:
        native_s, wasm_s, tosses = fit
        rows.append({"model": "fit", "integrator": "", "steps": "", "wasm_ns_per_step": "",
                     "native_ns_per_step": "", "ratio": f"{wasm_s / native_s:.2f}",
                     "frames_per_second": "",
                     "note": f"Phone-toss lab: {a.fit_minutes:g} min at 100 Hz ({tosses} tosses) "
                             f"fitted in {wasm_s:.1f} s in the page, {native_s:.1f} s by bookspin "
                             "fit (its charts and files included), wall time, best of 2"})
    for row in rows:
        row.update(machine=machine, date=date)
    out.parent.mkdir(parents=True, exist_ok=True)
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)

    print(f"explorer bench: {machine}, {date}; scene {scene_name}, {a.steps} steps per timing, "
          f"best of {a.rounds}×{a.repetitions}, wall time")
    print(f"{'model':18} {'integrator':18} {'wasm ns':>9} {'native ns':>9} {'ratio':>6}")
    for row in rows:
        if row["model"] == "fit" or not row["steps"]:
            continue
        limit = RATIO_LIMIT.get(row["model"])
        mark = "" if limit is None or float(row["ratio"]) <= limit else f"  > {limit}x"
        print(f"{row['model']:18} {row['integrator']:18} {row['wasm_ns_per_step']:>9} "
              f"{row['native_ns_per_step']:>9} {row['ratio']:>6}{mark}")
    print(f"frames per second playing at 1280x720: {fps['fps']:.1f} ({fps['frames']} frames in "
          f"{fps['seconds']:.1f} s; view {fps['width']}x{fps['height']}; WebGL renderer "
          f"{fps['renderer']}{': software, on the CPU' if software else ''})")
    print(f"browser CPU {fps['cpu_ms']:.0f} ms per frame (all its processes; load average "
          f"{fps['load']:.1f} on {os.cpu_count()} cores); main-thread ms per frame: " +
          ", ".join(f"{k} {v:.2f}" for k, v in fps["costs"].items()))
    if fit:
        print(f"fit: {fit[2]} tosses of {a.fit_minutes:g} min at 100 Hz: {fit[1]:.1f} s in the "
              f"page, {fit[0]:.1f} s by bookspin fit")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
