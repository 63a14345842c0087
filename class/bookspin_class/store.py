"""The class's data (docs/class.md, "What is kept"): classes, students and tosses, in SQLite (a
file in the teacher's folder, the default) or PostgreSQL (by URL), one schema and one set of
statements for both. Each write is committed before it returns, so a toss a phone was told is
held survives a SIGKILL of the server. Times are seconds since the epoch (UTC)."""
import hashlib
import os
import secrets
import sqlite3
import threading
import time

SCHEMA = [
    """CREATE TABLE IF NOT EXISTS classes (
         code TEXT PRIMARY KEY,
         teacher_key TEXT NOT NULL UNIQUE,
         created DOUBLE PRECISION NOT NULL,
         next_seq INTEGER NOT NULL DEFAULT 0)""",
    """CREATE TABLE IF NOT EXISTS students (
         id TEXT PRIMARY KEY,
         class_code TEXT NOT NULL REFERENCES classes(code) ON DELETE CASCADE,
         token_sha256 TEXT NOT NULL UNIQUE,
         name TEXT NOT NULL,
         joined DOUBLE PRECISION NOT NULL)""",
    """CREATE TABLE IF NOT EXISTS tosses (
         toss TEXT PRIMARY KEY,
         class_code TEXT NOT NULL REFERENCES classes(code) ON DELETE CASCADE,
         student TEXT NOT NULL REFERENCES students(id) ON DELETE CASCADE,
         seq INTEGER NOT NULL,
         name TEXT NOT NULL,
         recorded_at TEXT NOT NULL,
         csv TEXT NOT NULL,
         csv_sha256 TEXT NOT NULL,
         recording_sha256 TEXT NOT NULL,
         samples_sha256 TEXT,
         received DOUBLE PRECISION NOT NULL,
         excluded TEXT,
         UNIQUE (class_code, seq))""",
]


# The PostgreSQL channel a server tells the others of a class's change on (NOTIFY, in the
# change's own transaction; docs/class.md, "A school's server"): "KIND CODE SENDER", KIND one
# of join, toss, exclude, end; SENDER the Store's `instance`.
CHANNEL = "bookspin_class"

# The first key of the PostgreSQL advisory locks that mark a class as served (claim_class),
# the second the hash of its code: "bksc" in ASCII.
CLASS_LOCK_SPACE = 0x626B7363


def recording_sha256(csv):
    """The SHA-256 of a toss's CSV text, as sent."""
    return hashlib.sha256(csv.encode("utf-8")).hexdigest()


def samples_sha256(recording):
    """The SHA-256 of a recording's samples as the pooled fit compares them (src/fit/pool.cpp,
    check_not_twice: the times and ω equal as numbers, whatever the CSV's line ends or number
    format): `recording` is bookspin.read_gyro_csv's {"t": (N,) s, "omega": (N, 3) rad/s}, hashed
    as float64 little-endian with −0 read as 0 (equal as numbers). One recording is held once
    per class."""
    import numpy
    digest = hashlib.sha256()
    for key in ("t", "omega"):
        array = numpy.ascontiguousarray(recording[key], dtype="<f8") + 0.0  # −0 + 0 is +0
        digest.update(f"{key}{array.shape}".encode("ascii"))
        digest.update(array.tobytes())
    return digest.hexdigest()


def read_samples_sha256(csv):
    """samples_sha256 of a held toss's CSV text (read as the door read it); the text's own
    SHA-256 where the reader refuses it (a toss held before the door read recordings)."""
    import bookspin
    try:
        return samples_sha256(bookspin.read_gyro_csv(csv, "recording.csv"))
    except bookspin.Error:
        return "text:" + recording_sha256(csv)


def failure(error, description):
    """(HTTP status, one line) for a store's error that is the machine's state rather than a
    bug: its disk full (507) or the store (`description`, Store.description) read-only (503);
    None for any other error."""
    code = getattr(error, "sqlite_errorcode", None)
    sqlstate = getattr(error, "sqlstate", None)
    if code == sqlite3.SQLITE_FULL or sqlstate == "53100":
        return 507, ("the server's disk is full: nothing was stored (the teacher frees space "
                     "on the laptop; the phone sends it again)")
    if (code is not None and code & 0xFF in (sqlite3.SQLITE_READONLY, sqlite3.SQLITE_CANTOPEN)) \
            or sqlstate == "25006":
        return 503, (f"the store ({description}) is read-only: nothing was stored (the teacher "
                     "makes it writable again)")
    if lost_connection(error):
        return 503, (f"the store ({description}) cannot be reached: nothing was stored (the "
                     "phone sends it again)")
    return None


def lost_connection(error):
    """Whether `error` is psycopg's for a PostgreSQL connection lost or refused (SQLSTATE class
    08, a server shut down or restarted 57P0x, or none: the connection closed), not for a
    statement."""
    try:
        import psycopg
    except ImportError:
        return False
    sqlstate = getattr(error, "sqlstate", None)
    return isinstance(error, psycopg.OperationalError) and (
        sqlstate is None or sqlstate.startswith(("08", "57P")))


def token_sha256(token):
    """The stored form of a student's token: its SHA-256 in hex (the token itself is not kept)."""
    return hashlib.sha256(token.encode("utf-8")).hexdigest()


class TossRefused(Exception):
    """add_toss would not hold the toss: `status` and the one line to answer (403 the student
    holds max_tosses; 409 the same samples as a held toss)."""

    def __init__(self, status, line):
        super().__init__(line)
        self.status = status


class Store:
    """One writer connection, used under a lock, and a reader connection per thread that reads
    (`reader`: () -> a new connection; SQLite's WAL and PostgreSQL's MVCC let them read while
    the writer writes, each read seeing every commit made before it). The server calls it from
    its store's worker threads, off the event loop (docs/class.md, "A school's server").
    `marker` is the driver's paramstyle: "?" (sqlite3) or "%s" (psycopg); statements are
    written with "?" and translated."""

    def __init__(self, connection, marker, description, reader=None, reconnect=None):
        self.connection = connection
        self.marker = marker
        self.description = description
        self.lock = threading.Lock()
        self.reader = reader
        self.local = threading.local()
        self.readers = []  # every reader connection opened, closed by close()
        self.readers_lock = threading.Lock()
        self.instance = secrets.token_hex(8)  # this server process, in its notices
        self.reconnect = reconnect  # () -> a new writer connection, for one found broken
        self.claimed = set()        # the classes this server serves (claim_class)
        with self.lock:
            for statement in SCHEMA:
                self.connection.execute(statement)
            self.connection.commit()
        self._add_samples_sha256()
        self._add_next_seq()

    def _add_samples_sha256(self):
        """A store made before tosses had samples_sha256 gets the column, and every toss its
        hash (read from its CSV text, as the door reads a toss)."""
        try:
            self._all("SELECT samples_sha256 FROM tosses WHERE 1 = 0")
        except Exception:  # the drivers' "no such column" (sqlite3 and psycopg differ)
            self._write([("ALTER TABLE tosses ADD COLUMN samples_sha256 TEXT", ())])
        missing = self._all("SELECT toss, csv FROM tosses WHERE samples_sha256 IS NULL")
        if missing:
            self._write([("UPDATE tosses SET samples_sha256 = ? WHERE toss = ?",
                          (read_samples_sha256(csv), toss)) for toss, csv in missing])

    def _add_next_seq(self):
        """A store made before the class's counter of tosses (classes.next_seq, add_toss) gets
        the column, each class's set to the highest number its tosses hold. Two servers starting
        at once on one PostgreSQL: the second's ALTER fails on the column the first added."""
        try:
            self._all("SELECT next_seq FROM classes WHERE 1 = 0")
            return
        except Exception:  # the drivers' "no such column" (sqlite3 and psycopg differ)
            pass
        try:
            self._write([("ALTER TABLE classes ADD COLUMN next_seq INTEGER NOT NULL DEFAULT 0", ()),
                         ("UPDATE classes SET next_seq = (SELECT COALESCE(MAX(seq), 0) FROM "
                          "tosses WHERE tosses.class_code = classes.code)", ())])
        except Exception:
            self._all("SELECT next_seq FROM classes WHERE 1 = 0")  # added by the other server

    def notice(self, kind, code):
        """The statement that tells the other servers on this PostgreSQL of a change of class
        `code` (CHANNEL), to run in the change's transaction (delivered at its commit, never for
        a change rolled back), with the class's fit job (fit_job_table.enqueue) for a change of its
        tosses; none on SQLite, whose one server is the only one."""
        if self.marker == "?":
            return []
        from bookspin_class import fit_job_table  # a change of the fitted set: its fit job
        jobs = fit_job_table.enqueue(code) if kind in ("toss", "exclude") else []
        return jobs + [("SELECT pg_notify(?, ?)", (CHANNEL, f"{kind} {code} {self.instance}"))]

    def _sql(self, statement):
        return statement if self.marker == "?" else statement.replace("?", "%s")

    def _all(self, statement, args=()):
        with self.lock:
            try:
                cursor = self.connection.execute(self._sql(statement), args)
                rows = cursor.fetchall()
                self.connection.commit()
            except BaseException:
                self._rollback()  # PostgreSQL refuses all else in a failed transaction
                raise
            return rows

    def _rollback(self):
        """Ends the writer's failed transaction. A writer found broken (PostgreSQL restarted, its
        connection lost) is made again, with the advisory locks of the classes it served, so
        that the next request is stored (the phone's outbox sends the refused one again); where
        it cannot be made yet, the next failure tries again."""
        broken = getattr(self.connection, "closed", False) or \
            getattr(self.connection, "broken", False)
        if not broken:
            self.connection.rollback()
            return
        if self.reconnect is None:
            return
        try:
            connection = self.reconnect()
        except Exception:  # the database not back yet: one more try at the next failure
            return
        self.connection = connection
        for code in sorted(self.claimed):
            connection.execute(f"SELECT pg_try_advisory_lock({CLASS_LOCK_SPACE}, "
                               "hashtext(%s))", (code,))
        connection.commit()

    def _read(self, statement, args=()):
        """The rows of one reading statement, on this thread's reader connection (the writer's
        where there is no reader). A reader found broken (PostgreSQL restarted) is dropped and
        the next read opens another."""
        if self.reader is None:
            return self._all(statement, args)
        connection = getattr(self.local, "connection", None)
        if connection is None:
            connection = self.local.connection = self.reader()
            with self.readers_lock:
                self.readers.append(connection)
        try:
            return connection.execute(self._sql(statement), args).fetchall()
        except BaseException:
            if getattr(connection, "closed", False) or getattr(connection, "broken", False):
                self.local.connection = None
            raise

    def read(self, statement, args=()):
        """The rows of one reading statement (fit_jobs.stored), as _read."""
        return self._read(statement, args)

    def _write(self, statements):
        """Runs (statement, args) pairs as one transaction, committed before it returns."""
        with self.lock:
            try:
                for statement, args in statements:
                    self.connection.execute(self._sql(statement), args)
                self.connection.commit()
            except BaseException:
                self._rollback()
                raise

    # Classes.
    def add_class(self, code, teacher_key):
        self._write([("INSERT INTO classes (code, teacher_key, created) VALUES (?, ?, ?)",
                      (code, teacher_key, time.time()))])

    def latest_class(self):
        rows = self._read("SELECT code, teacher_key FROM classes ORDER BY created DESC LIMIT 1")
        return rows[0] if rows else None

    def class_exists(self, code):
        return bool(self._read("SELECT 1 FROM classes WHERE code = ?", (code,)))

    def class_of_key(self, key):
        rows = self._read("SELECT code FROM classes WHERE teacher_key = ?", (key,))
        return rows[0][0] if rows else None

    def teacher_key(self, code):
        rows = self._read("SELECT teacher_key FROM classes WHERE code = ?", (code,))
        return rows[0][0] if rows else None

    def class_codes(self):
        return [r[0] for r in self._read("SELECT code FROM classes ORDER BY created")]

    def class_list(self):
        """Every class in the store, oldest first: (code, created in seconds since the epoch,
        students, tosses)."""
        return self._read("SELECT c.code, c.created, "
                         "(SELECT COUNT(*) FROM students s WHERE s.class_code = c.code), "
                         "(SELECT COUNT(*) FROM tosses t WHERE t.class_code = c.code) "
                         "FROM classes c ORDER BY c.created, c.code")

    def claim_class(self, code):
        """Whether this server may serve the class: on PostgreSQL this session's advisory lock
        on the class's code, held until the connection closes (False where another server
        holds it); on SQLite always True (the data folder's lock guards the file)."""
        if self.marker == "?":
            return True
        claimed = bool(self._all(f"SELECT pg_try_advisory_lock({CLASS_LOCK_SPACE}, "
                                 "hashtext(?))", (code,))[0][0])
        if claimed:
            self.claimed.add(code)
        return claimed

    def delete_class(self, code):
        """Ends a class: its tosses, students and itself deleted (children first, so that no
        foreign-key setting of the database is relied on)."""
        self._write([("DELETE FROM tosses WHERE class_code = ?", (code,)),
                     ("DELETE FROM students WHERE class_code = ?", (code,)),
                     ("DELETE FROM classes WHERE code = ?", (code,))] +
                    self.notice("end", code))

    def delete_older_than(self, seconds):
        """Deletes every class created more than `seconds` ago with all its data; returns their
        codes."""
        cutoff = time.time() - seconds
        codes = [r[0] for r in self._all("SELECT code FROM classes WHERE created < ?", (cutoff,))]
        for code in codes:
            self.delete_class(code)
        return codes

    # Students.
    def add_student(self, student, code, token, name):
        self._write([("INSERT INTO students (id, class_code, token_sha256, name, joined) "
                      "VALUES (?, ?, ?, ?, ?)", (student, code, token_sha256(token), name,
                                                 time.time()))] + self.notice("join", code))

    def student_of_token(self, token):
        """(id, class code, name) of the student whose token this is, or None."""
        rows = self._read("SELECT id, class_code, name FROM students WHERE token_sha256 = ?",
                         (token_sha256(token),))
        return rows[0] if rows else None

    def students(self, code):
        return self._read("SELECT id, name FROM students WHERE class_code = ? ORDER BY joined, id",
                         (code,))

    # Tosses.
    def toss(self, toss):
        """(class code, student, csv_sha256, name, recorded_at) of a held toss id, or None."""
        rows = self._read("SELECT class_code, student, csv_sha256, name, recorded_at FROM tosses "
                         "WHERE toss = ?", (toss,))
        return rows[0] if rows else None

    def student_toss_count(self, student):
        return self._read("SELECT COUNT(*) FROM tosses WHERE student = ?", (student,))[0][0]

    def toss_of_samples(self, code, samples_sha256):
        """The id of the class's toss whose samples have this samples_sha256, or None."""
        rows = self._read("SELECT toss FROM tosses WHERE class_code = ? AND samples_sha256 = ? "
                         "ORDER BY seq", (code, samples_sha256))
        return rows[0][0] if rows else None

    def add_toss(self, toss, code, student, name, recorded_at, csv, csv_sha256, samples,
                 max_tosses=None):
        """Holds a toss, committed before it returns; its seq is the class's next number (the
        file name the pooled set gives it), allotted by the database: the class's counter
        (classes.next_seq) raised in the same transaction as the toss's INSERT, so that two
        servers on one PostgreSQL never give one number twice (the row's lock orders them; a
        read-then-write of MAX(seq) raced). `samples` is its samples_sha256. Raises the
        driver's integrity error when the id is held already (two requests at once: the caller
        looks again). Raises TossRefused, holding nothing, where the student holds
        `max_tosses` already or the class holds the same samples (judged in the same
        transaction, after the class's row is locked: two requests at once, on one server or
        two, cannot both pass)."""
        with self.lock:
            try:
                # The class's row first: its lock orders every server's tosses of the class, so
                # that the checks below see the other's commit (a refusal rolls the number back).
                cursor = self.connection.execute(
                    self._sql("UPDATE classes SET next_seq = next_seq + 1 WHERE code = ? "
                              "RETURNING next_seq"), (code,))
                rows = cursor.fetchall()
                if not rows:  # the class ended a moment ago
                    raise TossRefused(404, f"no class with code {code}")
                seq = rows[0][0]
                if max_tosses is not None and self.connection.execute(
                        self._sql("SELECT COUNT(*) FROM tosses WHERE student = ?"),
                        (student,)).fetchall()[0][0] >= max_tosses:
                    raise TossRefused(403, f"this student holds {max_tosses} tosses, the most "
                                           "one student may (--max-tosses)")
                twin = self.connection.execute(
                    self._sql("SELECT toss FROM tosses WHERE class_code = ? AND samples_sha256 "
                              "= ? AND toss <> ? ORDER BY seq LIMIT 1"),
                    (code, samples, toss)).fetchall()
                if twin:  # the pooled fit refuses the same samples given twice
                    raise TossRefused(409, f"the same recording as toss {twin[0][0]}, held "
                                           "already (the same samples; a recording is held "
                                           "once)")
                self.connection.execute(
                    self._sql("INSERT INTO tosses (toss, class_code, student, seq, name, "
                              "recorded_at, csv, csv_sha256, recording_sha256, samples_sha256, "
                              "received, excluded) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
                              "NULL)"),
                    (toss, code, student, seq, name, recorded_at, csv, csv_sha256,
                     recording_sha256(csv), samples, time.time()))
                for statement, args in self.notice("toss", code):
                    self.connection.execute(self._sql(statement), args)
                self.connection.commit()
            except BaseException:
                self._rollback()
                raise
        return seq

    def set_excluded(self, code, toss, reason):
        """Leaves a toss out (reason: a str) or puts it back (None); False when the class holds
        no such toss."""
        if not self._all("SELECT 1 FROM tosses WHERE class_code = ? AND toss = ?", (code, toss)):
            return False
        self._write([("UPDATE tosses SET excluded = ? WHERE class_code = ? AND toss = ?",
                      (reason, code, toss))] + self.notice("exclude", code))
        return True

    def tosses(self, code):
        """Every toss of a class, oldest first, as dicts (without the CSV text)."""
        rows = self._read("SELECT t.toss, t.student, s.name, t.seq, t.name, t.recorded_at, "
                         "t.received, t.excluded FROM tosses t JOIN students s "
                         "ON s.id = t.student WHERE t.class_code = ? ORDER BY t.seq", (code,))
        keys = ("toss", "student", "student_name", "seq", "name", "recorded_at", "received",
                "excluded")
        return [dict(zip(keys, row)) for row in rows]

    def csv_texts(self, code):
        """{seq: csv text} of the class's tosses that are not left out."""
        return dict(self._read("SELECT seq, csv FROM tosses WHERE class_code = ? AND excluded "
                              "IS NULL", (code,)))

    def left_out(self, code):
        """{seq: (csv text, the teacher's reason)} of the class's tosses left out."""
        return {seq: (csv, reason) for seq, csv, reason in self._read(
            "SELECT seq, csv, excluded FROM tosses WHERE class_code = ? AND excluded IS NOT "
            "NULL", (code,))}

    def counts(self):
        """Rows per table, for the tests' "nothing stored"."""
        return {table: self._all(f"SELECT COUNT(*) FROM {table}")[0][0]
                for table in ("classes", "students", "tosses")}

    def close(self):
        with self.readers_lock:
            for reader in self.readers:
                reader.close()
            self.readers = []
        with self.lock:
            self.connection.close()


def open_sqlite(path):
    """The default store: an SQLite file (WAL journal, synchronous=FULL: a commit is on disk
    when it returns), made if missing; the file and its -wal and -shm readable and writable by
    this account alone (0600; docs/class.md, "What is kept"). A store that cannot be written
    raises sqlite3.OperationalError saying why (read_only_reason)."""
    connection = None
    try:
        connection = sqlite3.connect(str(path), check_same_thread=False, isolation_level=None)
        connection.execute("PRAGMA journal_mode=WAL")
        connection.execute("PRAGMA synchronous=FULL")
        connection.execute("PRAGMA foreign_keys=ON")
        connection.isolation_level = ""  # transactions begin implicitly again; commit() ends them
        store = Store(connection, "?", f"SQLite {path}", reader=lambda: sqlite_reader(path))
    except sqlite3.Error as error:
        if connection is not None:
            connection.close()
        read_only = read_only_reason(path)
        if read_only is not None:
            raise sqlite3.OperationalError(f"the store {path} is read-only ({read_only})") \
                from error
        raise
    except BaseException:
        if connection is not None:
            connection.close()
        raise
    for suffix in ("", "-wal", "-shm"):
        if os.path.exists(f"{path}{suffix}"):
            os.chmod(f"{path}{suffix}", 0o600)
    return store


def sqlite_reader(path):
    """A connection that reads the SQLite store at `path` beside the writer (WAL: readers do
    not wait for it), each statement its own transaction."""
    connection = sqlite3.connect(str(path), check_same_thread=False, isolation_level=None)
    connection.execute("PRAGMA query_only=ON")
    return connection


def read_only_reason(path):
    """Why the SQLite store at `path` cannot be written (its file system mounted read-only, its
    file or folder not writable by this account), or None."""
    folder = os.path.dirname(os.path.abspath(path)) or "."
    try:
        if os.statvfs(folder).f_flag & os.ST_RDONLY:
            return f"{folder} is on a file system mounted read-only"
    except OSError:
        return None
    if os.path.exists(path) and not os.access(path, os.W_OK):
        return "the file is not writable by this account"
    if not os.access(folder, os.W_OK):
        return f"its folder {folder} is not writable by this account"
    return None


def open_postgres(url):
    """A school's PostgreSQL by URL (libpq's form: postgresql://USER@HOST/DB or
    postgresql:///DB?host=/socket/dir), the same schema, and the fit jobs' tables
    (fit_job_table.py)."""
    import psycopg
    from bookspin_class import fit_job_table
    connection = psycopg.connect(url)
    opened = Store(connection, "%s", "PostgreSQL " + connection.info.dbname,
                   reader=lambda: psycopg.connect(url, autocommit=True),
                   reconnect=lambda: psycopg.connect(url))
    fit_job_table.create_tables(connection)  # the classes' fits, taken by fit workers
    return opened


def integrity_errors():
    """The drivers' "unique key taken" errors, for the caller that inserts concurrently."""
    errors = [sqlite3.IntegrityError]
    try:
        import psycopg
        errors.append(psycopg.errors.IntegrityError)
    except ImportError:
        pass
    return tuple(errors)
