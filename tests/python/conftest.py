"""What the Python module's tests share (docs/python.md): the module, the bookspin program and
the source tree (from ctest's environment: PYTHONPATH=BUILD/python, BOOKSPIN_EXE,
BOOKSPIN_SOURCE_DIR), a command-line runner and CSV readers."""
import csv
import os
import pathlib
import signal
import subprocess
import sys
import textwrap
import time

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
    """Runs the bookspin program; returns (stdout, stderr), checking its exit status (`expect`,
    or one of a tuple of them)."""
    done = subprocess.run([EXE, *map(str, args)], cwd=cwd, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode in (expect if isinstance(expect, tuple) else (expect,)), \
        (args, done.returncode, done.stderr)
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


def read_png(path):
    """An 8-bit RGB or RGBA PNG (as bookspin writes its frames: output/png_writer.hpp) as a
    uint8 array (H, W, channels), decoded here with zlib: the scanlines' filters undone as the
    PNG specification says (§9.2: None, Sub, Up, Average, Paeth)."""
    import struct
    import zlib
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, (path, header)
    channels = 3 if colour == 2 else 4
    stride = width * channels
    raw = np.frombuffer(zlib.decompress(idat), dtype=np.uint8).reshape(height, stride + 1)
    out = np.zeros((height, stride), dtype=np.uint8)
    prior = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        kind, line = raw[y, 0], raw[y, 1:].astype(np.int32)
        if kind == 0:
            row = line
        elif kind == 1:
            row = np.cumsum(line.reshape(width, channels), axis=0).reshape(stride) % 256
        elif kind == 2:
            row = (line + prior) % 256
        else:
            row = np.zeros(stride, dtype=np.int32)
            for x in range(stride):
                a = row[x - channels] if x >= channels else 0
                b = prior[x]
                c = prior[x - channels] if x >= channels else 0
                if kind == 3:
                    predictor = (a + b) // 2
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    predictor = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                row[x] = (line[x] + predictor) % 256
        out[y] = row
        prior = row
    return out.reshape(height, width, channels)


def assert_same_error(module, call, *cli_args):
    """`call()` raises bookspin.Error with the one line the command line prints (exit 2) for
    `cli_args`."""
    _, stderr = run_cli(*cli_args, expect=2)
    with pytest.raises(module.Error) as raised:
        call()
    assert str(raised.value) == cli_error_line(stderr)


def interrupted_child(script, started, after, cwd=None, timeout=120):
    """Runs `script` in a fresh interpreter, waits for its first line `started`, sends SIGINT
    `after` seconds later and returns (stdout's lines, stderr, returncode, the time it was sent)."""
    child = subprocess.Popen([sys.executable, "-c", textwrap.dedent(script)], cwd=cwd,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == started
    time.sleep(after)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    stdout, stderr = child.communicate(timeout=timeout)
    return stdout.splitlines(), stderr, child.returncode, sent
