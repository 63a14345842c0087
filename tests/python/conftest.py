"""What the Python module's tests share (docs/python.md): the module, the bookspin program and
the source tree (from ctest's environment: PYTHONPATH=BUILD/python, BOOKSPIN_EXE,
BOOKSPIN_SOURCE_DIR), a command-line runner and CSV readers."""
import csv
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(
    os.environ.get("BOOKSPIN_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
EXE = os.environ.get("BOOKSPIN_EXE", str(SOURCE_DIR / "build" / "bookspin"))
SCENARIO_DIR = SOURCE_DIR / "scenes" / "flipcheck"


@pytest.fixture(scope="session")
def bookspin():
    import bookspin as module
    return module


def run_cli(*args, cwd=None, expect=0):
    """Runs the bookspin program; returns (stdout, stderr), checking its exit status."""
    done = subprocess.run([EXE, *map(str, args)], cwd=cwd, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == expect, (args, done.returncode, done.stderr)
    return done.stdout, done.stderr


def cli_error_line(stderr):
    """The one line after "bookspin: error: " that the command line printed."""
    lines = [l for l in stderr.splitlines() if l.startswith("bookspin: error: ")]
    assert len(lines) == 1, stderr
    return lines[0][len("bookspin: error: "):]


def read_csv(path):
    """A CSV as {column: list of cells (str)}, in the header's order."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: [row[i] for row in body] for i, name in enumerate(header)}


def numbers(cells, empty=np.nan):
    return np.array([float(c) if c != "" else empty for c in cells], dtype=np.float64)


def write_motion_csv(path, t, q, omega_world):
    """A motion file (docs/flipcheck.md, "The motion file"), every number in repr's round-trip
    form, so that the command line reads the very doubles the module is given."""
    with open(path, "w") as f:
        f.write("t,qw,qx,qy,qz,wx_world,wy_world,wz_world\n")
        for i in range(len(t)):
            f.write(",".join(repr(float(v)) for v in (t[i], *q[i], *omega_world[i])) + "\n")
