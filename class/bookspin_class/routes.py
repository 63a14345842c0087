"""The HTTP API (docs/class.md, "The API"): the phones' join, toss and read routes, the
teacher's projector, event stream, exclusions, download and end. Every refusal is
{"error": "<one line>"} with a 4xx; a refused request stores nothing."""
import asyncio
import concurrent.futures
import functools
import hashlib
import hmac
import json
import os
import secrets
import uuid

import bookspin
from aiohttp import web

from bookspin_class import limits, pooled, store
from bookspin_class.limits import refuse

TEACHER_COOKIE = "bookspin-teacher"
CODE_ALPHABET = "ABCDEFGHJKLMNPQRSTUVWXYZ23456789"  # no 0/O, 1/I: read from the back of a room


def new_class_code():
    return "".join(secrets.choice(CODE_ALPHABET) for _ in range(6))


def read_toss(csv, file_name):
    """What a toss needs of its own, done once on its arrival in a worker thread (the module
    releases the GIL while it reads, so tosses arriving together are read on every core): the
    recording read as `bookspin fit` reads it and its samples' hash. Raises bookspin.Error."""
    recording = bookspin.read_gyro_csv(csv, file_name)
    return store.samples_sha256(recording)


class ClassServer:
    """The state the routes share: the store, each class's pooled fit and event listeners.
    Every store call and every toss's reading runs in a worker thread (`db`, `work`), never on
    the event loop (docs/class.md, "A school's server")."""

    def __init__(self, store, join_base, page, rate_limit, gate=None):
        self.store = store
        self.join_base = join_base  # https://ADDRESS:PORT (the proxy's, --public-port)
        self.page = page            # the explorer.html served to phones
        self.rate_limit = rate_limit
        # The classes' fits one at a time (a class's own are, pooled.PooledFit): two at once on
        # the 2-core machine fitted a school of 20 classes in 47 s instead of 81 s but held its
        # tosses' path up (worst 6.2 s instead of 4.5 s; docs/performance-class.md, "A lecture hall
        # and a school"): the tosses first.
        self.gate = gate or asyncio.Semaphore(1)
        self.fits = {}              # code -> pooled.PooledFit
        self.listeners = {}         # code -> set of asyncio.Queue
        self.ended = set()          # the queues of the listeners of a class that ended
        self.pushing = {}           # code -> the task pushing the class's state to its listeners
        self.push_again = set()     # codes changed while their state was being made
        # The store's calls (I/O: SQLite's commits wait for the disk) and the tosses' reading
        # (CPU, the GIL released): threads of their own, so that neither waits for the other.
        self.store_threads = concurrent.futures.ThreadPoolExecutor(
            8, thread_name_prefix="bookspin-class-store")
        self.work_threads = concurrent.futures.ThreadPoolExecutor(
            os.cpu_count() or 1, thread_name_prefix="bookspin-class-read")

    async def db(self, call, *args, **kwargs):
        """call(*args, **kwargs) (a store's method, or a function of the store's reads) in a
        store thread."""
        return await asyncio.get_running_loop().run_in_executor(
            self.store_threads, functools.partial(call, *args, **kwargs))

    async def work(self, call, *args):
        return await asyncio.get_running_loop().run_in_executor(
            self.work_threads, functools.partial(call, *args))

    def close(self):
        self.store_threads.shutdown(wait=True, cancel_futures=True)
        self.work_threads.shutdown(wait=False, cancel_futures=True)

    # The class's pooled fit and its listeners.
    def fit_of(self, code):
        """The class's fit: fitted here (pooled.PooledFit), or on PostgreSQL read as the fit
        workers store it (stored_fit.StoredFit, where `jobs` is set)."""
        if code not in self.fits:
            if self.jobs:
                from bookspin_class import fit_jobs, stored_fit
                self.fits[code] = stored_fit.StoredFit(
                    lambda shown: fit_jobs.stored(self.store.read, code, shown), self.db,
                    lambda: self.notify(code))
            else:
                self.fits[code] = pooled.PooledFit(lambda: self.kept_files(code),
                                                   lambda: self.notify(code), self.gate)
        return self.fits[code]

    def kept_files(self, code):
        names = {t["seq"]: t["student_name"] for t in self.store.tosses(code)}
        return {pooled.file_stem(names[seq], seq): text
                for seq, text in self.store.csv_texts(code).items()}

    def notify(self, code):
        """Pushes the class's state to its projectors' streams: made in a store thread, once
        for every change that arrived while the last was being made (a burst of 350 tosses is a
        few states, not 350, each holding every toss held before it was read)."""
        if not self.listeners.get(code):
            return
        if code in self.pushing:
            self.push_again.add(code)
            return
        self.pushing[code] = asyncio.get_running_loop().create_task(self._push(code))

    async def _push(self, code):
        try:
            while True:
                self.push_again.discard(code)
                fit = self.fit_of(code)
                state = await self.db(lambda: json.dumps(self.class_state(code, fit),
                                                         ensure_ascii=False))
                for queue in self.listeners.get(code, ()):
                    queue.put_nowait(state)
                if code not in self.push_again:
                    return
        finally:
            self.pushing.pop(code, None)

    def changed(self, code):
        """A toss arrived, left or came back: tell the projector now, refit (coalesced)."""
        self.fit_of(code).request()
        self.notify(code)

    def remote_change(self, kind, code):
        """A change of class `code` another server on this PostgreSQL committed (notices.listen;
        `kind` join, toss, exclude, end, or fit: a fit worker stored the class's fit): shown on
        this server's projectors as if made here, refitted where this server keeps the class's
        fit."""
        if kind == "end":
            self.fits.pop(code, None)
            self.end_streams(code)
        elif kind == "join":
            self.notify(code)
        elif kind == "fit":  # read again, and shown where it changed (stored_fit.py)
            if code in self.fits:
                self.fits[code].request()
        elif code in self.fits or self.listeners.get(code):
            self.changed(code)

    def refresh(self):
        """Every class this server keeps a fit of or shows, refitted and shown again (the
        notices of other servers reconnected: some may have been missed)."""
        for code in set(self.fits) | {c for c, queues in self.listeners.items() if queues}:
            self.changed(code)

    def end_streams(self, code):
        """Each event stream of the class gets its last event, {"code", "ended": true}."""
        for queue in self.listeners.pop(code, set()):
            queue.put_nowait(json.dumps({"code": code, "ended": True}))
            self.ended.add(queue)

    def join_url(self, code):
        return f"{self.join_base}/explorer.html?class={code}#lab"

    def toss_view(self, fit, toss):
        stem = pooled.file_stem(toss["student_name"], toss["seq"])
        flights = [] if toss["excluded"] is not None else fit.flights.get(stem, [])
        main = next((f for f in flights if f["half_period_measured"] is not None),
                    flights[0] if flights else None)
        return {"toss": toss["toss"], "name": toss["name"], "recorded_at": toss["recorded_at"],
                "file": stem + ".csv", "held": True, "excluded": toss["excluded"],
                "half_period_measured": main and main["half_period_measured"],
                "half_period_predicted": main and main["half_period_predicted"],
                "sigma": main and main["sigma"], "within": main and main["within"],
                # Why the line has no prediction, no ± or no verdict, and the recording's own
                # fit's T/2 beside the class's (docs/class.md, "The class's T/2 and the
                # phone's own"): what a student's phone shows under its tosses.
                "not_predicted": main and main.get("not_predicted"),
                "prediction_interval": main and main.get("prediction_interval"),
                "half_period_measured_alone": main and main.get("half_period_measured_alone"),
                "flights": flights, "judgement": fit.judgements.get(stem),
                # Whether the numbers shown are of a fit that held this toss: a toss just
                # sent or put back waits for the next (docs/class.md, "The projector").
                "in_fit": toss["excluded"] is None and stem in fit.flights}

    def pooled_view(self, fit):
        result = fit.result
        return {"tosses": result["tosses"], "recordings": result["recordings"],
                "ratios": result["ratios"], "sigma": result["sigma"],
                "updated": result["updated"], "error": result.get("error"),
                "error_summary": result.get("error_summary")}

    def class_state(self, code, fit):
        """The whole class as the projector shows it, with its pooled fit `fit` (fit_of(code),
        taken on the event loop). Reads the store: called in a store thread."""
        students = {sid: {"student": sid, "name": name, "tosses": []}
                    for sid, name in self.store.students(code)}
        for toss in self.store.tosses(code):
            students[toss["student"]]["tosses"].append(self.toss_view(fit, toss))
        result = dict(fit.result)
        result["fitting"] = fit.fitting or fit.dirty
        return {"code": code, "join_url": self.join_url(code), "students": list(students.values()),
                "pooled": result, "fits": fit.fits}

    # Who is asking.
    async def teacher(self, request, code, changes=False):
        """Refuses (401/403/404) a request that is not the teacher's of class `code`: the key
        from the teacher's cookie or `Authorization: Bearer KEY`. A request that `changes` the
        class must also come from this server's own pages (docs/class.md, "Limits": OWASP's
        CSRF guidance beside SameSite): its Origin this server's (403 naming a foreign one),
        Sec-Fetch-Site, where sent, same-origin; a request with no Origin (curl, a script) only
        with the key as a Bearer token, never the cookie alone."""
        key = request.cookies.get(TEACHER_COOKIE)
        auth = request.headers.get("Authorization", "")
        bearer = auth.startswith("Bearer ")
        if bearer:
            key = auth[len("Bearer "):]
        if not key:
            raise refuse(401, "the teacher's key is needed (open the teacher's address, in "
                              "DATA/teacher-address.txt on the teacher's laptop)")
        if changes:
            self.same_origin(request, bearer)
        if not key.isascii() or len(key) > 200:
            raise refuse(403, f"this is not the teacher's key of class {code}")
        expected = await self.db(self.store.teacher_key, code)
        if expected is None:
            raise refuse(404, f"no class with code {code}")
        if not hmac.compare_digest(key.encode(), expected.encode()):
            raise refuse(403, f"this is not the teacher's key of class {code}")

    @staticmethod
    def same_origin(request, bearer):
        """Refuses (403) a state-changing request from another origin (teacher's docstring)."""
        origin = request.headers.get("Origin")
        site = request.headers.get("Sec-Fetch-Site")
        own = f"https://{request.host}"
        if origin is not None and origin != own:
            raise refuse(403, f"a request from another origin ({origin[:80]}) may not change "
                              f"the class: the teacher's page is {own[:80]}")
        if site is not None and site != "same-origin":
            raise refuse(403, f"a request from another site (Sec-Fetch-Site: {site[:40]}) may "
                              "not change the class")
        if origin is None and not bearer:
            raise refuse(403, "a request without an Origin may change the class only with the "
                              "teacher's key as Authorization: Bearer KEY")

    async def student(self, request, code):
        auth = request.headers.get("Authorization", "")
        if not auth.startswith("Bearer ") or len(auth) > 200 or not auth.isascii():
            raise refuse(401, "a student's token is needed (Authorization: Bearer TOKEN, from "
                              "joining the class)")
        found = await self.db(self.store.student_of_token, auth[len("Bearer "):])
        if found is None:
            if not await self.db(self.store.class_exists, code):
                raise refuse(404, f"no class with code {code}")
            raise refuse(401, "unknown student token: join the class again")
        student, student_code, name = found
        if student_code != code:
            raise refuse(403, f"this student's token is not of class {code}")
        return student, name

    async def class_code(self, request):
        return await self.db(self.class_code_of, request.match_info["code"])

    def class_code_of(self, code):
        """The class code as typed (any case, with spaces or hyphens: "k7pq 2m") in its
        stored form ("K7PQ2M"), when that class exists; 404 otherwise."""
        typed = code
        code = code.strip().replace(" ", "").replace("-", "").upper()
        if not 0 < len(code) <= 16 or not all(c in CODE_ALPHABET for c in code) or \
                not self.store.class_exists(code):
            shown = json.dumps(typed[:16], ensure_ascii=False)[1:-1]
            raise refuse(404, f"no class with code {shown}")
        return code

    # Phones.
    async def join(self, request):
        code = await self.class_code(request)
        body = await limits.json_body(request)
        name = limits.person_name(body, "name")
        student, token = str(uuid.uuid4()), secrets.token_urlsafe(32)
        await self.db(self.store.add_student, student, code, token, name)
        self.notify(code)
        return web.json_response({"student": student, "token": token, "name": name}, status=201,
                                 dumps=lambda v: json.dumps(v, ensure_ascii=False))

    async def post_toss(self, request):
        code = await self.class_code(request)
        student, _ = await self.student(request, code)
        body = await limits.json_body(request)
        toss = limits.toss_id(body.get("toss"))
        name = limits.person_name(body, "name")
        recorded_at = limits.iso_time(body.get("recorded_at"))
        csv = limits.text_field(body, "csv")
        digest = hashlib.sha256(json.dumps([name, recorded_at, csv]).encode()).hexdigest()
        answer = {"toss": toss, "held": True}
        held = await self.db(self.store.toss, toss)
        if held is None:
            try:
                samples = await self.work(read_toss, csv, f"{name}.csv")
            except bookspin.Error as error:
                raise refuse(400, str(error)) from None
            try:
                await self.db(self.store.add_toss, toss, code, student, name, recorded_at, csv,
                              digest, samples, max_tosses=self.max_tosses)
                self.changed(code)
                return web.json_response(answer, status=201)
            except store.TossRefused as refused:
                raise refuse(refused.status, str(refused)) from None
            except self.integrity_errors:
                held = await self.db(self.store.toss, toss)  # the same id stored a moment ago
                if held is None:
                    raise
        held_code, held_student, held_digest, _, _ = held
        if held_code != code:
            raise refuse(409, f"toss {toss} is held by another class")
        if held_student != student:
            raise refuse(409, f"toss {toss} is held for another student")
        if held_digest != digest:
            raise refuse(409, f"toss {toss} is held already with other contents (a toss is "
                              "never replaced)")
        return web.json_response(answer, status=200)

    async def me(self, request):
        code = await self.class_code(request)
        student, name = await self.student(request, code)
        fit = self.fit_of(code)
        tosses = [self.toss_view(fit, t) for t in await self.db(self.store.tosses, code)
                  if t["student"] == student]
        return web.json_response({"name": name, "tosses": tosses,
                                  "pooled": self.pooled_view(fit)},
                                 dumps=lambda v: json.dumps(v, ensure_ascii=False))

    async def pooled(self, request):
        code = await self.class_code(request)
        await self.student(request, code)
        return web.json_response(self.pooled_view(self.fit_of(code)))

    # The teacher.
    async def teacher_login(self, request):
        key = request.query.get("key", "")
        code = await self.db(self.store.class_of_key, key) if key.isascii() and \
            key.isprintable() and 0 < len(key) <= 200 else None
        if code is None:
            raise refuse(403, "unknown teacher's key")
        response = web.HTTPFound(f"/projector?class={code}")
        response.set_cookie(TEACHER_COOKIE, key, httponly=True, secure=True, samesite="Strict",
                            path="/")
        raise response

    async def state(self, request):
        code = await self.class_code(request)
        await self.teacher(request, code)
        return web.json_response(await self.db(self.class_state, code, self.fit_of(code)),
                                 dumps=lambda v: json.dumps(v, ensure_ascii=False))

    async def events(self, request):
        """Server-sent events: a `class` event with the whole state now and at every change."""
        code = await self.class_code(request)
        await self.teacher(request, code)
        response = web.StreamResponse(headers={"Content-Type": "text/event-stream",
                                               "Cache-Control": "no-store"})
        await response.prepare(request)
        queue = asyncio.Queue()
        self.listeners.setdefault(code, set()).add(queue)
        try:
            fit = self.fit_of(code)
            state = await self.db(lambda: json.dumps(self.class_state(code, fit),
                                                     ensure_ascii=False))
            while True:
                await response.write(f"event: class\ndata: {state}\n\n".encode("utf-8"))
                while True:  # a comment every 15 s keeps proxies and the page's timer content
                    try:
                        state = await asyncio.wait_for(queue.get(), 15.0)
                        break
                    except asyncio.TimeoutError:
                        await response.write(b": still here\n\n")
                while not queue.empty():  # only the latest state matters
                    state = queue.get_nowait()
                if queue in self.ended:  # the class's last event: the stream ends with it
                    await response.write(f"event: class\ndata: {state}\n\n".encode("utf-8"))
                    break
        except (ConnectionResetError, asyncio.CancelledError):
            pass
        finally:  # the class may have ended (end() took its listeners)
            self.listeners.get(code, set()).discard(queue)
            self.ended.discard(queue)
        return response

    async def set_excluded(self, request, reason):
        code = await self.class_code(request)
        await self.teacher(request, code, changes=True)
        toss = limits.toss_id(request.match_info["toss"], "toss id")
        if not await self.db(self.store.set_excluded, code, toss, reason):
            raise refuse(404, f"class {code} holds no toss {toss}")
        self.changed(code)
        return web.json_response({"toss": toss, "excluded": reason},
                                 dumps=lambda v: json.dumps(v, ensure_ascii=False))

    async def exclude(self, request):
        code = await self.class_code(request)
        await self.teacher(request, code, changes=True)  # before the body: a refusal reads none
        body = await limits.json_body(request)
        reason = limits.text_field(body, "reason", max_chars=200).strip()
        if not reason:
            raise refuse(400, '"reason": empty (say why the toss is left out)')
        return await self.set_excluded(request, reason)

    async def include(self, request):
        return await self.set_excluded(request, None)

    async def download(self, request):
        code = await self.class_code(request)
        await self.teacher(request, code)
        set_aside = list(self.fit_of(code).result.get("set_aside") or [])
        data = await self.db(self.set_zip, code, set_aside)
        return web.Response(body=data, content_type="application/zip", headers={
            "Content-Disposition": f'attachment; filename="class-{code}.zip"'})

    def set_zip(self, code, set_aside=()):
        """The class's set as the download's zip (pooled.set_zip), read from the store: the kept
        tosses, and apart each left out with the teacher's reason and each the class's fit set
        aside by itself (`set_aside`, the pooled result's: the same samples held twice, from a
        store of before the door compared samples) with the fit's, so that `bookspin fit
        class-CODE/*.csv` is still the projector's fit (docs/class.md, "The projector")."""
        names = {t["seq"]: t["student_name"] for t in self.store.tosses(code)}
        left_out = {pooled.file_stem(names[seq], seq): held
                    for seq, held in self.store.left_out(code).items()}
        kept = self.kept_files(code)
        for aside in set_aside:
            stem = aside["file"][:-len(".csv")] if aside["file"].endswith(".csv") else None
            if stem in kept:
                left_out[stem] = (kept.pop(stem), "set aside by the class's fit: " +
                                  (aside.get("why_summary") or aside.get("why") or ""))
        return pooled.set_zip(kept, f"class-{code}", left_out)

    async def end(self, request):
        code = await self.class_code(request)
        await self.teacher(request, code, changes=True)
        await self.db(self.store.delete_class, code)
        self.fits.pop(code, None)
        self.end_streams(code)
        return web.json_response({"ended": code, "deleted": True})

    # Pages.
    async def explorer(self, request):
        return web.FileResponse(self.page, headers={"Cache-Control": "no-cache"})

    async def front(self, request):
        """`/`, the short address a student types: the join form of the class being taught
        (302 to its phones' address, docs/class.md "The teacher's steps"); the page alone
        where no class is taught (ended)."""
        if self.taught and await self.db(self.store.class_exists, self.taught):
            raise web.HTTPFound(self.join_url(self.taught)[len(self.join_base):],
                                headers={"Cache-Control": "no-store"})
        return await self.explorer(request)

    integrity_errors = ()
    jobs = False  # the fits are fit workers' jobs (PostgreSQL: fit_jobs.py)
    max_tosses = 100
    taught = None  # the code of the class this server was started for


def add_routes(app, server):
    from bookspin_class import join_screen
    r = app.router
    r.add_get("/", server.front)
    r.add_get("/explorer.html", server.explorer)
    r.add_get("/teacher", server.teacher_login)
    r.add_post("/api/class/{code}/join", server.join)
    r.add_post("/api/class/{code}/tosses", server.post_toss)
    r.add_get("/api/class/{code}/me", server.me)
    r.add_get("/api/class/{code}/pooled", server.pooled)
    r.add_get("/api/class/{code}/state", server.state)
    r.add_get("/api/class/{code}/events", server.events)
    r.add_post("/api/class/{code}/tosses/{toss}/exclude", server.exclude)
    r.add_post("/api/class/{code}/tosses/{toss}/include", server.include)
    r.add_get("/api/class/{code}/download", server.download)
    r.add_delete("/api/class/{code}", server.end)
    join_screen.add_routes(app, server)
