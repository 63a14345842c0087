"""The teacher's data folder, --data (docs/class.md, "What is kept"): made readable by the
teacher's account alone (0700, its files 0600), served by one server at a time (a lock file,
DATA/server.lock, held with fcntl.flock while the server runs), and left as it was found when
a start cannot serve (what the start made is removed). It also holds the teacher's address
(DATA/teacher-address.txt, with the key) and the code of the class it serves
(DATA/class-taught.txt)."""
import fcntl
import os
import pathlib
import shutil

LOCK = "server.lock"
TEACHER_ADDRESS = "teacher-address.txt"
TAUGHT = "class-taught.txt"
# The files a server writes into DATA (and everything under DATA/tls/): what a start that
# cannot serve removes again when it made them.
OWN_FILES = ("class.sqlite3", "class.sqlite3-wal", "class.sqlite3-shm", "class.sqlite3-journal",
             LOCK, TEACHER_ADDRESS, TAUGHT)


class InUse(Exception):
    """Another server holds the folder's lock; `pid` is the process it wrote, or None."""

    def __init__(self, pid):
        super().__init__(pid)
        self.pid = pid


def write_private(path, data):
    """Writes `data` (bytes, or str as UTF-8) to `path`, readable by this account alone (0600),
    whole or not at all (a temporary file renamed over it). Raises OSError (a full disk)."""
    path = pathlib.Path(path)
    temporary = path.with_name(path.name + ".part")
    if isinstance(data, str):
        data = data.encode("utf-8")
    try:
        descriptor = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
        with os.fdopen(descriptor, "wb") as file:
            file.write(data)
            file.flush()
            os.fsync(file.fileno())
        os.chmod(temporary, 0o600)
        os.replace(temporary, path)
    except OSError as error:
        temporary.unlink(missing_ok=True)
        raise OSError(error.errno, error.strerror, str(path)) from None
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise


class DataFolder:
    """DATA: open() makes and locks it, undo() removes what this start made."""

    def __init__(self, path):
        self.path = pathlib.Path(path)
        self.made = False      # the folder itself made by this start
        self.found = set()     # the server's own files there before this start
        self.lock_file = None  # the open lock file, held while the server runs
        self.opened = False    # open() noted what the folder held
        self.saved = {}        # the small files' contents then (the addresses, tls/), by name

    def _own_files(self):
        names = {name for name in OWN_FILES if (self.path / name).exists()}
        tls = self.path / "tls"
        if tls.is_dir():
            names.add("tls")
            names.update(f"tls/{p.name}" for p in tls.iterdir())
        return names

    def open(self):
        """Makes the folder where it is missing (0700), notes what it holds, and takes its lock.
        An existing folder that holds a store or certificates is made 0700 too (one made by an
        earlier version was 0755, its files 0644: they are made 0600); another folder keeps its
        mode. Raises
        InUse where another server holds the lock, OSError where the folder cannot be made."""
        if not self.path.exists():
            self.path.mkdir(mode=0o700, parents=True)
            self.made = True
        self.found = self._own_files()
        self.saved = {name: (self.path / name).read_bytes() for name in self.found
                      if name in (TEACHER_ADDRESS, TAUGHT) or name.startswith("tls/")}
        self.opened = True
        if self.made or self.found & {"class.sqlite3", "tls"}:
            self.path.chmod(0o700)
        for name in self.found:
            (self.path / name).chmod(0o700 if name == "tls" else 0o600)
        descriptor = os.open(self.path / LOCK, os.O_RDWR | os.O_CREAT, 0o600)
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            text = os.read(descriptor, 32).decode("ascii", "replace").strip()
            os.close(descriptor)
            raise InUse(int(text) if text.isdigit() else None) from None
        os.ftruncate(descriptor, 0)
        os.pwrite(descriptor, f"{os.getpid()}\n".encode("ascii"), 0)
        self.lock_file = descriptor

    def undo(self):
        """Removes what this start made (the folder, or the server's files that were not there
        before), writes back the small files it rewrote (the teacher's address, the class
        taught, the certificates) and lets go of the lock."""
        if self.lock_file is not None:
            os.close(self.lock_file)
            self.lock_file = None
        if not self.opened:
            return
        if self.made:
            shutil.rmtree(self.path, ignore_errors=True)
            return
        for name in sorted(self._own_files() - self.found, reverse=True):  # tls/ files first
            path = self.path / name
            if path.is_dir():
                shutil.rmtree(path, ignore_errors=True)
            else:
                path.unlink(missing_ok=True)
        for name, data in self.saved.items():  # rewritten by this start: written back
            path = self.path / name
            if not path.is_file() or path.read_bytes() != data:
                write_private(path, data)

    def taught(self):
        """The code of the class this folder served last, or None."""
        try:
            return (self.path / TAUGHT).read_text(encoding="utf-8").strip() or None
        except OSError:
            return None

    def write(self, name, text):
        write_private(self.path / name, text)
        return self.path / name
