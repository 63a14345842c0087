#!/usr/bin/env python3
"""One version, from one place (docs/flipcheck.md, "Versions"): VERSION states it, and the
program (`bookspin --version`), the Python module and its wheel's metadata, the npm package's
package.json (where built), the example project that pins the npm package and every version the
docs name in a package's file name all say the same. The places that derive it take it from
VERSION at build time and state none of their own. And VERSION's kit line (the scenarios and
the judge's rules) does not change under the same version against the VERSION committed at
HEAD, its first parent and its merge base with main, where git has them.

Usage: check_versions.py SOURCE_DIR BUILD_DIR
"""
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

source, build = Path(sys.argv[1]), Path(sys.argv[2])
problems = []

text = (source / "VERSION").read_text()
versions = re.findall(r"^version (\d+\.\d+\.\d+)$", text, re.M)
kits = re.findall(r"^kit ([0-9a-f]{64})$", text, re.M)
if len(versions) != 1 or len(kits) != 1:
    sys.exit("VERSION: expected one line \"version MAJOR.MINOR.PATCH\" and one \"kit SHA256\"")
version = versions[0]


def same(what, got):
    if got != version:
        problems.append(f"{what}: {got!r}, VERSION says {version!r}")


# The program.
out = subprocess.run([str(build / "bookspin"), "--version"], capture_output=True, text=True)
same("bookspin --version", out.stdout.strip().removeprefix("bookspin "))
if out.returncode != 0 or not out.stdout.startswith("bookspin "):
    problems.append(f"bookspin --version: exit {out.returncode}, {out.stdout!r} {out.stderr!r}")

# The Python module and the wheel's metadata, where the module is built.
if (build / "python" / "pyproject.toml").exists():
    meta = re.search(r'^version = "([^"]*)"', (build / "python" / "pyproject.toml").read_text(), re.M)
    same("BUILD/python/pyproject.toml", meta and meta.group(1))
    env = dict(os.environ, PYTHONPATH=str(build / "python"))
    out = subprocess.run([sys.executable, "-c", "import bookspin; print(bookspin.__version__)"],
                         capture_output=True, text=True, env=env)
    same("bookspin.__version__", out.stdout.strip() or out.stderr.strip())

# The npm package, where built.
package = build / "npm" / "package" / "package.json"
if package.exists():
    same(str(package.relative_to(build)), json.loads(package.read_text())["version"])

# The example project pins the package it installs.
example = json.loads((source / "examples" / "flipcheck-npm" / "package.json").read_text())
same("examples/flipcheck-npm/package.json devDependencies.flipcheck",
     example["devDependencies"]["flipcheck"])

# The templates derive it; nothing else states one.
for path, marker in (("python/pyproject.toml.in", "@PROJECT_VERSION@"),
                     ("npm/package/package.json.in", "@VERSION@")):
    if marker not in (source / path).read_text():
        problems.append(f"{path}: takes its version from {marker} (VERSION)")
if re.search(r"project\(bookspin VERSION \d", (source / "CMakeLists.txt").read_text()):
    problems.append("CMakeLists.txt: project() states a version of its own: it reads VERSION")

# Every version the docs name in a package's file name, or the example's pin, is VERSION's.
names = re.compile(r"flipcheck-(\d+\.\d+\.\d+)\.tgz|bookspin-(\d+\.\d+\.\d+)-cp|\"flipcheck\": \"(\d+\.\d+\.\d+)\"")
for doc in [source / "README.md", *sorted((source / "docs").glob("*.md"))]:
    for n, line in enumerate(doc.read_text().splitlines(), 1):
        for m in names.finditer(line):
            same(f"{doc.relative_to(source)}:{n}", next(g for g in m.groups() if g))

# The kit (the scenarios and the judge's rules, which Flipcheck.TheKitIsTheOneItsVersionRecords
# holds to VERSION's kit line) changes only with the version: against the committed VERSION of
# HEAD, its first parent and its merge base with main (where git and they are there), a new kit
# line under the same version is a kit changed without a bump.
def committed_version(commit):
    if shutil.which("git") is None:
        return None
    done = subprocess.run(["git", "-C", str(source), "show", f"{commit}:VERSION"],
                          capture_output=True, text=True)
    if done.returncode != 0:
        return None
    v = re.findall(r"^version (\S+)$", done.stdout, re.M)
    k = re.findall(r"^kit (\S+)$", done.stdout, re.M)
    return (v[0], k[0]) if len(v) == 1 and len(k) == 1 else None


bases = ["HEAD", "HEAD^1"]
if shutil.which("git"):
    base = subprocess.run(["git", "-C", str(source), "merge-base", "HEAD", "main"],
                          capture_output=True, text=True)
    if base.returncode == 0:
        bases.append(base.stdout.strip())
for commit in bases:
    old = committed_version(commit)
    if old and old[0] == version and old[1] != kits[0]:
        problems.append(f"VERSION: the kit changed since {commit} ({old[1][:12]}… -> "
                        f"{kits[0][:12]}…) and the version did not ({version}): scenario or "
                        "judge rules changed: bump the version")

if problems:
    print("versions disagree (one version, from VERSION: docs/flipcheck.md, \"Versions\"):")
    for p in problems:
        print("  " + p)
    sys.exit(1)
print(f"one version: {version}")
