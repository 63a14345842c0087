"""Committed notebooks carry no outputs and no execution counts (docs/python.md, "The
notebook"): what git holds is the code and the words; `make test` executes each into the build
folder (tests/notebook/run_notebook.py). Usage: stripped_test.py SOURCE_DIR"""
import json
import pathlib
import subprocess
import sys


def offences(notebook, name):
    """Each code cell's outputs and execution count, one line each."""
    found = []
    for i, cell in enumerate(notebook.get("cells", [])):
        if cell.get("cell_type") != "code":
            continue
        if cell.get("outputs"):
            found.append(f"{name}: cell {i}: {len(cell['outputs'])} output(s)")
        if cell.get("execution_count") is not None:
            found.append(f"{name}: cell {i}: execution_count {cell['execution_count']}")
    return found


def committed_notebooks(source):
    """The notebooks git holds or would add; every one under examples/ where the tree is no git checkout."""
    done = subprocess.run(["git", "-C", str(source), "ls-files", "-z", "--cached", "--others",
                           "--exclude-standard", "--", "*.ipynb"],
                          capture_output=True, text=True)
    if done.returncode == 0:
        return [source / name for name in done.stdout.split("\0") if name]
    return sorted((source / "examples").rglob("*.ipynb"))


def main():
    source = pathlib.Path(sys.argv[1])
    # The check itself finds an output and a count, and passes a stripped cell.
    cell = {"cell_type": "code", "source": "1", "metadata": {}}
    assert len(offences({"cells": [dict(cell, outputs=[{"output_type": "stream"}],
                                        execution_count=3)]}, "x")) == 2
    assert offences({"cells": [dict(cell, outputs=[], execution_count=None)]}, "x") == []

    notebooks = committed_notebooks(source)
    if not notebooks:
        sys.exit("stripped_test: no notebook found (examples/intermediate-axis.ipynb)")
    found = []
    for path in notebooks:
        found += offences(json.loads(path.read_text()), path.relative_to(source))
    if found:
        print("\n".join(found))
        sys.exit(f"stripped_test: {len(found)} output(s) or count(s) in committed notebooks: "
                 "jupyter nbconvert --clear-output --inplace FILE strips them")
    print(f"stripped_test: {len(notebooks)} notebook(s) without outputs")


if __name__ == "__main__":
    main()
