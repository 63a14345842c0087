"""The class server (docs/class.md) as a class meets it: a real `bookspin-class` on 127.0.0.1,
real HTTPS clients posting the real recordings of ../shared/recordings-real/, the store SQLite
and a real PostgreSQL the tests start (every test of the suite runs on both: the `server`
fixture's parameter). The projector's pooled fit against `bookspin fit` of the downloaded set,
to the digit; SIGKILL and restart against every 201; each hostile request against the store's
row counts; the teacher's key against the students' tokens."""
import copy
import http.client
import io
import json
import os
import pathlib
import socket
import ssl
import subprocess
import threading
import time
import uuid
import zipfile

import pytest

from class_server import require_packages  # noqa: E402

require_packages('aiohttp', 'psycopg', 'segno')
import segno  # noqa: E402

from class_server import Server, in_ci, real_csv, restamped, require_real
from class_start_shared import page, postgres  # noqa: F401  (the fixtures)
from conftest import cli_error_line, read_csv, run_cli

PHONE = ["12-10-56", "12-13-01", "12-13-51"]  # the bare phone's recordings (their README)
PLATE = "12-22-44"                             # another body: the phone on a plate


@pytest.fixture(params=["sqlite", "postgres"])
def make_server(request, tmp_path, page, postgres):
    """make_server(extra=()) -> a started Server on a fresh store of the parameter's kind."""
    made = []

    def make(extra=(), new=False, data=None):
        url = None
        if request.param == "postgres":
            if isinstance(postgres, str):
                if in_ci():
                    pytest.fail(f"PostgreSQL could not start: {postgres}")
                pytest.skip(f"PostgreSQL could not start: {postgres}")
            url = postgres.new_database() if not made else made[0].postgres
        server = Server(data or tmp_path / f"data{len(made)}", page, url, extra)
        made.append(server)
        return server.start(new=new)

    yield make
    for server in made:
        server.stop()


def post_real(server, token, name, toss=None):
    status, answer = server.post_toss(token, real_csv(name), name=name, toss=toss)
    assert status == 201, answer
    return answer


def cli_fit_of_download(server, folder):
    """`bookspin fit` of the set the teacher downloads: its body row and toss rows."""
    status, data = server.request("GET", f"/api/class/{server.code}/download", token=server.key)
    assert status == 200
    with zipfile.ZipFile(io.BytesIO(data)) as archive:
        archive.extractall(folder)
    files = sorted(str(p) for p in pathlib.Path(folder).glob("class-*/*.csv"))  # not left-out/
    run_cli("fit", *files, "-o", pathlib.Path(folder) / "out")
    body = next((pathlib.Path(folder) / "out").glob("*-fit-body.csv"))
    tosses = next(p for p in (pathlib.Path(folder) / "out").glob("*-fit.csv"))
    return files, read_csv(body), read_csv(tosses)


def test_the_projectors_pooled_fit_is_bookspin_fit_of_the_downloaded_set(make_server, tmp_path):
    require_real()
    server = make_server()
    students = {name: server.join(name) for name in ("Anna", "太郎", "Zoë")}
    for (student, token), recording in zip(students.items(), PHONE):
        post_real(server, token, recording)
    plate = post_real(server, students["Anna"], PLATE)
    # The plate is another body: the teacher leaves it out, with the reason.
    status, answer = server.request("POST", f"/api/class/{server.code}/tosses/{plate['toss']}"
                                    "/exclude", {"reason": "another body (a plate)"},
                                    token=server.key)
    assert status == 200, answer
    state = server.fitted_state(3)
    files, body, tosses = cli_fit_of_download(server, tmp_path / "set")
    assert len(files) == 3
    pooled = state["pooled"]
    assert pooled["ratios"][:2] == [float(body["I1_over_I3"][0]), float(body["I2_over_I3"][0])]
    assert pooled["sigma"][:2] == [float(body["I1_sigma"][0]), float(body["I2_sigma"][0])]
    # Each student's toss: its flights' half periods are the command's rows, to the digit.
    shown = {}
    for student in state["students"]:
        for toss in student["tosses"]:
            for flight in toss["flights"]:
                shown[(toss["file"][:-4], flight["toss_in_set"])] = flight
            if toss["excluded"]:
                assert toss["excluded"] == "another body (a plate)" and toss["flights"] == []
            assert toss["in_fit"] is (toss["excluded"] is None), toss
    assert len(shown) == len(tosses["toss"]) > 0
    for i, number in enumerate(tosses["toss"]):
        flight = shown[(tosses["recording"][i], int(number))]
        for column, key in (("half_period_measured", "half_period_measured"),
                            ("half_period_predicted", "half_period_predicted"),
                            ("half_period_predicted_sigma", "sigma")):
            cell = tosses[column][i]
            assert flight[key] == (float(cell) if cell != "" else None), (column, i)
    names = {s["name"] for s in state["students"]}
    assert names == {"Anna", "太郎", "Zoë"}
    # Put back, the plate is pooled again: four recordings, and the download holds four.
    status, _ = server.request("POST", f"/api/class/{server.code}/tosses/{plate['toss']}"
                               "/include", {}, token=server.key)
    assert status == 200
    # Until the refit holds it, the plate's line is of no fit ("fitting…", never "no flight").
    plate_of = lambda s: next(t for st in s["students"] for t in st["tosses"]  # noqa: E731
                              if t["toss"] == plate["toss"])
    assert plate_of(server.state())["in_fit"] is False
    assert plate_of(server.fitted_state(4))["in_fit"] is True
    status, data = server.request("GET", f"/api/class/{server.code}/download", token=server.key)
    assert len(zipfile.ZipFile(io.BytesIO(data)).namelist()) == 4


def test_a_student_reads_only_the_pooled_body_and_their_own_tosses(make_server):
    require_real()
    server = make_server()
    anna, ben = server.join("Anna"), server.join("Ben")
    mine = post_real(server, anna, PHONE[1])
    post_real(server, ben, PHONE[0])
    status, me = server.request("GET", f"/api/class/{server.code}/me", token=anna)
    assert status == 200 and me["name"] == "Anna"
    assert [t["toss"] for t in me["tosses"]] == [mine["toss"]]
    # The class's body and, where its fit failed, why (the fit's line and the sentence to act
    # on): nothing of another student's.
    assert set(me["pooled"]) == {"tosses", "recordings", "ratios", "sigma", "updated", "error",
                                 "error_summary"}
    status, pooled = server.request("GET", f"/api/class/{server.code}/pooled", token=ben)
    assert status == 200 and set(pooled) == set(me["pooled"])
    # The teacher's views refuse a student's token, and no token at all.
    for method, path in (("GET", "state"), ("GET", "events"), ("GET", "download"),
                         ("GET", "qr.svg"), ("DELETE", "")):
        status, answer = server.request(method, f"/api/class/{server.code}/{path}".rstrip("/"),
                                        token=anna)
        assert status == 403 and "teacher's key" in answer["error"], (path, answer)
        status, answer = server.request(method, f"/api/class/{server.code}/{path}".rstrip("/"))
        assert status == 401 and "teacher's key" in answer["error"], (path, answer)


def test_sigkill_mid_class_and_restart_loses_no_toss_that_got_a_201(make_server):
    require_real()
    server = make_server()
    tokens = [server.join(f"student {i}") for i in range(6)]
    csv = real_csv(PHONE[1])
    held, sent, lock, stop = [], [], threading.Lock(), threading.Event()

    def phone(token):
        while not stop.is_set():
            toss = str(uuid.uuid4())
            with lock:
                sent.append(toss)
                offset = 10.0 * len(sent)  # each phone's recording its own (restamped)
            try:
                status, _ = server.post_toss(token, restamped(csv, offset), name="kill",
                                             toss=toss, timeout=10)
            except (OSError, http.client.HTTPException):
                return  # the server is gone
            if status == 201:
                with lock:
                    held.append(toss)

    threads = [threading.Thread(target=phone, args=(t,)) for t in tokens]
    for thread in threads:
        thread.start()
    deadline = time.monotonic() + 120
    while len(held) < 12:
        assert time.monotonic() < deadline and any(t.is_alive() for t in threads), held
        time.sleep(0.05)
    server.kill()  # mid-class: requests in flight
    stop.set()
    for thread in threads:
        thread.join(timeout=60)
    told = set(held)
    server.start()  # the same store: the class goes on
    stored = {t["toss"] for s in server.state()["students"] for t in s["tosses"]}
    assert told <= stored, told - stored
    assert server.counts()["tosses"] == len(stored)


def hostile_cases(server, other, tmp_path):
    """(what, request kwargs, status, a piece of the reason) of each hostile request."""
    token = server.join("Anna")
    other_token = other.join("Ben", code=other.code)
    held = post_real(server, token, PHONE[0])
    other_held = post_real(other, other_token, PHONE[1])
    csv = real_csv(PHONE[0])
    bad_csv = csv.replace("\n", "\nnot,a,number,row\n", 40).replace(
        "not,a,number,row\n", "", 39)
    code = server.code

    def toss(body_changes, token=token, code=code):
        body = {"toss": str(uuid.uuid4()), "name": "t", "recorded_at": "2022-05-03T12:13:01Z",
                "csv": csv}
        body.update(body_changes)
        return dict(method="POST", path=f"/api/class/{code}/tosses", body=body, token=token)

    big = "x" * (5 * 1024 * 1024)
    return [
        ("oversized body", toss({"csv": big}), 413, "over the limit"),
        ("malformed CSV", toss({"csv": bad_csv, "name": "bad"}), 400, None),
        ("not JSON", dict(method="POST", path=f"/api/class/{code}/tosses", raw=b"{toss",
                          token=token), 400, "not JSON"),
        ("not a UUID", toss({"toss": "1; DROP TABLE tosses"}), 400, "expected a UUID"),
        ("wrong code", toss({}, code="ZZZZZZ"), 404, "no class with code ZZZZZZ"),
        ("wrong code to join", dict(method="POST", path="/api/class/ZZZZZZ/join",
                                    body={"name": "Eve"}), 404, "no class with code"),
        ("no token", toss({}, token=None), 401, "token is needed"),
        ("unknown token", toss({}, token="forged"), 401, "unknown student token"),
        ("another class's token", toss({}, token=other_token), 403, "not of class"),
        ("replay with other bytes", toss({"toss": held["toss"], "name": "changed"}), 409,
         "other contents"),
        ("another class's toss id", toss({"toss": other_held["toss"]}), 409, "another class"),
        ("a held recording again under a new id", toss({}), 409, "the same recording as toss"),
        ("another class's toss left out", dict(
            method="POST", path=f"/api/class/{code}/tosses/{other_held['toss']}/exclude",
            body={"reason": "x"}, token=server.key), 404, "holds no toss"),
        ("another class's teacher key", dict(method="GET", path=f"/api/class/{code}/download",
                                             token=other.key), 403, "not the teacher's key"),
        ("a name with a control character", dict(
            method="POST", path=f"/api/class/{code}/join", body={"name": "Eve\u0007"}), 400,
         "not allowed in a name"),
        ("an empty reason", dict(
            method="POST", path=f"/api/class/{code}/tosses/{held['toss']}/exclude",
            body={"reason": " "}, token=server.key), 400, "empty"),
    ], bad_csv


def test_each_hostile_request_is_refused_with_its_reason_and_nothing_stored(make_server,
                                                                              tmp_path):
    require_real()
    first = make_server()
    first.stop()  # a second class in the same store, served by the same server (one a store)
    other = make_server(new=True, data=first.data)
    server = copy.copy(other)
    server.code, server.key = first.code, first.key
    cases, bad_csv = hostile_cases(server, other, tmp_path)
    for what, kwargs, status, reason in cases:
        before = server.counts()
        got, answer = server.request(kwargs.pop("method"), kwargs.pop("path"), **kwargs)
        assert got == status, (what, got, answer)
        assert isinstance(answer, dict) and set(answer) == {"error"}, (what, answer)
        assert "\n" not in answer["error"]
        if reason:
            assert reason in answer["error"], (what, answer)
        assert server.counts() == before, what
    # The malformed CSV's reason is the fit's reader's own line, as `bookspin fit` prints it.
    (tmp_path / "bad.csv").write_text(bad_csv)
    _, stderr = run_cli("fit", "bad.csv", "-o", "out", cwd=tmp_path, expect=2)
    status, answer = server.post_toss(server.join("Carl"), bad_csv, name="bad")
    assert status == 400 and answer["error"] == cli_error_line(stderr)
    # A replay with the same bytes is the same answer, 200, and stored once.
    token = server.join("Dora")
    toss = str(uuid.uuid4())
    assert server.post_toss(token, real_csv(PHONE[1]), name="d", toss=toss)[0] == 201
    before = server.counts()
    status, answer = server.post_toss(token, real_csv(PHONE[1]), name="d", toss=toss)
    assert (status, answer) == (200, {"toss": toss, "held": True})
    assert server.counts() == before


def test_a_student_holds_at_most_max_tosses(make_server):
    require_real()
    server = make_server(extra=["--max-tosses", "2"])
    token = server.join("Anna")
    post_real(server, token, PHONE[0])
    post_real(server, token, PHONE[1])
    before = server.counts()
    status, answer = server.post_toss(token, real_csv(PHONE[2]), name="third")
    assert status == 403 and "holds 2 tosses, the most one student may" in answer["error"]
    assert server.counts() == before
    post_real(server, server.join("Ben"), PHONE[2])  # another student may


def test_a_slow_client_is_cut_off_and_a_fast_one_is_rate_limited(make_server):
    server = make_server(extra=["--rate", "2", "--head-timeout", "1.5"])
    # Slow-loris: a request head sent a byte at a time, never finished.
    raw = socket.create_connection(("127.0.0.1", server.port), timeout=10)
    tls = server.context.wrap_socket(raw, server_hostname="127.0.0.1")
    started = time.monotonic()
    tls.sendall(b"POST /api/class/X/join HTTP/1.1\r\nHost: 127.0.0.1\r\n")
    answer = b""
    while True:
        try:
            chunk = tls.recv(4096)
        except (ConnectionError, ssl.SSLError):
            break
        if not chunk:
            break
        answer += chunk
        tls.sendall(b"X")
    tls.close()
    assert time.monotonic() - started < 6
    assert answer.startswith(b"HTTP/1.1 408 ") and b'"error"' in answer, answer
    # More than the rate allows: 429 with its reason, and the join not stored.
    before = server.counts()
    statuses = [server.request("POST", "/api/class/ZZZZZZ/join", {"name": "x"})[0]
                for _ in range(12)]
    assert 429 in statuses and set(statuses) <= {404, 429}, statuses
    assert server.counts() == before


def test_ending_a_class_and_old_data_delete_everything(make_server):
    require_real()
    server = make_server()
    post_real(server, server.join("Anna"), PHONE[0])
    assert server.counts()["tosses"] == 1
    status, answer = server.request("DELETE", f"/api/class/{server.code}", token=server.key)
    assert (status, answer) == (200, {"ended": server.code, "deleted": True})
    assert server.counts() == {"classes": 0, "students": 0, "tosses": 0}
    status, _ = server.request("POST", f"/api/class/{server.code}/join", {"name": "x"})
    assert status == 404
    # A class older than --keep-days is deleted when the server starts.
    server.stop()
    server.start(new=True)
    old = server.code
    post_real(server, server.join("Ben"), PHONE[0])
    server.stop()
    server.execute("UPDATE classes SET created = created - 3 * 86400")
    server.extra = ["--keep-days", "2"]
    server.start()  # deletes the old class, then starts a new one (none is left to go on)
    assert server.before == [f"bookspin-class: deleted class {old}: older than 2 days"]
    counts = server.counts()
    assert counts["students"] == 0 and counts["tosses"] == 0 and counts["classes"] == 1


def test_bad_options_exit_2_in_one_line_naming_the_option_and_write_nothing(tmp_path, page):
    cases = [(["--port", "http"], "--port"), (["--port", "70000"], "--port"),
             (["--keep-days", "-1"], "--keep-days"), (["--page", str(tmp_path / "no.html")],
                                                       "--page"),
             (["--postgres", "mysql://x"], "--postgres"), (["--rate", "0"], "--rate"),
             (["--max-tosses", "0"], "--max-tosses"), (["--head-timeout", "x"], "--head-timeout"),
             (["--proxy", "nginx.local"], "--proxy"), (["--bogus"], "--bogus")]
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(pathlib.Path(__file__).resolve().parents[2] /
                                             "class"), env.get("PYTHONPATH", "")])
    for args, option in cases:
        data = tmp_path / "data"
        full = ["--data", str(data), "--page", str(page), *args]
        done = subprocess.run([__import__("sys").executable, "-m", "bookspin_class", *full],
                              capture_output=True, text=True, env=env, timeout=60)
        assert done.returncode == 2, (args, done.stderr)
        lines = done.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("bookspin-class: error: "), done.stderr
        assert option in lines[0], (args, lines)
        assert not data.exists()


def test_the_join_screen_holds_the_phones_address_and_never_the_key(make_server, page):
    server = make_server()
    state = server.state()
    assert state["join_url"] == \
        f"https://127.0.0.1:{server.port}/explorer.html?class={server.code}#lab"
    status, svg = server.request("GET", f"/api/class/{server.code}/qr.svg", token=server.key)
    assert status == 200
    out = io.BytesIO()
    segno.make(state["join_url"], error="m", micro=False).save(
        out, kind="svg", scale=10, border=4, dark="#000", light="#fff", xmldecl=False)
    assert svg == out.getvalue()  # the QR code of the phones' address, nothing more
    assert server.key not in state["join_url"] and server.key not in svg.decode()
    # The phones' page is the file given, served whole at /explorer.html; / (the short address
    # a student types) sends to the class's join form (test_class_start.py).
    status, body = server.request("GET", "/explorer.html")
    assert (status, body) == (200, page.read_bytes())
    assert server.request("GET", "/")[0] == 302
    # The teacher's address sets the key as a cookie and opens the projector.
    status, body = server.request("GET", f"/teacher?key={server.key}")
    assert status == 302
    status, body = server.request("GET", "/teacher?key=forged")
    assert status == 403 and body == {"error": "unknown teacher's key"}
    status, body = server.request("GET", f"/projector?class={server.code}")
    assert status == 401


def test_the_projectors_event_stream_shows_each_toss_and_each_refit(make_server):
    require_real()
    server = make_server()
    connection = http.client.HTTPSConnection("127.0.0.1", server.port, context=server.context,
                                             timeout=30)
    connection.request("GET", f"/api/class/{server.code}/events",
                       headers={"Authorization": f"Bearer {server.key}"})
    response = connection.getresponse()
    assert response.status == 200
    assert response.getheader("Content-Type").startswith("text/event-stream")

    deadline = time.monotonic() + 90  # the stream sends a comment every 15 s at least

    def next_state():
        event = None
        for line in response:
            assert time.monotonic() < deadline, "the stream did not show it within 90 s"
            if line.startswith(b"event: "):
                event = line[7:].strip()
            elif line.startswith(b"data: "):
                assert event == b"class"
                return json.loads(line[6:])
        raise AssertionError("the stream ended")

    assert next_state()["students"] == []
    token = server.join("Anna")
    # The join on the stream (after, maybe, the state again as it was: the server's notices
    # connecting on PostgreSQL refresh its projectors, notices.listen).
    while [s["name"] for s in next_state()["students"]] != ["Anna"]:
        pass
    held = post_real(server, token, PHONE[1])
    # The toss is on the stream as soon as it is held, then again with its refit's numbers.
    while True:
        state = next_state()
        tosses = state["students"][0]["tosses"]
        if tosses and tosses[0]["toss"] == held["toss"]:
            if state["pooled"]["ratios"] is not None and not state["pooled"]["fitting"]:
                break
    assert tosses[0]["flights"] and tosses[0]["half_period_measured"] is not None
    connection.close()


def test_a_store_gone_wrong_is_an_internal_error_in_one_line(make_server):
    require_real()
    server = make_server()
    token = server.join("Anna")
    server.execute("DROP TABLE tosses")  # the store broken under the server's feet
    status, answer = server.post_toss(token, real_csv(PHONE[0]), name="t")
    assert (status, answer) == (500, {"error": "internal error (the server's terminal says "
                                               "more)"})
    assert server.process.poll() is None  # and it goes on serving, the store too
    assert server.request("GET", "/explorer.html")[0] == 200
    assert server.join("Ben")
