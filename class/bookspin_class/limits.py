"""What a request may be (docs/class.md, "Limits"): its size, its rate per client, how slowly it
may arrive, and the shape of each field. Every refusal is an HTTP error whose body is
{"error": "<one line>"}; nothing is stored for a refused request."""
import asyncio
import datetime
import json
import time
import unicodedata
import uuid

from aiohttp import web
from aiohttp.http_exceptions import LineTooLong
from aiohttp.web_protocol import RequestHandler

MAX_BODY = 4 * 1024 * 1024  # bytes: a toss's JSON (a 60 s recording at 100 Hz is ~2.5 MB)
MAX_NAME = 80               # characters of a student's or a recording's name
BODY_SECONDS = 10.0         # a request's body must arrive within this


def refuse(status, reason):
    """An HTTP error response {"error": reason} with `status` (raised by the handlers); a
    character UTF-8 cannot hold (a lone surrogate quoted from the request) is sent as "?"."""
    reason = reason.encode("utf-8", "replace").decode("utf-8")
    kind = web.HTTPException
    for candidate in (web.HTTPBadRequest, web.HTTPUnauthorized, web.HTTPForbidden,
                      web.HTTPNotFound, web.HTTPConflict, web.HTTPRequestEntityTooLarge,
                      web.HTTPTooManyRequests, web.HTTPRequestTimeout,
                      web.HTTPUnsupportedMediaType, web.HTTPMethodNotAllowed,
                      web.HTTPInternalServerError, web.HTTPServiceUnavailable,
                      web.HTTPInsufficientStorage):
        if candidate.status_code == status:
            kind = candidate
    if kind is web.HTTPRequestEntityTooLarge:
        return kind(max_size=MAX_BODY, actual_size=0, text=json.dumps({"error": reason}),
                    content_type="application/json")
    if kind is web.HTTPMethodNotAllowed:
        return kind("?", [], text=json.dumps({"error": reason}), content_type="application/json")
    return kind(text=json.dumps({"error": reason}, ensure_ascii=False),
                content_type="application/json")


async def json_body(request):
    """The request's JSON object, read within BODY_SECONDS and MAX_BODY bytes; 413, 408 or 400
    otherwise."""
    if request.content_length is not None and request.content_length > MAX_BODY:
        raise refuse(413, f"request body of {request.content_length} bytes is over the limit of "
                          f"{MAX_BODY} bytes")
    try:
        raw = await asyncio.wait_for(request.read(), BODY_SECONDS)
    except asyncio.TimeoutError:
        raise refuse(408, f"request body not received within {BODY_SECONDS:g} s") from None
    except web.HTTPRequestEntityTooLarge:
        raise refuse(413, f"request body over the limit of {MAX_BODY} bytes") from None
    try:
        value = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as error:
        raise refuse(400, f"request body is not JSON in UTF-8: {error}") from None
    except RecursionError:
        raise refuse(400, "request body is not JSON the server reads: arrays or objects nested "
                          "too deeply") from None
    if not isinstance(value, dict):
        raise refuse(400, "request body is not a JSON object")
    return value


def text_field(body, key, max_chars=None, required=True):
    """body[key] as a str of at most max_chars characters that UTF-8 can hold (no lone
    surrogate, which JSON's "\\ud800" makes) and the store can hold (no NUL, which PostgreSQL
    refuses); 400 naming the field otherwise."""
    value = body.get(key)
    if value is None and not required:
        return None
    if not isinstance(value, str):
        raise refuse(400, f'"{key}": expected a string')
    if max_chars is not None and len(value) > max_chars:
        raise refuse(400, f'"{key}": {len(value)} characters, over the limit of {max_chars}')
    return well_formed(value, f'"{key}"')


def well_formed(value, what):
    """`value` when it is text the store holds: UTF-8 (no lone surrogate) without NUL; 400
    naming `what` and the character's place otherwise."""
    try:
        value.encode("utf-8")
    except UnicodeEncodeError as error:
        raise refuse(400, f"{what}: a lone surrogate U+{ord(value[error.start]):04X} at "
                          f"character {error.start + 1} is not text (not UTF-8)") from None
    at = value.find("\0")
    if at >= 0:
        raise refuse(400, f"{what}: a NUL character (U+0000) at character {at + 1} is not "
                          "allowed")
    return value


# The format characters (Unicode's Cf) that ordinary spelling uses, allowed in a name: the
# zero-width non-joiner (Persian, Kurdish, Indic scripts: "می‌خواهم") and joiner (Indic
# half-forms, emoji sequences such as 👩‍🔬). The emoji variation selectors (U+FE0E, U+FE0F) are
# marks (Mn) and allowed as every mark is. Every other Cf is refused: the marks and overrides of
# direction and the isolates (which reorder a name as shown), invisible spaces and hyphens.
SPELLING_FORMAT = {"\u200c", "\u200d"}
# Emoji tag characters (U+E0020..U+E007E, ended by U+E007F CANCEL TAG): allowed only inside a
# flag's tag sequence after U+1F3F4 WAVING BLACK FLAG (🏴󠁧󠁢󠁳󠁣󠁴󠁿, Scotland).
TAG_FLAG, TAG_FIRST, TAG_END = "\U0001f3f4", 0xE0020, "\U000e007f"
# Code points this Python's Unicode (3.11: Unicode 14) does not know yet but a phone's keyboard
# may type: the blocks where new emoji arrive (🩷 U+1FA77, Unicode 15). Other unassigned code
# points are refused.
NEWER_EMOJI = ((0x1F900, 0x1F9FF), (0x1FA70, 0x1FAFF))


def name_problem(name):
    """Why `name` (NFC) cannot be a person's name, or "" when it can: a character not allowed
    (a control character, a format character other than SPELLING_FORMAT and a flag's tags, a
    surrogate, a private-use or unassigned code point, '/' or '\\'), or nothing visible."""
    in_tags = False
    visible = False
    for at, ch in enumerate(name):
        category = unicodedata.category(ch)
        if TAG_FIRST <= ord(ch) <= 0xE007E and (in_tags or (at and name[at - 1] == TAG_FLAG)):
            in_tags = True
            continue
        if ch == TAG_END and in_tags:
            in_tags = False
            continue
        in_tags = False
        allowed_unknown = category == "Cn" and any(a <= ord(ch) <= b for a, b in NEWER_EMOJI)
        if (category in ("Cc", "Cs", "Co", "Cn") and not allowed_unknown) or ch in "/\\" or \
                (category == "Cf" and ch not in SPELLING_FORMAT):
            return f"character U+{ord(ch):04X} is not allowed in a name"
        visible = visible or category[0] in "LNPS" or allowed_unknown
    return "" if visible else "no letter, digit or symbol"


def person_name(body, key="name"):
    """A name in any alphabet (NFC), 1..MAX_NAME characters, as people spell it (name_problem:
    the joiners of Persian and Indic spelling and of emoji allowed), no control characters, no
    marks of direction, no path separators (it becomes part of a file name in the class's set:
    pooled.file_stem). Raises refuse(400, '"KEY": …') otherwise."""
    name = unicodedata.normalize("NFC", text_field(body, key, max_chars=4 * MAX_NAME)).strip()
    if not name:
        raise refuse(400, f'"{key}": empty')
    if len(name) > MAX_NAME:
        raise refuse(400, f'"{key}": {len(name)} characters, over the limit of {MAX_NAME}')
    problem = name_problem(name)
    if problem:
        raise refuse(400, f'"{key}": {problem}')
    return name


def toss_id(value, what='"toss"'):
    """A toss id made on the phone: a UUID (any version), in its canonical lower-case form."""
    try:
        parsed = uuid.UUID(value) if isinstance(value, str) and len(value) <= 40 else None
    except ValueError:
        parsed = None
    if parsed is None:
        raise refuse(400, f"{what}: expected a UUID, got {json.dumps(value)[:60]}")
    return str(parsed)


def iso_time(value):
    """`value` when it is a real ISO 8601 date and time (2022-05-03T12:13:01Z, with or without
    seconds, fraction and offset; Python's datetime.fromisoformat, "Z" read as +00:00): a month
    13 or an hour 99 is refused (400), not only a wrong shape."""
    try:
        ok = isinstance(value, str) and len(value) <= 40 and value.isascii() and \
            value.isprintable() and "T" in value and \
            datetime.datetime.fromisoformat(value[:-1] + "+00:00" if value.endswith("Z")
                                            else value) is not None
    except ValueError:
        ok = False
    if not ok:
        raise refuse(400, f'"recorded_at": expected an ISO 8601 date and time, got '
                          f'{json.dumps(value, ensure_ascii=False)[:60]}')
    return value


class RateLimit:
    """A token bucket per client address: `rate` requests a second on average, `burst` at once;
    past it 429 "too many requests"."""

    def __init__(self, rate, burst):
        self.rate, self.burst = rate, burst
        self.buckets = {}

    def allow(self, client, now=None):
        now = time.monotonic() if now is None else now
        tokens, last = self.buckets.get(client, (self.burst, now))
        tokens = min(self.burst, tokens + (now - last) * self.rate)
        if tokens < 1.0:
            self.buckets[client] = (tokens, now)
            return False
        self.buckets[client] = (tokens - 1.0, now)
        if len(self.buckets) > 10000:  # forget the idle ones
            self.buckets = {k: v for k, v in self.buckets.items() if now - v[1] < 60}
        return True


class HeadDeadlineHandler(RequestHandler):
    """aiohttp's connection handler with a deadline for the first request's head: a connection
    that has not sent a whole request head within `head_seconds` of opening (a slow-loris) gets
    408 {"error": …} and is closed. aiohttp itself closes a kept-alive connection idle (or
    half-sent) for keepalive_timeout, and the handlers bound the body (BODY_SECONDS)."""

    head_seconds = 10.0

    def connection_made(self, transport):
        super().connection_made(transport)
        self.heads_seen = 0
        self._deadline = self._loop.call_later(self.head_seconds, self._head_overdue)

    def _head_overdue(self):
        if self.heads_seen == 0 and self.transport is not None:
            body = json.dumps({"error": f"request head not received within "
                                        f"{self.head_seconds:g} s"}).encode()
            self.transport.write(b"HTTP/1.1 408 Request Timeout\r\nContent-Type: "
                                 b"application/json\r\nConnection: close\r\nContent-Length: " +
                                 str(len(body)).encode() + b"\r\n\r\n" + body)
            transport = self.transport
            self.force_close()  # aiohttp's: closes the transport (and forgets it) where it can
            transport.close()  # closing twice is nothing; a closed transport is never None here

    def connection_lost(self, exc):
        self._deadline.cancel()
        super().connection_lost(exc)

    def handle_error(self, request, status=500, exc=None, message=None):
        """The answer to a request aiohttp refuses before any handler (a head line or header
        over 8190 bytes, a malformed head, a body shorter than its Content-Length followed by
        bytes that are no request): {"error": …} naming the cause, as every refusal is
        (docs/class.md, "The API"), and the connection closed; no traceback for a client's
        bad request."""
        if status >= 500:
            self.log_exception("Error handling request", exc_info=exc)
        if request.writer.output_size > 0:
            raise ConnectionError("Response is sent already, cannot send another response "
                                  "with the error message")
        cause = (message or (str(exc) if exc else "") or "").strip().splitlines()
        cause = cause[0][:160] if cause else ""
        if isinstance(exc, LineTooLong):
            cause = f"a line of the request's head is over {exc.args[1]} bytes (the address, a " \
                    "header or its token too long)"
        elif status == 400:
            cause = "the request is not HTTP the server reads" + (f": {cause}" if cause else "")
        elif status >= 500:
            cause = "internal error (the server's terminal says more)"
        response = web.json_response({"error": cause or f"HTTP {status}"}, status=status)
        response.force_close()
        return response


class GuardedServer(web.Server):
    """aiohttp's low-level server making HeadDeadlineHandler connections."""

    def __call__(self):
        return HeadDeadlineHandler(self, loop=self._loop, **self._kwargs)


class GuardedRunner(web.AppRunner):
    """web.AppRunner whose server makes HeadDeadlineHandler connections (aiohttp 3.8, Debian
    12's: the server object's class is swapped for GuardedServer, which adds no state)."""

    async def _make_server(self):
        server = await super()._make_server()
        server.__class__ = GuardedServer
        return server


def mark_head_seen(request):
    """Tells the connection's deadline that a whole request head arrived."""
    protocol = request.protocol
    if isinstance(protocol, HeadDeadlineHandler):
        protocol.heads_seen += 1
