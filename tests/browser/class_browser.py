"""The real class server for the browser tests and the class's benchmark (docs/class.md): started
on 127.0.0.1 by class/tests/class_server.py's Server with a class of its own, its certificate
trusted by Chromium through its public key's hash (nothing else ignored), and its SQLite store
read beside it."""
import base64
import contextlib
import hashlib
import os
import shutil
import sqlite3
import sys
import tempfile
from pathlib import Path

from browser import missing


def class_packages(source, binary):
    """Puts the class server's tests (class/tests: class_server.py) and this build's module on
    the path, for this process and the servers it starts; missing() where the server's packages
    are not installed."""
    os.environ["BOOKSPIN_SOURCE_DIR"] = str(source)
    os.environ["PYTHONPATH"] = os.pathsep.join([str(binary / "python"),
                                                os.environ.get("PYTHONPATH", "")])
    sys.path[:0] = [str(source / "class" / "tests"), str(binary / "python")]
    try:
        import aiohttp  # noqa: F401
        import cryptography  # noqa: F401
        import segno  # noqa: F401
    except ImportError as error:
        missing(f"the class server's packages ({error}): scripts/install-deps.sh")


class RealServer:
    """The class server (class/bookspin_class, docs/class.md) started on 127.0.0.1 with a class
    of its own by class/tests/class_server.py's Server, serving the page built for this test:
    its address, code, the switch that makes Chromium trust its certificate (its public key's
    hash: nothing else ignored), and what its store holds, read beside it. `extra`: more of the
    server's switches (a benchmark's higher --rate)."""

    def __init__(self, source, binary, page_file, extra=()):
        class_packages(source, binary)
        from cryptography import x509
        from cryptography.hazmat.primitives import serialization
        from class_server import Server
        self.work = Path(tempfile.mkdtemp(prefix="bookspin-phone-in-class-"))
        self.server = Server(self.work / "data", page_file, extra=extra).start()
        self.code = self.server.code
        self.url = f"https://127.0.0.1:{self.server.port}/"
        cert = x509.load_pem_x509_certificate((self.work / "data" / "tls" / "server.pem").read_bytes())
        spki = cert.public_key().public_bytes(serialization.Encoding.DER,
                                              serialization.PublicFormat.SubjectPublicKeyInfo)
        self.trust = "--ignore-certificate-errors-spki-list=" + base64.b64encode(hashlib.sha256(spki).digest()).decode()

    def query(self, statement, *args):
        with contextlib.closing(sqlite3.connect(str(self.work / "data" / "class.sqlite3"))) as db:
            return db.execute(statement, args).fetchall()

    def held(self):
        """Every toss the store holds for the class, in the order stored: {toss, name, csv}."""
        return [{"toss": t, "name": n, "csv": c} for t, n, c in
                self.query("SELECT toss, name, csv FROM tosses WHERE class_code = ? ORDER BY seq", self.code)]

    def students(self):
        return [n for (n,) in self.query("SELECT name FROM students WHERE class_code = ? ORDER BY joined", self.code)]

    def pooled(self, recordings):
        """The class's pooled fit once it holds `recordings` recordings: {ratios, sigma, …}."""
        return self.server.fitted_state(recordings)["pooled"]

    def close(self):
        self.server.stop()
        shutil.rmtree(self.work, ignore_errors=True)
