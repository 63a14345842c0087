#!/usr/bin/env python3
"""Each browser test, run where no browser can be found (PATH empty), skips with exit 77 and
says so, and under CI=true fails with exit 1 instead: a CI run without the browser must not
pass quietly (browser.py's missing()). Needs no browser itself.

Usage: skip_or_fail_test.py SOURCE_DIR
"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

TESTS = ("gallery_test.py", "gltf_test.py", "explorer_test.py")


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    here = Path(sys.argv[1]) / "tests" / "browser"
    errors = []
    with tempfile.TemporaryDirectory(prefix="bookspin-no-browser-") as empty:
        for test in TESTS:
            for ci, expected, word in (("", 77, "SKIPPED"), ("true", 1, "FAIL")):
                env = {k: v for k, v in os.environ.items() if k != "CI"}
                env.update(PATH=empty, CI=ci)
                # The arguments are never used: the browser is looked for first.
                r = subprocess.run([sys.executable, str(here / test), "bookspin", empty, empty],
                                   env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   text=True, timeout=60)
                print(f"{test}, CI={ci!r}: exit {r.returncode}: {r.stdout.strip()}")
                if r.returncode != expected or not r.stdout.startswith(word):
                    errors.append(f"{test} with CI={ci!r} and no browser exited {r.returncode} "
                                  f"({r.stdout.strip()!r}), expected {expected} and {word}")
    if errors:
        print("FAIL:\n  " + "\n  ".join(errors), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
