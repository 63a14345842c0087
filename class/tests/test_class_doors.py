"""The class server's doors (docs/class.md, "The API" and "Limits"), as a class and a hostile
client meet them: a real `bookspin-class` on 127.0.0.1 (SQLite and a real PostgreSQL the tests
start, as class/tests/test_class_server.py), real HTTPS clients, the real recordings of
../shared/recordings-real/. The class's set holds every toss; the same samples are held once
whatever their bytes; a client's bad input is a 4xx naming the field with the store unchanged;
every refusal, aiohttp's own too, is {"error": …}; the teacher's changes come from the
teacher's page; and the guards (rate, retention, slow clients) hold what they say."""
import contextlib
import decimal
import http.client
import io
import json
import os
import socket
import sqlite3
import ssl
import subprocess
import sys
import threading
import time
import uuid
import zipfile

import pytest

from class_server import Server, free_port, in_ci, real_csv, restamped
from conftest import SOURCE_DIR, read_csv, run_cli
from test_class_server import (PHONE, PLATE, make_server, page, post_real,  # noqa: F401
                               postgres, require_real)

sys.path.insert(0, str(SOURCE_DIR / "class"))
from bookspin_class import limits  # noqa: E402


@pytest.fixture
def sqlite_server(tmp_path, page):  # noqa: F811
    """sqlite_server(extra=()) -> a started Server on a fresh SQLite store (the doors that do
    not depend on the store)."""
    made = []

    def make(extra=(), data=None, wrap=None):
        server = Server(data or tmp_path / f"data{len(made)}", page, None, extra)
        if wrap:
            server.prefix = list(wrap)
        made.append(server)
        return server.start()

    yield make
    for server in made:
        server.stop()


def teacher_post(server, path, body=None, method="POST", origin="own", headers=None):
    """A teacher's state-changing request as the projector page sends it: the cookie and the
    page's own Origin ("own"), or `origin` as given (None: none)."""
    sent = {"Cookie": f"bookspin-teacher={server.key}"}
    if origin == "own":
        sent["Origin"] = f"https://127.0.0.1:{server.port}"
    elif origin is not None:
        sent["Origin"] = origin
    sent.update(headers or {})
    return server.request(method, path, body, headers=sent)


def download(server):
    status, data = server.request("GET", f"/api/class/{server.code}/download", token=server.key)
    assert status == 200, data
    return zipfile.ZipFile(io.BytesIO(data))


# Nothing lost: the class's set holds every toss.

def test_the_download_holds_every_toss_the_left_out_ones_apart_with_their_reasons(
        make_server, tmp_path):  # noqa: F811
    require_real()
    server = make_server()
    anna, ben = server.join("Anna"), server.join("Бен")
    post_real(server, anna, PHONE[0])
    post_real(server, ben, PHONE[1])
    plate = post_real(server, ben, PLATE)
    reason = "une assiette — another body"
    status, answer = teacher_post(server, f"/api/class/{server.code}/tosses/{plate['toss']}"
                                  "/exclude", {"reason": reason})
    assert status == 200, answer
    state = server.fitted_state(2)
    folder = f"class-{server.code}"
    with download(server) as archive:
        names = sorted(archive.namelist())
        assert names == sorted([f"{folder}/Anna-1.csv", f"{folder}/Бен-2.csv",
                                f"{folder}/left-out/Бен-3.csv", f"{folder}/left-out/README.txt"])
        # Every toss's bytes, as the phone sent them.
        for name, recording in (("Anna-1", PHONE[0]), ("Бен-2", PHONE[1]),
                                ("left-out/Бен-3", PLATE)):
            assert archive.read(f"{folder}/{name}.csv") == real_csv(recording).encode("utf-8")
        readme = archive.read(f"{folder}/left-out/README.txt").decode("utf-8")
        assert f"Бен-3.csv: {reason}" in readme.splitlines()
        archive.extractall(tmp_path / "set")
    # `bookspin fit class-CODE/*.csv` (the kept ones) is the projector's body, to the digit.
    kept = sorted(str(p) for p in (tmp_path / "set" / folder).glob("*.csv"))
    assert len(kept) == 2
    run_cli("fit", *kept, "-o", tmp_path / "out")
    body = read_csv(next((tmp_path / "out").glob("*-fit-body.csv")))
    assert state["pooled"]["ratios"][:2] == [float(body["I1_over_I3"][0]),
                                             float(body["I2_over_I3"][0])]
    assert state["pooled"]["sigma"][:2] == [float(body["I1_sigma"][0]),
                                            float(body["I2_sigma"][0])]


# The same recording twice never breaks the class.

def crlf(csv):
    return csv.replace("\r\n", "\n").replace("\n", "\r\n")


def plain_numbers(csv):
    """The same numbers in another format: every 1.1e-2 written 0.011 (exactly the same value)."""
    lines = csv.splitlines()
    out = [lines[0]]
    for line in lines[1:]:
        out.append(",".join(format(decimal.Decimal(cell), "f") if cell else cell
                            for cell in line.split(",")))
    return "\n".join(out) + "\n"


def test_the_same_samples_under_a_new_id_and_other_bytes_are_refused_naming_the_held_toss(
        make_server):  # noqa: F811
    require_real()
    server = make_server()
    anna, ben = server.join("Anna"), server.join("Ben")
    held = post_real(server, anna, PHONE[1])
    csv = real_csv(PHONE[1])
    assert plain_numbers(csv) != csv and crlf(csv) != csv
    before = server.counts()
    for who, variant in ((anna, crlf(csv)), (ben, plain_numbers(csv)),
                         (ben, crlf(plain_numbers(csv)))):
        status, answer = server.post_toss(who, variant, name="again")
        assert status == 409, answer
        assert answer["error"].startswith(f"the same recording as toss {held['toss']}"), answer
        assert server.counts() == before
    # The class's fit is not broken: one recording, a body.
    state = server.fitted_state(1)
    assert state["pooled"]["error"] is None and state["pooled"]["ratios"] is not None
    # Other samples of the same motion are another recording.
    status, answer = server.post_toss(ben, restamped(csv, 100.0), name="later")
    assert status == 201, answer


def test_a_store_made_before_the_samples_hash_is_migrated_and_refuses_a_copy(
        make_server):  # noqa: F811
    require_real()
    server = make_server()
    anna = server.join("Anna")
    held = post_real(server, anna, PHONE[0])
    server.stop()
    server.execute("ALTER TABLE tosses DROP COLUMN samples_sha256")  # the store as it was
    server.start()
    status, answer = server.post_toss(anna, crlf(real_csv(PHONE[0])), name="again")
    assert status == 409 and held["toss"] in answer["error"], answer
    assert server.counts()["tosses"] == 1


# A toss id is one student's.

def test_a_toss_id_another_student_holds_is_refused_even_with_the_same_contents(
        make_server):  # noqa: F811
    require_real()
    server = make_server()
    anna, ben = server.join("Anna"), server.join("Ben")
    toss = str(uuid.uuid4())
    csv = real_csv(PHONE[0])
    assert server.post_toss(anna, csv, name="t", toss=toss)[0] == 201
    before = server.counts()
    status, answer = server.post_toss(ben, csv, name="t", toss=toss)  # the very same body
    assert status == 409 and "held for another student" in answer["error"], answer
    assert server.counts() == before
    assert server.post_toss(anna, csv, name="t", toss=toss) == (200, {"toss": toss,
                                                                       "held": True})


# No 500 for a client's bad input.

def test_bad_input_is_a_4xx_naming_the_field_and_stores_nothing(make_server):  # noqa: F811
    require_real()
    server = make_server()
    token = server.join("Anna")
    held = post_real(server, token, PHONE[0])
    csv = real_csv(PHONE[1])
    code = server.code

    def toss(**changes):
        body = {"toss": str(uuid.uuid4()), "name": "t", "recorded_at": "2022-05-03T12:13:01Z",
                "csv": csv}
        body.update(changes)
        # ensure_ascii: a lone surrogate goes as JSON's own escape, "\ud800"
        return dict(method="POST", path=f"/api/class/{code}/tosses", token=token,
                    raw=json.dumps(body).encode("ascii"))

    def reason(text):
        return dict(method="POST", path=f"/api/class/{code}/tosses/{held['toss']}/exclude",
                    raw=json.dumps({"reason": text}).encode("ascii"), token=server.key)

    cases = [
        ("a lone surrogate in the CSV", toss(csv=csv[:300] + "\ud800" + csv[300:]), 400,
         '"csv": a lone surrogate U+D800'),
        ("a lone surrogate in the reason", reason("dropped \udfff"), 400,
         '"reason": a lone surrogate U+DFFF'),
        ("a lone surrogate in the name", toss(name="An\ud800na"), 400, '"name"'),
        ("a NUL in the CSV", toss(csv=csv[:300] + "\0" + csv[300:]), 400, '"csv": a NUL'),
        ("a NUL in the reason", reason("dropped\0"), 400, '"reason": a NUL'),
        ("a NUL in the name", toss(name="An\0na"), 400, '"name"'),
        ("a NUL in the time", toss(recorded_at="2022-05-03T12:13:01Z\0"), 400,
         '"recorded_at"'),
        ("a NUL in a name to join", dict(method="POST", path=f"/api/class/{code}/join",
                                         raw=b'{"name": "Eve\\u0000"}'), 400, '"name"'),
        ("a NUL in the code", dict(method="POST", path="/api/class/K7%00PQ/join",
                                   body={"name": "Eve"}), 404, "no class with code"),
        ("a NUL in the teacher's key", dict(method="GET", path="/teacher?key=ab%00cd"), 403,
         "unknown teacher's key"),
        ("100 000 nested arrays", dict(method="POST", path=f"/api/class/{code}/tosses",
                                       raw=b"[" * 100000, token=token), 400,
         "nested too deeply"),
        ("a time that is none", toss(recorded_at="2022-13-45T99:99:99Z"), 400,
         '"recorded_at": expected an ISO 8601 date and time'),
        ("a date that is none", toss(recorded_at="2022-02-30T12:00:00Z"), 400,
         '"recorded_at"'),
    ]
    for what, kwargs, status, piece in cases:
        before = server.counts()
        got, answer = server.request(kwargs.pop("method"), kwargs.pop("path"), **kwargs)
        assert got == status, (what, got, answer)
        assert isinstance(answer, dict) and set(answer) == {"error"}, (what, answer)
        assert "\n" not in answer["error"] and piece in answer["error"], (what, answer)
        assert server.counts() == before, what
    assert server.state()["students"][0]["tosses"][0]["excluded"] is None
    # A real time in another offset is held as sent.
    status, answer = server.post_toss(token, csv, name="t")
    assert status == 201, answer
    server.stop()
    assert "Traceback" not in server.process.stderr.read()


def test_a_class_code_typed_in_lower_case_or_with_spaces_joins(sqlite_server):
    server = sqlite_server()
    typed = f"{server.code[:3].lower()} {server.code[3:].lower()}"
    status, answer = server.request("POST", f"/api/class/{typed.replace(' ', '%20')}/join",
                                    {"name": "Anna"})
    assert status == 201, answer
    status, answer = server.request("POST", f"/api/class/{server.code[:3]}-{server.code[3:]}"
                                    "/join", {"name": "Ben"})
    assert status == 201, answer
    assert [s["name"] for s in server.state()["students"]] == ["Anna", "Ben"]
    status, answer = server.request("POST", "/api/class/zz%20zz/join", {"name": "Eve"})
    assert status == 404 and answer == {"error": "no class with code zz zz"}


# Ending the class: its stream ends, nothing is left.

def open_stream(server, rcvbuf=None):
    """The teacher's event stream on its own connection: (connection, response)."""
    connection = http.client.HTTPSConnection("127.0.0.1", server.port, context=server.context,
                                             timeout=30)
    if rcvbuf:
        raw = socket.socket()
        raw.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, rcvbuf)
        raw.settimeout(30)
        raw.connect(("127.0.0.1", server.port))
        connection.sock = server.context.wrap_socket(raw, server_hostname="127.0.0.1")
    connection.request("GET", f"/api/class/{server.code}/events",
                       headers={"Authorization": f"Bearer {server.key}"})
    response = connection.getresponse()
    assert response.status == 200
    return connection, response


def states(response):
    """Each state the stream sends, until it ends."""
    for line in response:
        if line.startswith(b"data: "):
            yield json.loads(line[6:])


def student_names(server):
    """Every student's name in the store, read beside the server."""
    if server.postgres:
        import psycopg
        with psycopg.connect(server.postgres) as connection:
            return sorted(r[0] for r in connection.execute("SELECT name FROM students"))
    with contextlib.closing(sqlite3.connect(str(server.data / "class.sqlite3"))) as connection:
        return sorted(r[0] for r in connection.execute("SELECT name FROM students"))


def test_ending_the_class_with_the_projector_open_ends_its_stream_and_deletes_every_name(
        make_server):  # noqa: F811
    require_real()
    other = make_server()  # another class in the same store, kept
    post_real(other, other.join("Zoë"), PHONE[2])
    other.stop()
    server = make_server(new=True, data=other.data)
    streams = [open_stream(server) for _ in range(2)]
    for name, recording in (("Anna Ωmega", PHONE[0]), ("Ben Ältere", PHONE[1])):
        post_real(server, server.join(name), recording)
    assert student_names(server) == ["Anna Ωmega", "Ben Ältere", "Zoë"]
    status, answer = teacher_post(server, f"/api/class/{server.code}", method="DELETE")
    assert (status, answer) == (200, {"ended": server.code, "deleted": True})
    for connection, response in streams:
        connection.sock.settimeout(10.0)  # less than the stream's 15 s between comments
        last = list(states(response))[-1]  # the stream ends with the class
        assert last == {"code": server.code, "ended": True}
        connection.close()
    # Every student's name and toss of the ended class is gone; the other class is whole.
    assert student_names(server) == ["Zoë"]
    assert server.counts() == {"classes": 1, "students": 1, "tosses": 1}
    server.stop()
    assert "Traceback" not in server.process.stderr.read()


def test_the_stream_sends_the_latest_state_after_a_burst(sqlite_server):
    server = sqlite_server(extra=["--rate", "10000"])
    # The projector's connection reads nothing for a while (a tiny receive window): the
    # server's writes block and the states queue behind them.
    connection, response = open_stream(server, rcvbuf=2048)
    names = [f"{i:03d} " + "漢" * 76 for i in range(160)]
    for name in names:
        server.join(name)
    time.sleep(1.0)
    connection.sock.settimeout(3.0)
    last = None
    try:
        for state in states(response):
            last = state
            if len(state["students"]) == len(names):
                break
    except (socket.timeout, TimeoutError):
        pass
    connection.close()
    assert last is not None and len(last["students"]) == len(names), \
        len(last["students"]) if last else None


# The teacher's changes come from the teacher's page.

def test_the_teachers_cookie_is_strict_and_changes_need_the_teachers_origin(sqlite_server):
    require_real()
    server = sqlite_server()
    connection = http.client.HTTPSConnection("127.0.0.1", server.port, context=server.context,
                                             timeout=30)
    connection.request("GET", f"/teacher?key={server.key}")
    response = connection.getresponse()
    cookie = response.getheader("Set-Cookie")
    connection.close()
    assert response.status == 302
    parts = {p.strip().split("=")[0].lower(): p.strip() for p in cookie.split(";")}
    assert parts["bookspin-teacher"] == f"bookspin-teacher={server.key}"
    assert parts["samesite"].lower() == "samesite=strict"
    assert {"httponly", "secure"} <= set(parts) and parts["path"] == "Path=/"
    held = post_real(server, server.join("Anna"), PHONE[0])
    exclude = f"/api/class/{server.code}/tosses/{held['toss']}/exclude"
    before = server.counts()
    cases = [
        ("another origin", dict(origin="https://evil.example"), "https://evil.example"),
        ("another port", dict(origin="https://127.0.0.1:1"), "https://127.0.0.1:1"),
        ("no origin, the cookie alone", dict(origin=None), "without an Origin"),
        ("another site", dict(headers={"Sec-Fetch-Site": "cross-site"}), "cross-site"),
    ]
    for what, kwargs, piece in cases:
        for path, body, method in ((exclude, {"reason": "x"}, "POST"),
                                   (exclude.replace("exclude", "include"), {}, "POST"),
                                   (f"/api/class/{server.code}", None, "DELETE")):
            status, answer = teacher_post(server, path, body, method=method, **kwargs)
            assert status == 403 and piece in answer["error"], (what, path, answer)
    assert server.counts() == before
    assert server.state()["students"][0]["tosses"][0]["excluded"] is None
    # The projector's own page (its Origin) and a script with the key as a Bearer token may.
    assert teacher_post(server, exclude, {"reason": "dropped"})[0] == 200
    status, answer = server.request("POST", exclude.replace("exclude", "include"), {},
                                    token=server.key)
    assert status == 200, answer
    status, answer = server.request("POST", exclude, {"reason": "x"}, token=server.key,
                                    headers={"Origin": "https://evil.example"})
    assert status == 403 and "evil.example" in answer["error"]


# Every refusal in the documented form.

def raw_exchange(server, data):
    """Sends `data` on a fresh TLS connection and reads until the server closes it (which it
    may do before all is sent: the sending is a thread's)."""
    raw = socket.create_connection(("127.0.0.1", server.port), timeout=20)
    tls = server.context.wrap_socket(raw, server_hostname="127.0.0.1")

    def send():
        with contextlib.suppress(OSError):
            tls.sendall(data)

    sender = threading.Thread(target=send)
    sender.start()
    answer = b""
    with contextlib.suppress(ConnectionError, ssl.SSLError, socket.timeout):
        while True:
            chunk = tls.recv(65536)
            if not chunk:
                break
            answer += chunk
    sender.join()
    tls.close()
    return answer


def responses(answer):
    """[(status, body)] of each HTTP/1.1 response in `answer` (Content-Length framed)."""
    out = []
    while answer:
        head, _, rest = answer.partition(b"\r\n\r\n")
        lines = head.split(b"\r\n")
        status = int(lines[0].split()[1])
        headers = {k.strip().lower(): v.strip() for k, _, v in
                   (line.decode("latin-1").partition(":") for line in lines[1:])}
        length = int(headers.get("content-length", "0"))
        out.append((status, headers.get("content-type", ""), rest[:length]))
        answer = rest[length:]
    return out


def test_refusals_aiohttp_makes_before_any_handler_are_json(sqlite_server):
    server = sqlite_server()
    host = f"Host: 127.0.0.1:{server.port}\r\n".encode()
    join = f"/api/class/{server.code}/join".encode()
    cases = [
        ("a 10 kB request line", b"GET /" + b"a" * 10240 + b" HTTP/1.1\r\n" + host + b"\r\n"),
        ("a 100 kB header", b"GET / HTTP/1.1\r\n" + host + b"X-Big: " + b"b" * 102400 +
         b"\r\n\r\n"),
        ("a 10 kB token", b"GET /api/class/" + server.code.encode() + b"/me HTTP/1.1\r\n" +
         host + b"Authorization: Bearer " + b"t" * 10240 + b"\r\n\r\n"),
        ("a Content-Length that lies", b"POST " + join + b" HTTP/1.1\r\n" + host +
         b"Content-Type: application/json\r\nContent-Length: 2\r\n\r\n" +
         b'{"name": "Eve"}\r\n\r\n'),
        ("a head that is no HTTP", b"\x16\x03\x01 hello\r\n\r\n"),
    ]
    before = server.counts()
    for what, data in cases:
        answered = responses(raw_exchange(server, data))
        assert answered, what
        for status, content_type, body in answered:
            assert 400 <= status < 500, (what, status, body)
            assert content_type.startswith("application/json"), (what, content_type, body)
            answer = json.loads(body)
            assert set(answer) == {"error"} and "\n" not in answer["error"], (what, answer)
    assert server.counts() == before
    server.stop()
    assert "Traceback" not in server.process.stderr.read()


def unshare_works():
    done = subprocess.run(["unshare", "-rm", "sh", "-c", "mount -t tmpfs -o size=1m tmpfs /mnt"],
                          capture_output=True, text=True)
    return done.returncode == 0, done.stderr.strip()


def test_a_full_disk_and_a_read_only_store_say_so_and_store_nothing(sqlite_server, tmp_path):
    require_real()
    works, why = unshare_works()
    if not works:
        pytest.skip(f"no mount namespace for a small or read-only file system here: {why}")
    # A store on a file system of 400 kB (its own mount namespace: unshare, tmpfs), with the
    # class and certificates of a first start copied in (the test trusts the CA and uses the
    # teacher's key it sees outside the namespace: the class goes on).
    data, side = tmp_path / "small", tmp_path / "tls"
    sqlite_server(data=data).stop()
    server = sqlite_server(data=data, wrap=[
        "unshare", "-rm", "sh", "-c", f'cp -a "{data}/." "{side}" && mount -t tmpfs -o '
        f'size=400k,mode=0700 tmpfs "{data}" && cp -a "{side}/." "{data}" && exec "$@"', "sh"])
    token = server.join("Anna")
    post_real(server, token, PHONE[0])
    big = real_csv(PHONE[1])
    for i in range(1, 12):  # the same motion again and again: 700 kB of one recording
        big = big.rstrip("\n") + "\n" + restamped(real_csv(PHONE[1]), 100.0 * i).split("\n", 1)[1]
    status, answer = server.post_toss(token, big, name="long")
    assert status == 507, answer
    assert answer == {"error": "the server's disk is full: nothing was stored (the teacher "
                               "frees space on the laptop; the phone sends it again)"}
    assert len(server.state()["students"][0]["tosses"]) == 1
    assert server.join("Ben")  # the server goes on
    server.stop()
    assert "Traceback" not in server.process.stderr.read()
    # A store whose file system is mounted read-only: the start says so in one line.
    data = tmp_path / "ro"
    server = sqlite_server(data=data)
    server.stop()
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(SOURCE_DIR / "class"),
                                         env.get("PYTHONPATH", "")])
    done = subprocess.run(
        ["unshare", "-rm", "sh", "-c", f'mount --bind "{data}" "{data}" && mount -o '
         f'remount,bind,ro "{data}" && exec "$@"', "sh", sys.executable, "-m",
         "bookspin_class", "--data", str(data), "--host", "127.0.0.1", "--address",
         "127.0.0.1", "--port", str(free_port()), "--page", str(server.page)],
        capture_output=True, text=True, timeout=60, env=env)
    lines = done.stderr.splitlines()
    assert done.returncode == 1 and len(lines) == 1, done.stderr
    assert "read-only" in lines[0] and str(data / "class.sqlite3") in lines[0], lines


# The guards: rate, retention, slow clients.

def test_the_rate_limit_allows_its_burst_then_its_rate_per_client():
    rate = limits.RateLimit(2.0, 6.0)
    assert [rate.allow("a", now=100.0) for _ in range(7)] == [True] * 6 + [False]
    assert rate.allow("b", now=100.0)  # another phone has its own bucket
    assert not rate.allow("a", now=100.4)  # 0.8 of a request earned
    assert rate.allow("a", now=100.5) and not rate.allow("a", now=100.5)
    # After a long pause, the burst again and no more.
    assert [rate.allow("a", now=1000.0) for _ in range(7)] == [True] * 6 + [False]


def test_a_phone_gets_a_burst_of_three_times_the_rate_then_429(sqlite_server):
    server = sqlite_server(extra=["--rate", "1"])
    statuses = [server.request("POST", "/api/class/ZZZZZZ/join", {"name": "x"})[0]
                for _ in range(5)]  # well within a second: under 1 request earned
    assert statuses == [404, 404, 404, 429, 429], statuses


def test_only_classes_older_than_keep_days_are_deleted(sqlite_server):
    require_real()
    server = sqlite_server()
    old = server.code
    post_real(server, server.join("Anna"), PHONE[0])
    server.stop()
    server.start(new=True)
    young = server.code
    post_real(server, server.join("Ben"), PHONE[1])
    server.stop()
    server.execute(f"UPDATE classes SET created = created - 3 * 86400 WHERE code = '{old}'")
    server.execute(f"UPDATE classes SET created = created - 1 * 86400 WHERE code = '{young}'")
    server.extra = ["--keep-days", "2"]
    server.start()
    assert server.before == [f"bookspin-class: deleted class {old}: older than 2 days"]
    assert server.code == young  # the class a day old goes on, whole
    assert server.counts() == {"classes": 1, "students": 1, "tosses": 1}
    assert [s["name"] for s in server.state()["students"]] == ["Ben"]


def test_a_client_that_sends_its_heads_is_not_cut_off_by_the_head_deadline(sqlite_server):
    server = sqlite_server(extra=["--head-timeout", "1.5"])
    # A kept-alive connection sending a request every 0.5 s for 4 s: every answer 404/201.
    connection = http.client.HTTPSConnection("127.0.0.1", server.port, context=server.context,
                                             timeout=10)
    started = time.monotonic()
    while time.monotonic() - started < 4.0:
        connection.request("GET", "/api/class/ZZZZZZ/pooled")
        response = connection.getresponse()
        assert response.status == 404 and json.loads(response.read())["error"]
        time.sleep(0.5)
    connection.close()
    # The projector's stream outlives the deadline and shows a join after it.
    stream, response = open_stream(server)
    first = next(states(response))
    assert first["students"] == []
    time.sleep(2.5)
    server.join("Anna")
    assert [s["name"] for s in next(states(response))["students"]] == ["Anna"]
    stream.close()
