"""bookspin.render against `bookspin render` on the same scene: the same files (names and
bytes), the MP4's path returned; the command line's error lines; Ctrl-C two seconds into a
750-frame render: KeyboardInterrupt within a second and no file left; the progress bar."""
import hashlib
import pathlib
import re
import subprocess
import sys
import textwrap

import pytest

from conftest import EXE, SOURCE_DIR, cli_error_line, interrupted_child, run_cli

SCENE = SOURCE_DIR / "scenes" / "fig09-matrix-unstable-x.toml"
NAME = "fig09-matrix-unstable-x"
SMALL = {"render.width": 160, "render.height": 90, "time.frames": 6, "render.panel": True}
SETS = ["render.width=160", "render.height=90", "time.frames=6", "render.panel=true"]


def cli_render(out, *more, scene=SCENE, sets=SETS, expect=0):
    args = ["render", scene, "-o", out, *more]
    for word in sets:
        args += ["--set", word]
    return run_cli(*args, expect=expect)


def files(folder):
    """Every file under `folder`, by its path relative to it."""
    return {str(p.relative_to(folder)): p for p in folder.rglob("*") if p.is_file()}


@pytest.mark.parametrize("png", [True, False], ids=["png", "no-png"])
def test_render_writes_the_files_the_command_line_writes(bookspin, tmp_path, png):
    cli_render(tmp_path / "cli", *([] if png else ["--no-png"]))
    mp4 = bookspin.render(SCENE, tmp_path / "py", SMALL, png=png, progress=False)
    assert mp4 == str(tmp_path / "py" / f"{NAME}.mp4")
    cli, py = files(tmp_path / "cli"), files(tmp_path / "py")
    assert sorted(py) == sorted(cli)
    assert any(name.startswith(f"{NAME}/frames/frame_") for name in py) == png
    assert f"{NAME}.mp4" in py and f"{NAME}/diagnostics.csv" in py
    # Byte for byte: the MP4 (x264 at the same settings and threads is deterministic, and the
    # muxer writes no date), the PNGs, the CSV, and the manifest (no time in it; the scene's
    # path is the same, the outputs' paths are relative to OUT, their hashes the files'), but
    # for its build id, the SHA-256 of the module that made it where the command line's is the
    # program's, and so the head's hash.
    manifest = f"{NAME}/manifest.json"
    for name, path in py.items():
        if name != manifest:
            assert path.read_bytes() == cli[name].read_bytes(), name
    module = hashlib.sha256(pathlib.Path(bookspin.__file__).read_bytes()).hexdigest()
    program = hashlib.sha256(pathlib.Path(EXE).read_bytes()).hexdigest()
    py_text, cli_text = py[manifest].read_text(), cli[manifest].read_text()
    assert f'"build_id": "sha256:{module}"' in py_text
    assert f'"build_id": "sha256:{program}"' in cli_text

    def without_build(text):
        text = text.replace(module, "BUILD").replace(program, "BUILD")
        return re.sub(r'"head_sha256": "[0-9a-f]{64}"', '"head_sha256": "HEAD"', text)
    assert without_build(py_text) == without_build(cli_text)


def test_a_bad_scene_raises_the_command_lines_line(bookspin, tmp_path):
    sets = SETS + ["body.mass=1e300"]
    _, stderr = cli_render(tmp_path / "cli", sets=sets, expect=2)
    with pytest.raises(bookspin.Error) as raised:
        bookspin.render(SCENE, tmp_path / "py", {**SMALL, "body.mass": 1e300}, progress=False)
    assert str(raised.value) == cli_error_line(stderr)
    assert not (tmp_path / "py").exists()
    # The interpreter goes on.
    assert bookspin.render(SCENE, tmp_path / "py", SMALL, progress=False).endswith(".mp4")


def test_a_failed_write_raises_oserror_naming_the_path(bookspin, tmp_path):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder\n")
    _, stderr = cli_render(blocker / "out", expect=1)
    with pytest.raises(OSError) as raised:
        bookspin.render(SCENE, blocker / "out", SMALL, progress=False)
    assert str(raised.value) == cli_error_line(stderr)
    assert str(blocker) in str(raised.value)


def run_python(script, cwd):
    return subprocess.run([sys.executable, "-c", textwrap.dedent(script)], cwd=cwd,
                          capture_output=True, text=True, timeout=120)


def test_progress_false_prints_nothing(tmp_path):
    done = run_python(f"""
        import bookspin
        bookspin.render({str(SCENE)!r}, "out", {SMALL!r}, progress=False)
    """, tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "" and done.stderr == ""


def test_the_bar_shows_on_stderr_with_tqdm(tmp_path):
    pytest.importorskip("tqdm")
    done = run_python(f"""
        import bookspin
        bookspin.render({str(SCENE)!r}, "out", {SMALL!r})
    """, tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout == ""
    assert NAME in done.stderr and "6/6" in done.stderr and "frame" in done.stderr, done.stderr


def test_without_tqdm_no_bar_and_no_error(tmp_path):
    done = run_python(f"""
        import sys
        sys.modules["tqdm"] = None  # import tqdm raises ImportError
        import bookspin
        print(bookspin.render({str(SCENE)!r}, "out", {SMALL!r}))
    """, tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == f"out/{NAME}.mp4" and done.stderr == ""


def test_ctrl_c_two_seconds_into_a_long_render(tmp_path):
    # 750 frames at 640 x 360, far longer than two seconds (about 16 s on two cores of llvmpipe):
    # KeyboardInterrupt within a second of SIGINT, and no file at all under the output folder
    # (no temporary, no partial video, frame or CSV).
    script = f"""
        import time
        import bookspin
        print("rendering", flush=True)
        try:
            bookspin.render({str(SCENE)!r}, "out", {{"render.width": 640, "render.height": 360,
                            "render.panel": True, "time.frames": 750}}, png=True)
            print("finished", flush=True)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic(), flush=True)
    """
    lines, stderr, returncode, sent = interrupted_child(script, "rendering", 2.0, cwd=tmp_path,
                                                        timeout=60)
    assert lines and lines[0].startswith("interrupted"), (lines, stderr)
    assert float(lines[0].split()[1]) - sent < 1.0
    assert returncode == 0, stderr
    assert files(tmp_path) == {}, files(tmp_path)
