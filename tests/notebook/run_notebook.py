"""Executes a notebook top to bottom as `make test` does (docs/python.md, "The notebook"):
Debian's `jupyter nbconvert --to notebook --execute`, the kernel Debian's python3 (the one the
module is built for) with BUILD/python on its path; the executed copy and each picture it
shows (PNG, for a person to look at) go to BUILD/notebooks/, nothing into the source tree.
Fails on an error in any cell (the notebooks assert what they show) or a notebook that shows
no picture. Exit 77 (skipped) where nbconvert, ipykernel or matplotlib is missing; a failure
under CI=true.
Usage: run_notebook.py SOURCE_DIR BINARY_DIR NOTEBOOK"""
import base64
import json
import os
import pathlib
import subprocess
import sys
import time

source, binary, notebook = (pathlib.Path(a).resolve() for a in sys.argv[1:4])
missing = [m for m in ("nbconvert", "ipykernel", "matplotlib")
           if subprocess.run([sys.executable, "-c", f"import {m}"], capture_output=True).returncode]
if missing:
    print(f"run_notebook: {sys.executable} lacks {', '.join(missing)} (jupyter-nbconvert, "
          "python3-ipykernel, python3-matplotlib: scripts/install-deps.sh)")
    sys.exit(1 if os.environ.get("CI") == "true" else 77)

out = binary / "notebooks"
# The kernel `python3` the notebooks name, this very interpreter, ahead of any other kernel
# spec of that name (a user's, another Python's): JUPYTER_PATH comes first.
spec = out / "jupyter" / "kernels" / "python3"
spec.mkdir(parents=True, exist_ok=True)
(spec / "kernel.json").write_text(json.dumps({
    "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
    "display_name": "Python 3 (bookspin test)", "language": "python"}))
env = dict(os.environ, PYTHONPATH=str(binary / "python"), JUPYTER_PATH=str(out / "jupyter"),
           JUPYTER_CONFIG_DIR=str(out / "config"), JUPYTER_RUNTIME_DIR=str(out / "runtime"),
           IPYTHONDIR=str(out / "ipython"), MPLCONFIGDIR=str(out / "matplotlib"),
           PYTHONDONTWRITEBYTECODE="1", PYDEVD_DISABLE_FILE_VALIDATION="1")
env.pop("DISPLAY", None)
env.pop("MPLBACKEND", None)  # the kernel's inline backend draws the pictures into the notebook

before = sorted(p.name for p in notebook.parent.iterdir())
started = time.monotonic()
subprocess.run([sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute",
                "--ExecutePreprocessor.kernel_name=python3", "--ExecutePreprocessor.timeout=120",
                "--output-dir", str(out), str(notebook)], env=env, check=True, cwd=out)
seconds = time.monotonic() - started
assert sorted(p.name for p in notebook.parent.iterdir()) == before, "wrote into the source tree"

executed = json.loads((out / notebook.name).read_text())
pictures = 0
for i, cell in enumerate(executed["cells"]):
    if cell["cell_type"] != "code":
        continue
    assert cell["execution_count"] is not None, f"cell {i} did not run"
    for output in cell["outputs"]:
        assert output["output_type"] != "error", (i, output.get("evalue"))
        png = output.get("data", {}).get("image/png")
        if png:
            pictures += 1
            (out / f"{notebook.stem}-cell{i}-{pictures}.png").write_bytes(base64.b64decode(png))
assert pictures > 0, f"{notebook.name} shows no picture"
print(f"run_notebook: {notebook.relative_to(source)} ran in {seconds:.1f} s, {pictures} "
      f"picture(s) in {out}")
