#!/usr/bin/env python3
"""The benchmark of the npm package's command against the command line (docs/performance-build.md,
"The npm package against the command line"): the wall time of `npx flipcheck export` of the
seven scenarios (node BUILD/npm/package/cli.mjs) against `bookspin flipcheck export --force` of
their scene files, and of `npx flipcheck judge` of a motion of 10^6 rows (the exact motion of
book-smallest-axis run to 10^6 steps, exported by the command line first) against `bookspin
flipcheck judge --force` of the same file, each a whole process as a user runs it. The two
sides are timed in alternation, --rounds times, each keeping its best (a shared machine disturbs
both alike), in one run on one machine; the ratio is npx's time over the command line's.

Usage: npm_bench.py BOOKSPIN PACKAGE_DIR [--rounds N] [--out CSV]
Writes CSV (default bench/results/npm-MACHINE.csv) and prints a table.
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
SCENES = ROOT / "scenes" / "flipcheck"


def described_machine():
    """(words, slug): the CPU's model name and cores, and the same as a file name's part."""
    found = re.search(r"^model name\s*:\s*(.+)$", Path("/proc/cpuinfo").read_text(), re.M)
    model = found.group(1).strip() if found else "unknown CPU"
    words = re.sub(r"\(.*?\)|processor|cpu|@.*", "", model, flags=re.I).split()[:3]
    return f"{model}, {os.cpu_count()} cores", f"{os.cpu_count()}core-" + "-".join(words).lower()


def seconds(args, cwd):
    """The wall time of one run of `args` (a whole process); exits naming it where it fails."""
    start = time.perf_counter()
    done = subprocess.run([str(a) for a in args], cwd=cwd, capture_output=True, text=True)
    took = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"npm_bench: {' '.join(map(str, args))} exited {done.returncode}:\n{done.stderr}")
    return took


def million_row_motion(bookspin, room):
    """The exact motion of book-smallest-axis at 10^6 steps (its dt, 10^4 frames of 100 steps),
    exported by the command line: (scene, motion CSV)."""
    scene = room / "book-smallest-axis-million.toml"
    text = (SCENES / "book-smallest-axis.toml").read_text()
    text = re.sub(r"^steps_per_frame = .*$", "steps_per_frame = 100", text, flags=re.M)
    scene.write_text(re.sub(r"^frames = .*$", "frames = 10001", text, flags=re.M))
    seconds([bookspin, "flipcheck", "export", scene, "-o", room / "kit"], room)
    return scene, room / "kit" / "book-smallest-axis-million-exact.csv"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bookspin", type=Path)
    ap.add_argument("package", type=Path, help="BUILD/npm/package (npm/build.sh makes it)")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--out", type=Path)
    a = ap.parse_args()
    bookspin, cli = a.bookspin.resolve(), (a.package / "cli.mjs").resolve()
    if shutil.which("node") is None or not cli.is_file():
        sys.exit(f"npm_bench: needs node and {cli} (make npm)")
    machine, slug = described_machine()
    out = a.out or ROOT / "bench" / "results" / f"npm-{slug}.csv"
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    scenes = sorted(SCENES.glob("*.toml"))
    with tempfile.TemporaryDirectory(prefix="bookspin-npm-bench-") as room:
        room = Path(room)
        scene, motion = million_row_motion(bookspin, room)
        json = motion.parent / "book-smallest-axis-million.json"
        runs = {
            "export": ([bookspin, "flipcheck", "export", *scenes, "--force", "-o", room / "cli"],
                       ["node", cli, "export", *[s.stem for s in scenes], "-o", room / "npx"],
                       f"the {len(scenes)} scenarios, their JSON and exact motion"),
            "judge": ([bookspin, "flipcheck", "judge", scene, motion, "--force", "-o", room / "cli"],
                      ["node", cli, "judge", json, motion, "-o", room / "npx"],
                      "a motion of 10^6 rows (book-smallest-axis to 10^6 steps)"),
        }
        best = {}
        for r in range(a.rounds):
            for name, (native, npx, _) in runs.items():
                for side, args in (("native", native), ("npx", npx)):
                    best[name, side] = min(best.get((name, side), float("inf")), seconds(args, room))
            print(f"round {r + 1}/{a.rounds} done", file=sys.stderr)
    rows = [{"command": name, "npx_s": f"{best[name, 'npx']:.2f}",
             "native_s": f"{best[name, 'native']:.2f}",
             "ratio": f"{best[name, 'npx'] / best[name, 'native']:.2f}",
             "note": f"{what}, wall time, best of {a.rounds}", "machine": machine, "date": date}
            for name, (_, _, what) in runs.items()]
    out.parent.mkdir(parents=True, exist_ok=True)
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"npm bench: {machine}, {date}; wall time, best of {a.rounds}")
    print(f"{'command':8} {'npx s':>8} {'native s':>9} {'ratio':>6}")
    for row in rows:
        print(f"{row['command']:8} {row['npx_s']:>8} {row['native_s']:>9} {row['ratio']:>6}")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
