"""The HTTP API (docs/class.md, "The API"; drafted in /work/notes/class-api.md): the phones'
join, toss and read routes, the teacher's projector, event stream, exclusions, download and end.
Every error is {"error": "<one line>"} with a 4xx; a refused request stores nothing."""
import asyncio
import hashlib
import hmac
import json
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


class ClassServer:
    """The state the routes share: the store, each class's pooled fit and event listeners."""

    def __init__(self, store, join_base, page, rate_limit, gate=None):
        self.store = store
        self.join_base = join_base  # https://ADDRESS:PORT
        self.page = page            # the explorer.html served to phones
        self.rate_limit = rate_limit
        self.gate = gate or asyncio.Semaphore(1)
        self.fits = {}              # code -> pooled.PooledFit
        self.listeners = {}         # code -> set of asyncio.Queue

    # The class's pooled fit and its listeners.
    def fit_of(self, code):
        if code not in self.fits:
            self.fits[code] = pooled.PooledFit(lambda: self.kept_files(code),
                                               lambda: self.notify(code), self.gate)
        return self.fits[code]

    def kept_files(self, code):
        names = {t["seq"]: t["student_name"] for t in self.store.tosses(code)}
        return {pooled.file_stem(names[seq], seq): text
                for seq, text in self.store.csv_texts(code).items()}

    def notify(self, code):
        if not self.listeners.get(code):
            return
        state = json.dumps(self.class_state(code), ensure_ascii=False)
        for queue in self.listeners[code]:
            queue.put_nowait(state)

    def changed(self, code):
        """A toss arrived, left or came back: tell the projector now, refit (coalesced)."""
        self.fit_of(code).request()
        self.notify(code)

    def join_url(self, code):
        return f"{self.join_base}/explorer.html?class={code}#lab"

    def toss_view(self, code, toss):
        fit = self.fit_of(code)
        stem = pooled.file_stem(toss["student_name"], toss["seq"])
        flights = [] if toss["excluded"] is not None else fit.flights.get(stem, [])
        main = next((f for f in flights if f["half_period_measured"] is not None),
                    flights[0] if flights else None)
        return {"toss": toss["toss"], "name": toss["name"], "recorded_at": toss["recorded_at"],
                "file": stem + ".csv", "held": True, "excluded": toss["excluded"],
                "half_period_measured": main and main["half_period_measured"],
                "half_period_predicted": main and main["half_period_predicted"],
                "sigma": main and main["sigma"], "within": main and main["within"],
                "flights": flights, "judgement": fit.judgements.get(stem)}

    def pooled_view(self, code):
        result = self.fit_of(code).result
        return {"tosses": result["tosses"], "recordings": result["recordings"],
                "ratios": result["ratios"], "sigma": result["sigma"],
                "updated": result["updated"]}

    def class_state(self, code):
        """The whole class as the projector shows it."""
        fit = self.fit_of(code)
        students = {sid: {"student": sid, "name": name, "tosses": []}
                    for sid, name in self.store.students(code)}
        for toss in self.store.tosses(code):
            students[toss["student"]]["tosses"].append(self.toss_view(code, toss))
        result = dict(fit.result)
        result["fitting"] = fit.fitting or fit.dirty
        return {"code": code, "join_url": self.join_url(code), "students": list(students.values()),
                "pooled": result, "fits": fit.fits}

    # Who is asking.
    def teacher(self, request, code):
        key = request.cookies.get(TEACHER_COOKIE)
        auth = request.headers.get("Authorization", "")
        if auth.startswith("Bearer "):
            key = auth[len("Bearer "):]
        if not key:
            raise refuse(401, "the teacher's key is needed (open the teacher's address the "
                              "server printed)")
        expected = self.store.teacher_key(code)
        if expected is None:
            raise refuse(404, f"no class with code {code}")
        if not hmac.compare_digest(key.encode(), expected.encode()):
            raise refuse(403, f"this is not the teacher's key of class {code}")

    def student(self, request, code):
        auth = request.headers.get("Authorization", "")
        if not auth.startswith("Bearer ") or len(auth) > 200:
            raise refuse(401, "a student's token is needed (Authorization: Bearer TOKEN, from "
                              "joining the class)")
        found = self.store.student_of_token(auth[len("Bearer "):])
        if found is None:
            if not self.store.class_exists(code):
                raise refuse(404, f"no class with code {code}")
            raise refuse(401, "unknown student token: join the class again")
        student, student_code, name = found
        if student_code != code:
            raise refuse(403, f"this student's token is not of class {code}")
        return student, name

    def class_code(self, request):
        return self.class_code_of(request.match_info["code"])

    def class_code_of(self, code):
        if len(code) > 16 or not self.store.class_exists(code):
            raise refuse(404, f"no class with code {code[:16]}")
        return code

    # Phones.
    async def join(self, request):
        code = self.class_code(request)
        body = await limits.json_body(request)
        name = limits.person_name(body, "name")
        student, token = str(uuid.uuid4()), secrets.token_urlsafe(32)
        self.store.add_student(student, code, token, name)
        self.notify(code)
        return web.json_response({"student": student, "token": token, "name": name}, status=201,
                                 dumps=lambda v: json.dumps(v, ensure_ascii=False))

    async def post_toss(self, request):
        code = self.class_code(request)
        student, _ = self.student(request, code)
        body = await limits.json_body(request)
        toss = limits.toss_id(body.get("toss"))
        name = limits.person_name(body, "name")
        recorded_at = limits.iso_time(body.get("recorded_at"))
        csv = limits.text_field(body, "csv")
        digest = hashlib.sha256(json.dumps([name, recorded_at, csv]).encode()).hexdigest()
        answer = {"toss": toss, "held": True}
        held = self.store.toss(toss)
        if held is None:
            if self.store.student_toss_count(student) >= self.max_tosses:
                raise refuse(403, f"this student holds {self.max_tosses} tosses, the most one "
                                  "student may (--max-tosses)")
            twin = self.store.toss_of_recording(code, store.recording_sha256(csv))
            if twin is not None:  # the fit refuses one recording given twice
                raise refuse(409, f"the same recording as toss {twin}, held already (a "
                                  "toss is held once)")
            try:
                await asyncio.to_thread(bookspin.read_gyro_csv, csv, f"{name}.csv")
            except bookspin.Error as error:
                raise refuse(400, str(error)) from None
            try:
                self.store.add_toss(toss, code, student, name, recorded_at, csv, digest)
                self.changed(code)
                return web.json_response(answer, status=201)
            except self.integrity_errors:
                held = self.store.toss(toss)  # the same id stored a moment ago: judged below
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
        code = self.class_code(request)
        student, name = self.student(request, code)
        tosses = [self.toss_view(code, t) for t in self.store.tosses(code)
                  if t["student"] == student]
        return web.json_response({"name": name, "tosses": tosses,
                                  "pooled": self.pooled_view(code)},
                                 dumps=lambda v: json.dumps(v, ensure_ascii=False))

    async def pooled(self, request):
        code = self.class_code(request)
        self.student(request, code)
        return web.json_response(self.pooled_view(code))

    # The teacher.
    async def teacher_login(self, request):
        key = request.query.get("key", "")
        code = self.store.class_of_key(key) if key else None
        if code is None:
            raise refuse(403, "unknown teacher's key")
        response = web.HTTPFound(f"/projector?class={code}")
        response.set_cookie(TEACHER_COOKIE, key, httponly=True, secure=True, samesite="Strict",
                            path="/")
        raise response

    async def state(self, request):
        code = self.class_code(request)
        self.teacher(request, code)
        return web.json_response(self.class_state(code),
                                 dumps=lambda v: json.dumps(v, ensure_ascii=False))

    async def events(self, request):
        """Server-sent events: a `class` event with the whole state now and at every change."""
        code = self.class_code(request)
        self.teacher(request, code)
        response = web.StreamResponse(headers={"Content-Type": "text/event-stream",
                                               "Cache-Control": "no-store"})
        await response.prepare(request)
        queue = asyncio.Queue()
        self.listeners.setdefault(code, set()).add(queue)
        try:
            state = json.dumps(self.class_state(code), ensure_ascii=False)
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
        except (ConnectionResetError, asyncio.CancelledError):
            pass
        finally:
            self.listeners[code].discard(queue)
        return response

    async def set_excluded(self, request, reason):
        code = self.class_code(request)
        self.teacher(request, code)
        toss = limits.toss_id(request.match_info["toss"], "toss id")
        if not self.store.set_excluded(code, toss, reason):
            raise refuse(404, f"class {code} holds no toss {toss}")
        self.changed(code)
        return web.json_response({"toss": toss, "excluded": reason},
                                 dumps=lambda v: json.dumps(v, ensure_ascii=False))

    async def exclude(self, request):
        body = await limits.json_body(request)
        reason = limits.text_field(body, "reason", max_chars=200).strip()
        if not reason:
            raise refuse(400, '"reason": empty (say why the toss is left out)')
        return await self.set_excluded(request, reason)

    async def include(self, request):
        return await self.set_excluded(request, None)

    async def download(self, request):
        code = self.class_code(request)
        self.teacher(request, code)
        data = pooled.set_zip(self.kept_files(code), f"class-{code}")
        return web.Response(body=data, content_type="application/zip", headers={
            "Content-Disposition": f'attachment; filename="class-{code}.zip"'})

    async def end(self, request):
        code = self.class_code(request)
        self.teacher(request, code)
        self.store.delete_class(code)
        self.fits.pop(code, None)
        for queue in self.listeners.pop(code, set()):
            queue.put_nowait(json.dumps({"code": code, "ended": True}))
        return web.json_response({"ended": code, "deleted": True})

    # Pages.
    async def explorer(self, request):
        return web.FileResponse(self.page, headers={"Cache-Control": "no-cache"})

    integrity_errors = ()
    max_tosses = 100


def add_routes(app, server):
    from bookspin_class import join_screen
    r = app.router
    r.add_get("/", server.explorer)
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
