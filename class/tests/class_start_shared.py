"""What the class server's start tests share (class/tests/test_class_start.py and
test_class_stays.py): the refusal's one line, a folder's listing, whether network namespaces
can be made here, and the fixtures: a stand-in page, a PostgreSQL of the tests' own, servers
stopped at a test's end."""
import os
import pathlib
import shutil
import subprocess
import tempfile

import pytest

from class_server import Postgres, in_ci

ERROR = "bookspin-class: error: "


def one_error_line(status, stdout, stderr, option, expected_status=2):
    """The refusal's one line (after "bookspin-class: error: "), checked: the exit status, one
    line naming `option`, nothing on stdout."""
    assert status == expected_status, (status, stdout, stderr)
    lines = stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(ERROR), stderr
    assert option in lines[0], (option, lines[0])
    assert stdout == "", stdout
    return lines[0][len(ERROR):]


def listing(folder):
    """Every path under `folder` (relative), or None where it does not exist."""
    folder = pathlib.Path(folder)
    if not folder.exists():
        return None
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


def namespace_problem():
    """Why network namespaces cannot be made here, or None; and whether they should be."""
    if shutil.which("ip") is None:
        return "no `ip` (iproute2)", False
    name = f"bkprobe{os.getpid()}"
    done = subprocess.run(["ip", "netns", "add", name], capture_output=True, text=True)
    if done.returncode:
        capabilities = pathlib.Path("/proc/self/status").read_text()
        effective = int(capabilities.split("CapEff:")[1].split()[0], 16)
        should = os.geteuid() == 0 and bool(effective & (1 << 21))  # CAP_SYS_ADMIN
        return f"`ip netns add` failed: {done.stderr.strip()}", should
    subprocess.run(["ip", "netns", "del", name], capture_output=True)
    return None, False


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    """A stand-in for explorer.html (the phones' page is the page's own tests' business)."""
    path = tmp_path_factory.mktemp("page") / "explorer.html"
    path.write_text("<!doctype html><title>bookspin explorer</title><p>lab</p>\n")
    return path


@pytest.fixture(scope="module")
def postgres():
    folder = pathlib.Path(tempfile.mkdtemp(prefix="bookspin-pg-"))
    server = Postgres(folder)
    why = server.start()
    if why:
        server.stop()
        if in_ci():
            pytest.fail(f"PostgreSQL could not start: {why}")
        yield why
        return
    yield server
    server.stop()
    shutil.rmtree(folder, ignore_errors=True)


@pytest.fixture
def servers():
    """servers(Server) -> the server, stopped at the test's end."""
    made = []

    def keep(server):
        made.append(server)
        return server

    yield keep
    for server in made:
        server.stop()
