"""The wheel as an engine's test suite meets it (docs/python.md, "The wheel"; docs/flipcheck.md,
"In your engine's tests"): BUILD/dist/bookspin-VERSION-cp311-*.whl installed offline into a
fresh environment made with the system's packages, then examples/flipcheck-pytest/ copied into
an empty folder and run there by pytest from that environment: the RK4 passes, the Euler step
fails with its reason. Nothing comes from the source tree or the build folder at run time: the
module and its scenarios are the environment's. Usage: wheel_example.py SOURCE_DIR BUILD_DIR"""
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile


def run(args, env, cwd=None, expect=0):
    done = subprocess.run([str(a) for a in args], env=env, cwd=cwd, capture_output=True,
                          text=True, timeout=300)
    if done.returncode != expect:
        sys.exit(f"FAIL: {args} exited {done.returncode}:\n{done.stdout}{done.stderr}")
    return done.stdout


def main(source, build):
    wheels = sorted((build / "dist").glob("bookspin-*-cp311-*.whl"))
    if len(wheels) != 1:
        sys.exit(f"FAIL: expected one wheel in {build / 'dist'}, found {[w.name for w in wheels]}")
    wheel = wheels[0]
    size = wheel.stat().st_size
    assert size < 30e6, f"the wheel is {size} bytes, over 30 MB"
    print(f"{wheel.name}: {size} bytes")
    with tempfile.TemporaryDirectory(prefix="bookspin-wheel-") as tmp:
        tmp = pathlib.Path(tmp)
        home = tmp / "home"
        home.mkdir()
        # No PYTHONPATH (the build folder must not be what imports), no pip configuration or
        # cache of the user's, and no network: a download would meet the discard port.
        proxy = "http://127.0.0.1:9"
        env = {k: v for k, v in os.environ.items()
               if k != "PYTHONPATH" and not k.startswith("PIP_") and not k.lower().endswith("_proxy")}
        env.update(HOME=str(home), PIP_CONFIG_FILE=os.devnull, PIP_CACHE_DIR=str(home / "cache"),
                   PIP_DISABLE_PIP_VERSION_CHECK="1", PYTHONDONTWRITEBYTECODE="1",
                   http_proxy=proxy, https_proxy=proxy, HTTP_PROXY=proxy, HTTPS_PROXY=proxy)
        venv = tmp / "venv"
        run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", venv], env)
        shutil.copy(wheel, tmp / wheel.name)  # the wheel alone, as a user downloads it
        run([venv / "bin" / "pip", "install", "--no-index", tmp / wheel.name], env)
        project = tmp / "my-engine"
        shutil.copytree(source / "examples" / "flipcheck-pytest", project)
        python = venv / "bin" / "python"
        lines = run([python, "-c", "import bookspin; print(bookspin.__file__); "
                     "print(bookspin.flipcheck.scenario_dir); "
                     "print(','.join(bookspin.flipcheck.scenarios()))"], env, cwd=project).splitlines()
        for path in lines[:2]:
            assert pathlib.Path(path).is_relative_to(venv), f"{path} is not the environment's"
        expected = ",".join(sorted(p.stem for p in (source / "scenes" / "flipcheck").glob("*.toml")))
        assert lines[2] == expected, (lines[2], expected)
        out = run([python, "-m", "pytest", "-q", "-p", "no:cacheprovider", "test_engine.py"], env,
                  cwd=project)
        print(out)
        assert "2 passed" in out, out
    print("PASS: the wheel installed offline and ran examples/flipcheck-pytest/")


if __name__ == "__main__":
    main(pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve())
