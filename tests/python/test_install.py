"""The offline install of docs/python.md: a virtual environment made with the system's
packages (numpy from Debian), the build's module folder put on its path by a .pth file; then
`import bookspin` works from any folder, nothing downloaded."""
import os
import pathlib
import subprocess
import sys


def test_a_venv_with_the_pth_line_imports_bookspin_from_anywhere(bookspin, tmp_path):
    module_dir = pathlib.Path(bookspin.__file__).parent
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip",
                    str(venv)], check=True)
    python = venv / "bin" / "python"
    purelib = subprocess.run([python, "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                             check=True, capture_output=True, text=True).stdout.strip()
    (pathlib.Path(purelib) / "bookspin.pth").write_text(f"{module_dir}\n")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    done = subprocess.run(
        [python, "-c", "import bookspin; print(bookspin.__file__); "
         "print(bookspin.exact_motion([1, 2, 3], [0, 1, 0.01], [0.0, 1.0])['q'].shape)"],
        cwd=elsewhere, env=env, check=True, capture_output=True, text=True)
    lines = done.stdout.splitlines()
    assert pathlib.Path(lines[0]).parent == module_dir
    assert lines[1] == "(2, 4)"
