"""What the class server's tests share with the Python module's (tests/python/conftest.py:
the module fixture, the bookspin program, the source tree, the command-line runner and the CSV
readers), loaded from there by its path so that one file holds them; the class's own helpers
are class_server.py and class_start_shared.py beside this file."""
import importlib.util
import pathlib

_spec = importlib.util.spec_from_file_location(
    "bookspin_python_conftest",
    pathlib.Path(__file__).resolve().parents[2] / "tests" / "python" / "conftest.py")
_shared = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_shared)

SOURCE_DIR = _shared.SOURCE_DIR
EXE = _shared.EXE
bookspin = _shared.bookspin
run_cli = _shared.run_cli
cli_error_line = _shared.cli_error_line
read_csv = _shared.read_csv
