"""bookspin.frames against the PNG frames `bookspin render` writes for the same scene: pixel for
pixel, every frame, at the times of its diagnostics CSV; a generator left half-way stops its
thread and writes nothing; Ctrl-C while a frame is awaited raises KeyboardInterrupt at once."""
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

from conftest import SOURCE_DIR, numbers, read_csv, read_png, run_cli

SCENES = SOURCE_DIR / "scenes"

# Tiny clips, decorated as the scenes ask and more: the caption, the panel, the sphere inset.
CASES = [
    ("fig09-matrix-unstable-x.toml",
     {"render.width": 160, "render.height": 90, "time.frames": 6, "render.panel": True,
      "render.sphere": True},
     ["render.width=160", "render.height=90", "time.frames=6", "render.panel=true",
      "render.sphere=true"]),
    ("compare-methods-x.toml", {"render.width": 192, "render.height": 108, "time.frames": 3},
     ["render.width=192", "render.height=108", "time.frames=3"]),
]


def cli_render(tmp_path, scene, sets, *more):
    """`bookspin render SCENE -o OUT --set ...`; returns OUT/<name>/, the frames' folder's parent."""
    out = tmp_path / "cli"
    args = ["render", scene, "-o", out, *more]
    for word in sets:
        args += ["--set", word]
    run_cli(*args)
    return out


def task_count():
    return len(os.listdir("/proc/self/task"))


@pytest.mark.parametrize("name, overrides, sets", CASES, ids=[c[0] for c in CASES])
def test_frames_are_the_png_frames_render_writes(bookspin, tmp_path, name, overrides, sets):
    out = cli_render(tmp_path, SCENES / name, sets)
    [folder] = [p for p in out.iterdir() if p.is_dir()]
    pngs = sorted((folder / "frames").glob("frame_*.png"))
    csvs = sorted(folder.glob("diagnostics*.csv"))
    times = numbers(read_csv(csvs[0])["t"])
    assert len(pngs) == overrides["time.frames"] == len(times)
    got = list(bookspin.frames(SCENES / name, overrides))
    assert len(got) == len(pngs)
    for k, ((t, image), png) in enumerate(zip(got, pngs)):
        assert isinstance(t, float) and t == times[k], (k, t, times[k])
        expected = read_png(png)
        assert image.dtype == np.uint8
        assert image.shape == (overrides["render.height"], overrides["render.width"], 3)
        assert expected.shape == image.shape, png
        differ = np.argwhere(np.any(image != expected, axis=2))
        assert len(differ) == 0, f"frame {k}: {len(differ)} pixels differ, first at {differ[0]}"


def test_a_generator_left_half_way_stops_and_writes_nothing(bookspin, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    scene = SCENES / "fig09-matrix-unstable-x.toml"
    small = {"render.width": 64, "render.height": 48, "time.frames": 200}
    list(bookspin.frames(scene, {**small, "time.frames": 2}))  # GL and its threads started once
    before = task_count()
    frames = bookspin.frames(scene, small)
    t0, first = next(frames)
    assert t0 == 0.0 and first.shape == (48, 64, 3)
    start = time.monotonic()
    del frames  # the loop's thread stops within a frame
    assert time.monotonic() - start < 1.0
    for t, image in bookspin.frames(scene, small):
        break
    stopped = bookspin.frames(scene, small)
    next(stopped)
    stopped.close()
    with pytest.raises(StopIteration):
        next(stopped)
    assert task_count() == before
    assert list(tmp_path.iterdir()) == []


def test_a_bad_scene_raises_at_the_call(bookspin, tmp_path):
    with pytest.raises(bookspin.Error) as raised:
        bookspin.frames(SCENES / "fig09-matrix-unstable-x.toml", {"render.width": 161})
    assert "render.width" in str(raised.value)
    assert len(list(bookspin.frames(SCENES / "fig09-matrix-unstable-x.toml",
                                    {"render.width": 32, "render.height": 32,
                                     "time.frames": 2}))) == 2


def test_ctrl_c_while_a_frame_is_awaited_raises_keyboard_interrupt(tmp_path):
    # A long clip, pulled in a loop until the signal: KeyboardInterrupt comes within a second,
    # and the loop's thread is gone.
    script = textwrap.dedent(f"""
        import os, sys, time
        import bookspin
        scene = {str(SCENES / "fig09-matrix-unstable-x.toml")!r}
        frames = bookspin.frames(scene, {{"render.width": 320, "render.height": 180,
                                         "render.panel": True, "time.frames": 100000}})
        next(frames)
        tasks = len(os.listdir("/proc/self/task"))
        print("started", flush=True)
        try:
            for t, image in frames:
                pass
            print("finished")
        except KeyboardInterrupt:
            print("interrupted", time.monotonic(), flush=True)
        del frames
        print("tasks", tasks, len(os.listdir("/proc/self/task")), flush=True)
    """)
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, cwd=tmp_path)
    assert child.stdout.readline().strip() == "started"
    time.sleep(0.5)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    stdout, stderr = child.communicate(timeout=60)
    lines = stdout.split("\n")
    assert lines[0].startswith("interrupted"), (stdout, stderr)
    assert float(lines[0].split()[1]) - sent < 1.0
    _, tasks_then, tasks_after = lines[1].split()
    # The loop's own thread has ended (GL's worker threads may stay with the display).
    assert int(tasks_after) <= int(tasks_then) - 1, lines[1]
    assert child.returncode == 0, stderr
    assert list(tmp_path.iterdir()) == []
