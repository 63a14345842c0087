"""The conformance kit run by outside engines (docs/flipcheck.md, "Any engine"): usage
flipcheck_engines_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR.

`bookspin flipcheck export` writes every scenario of scenes/flipcheck/; the JavaScript engines of
web/package-lock.json (cannon-es, Rapier, Jolt without and with mApplyGyroscopicForce, Havok,
Ammo.js, oimo, MuJoCo's WebAssembly module with each integrator) run each under node from its
JSON alone (web/flipcheck-engines.mjs); `bookspin simulate` writes MuJoCo's (Debian's) RK4 on
each; `bookspin flipcheck judge` judges them all with the exported exact motion. Then:
- every motion file is named by its package and the version in that package's installed
  package.json (read here, independently of the runner);
- the exact motion and MuJoCo's RK4 (Debian's and the WebAssembly one) pass every scenario;
- every engine's verdict in each of the seven scenarios is the one pinned in VERDICTS, for the
  reasons checked below it: the engines without a gyroscopic term (cannon-es, Jolt without its
  flag, Havok, oimo) fail the intermediate-axis scenarios with 0 turn-overs where the exact
  motion has some; Havok and Jolt without its flag keep the stable spins (energy drift below
  1e-4), which a damping left at the engine's default would not; Jolt with its flag fails both
  stable spins, tumbling within 10 % of the time the step's drift law gives (docs/physics.md
  §10.7: 41.6 time units about the largest axis, 105.4 about the smallest); Ammo.js and
  MuJoCo's implicit integrator turn over as often as the exact motion but lose energy (drift
  above 1e-3); MuJoCo's Euler and implicitfast tumble out of both stable spins;
- a second run with nothing changed is up to date and rewrites no motion file;
- bad input gets one line, exit 2 and nothing written (check_refusals): a package missing from
  web/node_modules (the runner copied beside a node_modules without Ammo.js, then without any),
  named with the install command, before any is imported, and `--check` says the same; a
  scenario file cut short, not JSON, named with its line and column; a missing file and a
  folder;
and prints the league table of docs/flipcheck.md.

Skipped (exit 77) where node or the npm packages (web/node_modules, scripts/install-deps.sh) are
missing; a failure under CI=true.
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from browser import fail, missing, require, run, test_arguments  # noqa: E402

# docs/physics.md §10.7, "averaged law": the tumble of the rescaled Euler step (Jolt's
# mApplyGyroscopicForce) from each stable spin's jiggled start at dt = 1/60.
TUMBLE = {"book-largest-axis": 41.6, "book-smallest-axis": 105.4}
SCENARIOS = ["book-intermediate-0.002", "book-intermediate-0.05", "book-intermediate-0.2",
             "book-largest-axis", "book-smallest-axis", "mujoco-test-box", "symmetric-top"]
# engine (package, mode) → its verdict in each scenario of SCENARIOS, in that order
# (p pass, f fail; measured 2026-11-25, docs/flipcheck.md's table gives the failing measures).
VERDICTS = {
    ("cannon-es", ""): "fffffff",
    ("@dimforge/rapier3d-compat", ""): "fffffpf",
    ("jolt-physics", ""): "fffppff",
    ("jolt-physics", "gyroscopic"): "fffffff",
    ("@babylonjs/havok", ""): "fffppff",
    ("ammo.js", ""): "fffffff",
    ("oimo", ""): "fffffff",
    ("mujoco-js", "euler"): "fffffff",
    ("mujoco-js", "rk4"): "ppppppp",
    ("mujoco-js", "implicit"): "fffppff",
    ("mujoco-js", "implicitfast"): "fffffff",
}
NO_GYROSCOPIC_TERM = [("cannon-es", ""), ("jolt-physics", ""), ("@babylonjs/havok", ""), ("oimo", "")]
KEEPS_STABLE_SPINS = [("jolt-physics", ""), ("@babylonjs/havok", ""), ("mujoco-js", "implicit"),
                      ("mujoco-js", "rk4")]
LOSES_ENERGY = [("ammo.js", ""), ("mujoco-js", "implicit")]
TUMBLES = [("mujoco-js", "euler"), ("mujoco-js", "implicitfast")]


def motion_name(source, package, mode):
    """The runner's name for an engine's motion: package and installed version, and mode."""
    with open(source / "web" / "node_modules" / package / "package.json") as f:
        version = json.load(f)["version"]
    name = package.lstrip("@").replace("/", "-") + "@" + version
    return name + ("+" + mode if mode else "")


def judged(bookspin, scene, motions, out):
    """motion file name → judge CSV row."""
    # Exit 3 where an engine fails (docs/flipcheck.md, "In a CI job"): the rows are judged here.
    r = subprocess.run([str(a) for a in [bookspin, "flipcheck", "judge", scene, *motions, "-o", out]],
                       capture_output=True, text=True)
    if r.returncode not in (0, 3):
        fail(f"bookspin flipcheck judge {scene} exited {r.returncode}: {r.stderr}")
    with open(Path(out) / f"{Path(scene).stem}-judge.csv", newline="") as f:
        return {row["motion"]: row for row in csv.DictReader(f)}


def refused(node, runner, args, want, out):
    """Runs the runner with `args`: exit 2, one line on stderr holding every string of `want`,
    nothing on stdout and nothing written to `out`; fail() otherwise."""
    r = subprocess.run([str(node), str(runner), *map(str, args)], capture_output=True, text=True,
                       timeout=300)
    lines = r.stderr.strip().splitlines()
    if r.returncode != 2 or len(lines) != 1 or r.stdout or any(w not in r.stderr for w in want):
        fail(f"{' '.join(map(str, args))}: exit {r.returncode}, expected 2 and one line with "
             f"{want}:\n{r.stdout}{r.stderr}")
    if Path(out).exists():
        fail(f"{' '.join(map(str, args))}: refused, yet {out} was made")
    return lines[0]


def check_refusals(node, source, scenario):
    """The runner's one-line answers to bad input, each with nothing written."""
    with tempfile.TemporaryDirectory(prefix="bookspin-engines-runner-") as tmp:
        tmp = Path(tmp)
        out = tmp / "out"
        # The runner and its adapters copied beside a node_modules of links to the installed
        # packages but Ammo.js's, then of none.
        web = tmp / "web"
        shutil.copytree(source / "web" / "src" / "engines", web / "src" / "engines")
        for name in ("flipcheck-engines.mjs", "package-lock.json"):
            shutil.copy(source / "web" / name, web / name)
        modules = web / "node_modules"
        for package in sorted({p for p, _ in VERDICTS} - {"ammo.js"}):
            (modules / package).parent.mkdir(parents=True, exist_ok=True)
            (modules / package).symlink_to(source / "web" / "node_modules" / package)
        runner = web / "flipcheck-engines.mjs"
        print(refused(node, runner, [out, scenario], ["ammo.js", "scripts/install-deps.sh"], out))
        refused(node, runner, ["--check"], ["ammo.js", "scripts/install-deps.sh"], out)
        shutil.rmtree(modules)
        modules.mkdir()
        line = refused(node, runner, [out, scenario], ["scripts/install-deps.sh"], out)
        if any(p not in line for p, _ in VERDICTS):
            fail(f"with no package installed, not every package named: {line}")
        # The installed runner: scenario files that are not JSON, missing, a folder.
        runner = source / "web" / "flipcheck-engines.mjs"
        text = Path(scenario).read_text()
        cut = tmp / "cut.json"
        cut.write_text(text[:len(text) // 2])
        before = text[:len(text) // 2].split("\n")
        print(refused(node, runner, [out, cut], [str(cut), "the file ends",
                      f"line {len(before)}, column {len(before[-1]) + 1}"], out))
        broken = tmp / "broken.json"
        broken.write_text('{"scenario": "x",\n  "mass": ]\n}\n')
        refused(node, runner, [out, broken], [str(broken), '"]" at line 2, column 11'], out)
        refused(node, runner, [out, tmp / "no-such.json"], ["no-such.json: no such file"], out)
        refused(node, runner, [out, tmp], [f"{tmp}: is a directory"], out)
        # Only a regular file is opened: a FIFO with no writer and a device are refused at once
        # (the test's own timeout would end a wait on either).
        fifo = tmp / "s.json"
        os.mkfifo(fifo)
        refused(node, runner, [out, fifo], [f"{fifo}: is a FIFO, not a regular file"], out)
        refused(node, runner, [out, "/dev/zero"], ["/dev/zero: is a device, not a regular file"], out)
        # An output that is no folder (a regular file, a FIFO, /dev/full): one line naming it,
        # exit 1, in npx's words (the npm package's makeOutputFolder), nothing run or written;
        # mkdirSync's EEXIST was a stack trace and exit 7.
        blocker = tmp / "a-file"
        blocker.write_text("kept\n")
        for target, what in ((blocker, "is a regular file"), (fifo, "is a FIFO"),
                             (Path("/dev/full"), "is a device")):
            r = subprocess.run([str(node), str(runner), str(target), str(scenario)],
                               capture_output=True, text=True, timeout=300)
            said = f'flipcheck-engines: error: cannot write "{target}": {what}, not a folder\n'
            if r.returncode != 1 or r.stderr != said or r.stdout:
                fail(f"output {target}: exit {r.returncode}, expected 1 and {said!r}:\n"
                     f"{r.stdout}{r.stderr}")
        if blocker.read_text() != "kept\n":
            fail(f"{blocker}: changed by a refused run")


def main():
    bookspin, source, binary = test_arguments(__doc__)
    node = require("node")[0]
    for package in sorted({p for p, _ in VERDICTS}):
        if not (source / "web" / "node_modules" / package).is_dir():
            missing(f"the npm package {package} (web/node_modules: scripts/install-deps.sh)")
    out = binary / "test-output" / "flipcheck-engines"
    scenes = [source / "scenes" / "flipcheck" / f"{name}.toml" for name in SCENARIOS]
    found = sorted(p.stem for p in (source / "scenes" / "flipcheck").glob("*.toml"))
    if found != SCENARIOS:
        fail(f"expected the kit's scenarios {SCENARIOS} in scenes/flipcheck, found {found}")
    run([bookspin, "flipcheck", "export", *scenes, "-o", out / "export", "--force"])
    jsons = [out / "export" / f"{s.stem}.json" for s in scenes]
    check_refusals(node, source, jsons[0])
    motions_dir = out / "motions"
    run([node, source / "web" / "flipcheck-engines.mjs", motions_dir, *jsons])
    names = {e: motion_name(source, *e) for e in VERDICTS}
    expected_files = {f"{s}-{n}.csv" for s in SCENARIOS for n in names.values()}
    written = {p.name for p in motions_dir.glob("*.csv")}
    if written != expected_files:
        fail(f"motion files not named by the installed packages: missing "
             f"{sorted(expected_files - written)[:4]}, unexpected {sorted(written - expected_files)[:4]}")
    # The cache: a second run with nothing changed writes nothing.
    stamps = {p.name: p.stat().st_mtime_ns for p in motions_dir.iterdir()}
    again = run([node, source / "web" / "flipcheck-engines.mjs", motions_dir, *jsons])
    if "up to date" not in again or stamps != {p.name: p.stat().st_mtime_ns for p in motions_dir.iterdir()}:
        fail(f"a second run with nothing changed wrote its motions again:\n{again}")
    failures = []
    table = {}
    for name, scene in zip(SCENARIOS, scenes):
        mujoco = motions_dir.parent / "native" / f"{name}-mujoco-rk4.csv"
        mujoco.parent.mkdir(parents=True, exist_ok=True)
        run([bookspin, "simulate", scene, "--set", 'model.kind="mujoco"',
             "--set", 'model.integrator="rk4"', "--csv", mujoco])
        motions = [out / "export" / f"{name}-exact.csv", mujoco] + [
            motions_dir / f"{name}-{n}.csv" for n in names.values()]
        rows = judged(bookspin, scene, motions, out / "judge")
        table[name] = {m[len(name) + 1:-4]: r for m, r in rows.items()}
    for name in SCENARIOS:
        rows = table[name]
        for must_pass in ("exact", "mujoco-rk4"):
            if rows[must_pass]["verdict"] != "pass":
                failures.append(f"{must_pass} on {name}: {rows[must_pass]['failures']}")
    for engine, verdicts in VERDICTS.items():
        for name, want in zip(SCENARIOS, verdicts):
            r = table[name][names[engine]]
            if r["verdict"][0] != want:
                failures.append(f"{names[engine]} on {name}: {r['verdict']} ({r['failures']}), "
                                f"pinned {'pass' if want == 'p' else 'fail'}")
            intermediate = name.startswith("book-intermediate")
            stable = name in TUMBLE
            e = float(r["energy_drift"]) if r["energy_drift"] else float("inf")
            if engine in NO_GYROSCOPIC_TERM and intermediate and not (
                    r["flips"] == "0" and int(r["flips_exact"]) > 0):
                failures.append(f"{names[engine]} on {name}: {r['flips']}/{r['flips_exact']} "
                                "turn-overs (no gyroscopic term: expected 0 of some)")
            if engine in KEEPS_STABLE_SPINS and stable and not e < 1e-4:
                failures.append(f"{names[engine]} on {name}: energy drift {e} (expected below 1e-4)")
            if engine in LOSES_ENERGY and intermediate and not (
                    r["flips"] == r["flips_exact"] and e > 1e-3):
                failures.append(f"{names[engine]} on {name}: {r['flips']}/{r['flips_exact']} "
                                f"turn-overs, energy drift {e} (expected every turn-over, drift > 1e-3)")
            if engine in TUMBLES and stable and not r["tumble_time"]:
                failures.append(f"{names[engine]} on {name}: no tumble out of the stable spin")
            if engine == ("jolt-physics", "gyroscopic") and stable:
                t = float(r["tumble_time"]) if r["tumble_time"] else None
                if t is None or abs(t / TUMBLE[name] - 1) > 0.10:
                    failures.append(f"{names[engine]} on {name}: tumbles at {t} "
                                    f"(the drift law: {TUMBLE[name]} ± 10 %)")
    # The league table (docs/flipcheck.md): verdict and turn-overs per motion and scenario.
    print("| motion | " + " | ".join(SCENARIOS) + " |")
    print("|---|" + "---|" * len(SCENARIOS))
    for m in ["exact", "mujoco-rk4"] + list(names.values()):
        cells = []
        for s in SCENARIOS:
            r = table[s][m]
            cell = f"{r['verdict']} {r['flips']}/{r['flips_exact']}, E {float(r['energy_drift']):.2g}"
            if r["tumble_time"]:
                cell += f", tumbles at t = {float(r['tumble_time']):.3g}"
            cells.append(cell)
        print(f"| {m} | " + " | ".join(cells) + " |")
    for f in failures:
        print("FAIL:", f)
    if failures:
        sys.exit(1)
    print("flipcheck engines: OK")


if __name__ == "__main__":
    main()
