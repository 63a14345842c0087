"""SIGINT, SIGTERM and SIGHUP at seeded random moments of the module's long calls (render,
simulate, exact_motion), in a child interpreter: the stop contract of the command line
(docs/outputs.md, "Signals") at any moment. SIGINT raises KeyboardInterrupt and the interpreter
goes on; SIGTERM and SIGHUP, which Python leaves to their default action, end the process with
that signal (exit 128 + n in a shell) once the call has stopped and removed what it began: no
temporary, no partial file, the earlier outputs byte for byte (killed mid-write, a render left
its temporary frames and CSV in the output folder)."""
import hashlib
import random
import signal
import subprocess
import sys
import textwrap
import time

import pytest

from conftest import SOURCE_DIR

SCENE = SOURCE_DIR / "scenes" / "fig09-matrix-unstable-x.toml"

CALLS = {
    # About 3000 frames at 320 x 180 with PNGs: far longer than the window.
    "render": f"""bookspin.render({str(SCENE)!r}, "out", {{"render.width": 320,
                    "render.height": 180, "time.frames": 3000}}, png=True, progress=False)""",
    "simulate": f"""bookspin.simulate({str(SCENE)!r}, {{"time.frames": 100000,
                    "time.steps_per_frame": 300}})""",
    "exact_motion": """bookspin.exact_motion([1, 2, 3], [0.1, 1, 0.05],
                    numpy.linspace(0.0, 1e4, 50_000_000))""",
}


# Seconds after the call began within which the signal comes: the render's first half second
# is the scene and the renderer being made, before it writes.
WINDOW = {"render": (0.5, 4.0)}


def files(folder):
    """Every file under `folder` with its SHA-256."""
    return {str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in folder.rglob("*") if p.is_file()}


@pytest.mark.parametrize("call", sorted(CALLS))
def test_any_moment_of_a_long_call_keeps_the_stop_contract(tmp_path, call):
    rng = random.Random(f"82-{call}")
    out = tmp_path / "out"
    # The earlier outputs a render must keep: a short render of the same scene.
    earlier = f"""bookspin.render({str(SCENE)!r}, "out", {{"render.width": 64,
                    "render.height": 36, "time.frames": 3}}, png=True, progress=False)"""
    done = subprocess.run([sys.executable, "-c", f"import bookspin\n{earlier}"], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    before = files(out)
    assert before
    script = textwrap.dedent(f"""
        import numpy, bookspin
        print("started", flush=True)
        try:
            {textwrap.dedent(CALLS[call]).strip()}
            print("finished", flush=True)
        except KeyboardInterrupt:
            print("interrupted", flush=True)
    """)
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        delay = rng.uniform(*WINDOW.get(call, (0.0, 2.0)))
        child = subprocess.Popen([sys.executable, "-c", script], cwd=tmp_path,
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert child.stdout.readline().strip() == "started"
        time.sleep(delay)
        child.send_signal(sig)
        stdout, stderr = child.communicate(timeout=60)
        what = (call, sig.name, delay, stdout, stderr)
        if sig == signal.SIGINT:
            assert stdout.strip() == "interrupted" and child.returncode == 0, what
        else:
            assert child.returncode == -sig, what
            assert "finished" not in stdout, what
        assert files(out) == before, what
