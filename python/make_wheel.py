"""Packs BUILD/python/ (the module CMake built, its stub and its scenarios) into a wheel,
BUILD/dist/bookspin-VERSION-cp311-cp311-linux_x86_64.whl, offline: pip's wheel command with
Debian's setuptools and wheel, no index, no build isolation (docs/python.md, "The wheel").
The wheel is written beside in a temporary folder and moved into place whole; an older
bookspin wheel in BUILD/dist/ is removed. Usage: make_wheel.py BUILD/python BUILD/dist VERSION"""
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile


def main(package, dist, version):
    package, dist = pathlib.Path(package).resolve(), pathlib.Path(dist).resolve()
    dist.mkdir(parents=True, exist_ok=True)
    env = {k: v for k, v in os.environ.items() if not k.startswith("PIP_")}
    env.update(PIP_CONFIG_FILE=os.devnull, PIP_DISABLE_PIP_VERSION_CHECK="1",
               PIP_NO_CACHE_DIR="1", PYTHONDONTWRITEBYTECODE="1")
    with tempfile.TemporaryDirectory(dir=dist, prefix=".wheel-") as scratch:
        done = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-build-isolation",
                               "--no-index", "--no-deps", "-q", "-w", scratch, str(package)],
                              env=env, capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"make_wheel: pip wheel failed:\n{done.stdout}{done.stderr}")
        made = list(pathlib.Path(scratch).glob("bookspin-*.whl"))
        if len(made) != 1 or not made[0].name.startswith(f"bookspin-{version}-"):
            sys.exit(f"make_wheel: expected one bookspin-{version}-*.whl, pip made "
                     f"{[p.name for p in made]}")
        for old in dist.glob("bookspin-*.whl"):
            old.unlink()
        target = dist / made[0].name
        shutil.move(made[0], target)
    print(f"make_wheel: {target} ({target.stat().st_size} bytes)")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
