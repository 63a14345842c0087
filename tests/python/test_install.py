"""The install line of the README and docs/python.md, "Install", done in a temporary folder:

    /usr/bin/python3 -m venv --system-site-packages VENV
    VENV/bin/pip install --no-build-isolation --no-index BUILD/python

offline (no index, and any download would meet a proxy that answers nothing); then `import
bookspin` works from another folder, the build folder is left as it was, and `pip uninstall`
takes the module and its stub away again."""
import os
import pathlib
import subprocess
import sys

import pytest


@pytest.fixture(scope="module")
def offline_env(tmp_path_factory):
    """No PYTHONPATH (the build folder must not be what imports), no pip configuration or cache
    of the user's, and no network."""
    home = tmp_path_factory.mktemp("home")
    env = {k: v for k, v in os.environ.items()
           if k != "PYTHONPATH" and not k.startswith("PIP_") and not k.lower().endswith("_proxy")}
    proxy = "http://127.0.0.1:9"  # the discard port: a download would fail
    env.update(HOME=str(home), PIP_CONFIG_FILE=os.devnull, PIP_CACHE_DIR=str(home / "cache"),
               PIP_DISABLE_PIP_VERSION_CHECK="1", http_proxy=proxy, https_proxy=proxy,
               HTTP_PROXY=proxy, HTTPS_PROXY=proxy)
    return env


def run(args, env, cwd=None):
    done = subprocess.run([str(a) for a in args], env=env, cwd=cwd, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, (args, done.stdout, done.stderr)
    return done.stdout


def listing(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


def test_pip_installs_the_built_module_and_uninstalls_it(bookspin, tmp_path, offline_env):
    package = pathlib.Path(bookspin.__file__).parent  # BUILD/python
    venv = tmp_path / "venv"
    # sys.executable is Debian's /usr/bin/python3, the Python the module is built for.
    run([sys.executable, "-m", "venv", "--system-site-packages", venv], offline_env)
    before = listing(package)
    run([venv / "bin" / "pip", "install", "--no-build-isolation", "--no-index", package],
        offline_env)
    assert listing(package) == before, "pip wrote into the build's module folder"

    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    python = venv / "bin" / "python"
    lines = run([python, "-c", "import bookspin, pathlib; print(bookspin.__file__); "
                 "print(bookspin.exact_motion([1, 2, 3], [0, 1, 0.01], [0.0, 1.0])['q'].shape); "
                 "print(len(bookspin.flipcheck.scenarios()) > 0)"],
                offline_env, cwd=elsewhere).splitlines()
    installed = pathlib.Path(lines[0])
    assert installed.parent.is_relative_to(venv), installed
    assert installed.name == pathlib.Path(bookspin.__file__).name
    assert installed.read_bytes() == pathlib.Path(bookspin.__file__).read_bytes()  # copied
    stub = installed.parent / "bookspin.pyi"
    assert stub.read_text() == (package / "bookspin.pyi").read_text()
    assert lines[1:] == ["(2, 4)", "True"]
    shown = run([venv / "bin" / "pip", "show", "-f", "bookspin"], offline_env)
    assert "Name: bookspin" in shown and "bookspin.pyi" in shown

    run([venv / "bin" / "pip", "uninstall", "-y", "bookspin"], offline_env)
    assert not installed.exists() and not stub.exists()
    gone = subprocess.run([python, "-c", "import bookspin"], env=offline_env, cwd=elsewhere,
                          capture_output=True, text=True)
    assert gone.returncode != 0 and "No module named 'bookspin'" in gone.stderr
