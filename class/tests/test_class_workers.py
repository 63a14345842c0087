"""The classes' fits as jobs that fit workers take from PostgreSQL (docs/class.md, "A school's
server"; class/bookspin_class/fit_jobs.py), and faults at a school's scale: a real PostgreSQL 15
and a real nginx started by the test, server processes and `bookspin-class --fit-worker`
processes, the real recordings of ../shared/recordings-real/ posted through the proxy, a server
and a fit worker SIGKILLed in the middle of the burst."""
import asyncio
import concurrent.futures
import hashlib
import http.client
import json
import os
import signal
import subprocess
import sys
import threading
import time
import uuid

import pytest

from class_server import SOURCE_DIR, Server, free_port, real_csv, require_packages, \
    require_real, restamped

require_packages("aiohttp", "psycopg", "segno")

import psycopg  # noqa: E402

from class_start_shared import page, postgres  # noqa: E402,F401  (the fixtures)
from test_class_school import PHONE, Nginx, database  # noqa: E402

sys.path.insert(0, str(SOURCE_DIR / "class"))
from bookspin_class import fit_job_table, fit_jobs, store  # noqa: E402


class FitWorker:
    """A `bookspin-class --fit-worker` process on the database `url`, its name (HOST:PID, as
    it stores it in fit_jobs.worker) read from its first line."""

    def __init__(self, url, lease):
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join([str(SOURCE_DIR / "class")] + [
            p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
        self.process = subprocess.Popen(
            [sys.executable, "-m", "bookspin_class", "--fit-worker", "--postgres", url,
             "--fit-lease", str(lease)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
            text=True, env=env)
        line = self.process.stdout.readline()
        assert " fit worker " in line, (line, self.process.stderr.read())
        self.name = line.split(" fit worker ")[1].split()[0]
        self.errors = []
        threading.Thread(target=lambda: self.errors.extend(self.process.stderr),
                         daemon=True).start()

    def kill(self):
        self.process.send_signal(signal.SIGKILL)
        self.process.wait(timeout=30)

    def stop(self):
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=120)
            except subprocess.TimeoutExpired:
                self.kill()


def classes(url, *codes):
    """A store on `url` holding the classes `codes` (made with their job tables)."""
    made = store.open_postgres(url)
    for code in codes:
        made.add_class(code, uuid.uuid4().hex)
    return made


def enqueue(connection, code):
    with connection.transaction():
        for statement, args in fit_job_table.enqueue(code):
            connection.execute(statement, args)


def hold_tosses(made, code, count):
    """`count` tosses of one student held by the store `made` in class `code` (the bare
    phone's real recordings, each restamped: other samples), as a server holds them."""
    student = uuid.uuid4().hex
    made.add_student(student, code, uuid.uuid4().hex, "Anna")
    for i in range(count):
        text = restamped(real_csv(PHONE[i % 3]), 40.0 * i)
        made.add_toss(str(uuid.uuid4()), code, student, f"t{i}", "2022-05-03T12:13:01Z", text,
                      hashlib.sha256(text.encode()).hexdigest(), uuid.uuid4().hex)


def job_row(connection, code):
    return connection.execute("SELECT state, stage, version, worker, attempts, not_before IS "
                              "NULL FROM fit_jobs WHERE class_code = %s", (code,)).fetchone()


def test_jobs_are_claimed_once_their_leases_expire_and_a_lost_lease_stores_nothing(postgres):
    """Two workers claiming at once take two jobs, neither waiting for the other's lock (SKIP
    LOCKED); a job held is taken by no one while its lease runs and by another worker once it
    expired (its worker killed); the worker that lost it stores nothing and cannot mark it
    done; the result is one row per class and version; a change during the fit makes the job
    pending again, coalesced."""
    url = database(postgres)
    made = classes(url, "AAAAAA", "BBBBBB")
    first, second, third = (psycopg.connect(url, autocommit=True) for _ in range(3))
    try:
        for code in ("AAAAAA", "BBBBBB"):
            enqueue(first, code)
        second.execute("SET lock_timeout = '20s'")  # a claim that waits fails, never hangs
        with first.transaction():  # the first worker's claim, not yet committed
            claimed = fit_jobs.claim(first, "w1", 60)
            other = fit_jobs.claim(second, "w2", 60)
        assert claimed[0] != other[0] and {claimed[0], other[0]} == {"AAAAAA", "BBBBBB"}
        assert claimed[1:] == (1, 1, "live") and other[1:] == (1, 1, "live")
        assert fit_jobs.claim(third, "w3", 60) is None  # both held, their leases running
        code = claimed[0]
        first.execute("UPDATE fit_jobs SET leased_until = now() - interval '1 second' "
                      "WHERE class_code = %s", (code,))  # w1 killed: its lease ran out
        assert fit_jobs.claim(third, "w3", 60) == (code, 1, 2, "live")
        assert fit_jobs.renew(first, code, "w1", 60) is None
        assert not fit_jobs.store_result(first, code, "w1", 1, '{"by": "w1"}')
        assert fit_jobs.store_result(third, code, "w3", 1, '{"by": "w3", "stage": 1}')
        assert fit_jobs.store_result(third, code, "w3", 1, '{"by": "w3", "stage": 2}')
        assert not fit_jobs.finish(first, code, "w1", 1)
        enqueue(second, code)  # a toss during w3's fit
        enqueue(second, code)
        assert fit_jobs.renew(third, code, "w3", 60) == 3
        assert fit_jobs.claim(first, "w1", 60) is None  # still w3's, not a second job
        assert fit_jobs.finish(third, code, "w3", 1)  # version 1 fitted: pending for 3
        assert fit_jobs.claim(first, "w1", 60) == (code, 3, 1, "live")
        assert fit_jobs.store_result(first, code, "w1", 3, '{"by": "w1"}')
        assert fit_jobs.finish(first, code, "w1", 3)
        rows = first.execute("SELECT version, result, worker FROM class_fits WHERE class_code "
                             "= %s", (code,)).fetchall()
        assert rows == [(3, '{"by": "w1"}', "w1")]
        assert first.execute("SELECT state, version, worker FROM fit_jobs WHERE class_code = "
                             "%s", (code,)).fetchone() == ("done", 3, None)
        made.delete_class(code)  # the class ended: its job and fit with it
        assert first.execute("SELECT COUNT(*) FROM fit_jobs WHERE class_code = %s",
                             (code,)).fetchone()[0] == 0
    finally:
        for connection in (first, second, third):
            connection.close()
        made.close()


def test_every_class_has_its_live_estimate_before_any_exact_fit(postgres):
    """The job's two stages: every pending live estimate is claimed before any exact fit (a
    school's classes each see their live body first), each the oldest first; an exact fit is
    claimed only once due (the class quiet); a change during the quiet, or during the exact
    fit, makes the live estimate pending again at once; a job whose workers died
    MAX_ATTEMPTS times is claimed once more, to give up (an attempt over MAX_ATTEMPTS)."""
    url = database(postgres)
    made = classes(url, "AAAAAA", "BBBBBB", "CCCCCC")
    connection = psycopg.connect(url, autocommit=True)
    try:
        enqueue(connection, "AAAAAA")
        enqueue(connection, "BBBBBB")
        assert fit_jobs.claim(connection, "w1", 60) == ("AAAAAA", 1, 1, "live")
        assert fit_jobs.finish(connection, "AAAAAA", "w1", 1, 0.0)  # exact due at once
        assert job_row(connection, "AAAAAA") == ("pending", "exact", 1, None, 0, False)
        enqueue(connection, "CCCCCC")  # a class whose first toss came after A's live estimate
        assert fit_jobs.claim(connection, "w1", 60) == ("BBBBBB", 1, 1, "live")
        assert fit_jobs.finish(connection, "BBBBBB", "w1", 1, 3600.0)  # quiet for an hour
        assert fit_jobs.claim(connection, "w1", 60) == ("CCCCCC", 1, 1, "live")  # before A's
        assert fit_jobs.claim(connection, "w2", 60) == ("AAAAAA", 1, 1, "exact")
        assert fit_jobs.claim(connection, "w3", 60) is None  # B's exact fit not due yet
        enqueue(connection, "BBBBBB")  # a toss during B's quiet: its live estimate, at once
        assert job_row(connection, "BBBBBB") == ("pending", "live", 2, None, 0, True)
        assert fit_jobs.claim(connection, "w3", 60) == ("BBBBBB", 2, 1, "live")
        enqueue(connection, "AAAAAA")  # a toss during A's exact fit: stays w2's until its end
        assert job_row(connection, "AAAAAA")[:4] == ("running", "live", 2, "w2")
        assert fit_jobs.finish(connection, "AAAAAA", "w2", 1)  # version 1 fitted, 2 is not
        assert job_row(connection, "AAAAAA") == ("pending", "live", 2, None, 0, True)
        assert fit_jobs.finish(connection, "CCCCCC", "w1", 1)  # nothing to show: done
        assert job_row(connection, "CCCCCC") == ("done", "live", 1, None, 0, True)
        # A job whose workers died: claimed again under an expired lease, its attempts counted;
        # the attempt after MAX_ATTEMPTS is the one that gives up; none after it.
        for attempt in range(2, fit_jobs.MAX_ATTEMPTS + 2):
            connection.execute("UPDATE fit_jobs SET leased_until = now() - interval '1 second' "
                               "WHERE class_code = 'BBBBBB'")
            assert fit_jobs.claim(connection, f"w{attempt + 2}", 60) == (
                "BBBBBB", 2, attempt, "live")
        connection.execute("UPDATE fit_jobs SET leased_until = now() - interval '1 second' "
                           "WHERE class_code = 'BBBBBB'")
        assert fit_jobs.claim(connection, "w9", 60) == ("AAAAAA", 2, 1, "live")
        assert fit_jobs.claim(connection, "w9", 60) is None
    finally:
        connection.close()
        made.close()


def test_a_job_that_killed_its_workers_five_times_says_so_and_waits_for_a_change(postgres):
    """A class whose fit killed its worker MAX_ATTEMPTS times (planted: its job running under
    an expired lease, that many attempts made): the next worker does not fit it a sixth time
    but stores the class's last result with the error saying so, announced, which the
    projector shows (fit_jobs.stored, as a server reads it, no longer fitting); the job is done
    until the class changes, and then fitted again from its first attempt."""
    url = database(postgres)
    code = "DDDDDD"
    made = classes(url, code)
    hold_tosses(made, code, 1)
    connection = psycopg.connect(url, autocommit=True)
    try:
        connection.execute("UPDATE fit_jobs SET state = 'running', worker = 'gone', attempts = "
                           "%s, leased_until = now() - interval '1 second'",
                           (fit_jobs.MAX_ATTEMPTS,))
        worker = fit_jobs.Worker(url, 30, "w-test")

        async def until_done():
            task = asyncio.get_running_loop().create_task(worker.run())
            deadline = time.monotonic() + 120  # a guard against a test that hangs
            while job_row(connection, code)[0] != "done":
                assert time.monotonic() < deadline and not task.done()
                await asyncio.sleep(0.1)
            task.cancel()
            await asyncio.gather(task, return_exceptions=True)

        asyncio.run(until_done())
        found, shown, job_version, state = fit_jobs.stored(
            lambda s, a: connection.execute(s, a).fetchall(), code)
        assert found["result"]["error"] == fit_jobs.GAVE_UP and state == "done"
        assert found["result"]["error_summary"] and found["result"]["live"] is False
        assert shown == (1, 1) and job_version == 1
        assert job_row(connection, code) == ("done", "live", 1, None, 0, True)
        assert fit_jobs.claim(connection, "w2", 60) is None  # not a sixth time
        hold_tosses(made, code, 1)  # the class changes: fitted again, its first attempt
        assert fit_jobs.claim(connection, "w2", 60) == (code, 2, 1, "live")
    finally:
        connection.close()
        made.close()


def test_a_worker_paused_past_its_lease_stores_nothing_when_it_goes_on(postgres, tmp_path):
    """A fit worker SIGSTOPped in the middle of a class's exact fit, past its lease: another
    worker takes the job and stores its fit; the paused one, SIGCONTinued, finds its lease
    lost, stores nothing over the other's result and does not mark the job, and goes on taking
    jobs (the class's next change is fitted)."""
    require_real()
    url = database(postgres)
    code = "EEEEEE"
    made = classes(url, code)
    hold_tosses(made, code, 6)
    paused = FitWorker(url, 2)
    other = None
    try:
        with psycopg.connect(url, autocommit=True) as connection:
            deadline = time.monotonic() + 120  # a guard against a test that hangs
            while job_row(connection, code)[:2] != ("running", "exact"):
                assert time.monotonic() < deadline, job_row(connection, code)
                time.sleep(0.02)
            paused.process.send_signal(signal.SIGSTOP)
            other = FitWorker(url, 2)
            while True:  # the other worker's exact fit and judgements, the job done
                assert time.monotonic() < deadline, job_row(connection, code)
                row = connection.execute("SELECT worker, stage, stored FROM class_fits WHERE "
                                         "class_code = %s", (code,)).fetchone()
                if job_row(connection, code)[0] == "done" and row and row[0] == other.name:
                    break
                time.sleep(0.1)
            paused.process.send_signal(signal.SIGCONT)
            while not any("the lease was lost" in line for line in paused.errors):
                assert time.monotonic() < deadline and paused.process.poll() is None
                time.sleep(0.1)
            time.sleep(1.0)  # what the paused worker would store after it
            assert connection.execute("SELECT worker, stage, stored FROM class_fits WHERE "
                                      "class_code = %s", (code,)).fetchone() == row
            assert job_row(connection, code) == ("done", "live", 6, None, 0, True)
            result = json.loads(connection.execute(
                "SELECT result FROM class_fits WHERE class_code = %s", (code,)).fetchone()[0])
            assert result["result"]["live"] is False and result["result"]["recordings"] == 6
            other.kill()  # the class's next change: the paused worker, alone, fits it
            other = None
            hold_tosses(made, code, 1)
            while connection.execute("SELECT worker FROM class_fits WHERE class_code = %s AND "
                                     "version = (SELECT version FROM fit_jobs WHERE class_code "
                                     "= %s)", (code, code)).fetchone() != (paused.name,):
                assert time.monotonic() < deadline
                time.sleep(0.1)
    finally:
        for worker in (paused, other):
            if worker is not None:
                worker.stop()
        made.close()
    assert not any("Traceback" in line for line in paused.errors), paused.errors


def proxy_stream(proxy, code, key):
    """The projector's event stream through the proxy, made again whenever it ends (the page's
    EventSource reconnects by itself): a function giving the next `class` event's data (within
    `seconds`: a guard against a test that hangs, not a timing), its `reconnects` counted."""
    held = {}

    def connect():
        connection = http.client.HTTPSConnection("127.0.0.1", proxy.port,
                                                 context=proxy.context, timeout=60)
        connection.request("GET", f"/api/class/{code}/events",
                           headers={"Authorization": f"Bearer {key}"})
        response = connection.getresponse()
        if response.status != 200:
            connection.close()
            return None
        held["connection"], held["response"] = connection, response
        return response

    def next_state(seconds=300):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            response = held.get("response") or connect()
            if response is None:
                time.sleep(0.5)
                continue
            try:
                for line in response:
                    if line.startswith(b"data: "):
                        return json.loads(line[6:])
                    assert time.monotonic() < deadline, "nothing new on the projector's stream"
            except (OSError, http.client.HTTPException):
                pass
            held.pop("connection").close()  # the server behind it is gone: reconnect
            held.pop("response")
            next_state.reconnects += 1
            time.sleep(0.2)
        raise AssertionError(f"the projector's stream not made again within {seconds} s")

    next_state.reconnects = 0
    return next_state


def post_until_held(proxy, code, token, toss, source):
    """A phone's outbox: the toss sent through the proxy until it is held (201 or 200, the
    same toss again), whatever a server killed meanwhile answered (502, a dropped connection).
    The first answer that holds it."""
    for _ in range(200):
        try:
            status, answer = proxy.request("POST", f"/api/class/{code}/tosses", toss,
                                           token=token, source=source)
        except (OSError, http.client.HTTPException):
            status, answer = None, None
        if status in (200, 201):
            return status
        assert status in (None, 429, 502, 503, 504), (status, answer)
        time.sleep(0.3)
    raise AssertionError(f"toss {toss['toss']} not held")


@pytest.fixture
def school_with_workers(postgres, page, tmp_path):
    """Two server processes behind nginx that fit nothing themselves (--fit-workers 0) and two
    fit workers, on one PostgreSQL."""
    require_real()
    url = database(postgres)
    extra = ["--proxy", "127.0.0.2", "--rate", "10000", "--fit-workers", "0"]
    first = Server(tmp_path / "first", page, url, extra).start()
    second = Server(tmp_path / "second", page, url, extra)
    started = [first]
    try:
        second.start(new=True)
        started.append(second)
        workers = [FitWorker(url, 3), FitWorker(url, 3)]
        started += workers
        proxy = Nginx(tmp_path / "nginx", free_port(), [first.port, second.port])
        started.append(proxy)
        yield first, second, workers, proxy
    finally:
        for thing in reversed(started):
            thing.stop()


def test_a_server_and_a_fit_worker_killed_mid_burst_lose_no_toss(school_with_workers):
    """The lecture hall's burst through the proxy to two servers: one server SIGKILLed in the
    middle of it, and the fit worker that holds the class's job SIGKILLed while it fits. Every
    toss a phone was answered 201 for is in the pooled fit the projector shows after it (its
    stream made again through the proxy); the job the killed worker held is taken and
    finished by the other, its result stored once, for the class's last version."""
    first, second, workers, proxy = school_with_workers
    code, count = first.code, 12
    tokens = []
    for i in range(count):
        status, answer = proxy.request("POST", f"/api/class/{code}/join", {"name": f"p{i}"},
                                       source=f"127.0.1.{i + 1}")
        assert status == 201, answer
        tokens.append(answer["token"])
    tosses = [{"toss": str(uuid.uuid4()), "name": f"t{i}", "recorded_at":
               "2022-05-03T12:13:01Z", "csv": restamped(real_csv(PHONE[i % 3]), 40.0 * i)}
              for i in range(count)]
    # Two projectors: the proxy sends their streams to either server in turn, one to each.
    projectors = [proxy_stream(proxy, code, first.key) for _ in range(2)]
    for next_state in projectors:
        next_state()
    answered = {}

    def phone(i):
        time.sleep(0.25 * i)  # the hall's phones, one after another over a few seconds
        answered[tosses[i]["toss"]] = post_until_held(proxy, code, tokens[i], tosses[i],
                                                      f"127.0.1.{i + 1}")

    killed_worker = None
    with psycopg.connect(first.postgres, autocommit=True) as connection, \
            concurrent.futures.ThreadPoolExecutor(count) as pool:
        posting = [pool.submit(phone, i) for i in range(count)]
        while len(answered) < count // 3:
            time.sleep(0.05)
        second.kill()  # a server process, in the middle of the burst
        deadline = time.monotonic() + 300  # a guard against a test that hangs, not a timing
        while killed_worker is None:  # the fit worker holding the class's job, while it fits
            assert time.monotonic() < deadline, "no worker took the class's job"
            held = connection.execute("SELECT worker FROM fit_jobs WHERE class_code = %s AND "
                                      "state = 'running' AND leased_until > now()",
                                      (code,)).fetchone()
            killed_worker = next((w for w in workers if held and w.name == held[0]), None)
            time.sleep(0.02)
        killed_worker.kill()
        for done in posting:
            done.result()
    assert len(answered) == count and set(answered.values()) <= {200, 201}
    assert 201 in answered.values()
    survivor = next(w for w in workers if w is not killed_worker)
    deadline = time.monotonic() + 300  # a guard against a test that hangs, not a timing
    for next_state in projectors:  # each projector until the fit holds every toss
        while True:
            state = next_state(deadline - time.monotonic())
            pooled = state["pooled"]
            shown = {t["toss"]: t for s in state["students"] for t in s["tosses"]}
            if set(shown) == set(answered) and pooled["recordings"] == count and \
                    not pooled["fitting"] and pooled["ratios"] is not None:
                break
        assert pooled["tosses"] >= count and not pooled["set_aside"], pooled
        assert pooled["live"] is False  # the exact fit, stored after the live estimate
        assert all(t["flights"] for t in shown.values()), shown
    assert sorted(p.reconnects for p in projectors) == [0, 1]  # the killed server's, again
    with psycopg.connect(first.postgres) as connection:
        job = connection.execute("SELECT state, version, worker FROM fit_jobs WHERE "
                                 "class_code = %s", (code,)).fetchone()
        fits = connection.execute("SELECT version, worker FROM class_fits WHERE class_code = "
                                  "%s", (code,)).fetchall()
        held = connection.execute("SELECT COUNT(*) FROM tosses WHERE class_code = %s",
                                  (code,)).fetchone()[0]
    assert held == count and job[0] == "done" and job[2] is None
    assert job[1] >= count  # a version a toss (and none for a join)
    assert fits == [(job[1], survivor.name)], (fits, job, survivor.name)
    assert survivor.process.poll() is None and first.process.poll() is None
    first.stop()
    survivor.stop()
    for output in (first.process.stderr.read(), "".join(survivor.errors)):
        assert "Traceback" not in output, output


def test_two_teachers_on_one_database_each_see_only_their_class(postgres, page, tmp_path):
    """Two teachers' servers on one PostgreSQL, their fits done by the first server's own fit
    worker (the default) and a separate one: each teacher's projector shows its own class's
    tosses and fit, and the teacher's key of one class opens nothing of the other."""
    require_real()
    for option in ("--fit-worker", "--fit-workers"):  # the laptop's SQLite fits in the server
        status, out, err = Server(tmp_path / "laptop", page, None,
                                  [option] + ["0"] * (option == "--fit-workers")).run()
        assert (status, out) == (2, "") and err == f"bookspin-class: error: {option}: only " \
            "with --postgres (the laptop's SQLite store fits in the server itself)\n", err
        assert not (tmp_path / "laptop").exists()
    url = database(postgres)
    first = Server(tmp_path / "first", page, url, ["--rate", "10000"]).start()
    second = Server(tmp_path / "second", page, url, ["--rate", "10000", "--fit-workers", "0"])
    worker = None
    try:
        second.start(new=True)
        worker = FitWorker(url, 30)
        assert "1 fit worker here" in first.line("fits:")
        assert "no fit worker here" in second.line("fits:")
        posted = {}
        for server, phones in ((first, PHONE[:2]), (second, PHONE[2:])):
            token = server.join("Anna")
            for name in phones:
                status, answer = server.post_toss(token, real_csv(name), name=name)
                assert status == 201, answer
                posted.setdefault(server.code, set()).add(answer["toss"])
        for server, other in ((first, second), (second, first)):
            state = server.fitted_state(len(posted[server.code]), timeout=120)
            shown = {t["toss"] for s in state["students"] for t in s["tosses"]}
            assert state["code"] == server.code and shown == posted[server.code]
            assert state["pooled"]["live"] is False  # the exact fit, after the live estimate
            assert all(t["flights"] for s in state["students"] for t in s["tosses"])
            status, answer = server.request("GET", f"/api/class/{other.code}/state",
                                            token=server.key)
            assert status == 403, answer
        with psycopg.connect(url) as connection:
            rows = dict(connection.execute("SELECT class_code, result FROM class_fits"))
        for code, tosses in posted.items():
            assert json.loads(rows[code])["result"]["recordings"] == len(tosses)
    finally:
        if worker is not None:
            worker.stop()
        second.stop()
        first.stop()
