"""What the class server's tests share (class/tests/test_class_server.py, docs/class.md): a
real `bookspin-class` server started on 127.0.0.1 (python3 -m bookspin_class, the module
BUILD/python/bookspin and class/bookspin_class), a real PostgreSQL started in a scratch folder
(initdb + pg_ctl as an unprivileged user, on a unix socket), plain HTTPS clients (http.client,
verifying the server's certificate against the class's own CA), and the store's row counts."""
import contextlib
import http.client
import json
import os
import pathlib
import pwd
import queue
import shutil
import signal
import socket
import sqlite3
import ssl
import subprocess
import sys
import threading
import time
import uuid

SOURCE_DIR = pathlib.Path(
    os.environ.get("BOOKSPIN_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))

REAL = SOURCE_DIR.parent / "shared" / "recordings-real" / "dvarkian-2022-05-03"
PG_BIN = pathlib.Path("/usr/lib/postgresql/15/bin")


def in_ci():
    return os.environ.get("CI", "").lower() in ("1", "true", "yes")




def require_real():
    """Skips a test where the real recordings are not beside the checkout (a failure under
    CI=true, where they are)."""
    import pytest
    if not REAL.is_dir():
        if in_ci():
            pytest.fail(f"no real recordings at {REAL} (CI has them)")
        pytest.skip(f"no real recordings at {REAL} (../shared/recordings-real/ beside the "
                    "checkout)")

def require_packages(*names):
    """Imports the class server's packages a test module needs (Debian's, from
    scripts/install-deps.sh); a module without them is skipped, saying which, and fails under
    CI=true. Call at a test module's top, before importing what needs them."""
    import importlib
    import pytest
    for name in names:
        try:
            importlib.import_module(name)
        except ImportError as missing_package:
            if in_ci():
                raise
            pytest.skip(f"the class server's packages are missing ({missing_package}): "
                        "scripts/install-deps.sh", allow_module_level=True)

def real_csv(name):
    """The CSV text of a real recording (its Raw Data.csv, or the single-sensor export)."""
    folder = REAL / name
    files = [folder / "Raw Data.csv"] if (folder / "Raw Data.csv").is_file() else \
        sorted(folder.glob("*.csv"))
    return files[0].read_text(encoding="utf-8")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Server:
    """A bookspin-class process on 127.0.0.1, its printed lines and code, the teacher's key
    (read from DATA/teacher-address.txt: the server never prints it), and clients.

    `address` is the --address given (None: none, the server picks one); `host` the --host;
    `prefix` a command the server runs under (e.g. `ip netns exec NAME`); `env` variables added
    to the server's environment; `seen_at` the data folder as this process sees it, where the
    server sees it elsewhere (a mount namespace of its own)."""

    def __init__(self, data, page, postgres=None, extra=(), port=None, address="127.0.0.1",
                 host="127.0.0.1", prefix=(), env=None, seen_at=None):
        self.data, self.page, self.postgres = pathlib.Path(data), page, postgres
        self.seen_at = pathlib.Path(seen_at or data)
        self.extra, self.port = list(extra), port or free_port()
        self.address, self.host, self.prefix = address, host, list(prefix)
        self.env = dict(env or {})
        self.process = None

    def command(self, new=False):
        """The server's command line."""
        args = [*self.prefix, sys.executable, "-m", "bookspin_class", "--data", str(self.data),
                "--host", self.host, "--port", str(self.port), "--page", str(self.page)]
        if self.address is not None:
            args += ["--address", self.address]
        args += self.extra
        if self.postgres:
            args += ["--postgres", self.postgres]
        if new:
            args.append("--new")
        return args

    def environment(self):
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join(
            [str(SOURCE_DIR / "class")] + [p for p in env.get("PYTHONPATH", "").split(os.pathsep)
                                            if p])
        env.update(self.env)
        return env

    def start(self, new=False):
        """Starts the server and reads its lines up to "Ctrl-C stops …" (a server of before
        that line: up to its certificate's); its output goes on into self.output."""
        self.process = subprocess.Popen(self.command(new), stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True,
                                        env=self.environment())
        self.output, arrived = [], queue.Queue()

        def drain(stream):
            for line in stream:
                self.output.append(line.rstrip("\n"))
                arrived.put(line.rstrip("\n"))
            arrived.put(None)

        threading.Thread(target=drain, args=(self.process.stdout,), daemon=True).start()
        lines, self.before = [], []
        while not lines or not lines[-1].startswith("  Ctrl-C stops"):
            last = lines and lines[-1].startswith("  certificate:")
            try:
                line = arrived.get(timeout=5 if last else 600)
            except queue.Empty:
                break
            if line is None:
                raise AssertionError(f"the server ended: {lines} {self.process.stderr.read()}")
            if line.startswith("bookspin-class: class ") or lines:
                lines.append(line)
            else:
                self.before.append(line)
        self.lines = lines
        self.code = self.line("class code:").split()[-1]
        address_file = self.seen_at / "teacher-address.txt"
        if address_file.is_file():
            self.key = address_file.read_text(encoding="utf-8").strip().split("key=")[1]
        else:  # a server of before the key left the terminal (test_class_start.py says so)
            self.key = self.line("projector:").split("key=")[1].split()[0]
        self.context = ssl.create_default_context(
            cafile=str(self.seen_at / "tls" / "bookspin-class-ca.pem"))
        return self

    def run(self, new=False, timeout=60):
        """Runs the server's command to its end (one that is refused): (exit status, stdout,
        stderr)."""
        done = subprocess.run(self.command(new), capture_output=True, text=True,
                              env=self.environment(), timeout=timeout)
        return done.returncode, done.stdout, done.stderr

    def line(self, label):
        """The printed line that begins with `label` (after its indent), without the label."""
        found = [line.strip()[len(label):].strip() for line in self.lines
                 if line.strip().startswith(label)]
        assert found, (label, self.lines)
        return found[0]

    def kill(self):
        self.process.send_signal(signal.SIGKILL)
        self.process.wait(timeout=30)

    def stop(self):
        if self.process and self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.kill()

    def request(self, method, path, body=None, token=None, raw=None, headers=None, timeout=60):
        """(status, decoded JSON or bytes) of one HTTPS request on a fresh connection."""
        connection = http.client.HTTPSConnection("127.0.0.1", self.port, context=self.context,
                                                 timeout=timeout)
        try:
            sent = dict(headers or {})
            if token:
                sent["Authorization"] = f"Bearer {token}"
            data = raw if raw is not None else (
                None if body is None else json.dumps(body, ensure_ascii=False).encode("utf-8"))
            if data is not None:
                sent.setdefault("Content-Type", "application/json")
            connection.request(method, path, body=data, headers=sent)
            response = connection.getresponse()
            payload = response.read()
            if response.getheader("Content-Type", "").startswith("application/json"):
                payload = json.loads(payload.decode("utf-8"))
            return response.status, payload
        finally:
            connection.close()

    def join(self, name, code=None):
        status, answer = self.request("POST", f"/api/class/{code or self.code}/join",
                                      {"name": name})
        assert status == 201, answer
        return answer["token"]

    def post_toss(self, token, csv, name="toss", toss=None, code=None, timeout=60):
        body = {"toss": toss or str(uuid.uuid4()), "name": name,
                "recorded_at": "2022-05-03T12:13:01Z", "csv": csv}
        return self.request("POST", f"/api/class/{code or self.code}/tosses", body, token=token,
                            timeout=timeout)

    def state(self, code=None, key=None):
        status, answer = self.request("GET", f"/api/class/{code or self.code}/state",
                                      token=key or self.key)
        assert status == 200, answer
        return answer

    def fitted_state(self, recordings, timeout=600):
        """The class's state once its pooled fit holds `recordings` recordings and is idle."""
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            state = self.state()
            pooled = state["pooled"]
            if not pooled["fitting"] and pooled["recordings"] == recordings and \
                    (pooled["ratios"] is not None or pooled["error"]):
                return state
            time.sleep(0.5)
        raise AssertionError(f"no fit of {recordings} recordings within {timeout} s: {state}")

    def counts(self):
        """Rows in each table of the store, read beside the server."""
        if self.postgres:
            import psycopg
            with psycopg.connect(self.postgres) as connection:
                return {t: connection.execute(f"SELECT COUNT(*) FROM {t}").fetchone()[0]
                        for t in ("classes", "students", "tosses")}
        with contextlib.closing(sqlite3.connect(str(self.seen_at / "class.sqlite3"))) as connection:
            return {t: connection.execute(f"SELECT COUNT(*) FROM {t}").fetchone()[0]
                    for t in ("classes", "students", "tosses")}

    def execute(self, statement):
        """Runs one statement on the store (the tests' way to age a class)."""
        if self.postgres:
            import psycopg
            with psycopg.connect(self.postgres) as connection:
                connection.execute(statement)
            return
        with contextlib.closing(sqlite3.connect(str(self.seen_at / "class.sqlite3"))) as connection:
            connection.execute(statement)
            connection.commit()


class Postgres:
    """A PostgreSQL 15 of the tests' own: initdb and pg_ctl in a scratch folder, run as the
    user `nobody` when the tests run as root (PostgreSQL refuses root), listening on a unix
    socket in that folder only; databases made per server."""

    def __init__(self, folder):
        self.folder = pathlib.Path(folder)
        self.user = None
        self.count = 0

    def _as_user(self, *args):
        command = [str(a) for a in args]
        if os.geteuid() == 0:
            command = ["runuser", "-u", "nobody", "--", *command]
        return subprocess.run(command, capture_output=True, text=True, timeout=120)

    def start(self):
        """None when started; otherwise the reason it could not start."""
        if not (PG_BIN / "initdb").is_file():
            return "PostgreSQL 15 is not installed (scripts/install-deps.sh: postgresql-15)"
        self.folder.mkdir(parents=True, exist_ok=True)
        if os.geteuid() == 0:
            if shutil.which("runuser") is None:
                return "running as root without runuser: PostgreSQL cannot start"
            os.chmod(self.folder, 0o777)
        self.user = "nobody" if os.geteuid() == 0 else pwd.getpwuid(os.geteuid()).pw_name
        done = self._as_user(PG_BIN / "initdb", "-D", self.folder / "db", "-A", "trust", "-U",
                             self.user, "-E", "UTF8", "--no-sync")
        if done.returncode:
            return f"initdb failed: {done.stderr.strip()[-300:]}"
        done = self._as_user(PG_BIN / "pg_ctl", "-D", self.folder / "db", "-l",
                             self.folder / "log", "-w", "-t", "60", "-o",
                             f"-k {self.folder} -c listen_addresses='' -c fsync=on", "start")
        if done.returncode:
            return f"pg_ctl start failed: {done.stderr.strip()[-300:]}"
        return None

    def new_database(self):
        import psycopg
        self.count += 1
        name = f"class{self.count}"
        with psycopg.connect(self.url("postgres"), autocommit=True) as connection:
            connection.execute(f"CREATE DATABASE {name}")
        return self.url(name)

    def url(self, database):
        return f"postgresql:///{database}?host={self.folder}&user={self.user}"

    def stop(self):
        self._as_user(PG_BIN / "pg_ctl", "-D", self.folder / "db", "-m", "immediate", "stop")


def restamped(csv, seconds):
    """A recording's CSV with every time `seconds` later: the same motion, other samples (so
    that one recording may stand for several phones' without being the same recording twice)."""
    lines = csv.splitlines()
    out = [lines[0]]
    for line in lines[1:]:
        cells = line.split(",")
        if cells and cells[0].strip():
            cells[0] = repr(float(cells[0].strip().strip('"')) + seconds)
        out.append(",".join(cells))
    return "\n".join(out) + "\n"
