"""The classes' fits as jobs in PostgreSQL (docs/class.md, "A school's server"): any fit worker,
in a server process or started alone (`bookspin-class --fit-worker`) on this machine or another,
takes them from the database; no queue of our own making.

One row of `fit_jobs` per class: `version` is raised, and the job made pending, in the very
transaction that holds, leaves out or puts back one of the class's tosses (enqueue, through
Store.notice), so that a change a phone was answered for is never without its job, whatever
process dies after. A worker claims a job that is pending, or running under a lease that
expired (its worker killed), with `SELECT … FOR UPDATE SKIP LOCKED` (two workers never take one
job, nor wait for each other), and renews its lease while it fits.

A job has two stages, each claimed on its own: 'live', the class's live estimate
(PooledFit.live_once: seconds at most), then 'exact', the exact fit and the judgements
(PooledFit.exact_once: minutes at 350), due once the class has been quiet for
pooled.QUIET_SECONDS. Every pending live estimate is claimed before any exact fit, the oldest
first: a school's 20 classes each see their live body before any worker spends minutes on one
class's exact fit. Each result is stored in `class_fits`, one row per class and version, only
by the worker that holds the lease, and announced by NOTIFY; every server process reads it on
the notice (stored_fit.py) and pushes it to its projectors. A stage ends with the job pending
again where a change came during it (the changes of a burst coalesce into the next live
estimate), else with the next stage pending, or the job done.

A job whose workers died MAX_ATTEMPTS times (a recording that kills the fit) is not fitted a
sixth time: the next worker stores the class's last result with the error saying so, for the
projector, and the job waits for the class's next change."""
import asyncio
import concurrent.futures
import json
import os
import socket
import sys

from bookspin_class import store

LEASE_SECONDS = 30.0  # a worker's hold on a job, renewed every third of it while it fits
POLL_SECONDS = 1.0    # a worker with nothing to do looks again after this (expired leases)
MAX_ATTEMPTS = 5      # a job whose worker died this often is left until the class changes
GAVE_UP = (f"the class's fit stopped its fit workers {MAX_ATTEMPTS} times, so it is not made "
           "again until a toss comes or the teacher leaves one out or puts one back; the "
           "fit workers' logs say why")


def announce(connection, code, worker):
    connection.execute("SELECT pg_notify(%s, %s)", (store.CHANNEL, f"fit {code} {worker}"))


def claim(connection, worker, lease):
    """(class code, version, attempt, stage) of the job this worker now holds for `lease`
    seconds, or None: of the jobs pending (an exact fit only once due) or running under an
    expired lease, that no other worker is claiming at this moment (SKIP LOCKED), a live
    estimate before any exact fit, each the oldest first. An attempt over MAX_ATTEMPTS is the
    one that gives up (Worker.give_up)."""
    with connection.transaction():
        row = connection.execute(
            "UPDATE fit_jobs SET state = 'running', worker = %s, attempts = attempts + 1, "
            "leased_until = now() + make_interval(secs => %s) WHERE class_code = ("
            "SELECT class_code FROM fit_jobs WHERE attempts <= %s AND ((state = 'pending' AND "
            "(not_before IS NULL OR not_before <= now())) OR (state = 'running' AND "
            "leased_until < now())) ORDER BY stage = 'exact', queued, class_code "
            "LIMIT 1 FOR UPDATE SKIP LOCKED) RETURNING class_code, version, attempts, stage",
            (worker, lease, MAX_ATTEMPTS)).fetchone()
    return tuple(row) if row else None


def renew(connection, code, worker, lease):
    """The class's version where this worker still holds its job (its lease made `lease`
    seconds again); None where it lost it (expired and taken by another)."""
    with connection.transaction():
        row = connection.execute(
            "UPDATE fit_jobs SET leased_until = now() + make_interval(secs => %s) "
            "WHERE class_code = %s AND worker = %s AND state = 'running' RETURNING version",
            (lease, code, worker)).fetchone()
    return row[0] if row else None


def read_class(connection, code):
    """(version, {stem: csv text} of the tosses not left out) of one snapshot of the class."""
    from bookspin_class.pooled import file_stem
    with connection.transaction():
        connection.execute("SET TRANSACTION ISOLATION LEVEL REPEATABLE READ")
        row = connection.execute("SELECT version FROM fit_jobs WHERE class_code = %s",
                                 (code,)).fetchone()
        rows = connection.execute(
            "SELECT s.name, t.seq, t.csv FROM tosses t JOIN students s ON s.id = t.student "
            "WHERE t.class_code = %s AND t.excluded IS NULL ORDER BY t.seq", (code,)).fetchall()
    return (row[0] if row else 0), {file_stem(name, seq): csv for name, seq, csv in rows}


def store_result(connection, code, worker, version, result):
    """Stores the fit `result` (JSON text) of the class's `version` and announces it, where this
    worker still holds the job's lease (checked under the job row's lock, in the same
    transaction): one row per class and version, the class's older ones deleted; its `stage`
    counts the results stored for the version (the live estimate, the exact fit, the
    judgements). False, storing nothing, where the lease was lost."""
    with connection.transaction():
        held = connection.execute(
            "SELECT attempts FROM fit_jobs WHERE class_code = %s AND worker = %s AND state = "
            "'running' AND leased_until > now() FOR UPDATE", (code, worker)).fetchone()
        if held is None:
            return False
        connection.execute(
            "INSERT INTO class_fits (class_code, version, result, worker, attempt) VALUES "
            "(%s, %s, %s, %s, %s) ON CONFLICT (class_code, version) DO UPDATE SET result = "
            "excluded.result, worker = excluded.worker, attempt = excluded.attempt, stage = "
            "class_fits.stage + 1, stored = now()", (code, version, result, worker, held[0]))
        connection.execute("DELETE FROM class_fits WHERE class_code = %s AND version < %s",
                           (code, version))
        announce(connection, code, worker)
    return True


def finish(connection, code, worker, version, exact_in=None):
    """Ends this worker's hold on the job's stage (its attempts counted again from 0: this one
    succeeded). Where `version` (the one fitted) is still the class's: the job done, or, with
    `exact_in` seconds, its exact fit pending then. Where a change came during the stage: its
    live estimate pending again, at once. False where the lease was lost."""
    exact = exact_in is not None
    with connection.transaction():
        # `version = %(version)s`: no change came during the stage; `exact`: the exact fit next.
        row = connection.execute(
            "UPDATE fit_jobs SET "
            "state = CASE WHEN version = %(version)s AND NOT %(exact)s THEN 'done' "
            "ELSE 'pending' END, "
            "stage = CASE WHEN version = %(version)s AND %(exact)s THEN 'exact' ELSE 'live' END, "
            "not_before = CASE WHEN version = %(version)s AND %(exact)s "
            "THEN now() + make_interval(secs => %(exact_in)s) END, "
            "worker = NULL, leased_until = NULL, attempts = 0, "
            "queued = CASE WHEN version = %(version)s AND NOT %(exact)s THEN queued ELSE now() END "
            "WHERE class_code = %(code)s AND worker = %(worker)s AND state = 'running' "
            "RETURNING state",
            {"version": version, "exact": exact, "exact_in": exact_in or 0.0, "code": code,
             "worker": worker}).fetchone()
        if row is not None:
            announce(connection, code, worker)
    return row is not None


def release(connection, code, worker, counted=False):
    """A worker hands its job back at once, pending: one that stops, its attempt not counted;
    one whose fit raised (`counted`), its attempt counted as if it had died."""
    with connection.transaction():
        connection.execute(
            "UPDATE fit_jobs SET state = 'pending', worker = NULL, leased_until = NULL, "
            "attempts = GREATEST(attempts - %s, 0) WHERE class_code = %s AND worker = %s AND "
            "state = 'running'", (0 if counted else 1, code, worker))


def stored(read, code, shown=None):
    """What a server shows of the class's fit, through `read` (Store.read): (the stored result
    {"result", "flights", "judgements"}, None where none is stored or it is `shown`, the one
    shown already; its (version, stage); the job's version and state, or None)."""
    version, stage = shown or (None, None)
    rows = read("SELECT CASE WHEN f.version IS DISTINCT FROM %s OR f.stage IS DISTINCT FROM %s "
                "THEN f.result END, f.version, f.stage, j.version, j.state FROM fit_jobs j "
                "LEFT JOIN class_fits f ON f.class_code = j.class_code WHERE j.class_code = %s "
                "ORDER BY f.version DESC LIMIT 1", (version, stage, code))
    if not rows:
        return None, None, None, None
    result, version, stage, job_version, state = rows[0]
    return (json.loads(result) if result else None), (version, stage), job_version, state


def worker_name(index=0):
    """HOST:PID (and -INDEX for a server's second worker on): one word, for the notices."""
    name = f"{socket.gethostname()}:{os.getpid()}"
    return name if index == 0 else f"{name}-{index}"


def say(line):
    print(f"bookspin-class: {line}", file=sys.stderr, flush=True)


def one_line(error):
    text = str(error).strip()
    return text.splitlines()[0] if text else type(error).__name__


class Worker:
    """A fit worker: takes the jobs of every class of the PostgreSQL at `url`, one stage at a
    time, and fits each with pooled.PooledFit (kept per class between jobs, so that what it
    keeps of the last fit serves the next, until the class ends). Its own connection, used from
    one thread at a time."""

    def __init__(self, url, lease=LEASE_SECONDS, name=None):
        import threading
        self.url, self.lease, self.name = url, lease, name or worker_name()
        self.lock = threading.Lock()
        self.connection = None
        self.writes = concurrent.futures.ThreadPoolExecutor(1, thread_name_prefix="fit-jobs")
        self.fits = {}       # code -> pooled.PooledFit
        self.read_version = {}  # code -> the version its last files were read at
        self.job = None      # (code, version, attempt) held
        self.lost = False
        self.pending = []    # the stores of the job's results, in order
        self.wake = None

    def call(self, function, *args):
        """function(connection, *args) on this worker's connection, made again where lost."""
        import psycopg
        with self.lock:
            if self.connection is None or self.connection.closed or self.connection.broken:
                self.connection = psycopg.connect(self.url, autocommit=True)
            try:
                return function(self.connection, *args)
            except psycopg.Error:
                if self.connection.broken or self.connection.closed:
                    self.connection = None
                raise

    def call_again(self, function, *args):
        """call(), made again every POLL_SECONDS while PostgreSQL is away (restarting), up to
        30 times: a fit's result outlives a restart of the database under it."""
        import time
        for _ in range(30):
            try:
                return self.call(function, *args)
            except Exception as error:
                if not store.lost_connection(error):
                    raise
                last = error
                time.sleep(POLL_SECONDS)
        raise last

    async def run(self):
        """Takes and fits jobs until cancelled (a job held then is handed back)."""
        from bookspin_class import notices
        self.wake = asyncio.Event()
        listening = asyncio.get_running_loop().create_task(notices.listen(
            self.url, self.name, self.noticed, self.wake.set))
        try:
            while True:
                try:
                    self.job = await asyncio.to_thread(self.call, claim, self.name, self.lease)
                except Exception as error:  # PostgreSQL away: again soon
                    say(f"fit worker {self.name} waits for the store: {one_line(error)}")
                    self.job = None
                    await asyncio.sleep(POLL_SECONDS)
                    continue
                if self.job is None:
                    self.wake.clear()
                    try:
                        await asyncio.wait_for(self.wake.wait(), POLL_SECONDS)
                    except asyncio.TimeoutError:
                        pass
                    continue
                try:
                    await self.fit(*self.job)
                except Exception as error:  # the store away for long, or a bug: counted
                    say(f"fit worker {self.name}: class {self.job[0]}: the fit failed: "
                        f"{one_line(error)}")
                    try:
                        await asyncio.to_thread(self.call, release, self.job[0], self.name, True)
                    except Exception:
                        pass  # the lease expires instead
                self.job = None
        finally:
            listening.cancel()
            if self.job is not None:
                try:
                    await asyncio.to_thread(self.call, release, self.job[0], self.name)
                except Exception:
                    pass  # the lease expires instead
            self.writes.shutdown(wait=False)

    def noticed(self, kind, code):
        """A notice on the database: a job may be waiting; a toss of the class being fitted
        joins its stage (the live estimate's preparing, or makes the exact fit stale); a class
        ended is forgotten."""
        self.wake.set()
        fit = self.fits.get(code)
        if kind == "end" and (self.job is None or self.job[0] != code):
            self.fits.pop(code, None)
            self.read_version.pop(code, None)
        elif self.job is not None and self.job[0] == code and kind in ("toss", "exclude") \
                and fit is not None:
            fit.note_change()

    async def fit_of(self, code):
        """The class's PooledFit, made the first time with what is shown of the class (the
        stored result goes on being shown until this worker's replaces it)."""
        from bookspin_class import pooled
        fit = self.fits.get(code)
        if fit is None:
            fit = self.fits[code] = pooled.PooledFit(lambda: self.files(code),
                                                     lambda: self.done(code),
                                                     asyncio.Semaphore(1))
            try:
                found = (await asyncio.to_thread(self.call, lambda c: stored(
                    lambda s, a: c.execute(s, a).fetchall(), code)))[0]
            except Exception:
                found = None
            if found is not None:
                fit.result, fit.flights = found["result"], found["flights"]
                fit.judgements = found["judgements"]
        return fit

    async def fit(self, code, version, attempt, stage):
        """One stage of the class's job: its live estimate (the exact fit due after the
        quiet, or at once where none could be shown), or its exact fit and judgements (done; or,
        where a toss made them stale, the job handed back for that toss's live estimate)."""
        from bookspin_class import pooled
        fit = await self.fit_of(code)
        self.lost, self.pending = False, []
        self.read_version[code] = version
        renewing = asyncio.get_running_loop().create_task(self.renew(code, fit))
        try:
            if attempt > MAX_ATTEMPTS:
                exact_in = None
                self.give_up(code, fit)
            elif stage == "live":
                exact_in = pooled.QUIET_SECONDS if await fit.live_once() else 0.0
            else:
                exact_in = None if await fit.exact_once() else pooled.QUIET_SECONDS
        finally:
            renewing.cancel()
        for write in self.pending:
            await write
        if self.lost:
            return
        try:
            if not await asyncio.to_thread(self.call_again, finish, code, self.name,
                                           self.read_version[code], exact_in):
                self.fits.pop(code, None)  # the class ended (or the lease was lost)
        except Exception as error:  # the lease expires; another worker fits it again
            say(f"fit worker {self.name}: class {code}: not marked done: {one_line(error)}")

    def give_up(self, code, fit):
        """The job whose workers died MAX_ATTEMPTS times: the class's last result stored again
        with GAVE_UP as its error, for the projector (its body, if any, still shown)."""
        from bookspin_class import pooled
        say(f"fit worker {self.name}: class {code}: {GAVE_UP}")
        fit.result = dict(fit.result, error=GAVE_UP, error_summary=pooled.error_summary(GAVE_UP),
                          judging=False, live=False)
        self.done(code)

    def files(self, code):
        """PooledFit's files_of, in a thread: the class's files and the version they are of
        (waiting for PostgreSQL while it restarts, as call_again)."""
        version, files = self.call_again(read_class, code)
        self.read_version[code] = version
        return files

    def done(self, code):
        """PooledFit's on_done, on the event loop: the result stored in order, off the loop."""
        fit = self.fits[code]
        text = json.dumps({"result": fit.result, "flights": fit.flights,
                           "judgements": fit.judgements}, ensure_ascii=False)
        version = self.read_version[code]

        def write():
            try:
                if not self.lost and not self.call_again(store_result, code, self.name,
                                                         version, text):
                    self.lost = True
                    say(f"fit worker {self.name}: class {code} version {version}: the lease "
                        "was lost (another worker took the job): this result is dropped")
            except Exception as error:
                self.lost = True
                say(f"fit worker {self.name}: class {code}: result not stored: "
                    f"{one_line(error)}")

        self.pending.append(asyncio.get_running_loop().run_in_executor(self.writes, write))

    async def renew(self, code, fit):
        """Renews the lease every third of it while the stage runs; a newer version of the
        class (a change whose notice was missed) is told to the PooledFit, as the notice does."""
        while True:
            await asyncio.sleep(self.lease / 3.0)
            try:
                version = await asyncio.to_thread(self.call, renew, code, self.name,
                                                  self.lease)
            except Exception as error:
                say(f"fit worker {self.name}: lease not renewed: {one_line(error)}")
                continue
            if version is None:
                if not self.lost:
                    say(f"fit worker {self.name}: class {code}: the lease was lost (another "
                        "worker took the job)")
                self.lost = True
                return
            if version != self.read_version.get(code):
                fit.note_change()


async def serve_workers(url, count, lease, stop):
    """`count` workers in this process until `stop` is set (a server's own, or --fit-worker)."""
    tasks = [asyncio.get_running_loop().create_task(
        Worker(url, lease, worker_name(i)).run()) for i in range(count)]
    await stop.wait()
    for task in tasks:
        task.cancel()
    await asyncio.gather(*tasks, return_exceptions=True)
