"""`bookspin-class` (docs/class.md): the teacher's one command. Reads its options (a bad one:
one line naming it, exit 2, nothing written), opens the store, resumes the latest class or
starts one, prints the phones' address, the class code and the teacher's address with its key,
and serves https until Ctrl-C. Data older than --keep-days is deleted at start and daily."""
import argparse
import asyncio
import pathlib
import secrets
import signal
import socket
import sys
import traceback

from aiohttp import web

PROGRAM = "bookspin-class"


class OptionError(Exception):
    pass


class StoreError(Exception):
    """The store could not be opened (a PostgreSQL that does not answer, a folder not writable)."""


class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise OptionError(message)


def parse_options(argv):
    parser = Parser(prog=PROGRAM, description="Serve the phone lab to a class and show its "
                    "tosses, fitted as one body, on the projector (docs/class.md).")
    parser.add_argument("--data", default="bookspin-class", metavar="DIR",
                        help="folder of the class's SQLite database and certificates "
                             "(default: ./bookspin-class)")
    parser.add_argument("--postgres", metavar="URL",
                        help="keep the class in this PostgreSQL database instead of SQLite "
                             "(postgresql://USER@HOST/DB)")
    parser.add_argument("--port", default="8443", metavar="N", help="https port (default 8443)")
    parser.add_argument("--host", default="0.0.0.0", metavar="ADDR",
                        help="address to listen on (default 0.0.0.0: every interface)")
    parser.add_argument("--address", metavar="ADDR",
                        help="the address phones use (default: this laptop's own on the "
                             "classroom's network)")
    parser.add_argument("--page", default="out/explorer.html", metavar="FILE",
                        help="the explorer page phones get, as `bookspin explore` writes it "
                             "(default out/explorer.html)")
    parser.add_argument("--keep-days", default="7", metavar="N",
                        help="delete classes older than N days, at start and daily (default 7)")
    parser.add_argument("--new", action="store_true",
                        help="start a new class (default: go on with the latest)")
    parser.add_argument("--rate", default="20", metavar="R",
                        help="requests a second per phone, on average (default 20; 3R at once)")
    parser.add_argument("--max-tosses", default="100", metavar="N",
                        help="tosses one student may have held (default 100)")
    parser.add_argument("--head-timeout", default="10", metavar="S",
                        help="seconds a connection has to send a request's head (default 10)")
    options = parser.parse_args(argv)

    def number(option, text, kind, low, high):
        try:
            value = kind(text)
        except ValueError:
            raise OptionError(f"{option}: expected a number, got '{text}'") from None
        if not low <= value <= high:
            raise OptionError(f"{option}: {text} is outside {low}..{high}")
        return value

    options.port = number("--port", options.port, int, 1, 65535)
    options.keep_days = number("--keep-days", options.keep_days, float, 0.01, 3650)
    options.rate = number("--rate", options.rate, float, 0.1, 10000)
    options.max_tosses = number("--max-tosses", options.max_tosses, int, 1, 100000)
    options.head_timeout = number("--head-timeout", options.head_timeout, float, 0.1, 600)
    page = pathlib.Path(options.page)
    if not page.is_file():
        raise OptionError(f"--page: no such file {page} (`bookspin explore SCENE -o out` "
                          "writes out/explorer.html)")
    if options.postgres is not None and not options.postgres.startswith(("postgresql:",
                                                                           "postgres:")):
        raise OptionError(f"--postgres: expected a URL postgresql://…, got '{options.postgres}'")
    data = pathlib.Path(options.data)
    if data.exists() and not data.is_dir():
        raise OptionError(f"--data: {data} is not a folder")
    return options


def lan_address():
    """This laptop's address on its network: the source address of a route to a documentation
    address (a UDP socket connected, nothing sent); 127.0.0.1 where there is none."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        try:
            probe.connect(("192.0.2.1", 9))
            return probe.getsockname()[0]
        except OSError:
            return "127.0.0.1"


def open_store(options):
    from bookspin_class import store
    if options.postgres:
        return store.open_postgres(options.postgres)
    pathlib.Path(options.data).mkdir(parents=True, exist_ok=True)
    return store.open_sqlite(pathlib.Path(options.data) / "class.sqlite3")


async def serve(options, stop):
    from bookspin_class import limits, routes, store, tls
    data = pathlib.Path(options.data)
    try:
        db = open_store(options)
    except Exception as error:  # the driver's own error, whichever driver: one line, exit 1
        raise StoreError(str(error).strip().splitlines()[0] if str(error).strip() else
                         type(error).__name__) from None
    data.mkdir(parents=True, exist_ok=True)
    keep_seconds = options.keep_days * 86400.0
    for code in db.delete_older_than(keep_seconds):
        print(f"{PROGRAM}: deleted class {code}: older than {options.keep_days:g} days",
              flush=True)
    latest = None if options.new else db.latest_class()
    if latest is None:
        code, key = routes.new_class_code(), secrets.token_urlsafe(24)
        while db.class_exists(code):
            code = routes.new_class_code()
        db.add_class(code, key)
        started = "started"
    else:
        (code, key), started = latest, "goes on"
    address = options.address or lan_address()
    names = [address] + [n for n in ("127.0.0.1", "localhost") if n != address]
    context, ca_file = tls.server_context(data, names)
    rate = limits.RateLimit(options.rate, 3 * options.rate)
    limits.HeadDeadlineHandler.head_seconds = options.head_timeout
    host_part = f"[{address}]" if ":" in address else address
    server = routes.ClassServer(db, f"https://{host_part}:{options.port}",
                                pathlib.Path(options.page), rate)
    server.ca_file = ca_file
    server.integrity_errors = store.integrity_errors()
    server.max_tosses = options.max_tosses

    @web.middleware
    async def guard(request, handler):
        limits.mark_head_seen(request)
        client = request.remote or "?"
        try:
            if not rate.allow(client):
                raise limits.refuse(429, f"too many requests from {client}: at most "
                                         f"{options.rate:g} a second")
            response = await handler(request)
        except web.HTTPException as error:
            if error.content_type != "application/json" and error.status >= 400:
                reason = error.reason if error.status != 413 else \
                    f"request body over the limit of {limits.MAX_BODY} bytes"
                error = limits.refuse(error.status, f"{reason}: {request.method} "
                                                    f"{request.path[:80]}")
            if error.status < 400:
                raise
            response = error
        except (asyncio.CancelledError, ConnectionResetError):
            raise
        except Exception as error:
            # The machine's state (a full disk, a read-only store) in its own words, 507/503;
            # a bug or a store gone: 500 in one line, the trace on the terminal.
            failed = store.failure(error, db.description)
            if failed is not None:
                print(f"{PROGRAM}: {request.method} {request.path[:80]}: {failed[1]} ({error})",
                      file=sys.stderr, flush=True)
                response = web.json_response({"error": failed[1]}, status=failed[0])
            else:
                traceback.print_exc()
                response = web.json_response({"error": "internal error (the server's terminal "
                                                       "says more)"}, status=500)
        response.headers.setdefault("X-Content-Type-Options", "nosniff")
        response.headers.setdefault("Referrer-Policy", "no-referrer")
        return response

    app = web.Application(middlewares=[guard], client_max_size=limits.MAX_BODY)
    routes.add_routes(app, server)
    runner = limits.GuardedRunner(app, keepalive_timeout=15.0, access_log=None)
    await runner.setup()
    site = web.TCPSite(runner, options.host, options.port, ssl_context=context,
                       shutdown_timeout=1.0, backlog=256)
    await site.start()
    print(f"{PROGRAM}: class {code} {started} ({db.description})", flush=True)
    print(f"  phones join:  {server.join_url(code)}", flush=True)
    print(f"  class code:   {code}", flush=True)
    print(f"  projector:    https://127.0.0.1:{options.port}/teacher?key={key}  "
          "(on this laptop; the key is the teacher's alone)", flush=True)
    print(f"  certificate:  https://{host_part}:{options.port}/ca.pem  (docs/class.md)",
          flush=True)
    for known in db.class_codes():
        server.fit_of(known).request()  # the held tosses fitted again after a restart

    async def daily():
        while True:
            await asyncio.sleep(86400.0)
            for old in db.delete_older_than(keep_seconds):
                server.fits.pop(old, None)
                print(f"{PROGRAM}: deleted class {old}: older than {options.keep_days:g} "
                      "days", flush=True)

    retention = asyncio.get_running_loop().create_task(daily())
    await stop.wait()
    retention.cancel()
    await runner.cleanup()
    db.close()


def main(argv):
    try:
        options = parse_options(argv)
    except OptionError as error:
        print(f"{PROGRAM}: error: {error}", file=sys.stderr)
        return 2
    try:
        # The fit (PYTHONPATH=BUILD/python, as the launcher sets) and numpy, imported here on
        # the main thread: the module's first array would otherwise import numpy in a worker
        # thread while the event loop starts another, which deadlocks on the import lock.
        import bookspin  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as error:
        print(f"{PROGRAM}: error: the bookspin Python module is not found ({error}); run "
              "BUILD/bookspin-class, which sets PYTHONPATH", file=sys.stderr)
        return 2

    async def run():
        stop = asyncio.Event()
        loop = asyncio.get_running_loop()
        for sig in (signal.SIGINT, signal.SIGTERM):
            loop.add_signal_handler(sig, stop.set)
        await serve(options, stop)

    try:
        asyncio.run(run())
    except StoreError as error:
        where = "--postgres" if options.postgres else "--data"
        print(f"{PROGRAM}: error: {where}: cannot open the store: {error}", file=sys.stderr)
        return 1
    except OSError as error:
        print(f"{PROGRAM}: error: {error}", file=sys.stderr)
        return 1
    return 0
