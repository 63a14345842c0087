"""One answer at every door for the same file and the same text (docs/python.md, "Errors"): a
file whose name is bytes that are no UTF-8, a lone surrogate, a NUL and a loop of symbolic links
each get their true cause, in bookspin.Error (never pybind11's "Unable to cast" RuntimeError),
in the command line's words where it can be given the same thing; and in the npm package's
words where only it and Python can (tests/npm/index_test.mjs says the same lines)."""
import os
import subprocess

import pytest

from conftest import EXE, SCENARIO_DIR, cli_error_line, run_cli

# A recording without a flight: both doors read it whole and refuse it with a line naming it.
STILL = "t,wx,wy,wz\n" + "".join(f"{i * 0.01:.2f},0.01,0.02,0.03\n" for i in range(300))


def cli_bytes(*args):
    """The program run with arguments as bytes (a file's name that is no UTF-8): exit status and
    its error line, read back as Python reads such a name (surrogateescape)."""
    done = subprocess.run([os.fsencode(EXE), *args], capture_output=True, timeout=600)
    return done.returncode, cli_error_line(done.stderr.decode("utf-8", "surrogateescape"))


def test_a_file_name_that_is_no_utf8_is_read_at_both_doors(bookspin, tmp_path):
    # Latin-1's "café", as a file made on another system names it: os.listdir gives its byte
    # 0xe9 as the lone surrogate U+DCE9, which bookspin.fit took for text and pybind11 could not
    # cast ("Unable to cast Python instance to C++ type", a RuntimeError).
    raw = os.fsencode(str(tmp_path)) + b"/caf\xe9.csv"
    with open(raw, "w") as f:
        f.write(STILL)
    (name,) = os.listdir(tmp_path)
    assert name == "caf\udce9.csv"
    status, cli_line = cli_bytes(b"fit", raw, b"-o", os.fsencode(str(tmp_path / "out")))
    assert status == 2
    assert f"{tmp_path}/caf\udce9.csv: no free flight found" in cli_line, cli_line
    with pytest.raises(bookspin.Error) as raised:
        bookspin.fit(os.path.join(str(tmp_path), name))
    # The same line, each door naming its own option for flights by hand.
    assert str(raised.value) == cli_line.replace("--tosses START:END[,START:END...]",
                                                 "tosses=[(START, END), ...]")


def test_a_lone_surrogate_is_named_at_its_argument_in_bookspin_error(bookspin):
    # No file's name gives U+D800 (os.listdir's surrogates are U+DC80 … U+DCFF): pybind11's cast
    # error named no argument.
    with pytest.raises(bookspin.Error) as raised:
        bookspin.fit("m\ud800x.csv")
    assert str(raised.value) == ('recording: "m\\ud800x.csv" holds a lone surrogate (U+D800) at '
                                 'character 2: no UTF-8 text holds one')
    arrays = bookspin.flipcheck.export("mujoco-test-box")[1]
    with pytest.raises(bookspin.Error) as raised:
        bookspin.flipcheck.judge("mujoco-test-box", arrays["t"], arrays["q"],
                                 arrays["omega_world"], motion="m\ud800x")
    # The npm package's judge() says this very line (tests/npm/index_test.mjs); it wrote the
    # label "m\U00010078", the x taken into the surrogate.
    assert str(raised.value) == ('flipcheck.judge: motion: "m\\ud800x" holds a lone surrogate '
                                 '(U+D800) at character 2: no UTF-8 text holds one')
    with pytest.raises(bookspin.Error, match=r'^tosses: "a\\udfffb" holds a lone surrogate '
                                             r'\(U\+DFFF\) at character 2'):
        bookspin.fit("m.csv", tosses="a\udfffb")


def test_a_nul_in_a_path_is_named_not_the_path_cut_at_it(bookspin, tmp_path):
    # The OS takes a path up to its NUL: "still.csv\0x" opened still.csv, and a missing one was
    # said with its name cut at the NUL.
    (tmp_path / "still.csv").write_text(STILL)
    with pytest.raises(bookspin.Error) as raised:
        bookspin.fit(str(tmp_path / "still.csv") + "\0x")
    assert str(raised.value) == (f"recording: holds a NUL byte at character "
                                 f"{len(str(tmp_path / 'still.csv')) + 1} (no file's name holds one)")
    with pytest.raises(bookspin.Error, match="^out: holds a NUL byte at character 2"):
        bookspin.render(SCENARIO_DIR / "mujoco-test-box.toml", "a\0b", progress=False)


def test_a_loop_of_symbolic_links_is_said_so_at_every_door(bookspin, tmp_path):
    # It was "no such file" at the command line and in Python, a loop at npx.
    loop = tmp_path / "loop.csv"
    loop.symlink_to(tmp_path / "loop.csv")
    _, stderr = run_cli("fit", loop, "-o", tmp_path / "out", expect=2)
    assert cli_error_line(stderr) == f"{loop}: its symbolic links make a loop"
    with pytest.raises(bookspin.Error) as raised:
        bookspin.fit(loop)
    assert str(raised.value) == cli_error_line(stderr)
    kit = tmp_path / "kit"
    run_cli("flipcheck", "export", SCENARIO_DIR / "mujoco-test-box.toml", "-o", kit)
    _, stderr = run_cli("flipcheck", "judge", kit / "mujoco-test-box.json", loop, "-o",
                        tmp_path / "judged", expect=2)
    assert cli_error_line(stderr) == (f"{loop}: cannot read the motion file: its symbolic links "
                                      "make a loop"), stderr
