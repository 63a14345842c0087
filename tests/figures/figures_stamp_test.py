#!/usr/bin/env python3
"""`make figures`' stamp (scripts/figures.sh, docs/outputs.md): nothing changed, nothing done;
anything changed, everything run again; a failed run leaves no stamp.

The script is copied into a small tree of its own (a scene, a scenario, a sweep, a recording, a
source and a page file, each a line of text, and a scripts/render-all.sh that writes the
gallery), and run with a `bookspin` written here that logs each command and writes one file per
product into OUT, on a PATH without node, npm or em++ (the page and the JavaScript engines left
out, as on a machine without them). Each case is judged by the log of the commands run and the
stamp file, OUT/.logs/figures.stamp, never by the script's own words alone:
  - the first run runs every stage and writes the stamp; a second, with nothing changed, runs
    no command and rewrites no file under OUT;
  - each input the script names changed (a scene's, a scenario's, a sweep's, a recording's, a
    source's, a page file's, a script's bytes; a scene added; the program's bytes; --quick
    given or dropped) runs the stages again, and then the next run is up to date;
  - an output under OUT changed (its bytes, the same size) or removed runs them again; a log
    under OUT/.logs changed does not; nor does a file under web/node_modules;
  - a run whose stage fails exits non-zero and leaves no stamp, even where an earlier run left
    one: the next run runs again.
About a second (the unit tier: no program of the project is run).

Usage: figures_stamp_test.py SOURCE_DIR
"""
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

FAKE_BOOKSPIN = r"""#!/bin/bash
# Logs its command; writes one file per product into the folder after -o; fails when the
# command starts with $FAKE_FAIL.
echo "$*" >> "$FAKE_LOG"
if [ -n "${FAKE_FAIL:-}" ] && [[ "$*" == "$FAKE_FAIL"* ]]; then echo "fake: $1 failed" >&2; exit 1; fi
out=
while [ $# -gt 0 ]; do [ "$1" = -o ] && out=$2; shift; done
[ -n "$out" ] || exit 0
mkdir -p "$out/flipcheck"
echo "product of $(tail -n 1 "$FAKE_LOG")" > "$out/product-$(wc -l < "$FAKE_LOG" | tr -d ' ').txt"
echo exact > "$out/flipcheck/x-exact.csv"
"""

FAKE_RENDER_ALL = r"""#!/usr/bin/env bash
# The gallery: one file, and the command logged.
echo "render-all $2" >> "$FAKE_LOG"
echo "<html>gallery</html>" > "$2/index.html"
mkdir -p "$2/.logs" && echo log > "$2/.logs/summary.tsv"
"""

# The tools scripts/figures.sh and the fakes run, and nothing else (no node, npm or em++).
TOOLS = ["bash", "sha256sum", "find", "sort", "xargs", "cut", "cat", "rm", "mv", "mkdir", "date",
         "tail", "dirname", "tr", "wc", "touch", "sleep"]


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


class Tree:
    def __init__(self, source, tmp):
        self.root = tmp / "root"
        self.build = tmp / "build"
        self.out = tmp / "out"
        self.log = tmp / "commands.log"
        self.bin = tmp / "bin"
        for d in ("scripts", "scenes/flipcheck", "sweeps", "recordings/sample", "src/physics",
                  "web/src", "web/node_modules/pkg", "sweeps"):
            (self.root / d).mkdir(parents=True, exist_ok=True)
        shutil.copy(source / "scripts" / "figures.sh", self.root / "scripts" / "figures.sh")
        (self.root / "scripts" / "render-all.sh").write_text(FAKE_RENDER_ALL)
        files = {"scenes/a.toml": "a = 1\n", "scenes/flipcheck/x.toml": "x = 1\n",
                 "sweeps/s.toml": "s = 1\n", "recordings/sample/Raw Data.csv": "t,wx,wy,wz\n",
                 "src/physics/a.cpp": "int a;\n", "web/src/main.js": "let a;\n",
                 "web/package-lock.json": "{}\n", "web/node_modules/pkg/index.js": "1;\n"}
        for path, text in files.items():
            (self.root / path).write_text(text)
        self.build.mkdir()
        (self.build / "bookspin").write_text(FAKE_BOOKSPIN)
        (self.build / "bookspin").chmod(0o755)
        self.bin.mkdir()
        for tool in TOOLS:
            found = shutil.which(tool)
            if not found:
                fail(f"{tool} not found")
            (self.bin / tool).symlink_to(found)

    def run(self, *extra, fail_at=None, expect_ok=True):
        """Runs the script; returns (exit code, output, the commands it ran)."""
        self.log.write_text("")
        env = {"PATH": str(self.bin), "FAKE_LOG": str(self.log), "HOME": str(self.root),
               "LC_ALL": "C"}
        if fail_at:
            env["FAKE_FAIL"] = fail_at
        r = subprocess.run(["bash", str(self.root / "scripts" / "figures.sh"), str(self.build),
                            str(self.out), *extra], env=env, capture_output=True, text=True,
                           timeout=60)
        if expect_ok and r.returncode != 0:
            fail(f"figures.sh {' '.join(extra)}: exit {r.returncode}\n{r.stdout}{r.stderr}")
        return r.returncode, r.stdout + r.stderr, self.log.read_text().splitlines()

    def outputs(self):
        """Every file under OUT but its logs: path → (bytes, modification time)."""
        return {p.relative_to(self.out): (p.read_bytes(), p.stat().st_mtime_ns)
                for p in self.out.rglob("*") if p.is_file() and ".logs" not in p.parts}

    def stamp(self):
        return self.out / ".logs" / "figures.stamp"


def ran_everything(what, commands):
    """fail() unless `commands` hold every stage: the sweeps, the accuracy, the league, the fit
    and the gallery."""
    for stage in ("sweep ", "accuracy ", "flipcheck export", "flipcheck league", "fit ",
                  "render-all"):
        if not any(c.startswith(stage) for c in commands):
            fail(f"{what}: the stage {stage.strip()!r} did not run: {commands}")


def up_to_date(tree, what, *extra):
    before = tree.outputs()
    stamp = tree.stamp().read_text()
    _, output, commands = tree.run(*extra)
    if commands:
        fail(f"{what}: nothing changed, yet it ran {commands}\n{output}")
    if tree.outputs() != before or tree.stamp().read_text() != stamp:
        fail(f"{what}: nothing changed, yet files under OUT were rewritten")


def runs_again(tree, what, *extra):
    _, output, commands = tree.run(*extra)
    ran_everything(what, commands)
    if not tree.stamp().is_file():
        fail(f"{what}: a whole run left no stamp")
    up_to_date(tree, f"{what}, then nothing changed", *extra)


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    source = Path(sys.argv[1]).resolve()
    with tempfile.TemporaryDirectory(prefix="bookspin-figures-stamp-") as tmp:
        tree = Tree(source, Path(tmp))
        root = tree.root

        # The first run and a second with nothing changed.
        _, output, commands = tree.run("--quick")
        ran_everything("the first run", commands)
        if not tree.stamp().is_file():
            fail(f"the first run wrote no stamp:\n{output}")
        up_to_date(tree, "the second run", "--quick")
        print(f"first run: {len(commands)} commands, the stamp written; the second: none")

        # Every input: changed, the stages run again; then up to date.
        for path in ("scenes/a.toml", "scenes/flipcheck/x.toml", "sweeps/s.toml",
                     "recordings/sample/Raw Data.csv", "src/physics/a.cpp", "web/src/main.js",
                     "web/package-lock.json", "scripts/render-all.sh"):
            with open(root / path, "a") as f:
                f.write("# changed\n")
            runs_again(tree, f"{path} changed", "--quick")
        (root / "scenes" / "b.toml").write_text("b = 2\n")
        runs_again(tree, "a scene added", "--quick")
        with open(tree.build / "bookspin", "a") as f:
            f.write("# rebuilt\n")
        runs_again(tree, "the program rebuilt", "--quick")
        runs_again(tree, "--quick dropped")
        runs_again(tree, "--quick given again", "--quick")
        print("each input changed (8 files, a scene added, the program, --quick): run again")

        # The outputs: one changed (same size) or removed runs again; a log or a package not.
        product = sorted(tree.outputs())[0]
        text = (tree.out / product).read_bytes()
        (tree.out / product).write_bytes(bytes(reversed(text)))
        runs_again(tree, f"{product} changed", "--quick")
        (tree.out / product).unlink()
        runs_again(tree, f"{product} removed", "--quick")
        (tree.out / ".logs" / "summary.tsv").write_text("another log\n")
        up_to_date(tree, "a log changed", "--quick")
        (root / "web" / "node_modules" / "pkg" / "index.js").write_text("2;\n")
        up_to_date(tree, "a file under web/node_modules changed", "--quick")
        print("an output changed or removed: run again; a log or web/node_modules: not")

        # A failed stage: non-zero, no stamp, even over an earlier run's; the next run runs.
        for stage in ("flipcheck league", "fit "):
            with open(root / "scenes" / "a.toml", "a") as f:
                f.write("# changed\n")
            code, output, commands = tree.run("--quick", fail_at=stage, expect_ok=False)
            if code == 0:
                fail(f"{stage.strip()} failed, yet the script exited 0:\n{output}")
            if tree.stamp().exists():
                fail(f"{stage.strip()} failed, yet {tree.stamp()} is there")
            runs_again(tree, f"after {stage.strip()} failed", "--quick")
        print("a failed stage: non-zero, no stamp; the next run runs again")
    print("figures stamp: OK")


if __name__ == "__main__":
    main()
