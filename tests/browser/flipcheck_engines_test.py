"""The conformance kit run by outside engines (docs/flipcheck.md, "Any engine"): usage
flipcheck_engines_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR.

`bookspin flipcheck export` writes every scenario of scenes/flipcheck/; the JavaScript engines of
web/package-lock.json (cannon-es, Rapier, Jolt without and with mApplyGyroscopicForce) run each
under node from its JSON alone (web/flipcheck-engines.mjs); `bookspin simulate` writes MuJoCo's
RK4 on each; `bookspin flipcheck judge` judges them all with the exported exact motion. Then:
- the exact motion and MuJoCo's RK4 pass every scenario;
- cannon-es (no gyroscopic term) fails the intermediate-axis scenarios with 0 turn-overs where
  the exact motion has some;
- Jolt with mApplyGyroscopicForce fails both stable spins, tumbling within 10 % of the time the
  step's drift law gives (docs/physics.md §10.7, the law averaged over the exact orbits: 41.6
  time units about the largest axis, 105.4 about the smallest);
and prints the league table of docs/flipcheck.md.

Skipped (exit 77) where node or the npm packages (web/node_modules, scripts/install-deps.sh) are
missing; a failure under CI=true.
"""
import csv
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from browser import fail, missing, require, run, test_arguments  # noqa: E402

# docs/physics.md §10.7, "averaged law": the tumble of the rescaled Euler step (Jolt's
# mApplyGyroscopicForce) from each stable spin's jiggled start at dt = 1/60.
TUMBLE = {"book-largest-axis": 41.6, "book-smallest-axis": 105.4}
ENGINES = ["cannon-es", "rapier", "jolt", "jolt-gyroscopic"]


def judged(bookspin, scene, motions, out):
    """scenario name → {motion file name → judge CSV row}."""
    run([bookspin, "flipcheck", "judge", scene, *motions, "-o", out])
    name = Path(scene).stem
    with open(Path(out) / f"{name}-judge.csv", newline="") as f:
        return {row["motion"]: row for row in csv.DictReader(f)}


def main():
    bookspin, source, binary = test_arguments(__doc__)
    node = require("node")[0]
    if not (source / "web" / "node_modules" / "jolt-physics").is_dir():
        missing("the explorer's npm packages (web/node_modules: scripts/install-deps.sh)")
    out = binary / "test-output" / "flipcheck-engines"
    scenes = sorted((source / "scenes" / "flipcheck").glob("*.toml"))
    if len(scenes) < 7:
        fail(f"expected the kit's 7 scenarios in scenes/flipcheck, found {len(scenes)}")
    run([bookspin, "flipcheck", "export", *scenes, "-o", out / "export", "--force"])
    jsons = [out / "export" / f"{s.stem}.json" for s in scenes]
    run([node, source / "web" / "flipcheck-engines.mjs", out / "motions", *jsons])
    failures = []
    table = {}
    for scene in scenes:
        name = scene.stem
        mujoco = out / "motions" / f"{name}-mujoco-rk4.csv"
        run([bookspin, "simulate", scene, "--set", 'model.kind="mujoco"',
             "--set", 'model.integrator="rk4"', "--csv", mujoco])
        motions = [out / "export" / f"{name}-exact.csv", mujoco] + [
            out / "motions" / f"{name}-{e}.csv" for e in ENGINES]
        rows = judged(bookspin, scene, motions, out / "judge")
        table[name] = rows
        for must_pass in (f"{name}-exact.csv", f"{name}-mujoco-rk4.csv"):
            if rows[must_pass]["verdict"] != "pass":
                failures.append(f"{must_pass}: {rows[must_pass]['failures']}")
        cannon = rows[f"{name}-cannon-es.csv"]
        if name.startswith("book-intermediate"):
            if not (cannon["verdict"] == "fail" and cannon["flips"] == "0"
                    and int(cannon["flips_exact"]) > 0):
                failures.append(f"cannon-es on {name}: {cannon['flips']}/{cannon['flips_exact']} "
                                f"turn-overs, {cannon['verdict']} (expected 0 and a fail)")
        if name in TUMBLE:
            jolt = rows[f"{name}-jolt-gyroscopic.csv"]
            t = float(jolt["tumble_time"]) if jolt["tumble_time"] else None
            if jolt["verdict"] != "fail" or t is None or abs(t / TUMBLE[name] - 1) > 0.10:
                failures.append(f"Jolt with mApplyGyroscopicForce on {name}: {jolt['verdict']}, "
                                f"tumbles at {t} (the drift law: {TUMBLE[name]} ± 10 %)")
    # The league table (docs/flipcheck.md): verdict and turn-overs per motion and scenario.
    methods = ["exact", "mujoco-rk4"] + ENGINES
    print("| motion | " + " | ".join(s.stem for s in scenes) + " |")
    print("|---|" + "---|" * len(scenes))
    for m in methods:
        cells = []
        for s in scenes:
            r = table[s.stem][f"{s.stem}-{m}.csv"]
            cell = f"{r['verdict']} {r['flips']}/{r['flips_exact']}"
            if r["tumble_time"]:
                cell += f", tumbles at {float(r['tumble_time']):.3g}"
            cells.append(cell)
        print(f"| {m} | " + " | ".join(cells) + " |")
    for f in failures:
        print("FAIL:", f)
    if failures:
        sys.exit(1)
    print("flipcheck engines: OK")


if __name__ == "__main__":
    main()
