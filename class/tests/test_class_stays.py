"""The class stays the class (docs/class.md, "The teacher's steps"): a start that cannot serve
writes nothing (a port in use, a host that does not resolve, a full disk at any step: a small
tmpfs in a mount namespace), a restart goes on with the class being taught, every class of a
store is listed and one chosen by its code, and a second server on a store in use is refused
(SQLite and PostgreSQL). Real servers, real HTTPS clients. The start itself:
test_class_start.py."""
import os
import pathlib
import shutil
import socket
import subprocess

import pytest

from class_server import require_packages  # noqa: E402

require_packages('aiohttp')

from class_server import Server, in_ci
from class_start_shared import (listing, namespace_problem, one_error_line, page,  # noqa: F401
                                postgres, servers)


# A start that cannot serve.

def test_a_start_that_cannot_serve_writes_nothing_and_the_class_goes_on(tmp_path, page,
                                                                      servers):
    data = tmp_path / "data"
    with socket.create_server(("127.0.0.1", 0)) as taken:
        port = taken.getsockname()[1]
        line = one_error_line(*Server(data, page, port=port).run(), "--port", 1)
        assert "in use" in line
    assert not data.exists()
    line = one_error_line(*Server(data, page, host="no-such-host.invalid").run(), "--host")
    assert "does not resolve" in line
    assert not data.exists()
    # A store with a class: a start that cannot serve changes nothing, and the next goes on.
    server = servers(Server(data, page)).start()
    code, key = server.code, server.key
    server.join("Anna")
    server.stop()
    before = listing(data), server.counts(), (data / "teacher-address.txt").read_text()
    with socket.create_server(("127.0.0.1", 0)) as taken:
        again = Server(data, page, port=taken.getsockname()[1])
        one_error_line(*again.run(), "--port", 1)
    one_error_line(*Server(data, page, host="no-such-host.invalid").run(new=True), "--host")
    assert (listing(data), server.counts(), (data / "teacher-address.txt").read_text()) == before
    server.start()
    assert server.lines[0].startswith(f"bookspin-class: class {code} goes on")
    assert (server.code, server.key) == (code, key)
    assert [s["name"] for s in server.state()["students"]] == ["Anna"]


class SmallDisk:
    """A tmpfs on `folder`, in a mount namespace a sleeping process holds: `prefix` runs a
    command in that namespace (nsenter), `view` is the folder as this process sees it (through
    /proc/PID/root), resize(kib) sets its size."""

    def __init__(self, folder):
        self.folder = pathlib.Path(folder)
        self.folder.mkdir()
        self.holder = subprocess.Popen(
            ["unshare", "--mount", "--propagation", "private", "sh", "-c",
             f"mount -t tmpfs -o size=64k tmpfs '{self.folder}' && echo ready && exec sleep 3600"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        ready = self.holder.stdout.readline()
        if ready.strip() != "ready":
            self.holder.wait()
            raise OSError(f"no tmpfs in a mount namespace: {self.holder.stderr.read().strip()}")
        self.prefix = ["nsenter", f"--mount=/proc/{self.holder.pid}/ns/mnt", "--"]
        self.view = pathlib.Path(f"/proc/{self.holder.pid}/root") / \
            self.folder.relative_to(self.folder.anchor)

    def resize(self, kib):
        subprocess.run([*self.prefix, "mount", "-o", f"remount,size={kib}k", str(self.folder)],
                       check=True, capture_output=True)

    def used_kib(self):
        stats = os.statvfs(self.view)
        return (stats.f_blocks - stats.f_bfree) * stats.f_frsize // 1024

    def close(self):
        self.holder.kill()
        self.holder.wait()


def attempt(server, new=False):
    """(None, the lines) where the server started (stopped again); (exit status, its stderr)
    where it ended instead."""
    try:
        server.start(new)
    except AssertionError as error:
        server.process.wait(timeout=60)
        return server.process.returncode, str(error).split("] ", 1)[1]
    server.stop()
    return None, server.lines


def contents(folder):
    """{path: bytes} of every file under `folder` but the lock file (it holds the last pid)."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in pathlib.Path(folder).rglob("*")
            if p.is_file() and p.name != "server.lock"}


def test_a_full_disk_at_any_step_of_a_start_writes_nothing(tmp_path, page):
    """The data folder on a tmpfs of 8 KiB, then 16, 24 … until the server starts: each start
    that ran out of space (at the store, the certificates, the class, the teacher's address)
    says so in one line and leaves the disk empty. Then a store with a class on a disk with
    0, 8, 16 … KiB free: a start of a new class for a new address (a new CA) that runs out of
    space leaves every file as it was, and the class goes on."""
    why, should = namespace_problem()
    if why or shutil.which("unshare") is None or shutil.which("nsenter") is None:
        if in_ci() and should:
            pytest.fail(f"a mount namespace should work here: {why}")
        pytest.skip(f"no mount namespace for a small tmpfs: {why or 'no unshare or nsenter'}")
    disk = SmallDisk(tmp_path / "disk")
    server = other = None
    try:
        server = Server(disk.folder / "data", page, prefix=disk.prefix,
                        seen_at=disk.view / "data")
        failures = []
        for size in range(8, 1024, 8):
            disk.resize(size)
            status, said = attempt(server)
            if status is None:
                break
            line = one_error_line(status, "", said, "", 1)
            assert listing(disk.view) == [], (size, line, listing(disk.view))
            failures.append(line)
        else:
            pytest.fail(f"the server did not start on 1 MiB: {failures[-1]}")
        code, key = server.code, server.key
        disk.resize(4096)
        server.start()
        server.join("Anna")
        server.stop()
        before = contents(disk.view)
        other = Server(disk.folder / "data", page, address="192.0.2.77", prefix=disk.prefix,
                       seen_at=disk.view / "data")
        for free in range(0, 1024, 8):
            disk.resize(disk.used_kib() + free)
            status, said = attempt(other, new=True)
            if status is None:
                break
            line = one_error_line(status, "", said, "", 1)
            assert contents(disk.view) == before, (free, line)
            failures.append(line)
        else:
            pytest.fail(f"the server did not start with 1 MiB free: {failures[-1]}")
        assert other.code != code and other.key != key and len(failures) > 1
    finally:
        for started in (server, other):
            if started is not None:
                started.stop()
        disk.close()
    kinds = {kind for kind in ("cannot open the store", "cannot write", "cannot store")
             for line in failures if kind in line}
    assert len(kinds) >= 2, failures  # several steps of the start ran out of space
    assert all("space" in line or "full" in line for line in failures), failures


# The class that goes on, and the one chosen.

def test_a_restart_goes_on_with_the_class_taught_and_any_class_can_be_chosen(tmp_path, page,
                                                                            servers):
    data = tmp_path / "data"
    first = servers(Server(data, page)).start()
    a, a_key = first.code, first.key
    first.join("Anna")
    first.stop()
    second = servers(Server(data, page)).start(new=True)
    b = second.code
    second.stop()
    assert a != b

    def listed():
        done = subprocess.run(Server(data, page, extra=["--list"]).command(), capture_output=True,
                              text=True, env=first.environment(), timeout=60)
        assert done.returncode == 0 and done.stderr == "", done.stderr
        return done.stdout.splitlines()

    lines = listed()
    assert lines[0].startswith("bookspin-class: 2 classes in SQLite ") and "--class" in lines[0]
    assert [line.split()[0] for line in lines[1:]] == [a, b]
    assert "1 student" in lines[1] and lines[2].endswith("(taught last)")
    # Chosen by its code (typed in lower case, with a space), it goes on with its key.
    chosen = servers(Server(data, page, extra=["--class", f"{a[:3].lower()} {a[3:].lower()}"]))
    chosen.start()
    assert chosen.lines[0].startswith(f"bookspin-class: class {a} goes on")
    assert chosen.key == a_key and [s["name"] for s in chosen.state()["students"]] == ["Anna"]
    assert chosen.request("GET", "/")[0] == 302
    chosen.stop()
    # A plain restart goes on with the class taught last, not the newest.
    plain = servers(Server(data, page)).start()
    assert plain.code == a and plain.key == a_key
    plain.stop()
    assert listed()[1].endswith("(taught last)")
    counts = plain.counts()
    one_error_line(*Server(data, page, extra=["--class", "ZZZZZZ"]).run(), "--class")
    one_error_line(*Server(data, page, extra=["--class", a]).run(new=True), "--class")
    assert plain.counts() == counts
    # A store not made yet is listed as empty, and not made.
    done = subprocess.run(Server(tmp_path / "none", page, extra=["--list"]).command(),
                          capture_output=True, text=True, env=first.environment(), timeout=60)
    assert done.returncode == 0 and "no classes" in done.stdout
    assert not (tmp_path / "none").exists()


@pytest.mark.parametrize("kind", ["sqlite", "postgres"])
def test_a_second_server_on_a_store_in_use_is_refused(tmp_path, page, servers, postgres, kind):
    url = None
    if kind == "postgres":
        if isinstance(postgres, str):
            pytest.skip(f"PostgreSQL could not start: {postgres}")
        url = postgres.new_database()
    data = tmp_path / "data"
    first = servers(Server(data, page, url)).start()
    first.join("Anna")
    before = listing(data), first.counts()
    # The same data folder, another port.
    line = one_error_line(*Server(data, page, url).run(), "--data", 1)
    assert "in use by another bookspin-class" in line
    assert f"process {first.process.pid}" in line
    assert (listing(data), first.counts()) == before
    assert [s["name"] for s in first.state()["students"]] == ["Anna"]
    if kind == "postgres":
        # Another data folder on the same database: the class being served is refused (the
        # first teacher's key goes nowhere); another class beside it is the teacher's own.
        other = tmp_path / "other"
        line = one_error_line(*Server(other, page, url).run(), "--postgres", 1)
        assert f"class {first.code} is served by another bookspin-class" in line
        assert not other.exists()
        beside = servers(Server(other, page, url)).start(new=True)
        assert beside.code != first.code and beside.key != first.key
        assert first.key not in (other / "teacher-address.txt").read_text()
