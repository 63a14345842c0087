"""The class server under a class's load (docs/performance-class.md, "A class at once"): a real
bookspin-class on 127.0.0.1 serving the real explorer page, the teacher's event stream open, and
N phones (default 30) keeping a real recording of ../shared/recordings-real/ each at the same
moment (with --spread S, each at its own moment within the same S seconds, as a lecture hall's
phones keep theirs):
  - K of them (--browsers, default 3) headless Chromium at a phone's size (390x844, touch), each
    opening the class's address (explorer.html?class=CODE#lab), joining under a name, and
    recording a real toss fed sample by sample at its own rate through the sensor override
    (tests/browser/explorer_phone_in_class_test.py and explorer_records_gyro_test.py's helpers:
    the server, its certificate trusted by its key's hash, feed, override, tap); Stop tapped at
    the moment the plain clients post (with --spread, at its own moment). A browser's toss is
    timed from the moment the page kept it (the recording's `when`, new Date() in the
    recorder's keep: the page's wall clock, this machine's) to its first appearance on the
    teacher's stream (time.time(): the same clock);
  - the other N - K plain HTTPS clients, each joining and posting a real recording (the seven
    in turn, each restamped so that no two are the same recording: the fit refuses one given
    twice), timed from their POST's start to its 201 and to the stream, and that path split at
    the moment the server held the toss (the store's `received`): the phone's part (its TLS,
    its 70 kB body, the server's reading and commit) and the server's after it (to the stream).
Then the seconds to the live estimate and to the exact pooled fit that hold every toss; the
server's CPU seconds and peak memory from /proc. With --classes C (a school: docs/performance-class.md,
"A school at once") the store is a PostgreSQL the bench starts (as class/tests/class_server.py
does), C classes are made on it (each by a server started with --new, then stopped), and the
one server serves all of them, PHONES phones in each, the browsers in the first. Prints a
table; run from the repository root:

    PYTHONPATH=build/python python3 bench/class_load.py BUILD_DIR [PHONES] [--browsers K]
        [--classes C] [--postgres] [--spread S [--seed N]]

The page is written by BUILD_DIR/bookspin explore into a scratch folder (its shell built first:
web/build.sh BUILD_DIR); --browsers 0 needs neither it nor Chromium.
"""
import argparse
import datetime
import shutil
import http.client
import json
import os
import pathlib
import random
import statistics
import subprocess
import sys
import tempfile
import threading
import time
import uuid

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("build", type=pathlib.Path, help="the build folder (bookspin, python/)")
parser.add_argument("phones", type=int, nargs="?", default=30, help="phones in all, in each class with --classes (default 30)")
parser.add_argument("--browsers", type=int, default=3,
                    help="how many of them are headless Chromium (default 3)")
parser.add_argument("--fit-wait", type=float, default=600,
                    help="seconds to wait for the pooled fit of every toss (default 600)")
parser.add_argument("--classes", type=int, default=1,
                    help="classes at once, PHONES phones each, on one server and a PostgreSQL "
                         "the bench starts (default 1)")
parser.add_argument("--postgres", action="store_true",
                    help="the store a PostgreSQL the bench starts (with --classes over 1 always)")
parser.add_argument("--processes", type=int, default=1,
                    help="server processes on the PostgreSQL (a school's layout: class k's "
                         "phones post to process k mod P, its projector reads process k+1 mod "
                         "P; default 1)")
parser.add_argument("--workers", type=int, default=0,
                    help="fit workers of their own (bookspin-class --fit-worker), the servers "
                         "then fitting nothing themselves (default 0: each server's own)")
parser.add_argument("--spread", type=float, default=0.0, metavar="SECONDS",
                    help="each phone keeps its toss at its own moment within this window "
                         "(uniform, seeded by --seed), the browsers' Stop tapped likewise; 0, "
                         "the default: all at the same instant")
parser.add_argument("--seed", type=int, default=114,
                    help="the seed of the phones' moments within --spread (default 114)")
parser.add_argument("--keep-set", type=pathlib.Path, metavar="ZIP",
                    help="the first class's set, as the teacher downloads it, written to ZIP "
                         "(to time `bookspin fit` of it apart)")
a = parser.parse_args()
if a.processes < 1 or a.workers < 0 or not 0 <= a.spread <= 600:
    parser.error("--processes must be 1 or more, --workers 0 or more, --spread from 0 to 600")
if not 0 <= a.browsers <= a.phones:
    parser.error(f"--browsers must be from 0 to the phones ({a.phones})")
build = a.build.resolve()
phones, browsers = a.phones, a.browsers
source = pathlib.Path(__file__).resolve().parents[1]
os.environ["BOOKSPIN_SOURCE_DIR"] = str(source)
os.environ["PYTHONPATH"] = os.pathsep.join([str(build / "python"),
                                            os.environ.get("PYTHONPATH", "")])
sys.path[:0] = [str(source / "class" / "tests"), str(source / "tests" / "browser")]
from class_server import REAL, Postgres, Server, real_csv, restamped  # noqa: E402
from browser import find_browser, open_browser, wait_for  # noqa: E402
from explorer_phone_in_class_test import SIZE, RealServer, open_class_page, type_into  # noqa: E402
from explorer_records_gyro_test import feed, feed_at_own_rate, readings, tap  # noqa: E402

names = sorted(p.name for p in REAL.iterdir() if p.is_dir())
# The browsers' recordings: those with the app's full export (time, x, y, z in its columns).
raw = [n for n in names if (REAL / n / "Raw Data.csv").is_file()]
work = pathlib.Path(tempfile.mkdtemp(prefix="bookspin-class-bench-"))
page = work / "page" / "explorer.html"
if browsers:
    chromium, driver_path = find_browser()
    if not (build / "web" / "explorer-shell.html").is_file():
        sys.exit(f"class_load: no page shell in {build}/web: run web/build.sh {build} first")
    subprocess.run([str(build / "bookspin"), "explore", str(source / "scenes" / "exact-unstable-x.toml"),
                    "-o", str(page.parent)], check=True, stdout=subprocess.DEVNULL)
else:
    page.parent.mkdir(parents=True)
    page.write_text("<!doctype html><title>explorer</title>\n")
extra, database = ["--rate", "10000"], None
if a.postgres or a.classes > 1 or a.processes > 1 or a.workers:
    database = Postgres(tempfile.mkdtemp(prefix="bookspin-pg-"))  # its own: the server's user
    why = database.start()
    if why:
        sys.exit(f"class_load: PostgreSQL could not start: {why}")
    extra += ["--postgres", database.new_database()]
if a.workers:
    extra += ["--fit-workers", "0"]
real_server = RealServer(source, build, page, extra=extra)
server = real_server.server
# A school's layout: more server processes on the database (each starting a class of its own,
# unused) and fit workers of their own; the CPU and memory are all of theirs together.
servers = [server] + [Server(work / f"server-{j}", page, extra=extra).start(new=True)
                      for j in range(1, a.processes)]
workers = [subprocess.Popen([sys.executable, "-m", "bookspin_class", "--fit-worker", "--postgres",
                             extra[extra.index("--postgres") + 1]], env=server.environment(),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
           for _ in range(a.workers)]
pids = [s.process.pid for s in servers] + [w.pid for w in workers]
classes = [(server.code, server.key)]
for k in range(1, a.classes):  # each class made by a teacher's server of its own, then stopped
    teacher = Server(work / f"class-{k}", page, extra=extra).start(new=True)
    classes.append((teacher.code, teacher.key))
    teacher.stop()
everyone = phones * a.classes
ticks = os.sysconf("SC_CLK_TCK")


def cpu_seconds():
    total = 0
    for pid in pids:
        fields = pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        # Its own and its children's that ended (the exact fits' processes, fit_process.py).
        total += sum(int(fields[k]) for k in (11, 12, 13, 14))
    return total / ticks


def peak_rss_mib():
    """The sum of each process's peak (an upper bound of the peak of them all at once)."""
    total = 0
    for pid in pids:
        for line in pathlib.Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith("VmHWM:"):
                total += int(line.split()[1]) / 1024
    return total


exact_fits = set()  # the exact fits' processes seen (fit_process.py), by pid


def resident_mib_with_children():
    """The resident memory now of the servers and workers and every process they started,
    summed; the exact fits' processes among those (fit_process.py: spawned) added to
    `exact_fits` as it meets them (one scan of /proc for both)."""
    parent, rss = {}, {}
    for status in pathlib.Path("/proc").glob("[0-9]*/status"):
        try:
            lines = status.read_text().splitlines()
        except OSError:
            continue
        fields = dict(line.split(":", 1) for line in lines if ":" in line)
        pid = int(status.parent.name)
        parent[pid] = int(fields.get("PPid", "0"))
        rss[pid] = int(fields.get("VmRSS", "0 kB").split()[0]) / 1024

    def ours(pid):
        while pid > 1:
            if pid in pids:
                return True
            pid = parent.get(pid, 0)
        return False
    for pid in rss:
        if pid not in pids and ours(pid):
            try:
                if b"spawn_main" in pathlib.Path(f"/proc/{pid}/cmdline").read_bytes():
                    exact_fits.add(pid)
            except OSError:
                pass
    return sum(size for pid, size in rss.items() if ours(pid))


sampled_peak = [0.0]


def sample_memory(stop):
    while not stop.wait(0.5):
        sampled_peak[0] = max(sampled_peak[0], resident_mib_with_children())


sampling = threading.Event()
threading.Thread(target=sample_memory, args=(sampling,), daemon=True).start()
seen, seen_lock, last_pooled = {}, threading.Lock(), [None]
live_at = {}  # class -> when its projector first showed the live estimate of every toss
exact_at = {}  # class -> when it first showed the exact fit's body of every toss (judging on)
fitted = {code: threading.Event() for code, _ in classes}


def listen(code, key, shown_by):
    connection = http.client.HTTPSConnection("127.0.0.1", shown_by.port,
                                             context=shown_by.context)
    connection.request("GET", f"/api/class/{code}/events",
                       headers={"Authorization": f"Bearer {key}"})
    response = connection.getresponse()
    for line in response:
        if not line.startswith(b"data: "):
            continue
        now = time.time()
        state = json.loads(line[6:])
        with seen_lock:
            for student in state["students"]:
                for toss in student["tosses"]:
                    seen.setdefault(toss["toss"], now)
        pooled = last_pooled[0] = state["pooled"]
        if pooled.get("live") and pooled["recordings"] == phones and pooled["ratios"]:
            live_at.setdefault(code, now)
        if not pooled.get("live") and pooled["recordings"] == phones and pooled["ratios"]:
            exact_at.setdefault(code, now)
        if pooled["recordings"] == phones and not pooled["fitting"] and \
                (pooled["ratios"] or pooled["error"]):
            fitted[code].set()
            return


for k, (code, key) in enumerate(classes):
    threading.Thread(target=listen, args=(code, key, servers[(k + 1) % len(servers)]),
                     daemon=True).start()
# The plain phones: (class, number in it), the browsers the first class's first.
plain = [(c, i) for c in range(a.classes) for i in range(browsers if c == 0 else 0, phones)]
tokens = {p: server.join(f"phone {p[1]}", code=classes[p[0]][0]) for p in plain}
# Each plain phone a recording of its own: the real ones in turn, each restamped (the same
# motion, other samples), as the fit refuses one recording given twice. The browsers' are
# re-timed by the browser's clock: none is one of these.
texts = {p: restamped(real_csv(names[p[1] % len(names)]), 100.0 * p[1]) for p in plain}
ids = {p: str(uuid.uuid4()) for p in plain}
sent, answered, statuses = {}, {}, {}
# Each phone's moment after the start (the browsers' keyed by their number): all 0 unless --spread.
moments = random.Random(a.seed)
moment = {p: moments.uniform(0.0, a.spread) for p in plain}
moment.update({b: moments.uniform(0.0, a.spread) for b in range(browsers)})
# Every phone ready (the browsers recording, their readings fed), then all at once: the plain
# clients post and the browsers' Stop is tapped.
go = threading.Barrier(everyone + 1, timeout=900)
recording = threading.Barrier(max(browsers, 1), timeout=600)
# The browsers' recordings (time in s, omega in rad/s), the real ones with the app's export.
fed = [readings(REAL / raw[b % len(raw)] / "Raw Data.csv") for b in range(browsers)]
longest = max((t[-1] - t[0] for t, _ in fed), default=0.0)
problems = []


def phone(i):
    go.wait()
    time.sleep(moment[i])
    sent[i] = time.time()
    statuses[i], _ = servers[i[0] % len(servers)].post_toss(
        tokens[i], texts[i], name=f"toss-{i[1]}", toss=ids[i], code=classes[i[0]][0],
        timeout=600)
    answered[i] = time.time()


kept_at, browser_toss, stopped_at, fed_as = {}, {}, {}, {}


def browser_phone(b):
    """Browser b: the class's page opened, joined, a real recording fed; Stop at the barrier;
    the moment its page kept the toss and the toss's id."""
    try:
        with open_browser(chromium, driver_path, size=SIZE, exact_viewport=True,
                          extra_args=[real_server.trust]) as driver:
            driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
                "width": SIZE[0], "height": SIZE[1], "deviceScaleFactor": 1, "mobile": True})
            driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled",
                                   {"enabled": True, "maxTouchPoints": 5})
            open_class_page(driver, f"{real_server.url}explorer.html?class={server.code}#lab")
            type_into(driver, "className", f"browser {b}")
            tap(driver, "classJoinButton")
            said = wait_for(driver, "return document.getElementById('classState').textContent",
                            lambda s: s.startswith("In class"), 60)
            if not said.startswith("In class"):
                raise RuntimeError(f"browser {b} did not join: {said!r}")
            t, omega = fed[b]
            # Time enough to wait for the others (the recorder's own limit: 20 s unless set).
            driver.execute_script("document.getElementById('labRecordSeconds').value = '120'")
            # The browsers start together, each the later the shorter its recording, so that
            # all end at once: no reading held still at either end while it waits.
            recording.wait()
            time.sleep(longest - (t[-1] - t[0]))
            feed(driver, omega[0])
            tap(driver, "labRecord")
            said = wait_for(driver, "return document.getElementById('labRecordState').textContent",
                            lambda s: s.startswith(("recording", "error")), 60)
            if not said.startswith("recording"):
                raise RuntimeError(f"browser {b}: the recording did not start: {said!r}")
            feed_at_own_rate(driver, t, omega)
            go.wait()
            time.sleep(moment[b])  # the phone still, as after a catch, until its Stop
            stopped_at[b] = time.time()
            tap(driver, "labRecord")
            kept = wait_for(driver, "return window.explorer.labRecordings()", lambda r: len(r) > 0, 120)
            if not kept:
                raise RuntimeError(f"browser {b}: no recording kept")
            when = datetime.datetime.fromisoformat(kept[-1]["when"].replace("Z", "+00:00"))
            kept_at[b] = when.timestamp()
            fed_as[b] = f"{kept[-1]['samples']} samples at {kept[-1]['rate']:.0f} Hz"
            browser_toss[b] = driver.execute_script("return window.explorer.labTossIds()")[kept[-1]["name"]]
            # The page open until its toss is on the stream (its outbox sends it).
            end = time.monotonic() + 120
            while browser_toss[b] not in seen and time.monotonic() < end:
                time.sleep(0.05)
    except BaseException as error:  # noqa: B036 (the bench ends, saying which phone failed)
        problems.append(f"browser {b}: {error!r}")
        recording.abort()
        go.abort()


time.sleep(0.5)
threads = [threading.Thread(target=browser_phone, args=(b,)) for b in range(browsers)]
threads += [threading.Thread(target=phone, args=(i,)) for i in plain]
for thread in threads:
    thread.start()
try:
    go.wait()
except threading.BrokenBarrierError:
    real_server.close()
    shutil.rmtree(work, ignore_errors=True)
    sys.exit(f"class_load: a phone failed: {problems}")
start = time.time()
cpu_before = cpu_seconds()
for thread in threads:
    thread.join()
deadline = time.monotonic() + a.fit_wait
all_fitted = all(event.wait(timeout=max(0.0, deadline - time.monotonic()))
                 for event in fitted.values())
end = time.time()
cpu = cpu_seconds() - cpu_before
peak = peak_rss_mib()
sampling.set()


def held_at():
    """toss id -> the moment a server held it (the store's `received`, stamped by the server on
    this machine's clock as it commits the toss): what splits a toss's path into the phone's
    part (its TLS, its body, the server's reading of it) and the server's after it."""
    if database is not None:
        import psycopg
        with psycopg.connect(extra[extra.index("--postgres") + 1]) as connection:
            return dict(connection.execute("SELECT toss, received FROM tosses").fetchall())
    import sqlite3
    connection = sqlite3.connect(f"file:{server.seen_at / 'class.sqlite3'}?mode=ro", uri=True)
    try:
        return dict(connection.execute("SELECT toss, received FROM tosses").fetchall())
    finally:
        connection.close()


held = held_at()
if a.keep_set:
    status, data = server.request("GET", f"/api/class/{server.code}/download", token=server.key,
                                  timeout=600)
    if status != 200:
        sys.exit(f"class_load: the class's set not downloaded: {status} {data!r}")
    a.keep_set.write_bytes(data)
for worker in workers:
    worker.terminate()
    worker.wait(timeout=60)
for other in servers[1:]:
    other.stop()
real_server.close()
if database is not None:
    database.stop()
    shutil.rmtree(database.folder, ignore_errors=True)
shutil.rmtree(work, ignore_errors=True)

if problems:
    sys.exit(f"class_load: {problems}")
assert [statuses[i] for i in plain] == [201] * len(plain), statuses
missed = [i for i in plain if ids[i] not in seen] + [f"browser {b}" for b in range(browsers)
                                                     if browser_toss.get(b) not in seen]
assert not missed, f"never on the stream: {missed}"


def line(what, values):
    return (f"  {what:<34} median {statistics.median(values):.3f} s, worst {max(values):.3f} s, "
            f"within 2 s: {sum(v <= 2.0 for v in values)}/{len(values)}")


school = f" in {a.classes} classes of {phones} on one PostgreSQL" if a.classes > 1 else \
    (" (PostgreSQL)" if database else "")
when = f"within the same {a.spread:g} s (seed {a.seed})" if a.spread else "at once"
print(f"{everyone} phones keeping a real recording each {when}{school}: {browsers} headless "
      f"Chromium, {len(plain)} plain HTTPS clients ({len(names)} recordings of ../shared/recordings-real/ "
      "in turn)")
if plain:
    print(line("plain: POST to 201", [answered[i] - sent[i] for i in plain]))
    print(line("plain: POST to the event stream", [seen[ids[i]] - sent[i] for i in plain]))
    print(line("plain: POST to held (phone's part)", [held[ids[i]] - sent[i] for i in plain]))
    print(line("plain: held to the event stream", [seen[ids[i]] - held[ids[i]] for i in plain]))
if browsers:
    print("  the browsers' recordings kept: " + "; ".join(
        f"{raw[b % len(raw)]} as {fed_as[b]}" for b in range(browsers)))
    print(line("browser: Stop tapped to kept", [kept_at[b] - stopped_at[b] for b in range(browsers)]))
    print(line("browser: kept to the event stream",
               [seen[browser_toss[b]] - kept_at[b] for b in range(browsers)]))
    print(line("browser: kept to held (phone's part)",
               [held[browser_toss[b]] - kept_at[b] for b in range(browsers)]))
    print(line("browser: held to the event stream",
               [seen[browser_toss[b]] - held[browser_toss[b]] for b in range(browsers)]))
each = f" (each class's {phones})" if a.classes > 1 else ""
# The "within 15 s of the last toss": from the last POST's start or the last browser's
# kept toss, whichever is later.
last = max(list(sent.values()) + list(kept_at.values()))


def since(moment):
    return f"{moment - last:.2f} s after the last toss ({moment - start:.2f} s after the start)"


if live_at:
    print(f"  the live estimate of all {phones}{each}: {since(max(live_at.values()))} "
          "(docs/class.md, \"The projector's numbers\")")
if exact_at and len(exact_at) == len(classes):
    print(f"  the exact fit's body of all {phones}{each}: {since(max(exact_at.values()))} "
          "(each toss's judgement then follows)")
print(f"  the pooled fit of all {phones}{each}: " +
      (since(end) if all_fitted else f"not within {a.fit_wait:g} s") +
      (f" (the fit's error: {last_pooled[0]['error']})" if all_fitted and last_pooled[0]["error"]
       else ""))
aside = (last_pooled[0] or {}).get("set_aside") or []
if aside:  # a recording the fit refused, fitted again without it (docs/class.md)
    print(f"  set aside by the last fit: {len(aside)} ({aside[0]['file']}: {aside[0]['why']})")
layout = f" ({len(servers)} processes, {len(workers)} fit workers)" if pids[1:] else ""
print(f"  server{layout}: {cpu:.2f} CPU seconds over {end - start:.2f} s, peak resident memory "
      f"{peak:.0f} MiB; with the exact fits' processes, sampled every 0.5 s: "
      f"{sampled_peak[0]:.0f} MiB; exact fits started: {len(exact_fits)}")
