"""A school's server (docs/class.md, "A school's server"): several `bookspin-class` processes on
one real PostgreSQL 15 (started by the test, as Python.class_server does), real HTTPS clients
posting the real recordings of ../shared/recordings-real/. The toss numbers allotted by the
database under concurrent posts through two processes; a toss held by one process on the other's
projector stream (LISTEN/NOTIFY); the laptop's SQLite store made before the counter goes on."""
import concurrent.futures
import contextlib
import http.client
import json
import os
import pathlib
import shutil
import socket
import ssl
import subprocess
import time
import uuid

import pytest

try:
    import aiohttp  # noqa: F401
    import psycopg
    import segno  # noqa: F401
except ImportError as missing_package:
    if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
        raise
    pytest.skip(f"the class server's packages are missing ({missing_package}): "
                "scripts/install-deps.sh", allow_module_level=True)

from class_server import (PG_BIN, REAL, Server, free_port, in_ci, real_csv, restamped,
                          require_real)
from class_start_shared import page, postgres  # noqa: F401  (the fixtures)

PHONE = ["12-10-56", "12-13-01", "12-13-51"]  # the bare phone's recordings (their README)


def database(postgres):
    """A fresh database of the tests' PostgreSQL (class_start_shared.postgres), or skip saying
    why it could not start (a failure under CI=true)."""
    if isinstance(postgres, str):
        pytest.skip(f"PostgreSQL could not start: {postgres}")
    return postgres.new_database()


@pytest.fixture
def two_servers(postgres, page, tmp_path):
    """Two server processes on one PostgreSQL database: the first teaching class A, the second
    started with --new (class B); either serves the API of every class of the database."""
    url = database(postgres)
    first = Server(tmp_path / "first", page, url, ["--rate", "10000"]).start()
    second = Server(tmp_path / "second", page, url, ["--rate", "10000"])
    try:
        second.start(new=True)
        yield first, second
    finally:
        second.stop()
        first.stop()


def test_two_servers_on_one_postgres_allot_distinct_toss_numbers(two_servers):
    """Tosses of one class posted at once through two processes: every one 201 and held once,
    their numbers (the set's file names) 1..N, none twice. A read-then-write of MAX(seq) gave
    two a number and the second a 500 (UNIQUE (class_code, seq))."""
    require_real()
    first, second = two_servers
    assert first.code != second.code
    count = 24
    tokens = [first.join(f"student {i}") for i in range(count)]
    texts = [restamped(real_csv(PHONE[i % 3]), 50.0 * i) for i in range(count)]

    def post(i):
        via = (first, second)[i % 2]  # alternately through each process, class A's code
        return via.post_toss(tokens[i], texts[i], name=f"toss {i}", code=first.code)

    with concurrent.futures.ThreadPoolExecutor(count) as pool:
        answers = list(pool.map(post, range(count)))
    assert [status for status, _ in answers] == [201] * count, answers
    with psycopg.connect(first.postgres) as connection:
        seqs = [row[0] for row in connection.execute(
            "SELECT seq FROM tosses WHERE class_code = %s ORDER BY seq", (first.code,))]
        counter = connection.execute("SELECT next_seq FROM classes WHERE code = %s",
                                     (first.code,)).fetchone()[0]
    assert seqs == list(range(1, count + 1)) and counter == count
    files = sorted(t["file"] for s in first.state()["students"] for t in s["tosses"])
    assert len(set(files)) == count


def test_a_third_server_may_not_go_on_with_a_class_another_serves(two_servers, tmp_path, page):
    """Two teachers never share a class: the advisory lock of the server that serves it."""
    first, second = two_servers
    for code in (first.code, second.code):
        third = Server(tmp_path / f"third-{code}", page, first.postgres, ["--class", code])
        status, _, err = third.run()
        assert status == 1 and f"class {code} is served by another bookspin-class" in err, err


def test_a_sqlite_store_made_before_the_counter_goes_on_numbering(tmp_path, page):
    """A laptop's store of before classes.next_seq: the column is added at start, set to the
    class's highest toss number, and the next toss is numbered after it."""
    require_real()
    server = Server(tmp_path / "data", page, None).start()
    try:
        token = server.join("Anna")
        for name in PHONE[:2]:
            status, answer = server.post_toss(token, real_csv(name), name=name)
            assert status == 201, answer
    finally:
        server.stop()
    server.execute("ALTER TABLE classes DROP COLUMN next_seq")  # as a store of before it
    server.start()
    try:
        status, answer = server.post_toss(server.join("Ben"), real_csv(PHONE[2]), name="c")
        assert status == 201, answer
        files = sorted(t["file"] for s in server.state()["students"] for t in s["tosses"])
        assert files == ["Anna-1.csv", "Anna-2.csv", "Ben-3.csv"]
    finally:
        server.stop()


def open_stream(server, code):
    """The teacher's event stream of class `code` on `server`: a function giving its next
    `class` event's data (within `seconds`, else AssertionError)."""
    connection = http.client.HTTPSConnection("127.0.0.1", server.port, context=server.context,
                                             timeout=30)
    connection.request("GET", f"/api/class/{code}/events",
                       headers={"Authorization": f"Bearer {server.key}"})
    response = connection.getresponse()
    assert response.status == 200

    def next_state(seconds=20):
        deadline = time.monotonic() + seconds
        for line in response:
            assert time.monotonic() < deadline, f"nothing new on the stream within {seconds} s"
            if line.startswith(b"data: "):
                return json.loads(line[6:])
        raise AssertionError("the stream ended")

    return connection, next_state


def test_a_toss_held_by_one_server_is_on_the_others_projector(two_servers):
    """Two processes on one PostgreSQL: a student joining and a toss held through the second
    reach the first's projector stream (LISTEN/NOTIFY), refitted there; the class ended through
    the second ends the first's stream."""
    require_real()
    first, second = two_servers
    connection, next_state = open_stream(first, first.code)
    assert next_state()["students"] == []
    token = second.join("Anna", code=first.code)
    # The join on the stream (after, maybe, the state again as it was: the first server's
    # notices connecting refresh its projectors, notices.listen).
    while [s["name"] for s in next_state()["students"]] != ["Anna"]:
        pass
    status, held = second.post_toss(token, real_csv(PHONE[1]), name="a", code=first.code)
    assert status == 201, held
    while True:  # on the first's stream, then with the first's own refit of it
        state = next_state(60)
        tosses = state["students"][0]["tosses"]
        if tosses and tosses[0]["toss"] == held["toss"] and \
                state["pooled"]["ratios"] is not None and not state["pooled"]["fitting"]:
            break
    assert state["pooled"]["recordings"] == 1 and tosses[0]["half_period_measured"]
    status, answer = second.request("DELETE", f"/api/class/{first.code}", token=first.key)
    assert status == 200, answer
    while True:
        state = next_state()
        if state.get("ended"):
            break
    assert state == {"code": first.code, "ended": True}
    connection.close()


class Nginx:
    """Debian's nginx as the school's reverse proxy, started by the test in a scratch folder:
    TLS terminated on 127.0.0.1:`port` with the school's certificate (made here by openssl
    for 127.0.0.1), the requests sent on to the `upstreams` (the servers' https ports) in turn
    from the address 127.0.0.2, X-Forwarded-For appended, the event streams unbuffered. With
    `rate` (requests a second), the proxy's own per-phone limit across every server process
    (docs/class.md, "A school's server": limit_req, 3 × rate at once, refused 429 in the API's
    JSON form)."""

    def __init__(self, folder, port, upstreams, rate=None):
        self.folder, self.port = pathlib.Path(folder), port
        self.folder.mkdir(parents=True, exist_ok=True)
        self.certificate = self.folder / "school.pem"
        subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1",
                        "-subj", "/CN=school", "-addext", "subjectAltName=IP:127.0.0.1",
                        "-keyout", self.folder / "school-key.pem", "-out", self.certificate],
                       check=True, capture_output=True)
        servers = "".join(f"server 127.0.0.1:{port};" for port in upstreams)
        user = "user root root;" if os.geteuid() == 0 else ""
        zone = limit = ""
        if rate is not None:
            zone = f"limit_req_zone $binary_remote_addr zone=phones:1m rate={rate}r/s;"
            limit = (f"limit_req zone=phones burst={3 * rate} nodelay; limit_req_status 429; "
                     "error_page 429 = @too_many;")
        (self.folder / "nginx.conf").write_text(f"""
{user} daemon off; worker_processes 1; pid {self.folder}/nginx.pid;
error_log {self.folder}/error.log;
events {{ worker_connections 256; }}
http {{
  access_log off; client_max_body_size 5m;
  client_body_temp_path {self.folder}/body; proxy_temp_path {self.folder}/proxy;
  fastcgi_temp_path {self.folder}/fastcgi; uwsgi_temp_path {self.folder}/uwsgi;
  scgi_temp_path {self.folder}/scgi;
  upstream class {{ {servers} }}
  {zone}
  server {{
    listen 127.0.0.1:{port} ssl;
    ssl_certificate {self.certificate}; ssl_certificate_key {self.folder}/school-key.pem;
    location @too_many {{
      default_type application/json;
      return 429 '{{"error": "too many requests from $remote_addr: wait a moment (a limit of the proxy)"}}';
    }}
    location / {{
      {limit}
      proxy_pass https://class; proxy_bind 127.0.0.2;
      proxy_http_version 1.1; proxy_set_header Connection "";
      proxy_set_header Host $http_host;
      proxy_set_header X-Forwarded-For $proxy_add_x_forwarded_for;
      proxy_buffering off; proxy_read_timeout 1h;
    }}
  }}
}}
""")
        self.process = subprocess.Popen(["nginx", "-c", self.folder / "nginx.conf", "-p",
                                         self.folder], stderr=subprocess.PIPE, text=True)
        deadline = time.monotonic() + 30
        while True:
            try:
                socket.create_connection(("127.0.0.1", port), timeout=1).close()
                break
            except OSError:
                assert self.process.poll() is None, self.process.stderr.read()
                assert time.monotonic() < deadline, "nginx did not start within 30 s"
                time.sleep(0.1)
        self.context = ssl.create_default_context(cafile=str(self.certificate))

    def request(self, method, path, body=None, token=None, source="127.0.0.3", headers=None):
        """(status, decoded JSON or bytes) of one request through the proxy from `source`."""
        connection = http.client.HTTPSConnection("127.0.0.1", self.port, context=self.context,
                                                 timeout=60, source_address=(source, 0))
        try:
            sent = dict(headers or {})
            if token:
                sent["Authorization"] = f"Bearer {token}"
            data = None if body is None else json.dumps(body).encode("utf-8")
            if data is not None:
                sent["Content-Type"] = "application/json"
            connection.request(method, path, body=data, headers=sent)
            response = connection.getresponse()
            payload = response.read()
            if response.getheader("Content-Type", "").startswith("application/json"):
                payload = json.loads(payload)
            return response.status, payload
        finally:
            connection.close()

    def stop(self):
        self.process.terminate()
        try:
            self.process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self.process.kill()


@contextlib.contextmanager
def behind_nginx(postgres, page, tmp_path, server_rate, proxy_rate=None):
    """Two server processes on one PostgreSQL (--proxy 127.0.0.2, --rate `server_rate`) behind
    nginx (its own per-phone limit `proxy_rate`, or none): (first, second, proxy)."""
    if shutil.which("nginx") is None:
        if in_ci():
            pytest.fail("nginx is not installed (scripts/install-deps.sh: nginx-light)")
        pytest.skip("nginx is not installed (scripts/install-deps.sh: nginx-light)")
    url = database(postgres)
    extra = ["--proxy", "127.0.0.2", "--rate", str(server_rate)]
    first = Server(tmp_path / "first", page, url, extra).start()
    second = Server(tmp_path / "second", page, url, extra)
    proxy = None
    try:
        second.start(new=True)
        proxy = Nginx(tmp_path / "nginx", free_port(), [first.port, second.port], proxy_rate)
        yield first, second, proxy
    finally:
        if proxy is not None:
            proxy.stop()
        second.stop()
        first.stop()


@pytest.fixture
def school(postgres, page, tmp_path):
    """Two server processes on one PostgreSQL behind nginx (--proxy 127.0.0.2, --rate 2)."""
    with behind_nginx(postgres, page, tmp_path, 2) as servers:
        yield servers


def test_behind_nginx_the_rate_limit_sees_each_phone_and_every_toss_is_held_once(school):
    """The school's proxy terminates TLS and sends requests to both processes in turn: a class's
    tosses through it are each held once, on the teacher's stream of the first process; the
    rate limit counts each phone's own address (X-Forwarded-For from the proxy alone), so one
    phone past it leaves the other served, and a forged X-Forwarded-For sent straight to a
    server is not believed."""
    require_real()
    first, second, proxy = school
    code = first.code
    connection, next_state = open_stream(first, code)
    next_state()
    tokens = []
    for i, source in enumerate(("127.0.0.3", "127.0.0.4")):
        status, answer = proxy.request("POST", f"/api/class/{code}/join", {"name": f"p{i}"},
                                       source=source)
        assert status == 201, answer
        tokens.append(answer["token"])
    held = set()
    for i in range(4):  # two tosses a phone, through the proxy to either process
        source = ("127.0.0.3", "127.0.0.4")[i % 2]
        toss = {"toss": str(uuid.uuid4()), "name": f"t{i}", "recorded_at": "2022-05-03T12:13:01Z",
                "csv": restamped(real_csv(PHONE[i % 3]), 40.0 * i)}
        for _ in range(20):  # a phone's outbox: sent again after a 429, a moment later
            status, answer = proxy.request("POST", f"/api/class/{code}/tosses", toss,
                                           token=tokens[i % 2], source=source)
            if status != 429:
                break
            time.sleep(0.5)
        assert status == 201, answer
        held.add(toss["toss"])
    seen = set()
    deadline = time.monotonic() + 60
    while seen != held:
        assert time.monotonic() < deadline, (seen, held)
        state = next_state(60)
        seen = {t["toss"] for s in state["students"] for t in s["tosses"]}
    connection.close()
    with psycopg.connect(first.postgres) as database:
        assert database.execute("SELECT COUNT(*) FROM tosses").fetchone()[0] == 4
    time.sleep(2.0)  # the buckets full again
    # One phone past --rate 2 (6 at once) on each process: refused, naming its own address.
    refused = [answer for status, answer in (proxy.request("GET", "/api/class/XXXXXX/pooled",
                                                           source="127.0.0.3")
                                             for _ in range(24)) if status == 429]
    assert refused and "too many requests from 127.0.0.3:" in refused[-1]["error"], refused
    assert proxy.request("GET", "/explorer.html", source="127.0.0.4")[0] == 200
    # Straight to a server, not from the proxy: X-Forwarded-For is the client's own word.
    refused = [answer for status, answer in (first.request(
        "GET", "/api/class/XXXXXX/pooled", headers={"X-Forwarded-For": "127.0.0.9"})
        for _ in range(12)) if status == 429]
    assert refused and "too many requests from 127.0.0.1:" in refused[-1]["error"], refused


def test_postgres_restarted_the_phones_resent_tosses_are_held_once(postgres, page, tmp_path):
    """PostgreSQL restarted under a class: the requests meeting the lost connections are
    refused 503 in one line (nothing stored; never a 500), the server makes its connections
    again, and each toss a phone's outbox sends again is held once, all on the projector."""
    require_real()
    server = Server(tmp_path / "data", page, database(postgres), ["--rate", "10000"]).start()
    try:
        token = server.join("Anna")
        texts = [restamped(real_csv(PHONE[i % 3]), 30.0 * i) for i in range(5)]
        ids = [str(uuid.uuid4()) for _ in texts]
        for i in range(2):
            assert server.post_toss(token, texts[i], name=f"t{i}", toss=ids[i])[0] == 201
        done = postgres._as_user(PG_BIN / "pg_ctl", "-D", postgres.folder / "db", "-l",
                                 postgres.folder / "log", "-m", "fast", "-w", "-t", "60",
                                 "restart")
        assert done.returncode == 0, done.stderr
        seen = []
        for i in range(2, 5):  # each phone's outbox: the toss sent again until it is held
            deadline = time.monotonic() + 60
            while True:
                status, answer = server.post_toss(token, texts[i], name=f"t{i}", toss=ids[i])
                seen.append((status, answer))
                if status in (200, 201) or time.monotonic() > deadline:
                    break
                time.sleep(0.2)
            assert status in (200, 201), seen
        assert all(s in (200, 201, 503) for s, _ in seen), seen
        refused = [a for s, a in seen if s == 503]
        assert refused and all("cannot be reached: nothing was stored" in a["error"]
                               for a in refused), seen
        with psycopg.connect(server.postgres) as connection:
            held = sorted(r[0] for r in connection.execute("SELECT toss FROM tosses"))
        assert held == sorted(ids)
        shown = {t["toss"] for s in server.state()["students"] for t in s["tosses"]}
        assert shown == set(ids)
        # The server's own fit worker (fit_jobs.py) lost its connections too: it fits them all.
        state = server.fitted_state(len(ids), timeout=300)
        assert {t["toss"] for s in state["students"] for t in s["tosses"] if t["flights"]} == \
            set(ids)
    finally:
        server.stop()
    assert "Traceback" not in server.process.stderr.read()


def test_behind_nginx_a_phone_is_limited_once_across_every_server_process(postgres, page,
                                                                        tmp_path):
    """Each server's own limit counts only what reaches it: behind a proxy that sends a phone's
    requests to both in turn, a phone would get twice --rate. The school's proxy limits each
    phone once (limit_req on its address, docs/class.md "A school's server"): one phone's burst
    is refused past 3 × the rate in all, in the API's JSON form naming its address, while
    another phone is served; the servers' own limits (here 1000) never reached."""
    with behind_nginx(postgres, page, tmp_path, 1000, proxy_rate=2) as (first, _, proxy):
        answers = [proxy.request("GET", "/api/class/XXXXXX/pooled", source="127.0.0.3")
                   for _ in range(24)]
        served = [status for status, _ in answers if status != 429]
        refused = [answer for status, answer in answers if status == 429]
        # Both processes answered (404: no such class), 6 at once and about 2 a second more.
        assert 6 <= len(served) <= 12 and set(served) == {404}, answers
        assert refused and all(isinstance(a, dict) for a in refused), refused
        assert refused[-1]["error"].startswith("too many requests from 127.0.0.3:"), refused
        assert proxy.request("GET", "/explorer.html", source="127.0.0.4")[0] == 200

