"""The class server under a class's load (docs/performance.md, "A class at once"): a real
bookspin-class on 127.0.0.1, the teacher's event stream open, and N phones (plain HTTPS clients,
default 30) each joining and posting a real recording of ../shared/recordings-real/ (in turn, each
restamped so that no two are the same recording) at the same moment. For each toss: the seconds from its POST's start to its 201, and to the first `class`
event that shows it (the projector's stream); then to the pooled fit that holds every toss. The
server's CPU seconds and peak memory from /proc. Prints a table; run from the repository root:

    PYTHONPATH=build/python python3 bench/class_load.py BUILD_DIR [PHONES]
"""
import http.client
import json
import os
import pathlib
import statistics
import sys
import tempfile
import threading
import time
import uuid

build = pathlib.Path(sys.argv[1]).resolve()
phones = int(sys.argv[2]) if len(sys.argv) > 2 else 30
source = pathlib.Path(__file__).resolve().parents[1]
os.environ["BOOKSPIN_SOURCE_DIR"] = str(source)
os.environ["PYTHONPATH"] = os.pathsep.join([str(build / "python"),
                                            os.environ.get("PYTHONPATH", "")])
sys.path[:0] = [str(source / "tests" / "python")]
from class_server import REAL, Server, real_csv, restamped  # noqa: E402

names = sorted(p.name for p in REAL.iterdir() if p.is_dir())
work = pathlib.Path(tempfile.mkdtemp(prefix="bookspin-class-bench-"))
(work / "explorer.html").write_text("<!doctype html><title>explorer</title>\n")
server = Server(work / "data", work / "explorer.html", extra=["--rate", "10000"]).start()
pid = server.process.pid
ticks = os.sysconf("SC_CLK_TCK")


def cpu_seconds():
    fields = pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / ticks


def peak_rss_mib():
    for line in pathlib.Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) / 1024


seen, seen_lock, fitted_all = {}, threading.Lock(), threading.Event()


def listen():
    connection = http.client.HTTPSConnection("127.0.0.1", server.port, context=server.context)
    connection.request("GET", f"/api/class/{server.code}/events",
                       headers={"Authorization": f"Bearer {server.key}"})
    response = connection.getresponse()
    for line in response:
        if not line.startswith(b"data: "):
            continue
        now = time.monotonic()
        state = json.loads(line[6:])
        with seen_lock:
            for student in state["students"]:
                for toss in student["tosses"]:
                    seen.setdefault(toss["toss"], now)
        pooled = state["pooled"]
        if pooled["recordings"] == phones and pooled["ratios"] and not pooled["fitting"]:
            fitted_all.set()
            return


listener = threading.Thread(target=listen, daemon=True)
listener.start()
tokens = [server.join(f"phone {i}") for i in range(phones)]
# Each phone a recording of its own: the real ones in turn, each restamped (the same motion,
# other samples), as the fit refuses one recording given twice.
texts = [restamped(real_csv(names[i % len(names)]), 100.0 * i) for i in range(phones)]
ids = [str(uuid.uuid4()) for _ in range(phones)]
sent, answered, statuses = [0.0] * phones, [0.0] * phones, [0] * phones
go = threading.Barrier(phones + 1)


def phone(i):
    go.wait()
    sent[i] = time.monotonic()
    statuses[i], _ = server.post_toss(tokens[i], texts[i], name=f"toss-{i}", toss=ids[i])
    answered[i] = time.monotonic()


time.sleep(0.5)
cpu_before = cpu_seconds()
threads = [threading.Thread(target=phone, args=(i,)) for i in range(phones)]
for thread in threads:
    thread.start()
go.wait()
start = time.monotonic()
for thread in threads:
    thread.join()
streamed = time.monotonic()
fit_wait = float(os.environ.get("FIT_WAIT", "600"))
fitted = fitted_all.wait(timeout=fit_wait)
end = time.monotonic()
cpu = cpu_seconds() - cpu_before
peak = peak_rss_mib()
server.stop()

assert statuses == [201] * phones, statuses
to_201 = [answered[i] - sent[i] for i in range(phones)]
to_stream = [seen[ids[i]] - sent[i] for i in range(phones)]
print(f"{phones} phones posting a real recording each at once "
      f"({len(names)} recordings of ../shared/recordings-real/ in turn)")
print(f"  POST to 201:              median {statistics.median(to_201):.3f} s, "
      f"worst {max(to_201):.3f} s")
print(f"  POST to the event stream: median {statistics.median(to_stream):.3f} s, "
      f"worst {max(to_stream):.3f} s, within 2 s: "
      f"{sum(t <= 2.0 for t in to_stream)}/{phones}")
print(f"  first POST to the pooled fit of all {phones}: " +
      (f"{end - start:.2f} s" if fitted else f"not within {fit_wait:g} s"))
print(f"  server: {cpu:.2f} CPU seconds over {end - start:.2f} s, peak resident memory "
      f"{peak:.0f} MiB")
