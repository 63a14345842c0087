"""`bookspin-class` (docs/class.md): the teacher's one command. Reads its options (a bad one:
one line naming it, exit 2, nothing written), binds its port, locks and opens the store, goes on
with the class it taught last (or one chosen, or a new one), writes the teacher's address to
DATA/teacher-address.txt (never to the terminal, which a projector may mirror), prints the
phones' address and the class code, and serves https until Ctrl-C. A start that cannot serve
leaves the store and DATA as it found them. Data older than --keep-days is deleted at start and
daily."""
import asyncio
import errno
import ipaddress
import os
import pathlib
import secrets
import shutil
import signal
import socket
import sys
import time
import traceback
import webbrowser

from bookspin_class.options import (PROGRAM, OptionError, check_imports, import_error_line,
                                    parse_options)

WILDCARDS = ("0.0.0.0", "::")  # --host: every interface


class StoreError(Exception):
    """The store could not be opened (a PostgreSQL that does not answer, a folder not writable)."""


class StartError(Exception):
    """The server cannot serve: `line` says why and what to do; `status` is the exit status
    (2 an option to change, 1 the machine's state)."""

    def __init__(self, line, status):
        super().__init__(line)
        self.status = status


def open_store(options, create=True):
    """The store; None for --list where the SQLite file is not there yet. Raises StoreError."""
    from bookspin_class import store
    path = pathlib.Path(options.data) / "class.sqlite3"
    try:
        if options.postgres:
            return store.open_postgres(options.postgres)
        if not create and not path.is_file():
            return None
        return store.open_sqlite(path)
    except Exception as error:  # the driver's own error, whichever driver: one line, exit 1
        line = str(error).strip().splitlines()[0] if str(error).strip() else \
            type(error).__name__
        if options.postgres:
            raise StoreError(line) from None
        free = shutil.disk_usage(path.parent).free if path.parent.is_dir() else None
        if free is not None and free < 1 << 20:  # SQLite says "disk I/O error" for some
            line += f" (the disk is full: {free // 1024} KiB free)"
        raise StoreError(f"{path}: {line}") from None


def list_classes(options):
    """--list: every class of the store, one a line, the one taught last marked."""
    from bookspin_class import data_folder
    db = open_store(options, create=False)
    if db is None:
        print(f"{PROGRAM}: no classes: {options.data} holds no store yet", flush=True)
        return
    try:
        rows = db.class_list()
    finally:
        db.close()
    taught = data_folder.DataFolder(options.data).taught()
    count = f"{len(rows)} class" if len(rows) == 1 else f"{len(rows)} classes"
    print(f"{PROGRAM}: {count} in {db.description} (--class CODE goes on with one)", flush=True)
    for code, created, students, tosses in rows:
        started = time.strftime("%Y-%m-%d %H:%M", time.localtime(created))
        print(f"  {code}  started {started}  {students} student{'s' * (students != 1)}  "
              f"{tosses} toss{'es' * (tosses != 1)}{'  (taught last)' * (code == taught)}",
              flush=True)


def bind(options):
    """The listening socket, bound before anything is written. Raises StartError."""
    try:
        found = socket.getaddrinfo(options.host, options.port, type=socket.SOCK_STREAM,
                                   flags=socket.AI_PASSIVE)
    except socket.gaierror as error:
        raise StartError(f"--host: {options.host!r} does not resolve ({error.strerror}): give "
                         "an address of this laptop, e.g. --host 0.0.0.0 (every interface)",
                         2) from None
    family, _, _, _, address = found[0]
    try:
        return socket.create_server(address, family=family, backlog=256, dualstack_ipv6=(
            family == socket.AF_INET6 and options.host == "::" and socket.has_dualstack_ipv6()))
    except OSError as error:
        if error.errno == errno.EADDRINUSE:
            raise StartError(f"--port: {options.port} is in use by another program (another "
                             "bookspin-class?): stop it, or choose another --port", 1) from None
        if error.errno == errno.EADDRNOTAVAIL:
            raise StartError(f"--host: {options.host} is not an address of this laptop (`ip "
                             "addr` lists them; --host 0.0.0.0 listens on every one)",
                             2) from None
        if error.errno == errno.EACCES:
            raise StartError(f"--port: {options.port} needs root (a port under 1024): choose "
                             "1024 or over, e.g. --port 8443", 2) from None
        raise StartError(f"--host {options.host} --port {options.port}: cannot listen: "
                         f"{error.strerror}", 1) from None


def phones_address(options):
    """(the address phones are sent to, [the laptop's other addresses], why phones cannot reach
    it or None): --address, else --host where it is one address, else the best of the laptop's
    interfaces (addresses.reachable_addresses), else 127.0.0.1."""
    from bookspin_class import addresses
    if options.address:
        return options.address, [], None
    if options.host not in WILDCARDS:
        try:
            host = ipaddress.ip_address(options.host)
        except ValueError:
            host = None
        if host is not None and host.is_loopback:
            return str(host), [], (f"the server listens on --host {host}, this laptop alone; "
                                   "--host 0.0.0.0 listens on every interface")
        if host is not None:
            return str(host), [], None
    found = addresses.reachable_addresses()
    if not found:
        return "127.0.0.1", [], ("this laptop has no network but its own (loopback, "
                                 "127.0.0.1); join the classroom's Wi-Fi or start the laptop's "
                                 "hotspot, then start again (or give --address)")
    return found[0].address, found[1:], None


def teacher_host(options, address):
    """The host of the teacher's address, opened on this laptop: 127.0.0.1 where the server
    listens on every interface or on loopback."""
    if options.host in WILDCARDS or options.host in ("127.0.0.1", "localhost"):
        return "127.0.0.1"
    return address


def url_host(host):
    return f"[{host}]" if ":" in host else host


def origin(host, port):
    """https://HOST:PORT, the port left out where it is https's own (443)."""
    return f"https://{url_host(host)}" + ("" if port == 443 else f":{port}")


async def start(options, folder):
    """Binds, locks DATA, opens the store, chooses the class, makes the certificate and writes
    the teacher's address: (runner, the state to serve) ready. On any failure what was made is
    removed (the caller's folder.undo()) and nothing is added to the store."""
    from aiohttp import web
    from bookspin_class import data_folder, limits, routes, store, tls
    sock = bind(options)
    db = None
    try:
        try:
            folder.open()
        except data_folder.InUse as error:
            by = f" (process {error.pid})" if error.pid else ""
            raise StartError(f"--data: {folder.path} is in use by another bookspin-class{by}: "
                             "stop it first, or give another --data", 1) from None
        except OSError as error:
            read_only = store.read_only_reason(folder.path / "class.sqlite3")
            if read_only is not None:  # the store's own words, as a request that meets it
                raise StartError(f"--data: the store {folder.path / 'class.sqlite3'} is "
                                 f"read-only ({read_only})", 1) from None
            raise StartError(f"--data: cannot write in {folder.path}: {error.strerror}",
                             1) from None
        db = open_store(options)
        where = "--postgres" if options.postgres else "--data"
        keep_seconds = options.keep_days * 86400.0
        expired = {code for code, created, _, _ in db.class_list()
                   if created < time.time() - keep_seconds}
        if options.class_code:
            code = options.class_code
            if code in expired or not db.class_exists(code):
                raise StartError(f"--class: no class {code} in {db.description} (--list lists "
                                 "them)", 2)
        elif options.new:
            code = None
        else:
            taught = folder.taught()
            latest = db.latest_class()
            code = taught if taught and taught not in expired and db.class_exists(taught) \
                else latest and latest[0] not in expired and latest[0] or None
        if code is None:
            code, key, started = routes.new_class_code(), secrets.token_urlsafe(24), "started"
            while db.class_exists(code):
                code = routes.new_class_code()
        else:
            key, started = db.teacher_key(code), "goes on"
        if not db.claim_class(code):
            raise StartError(f"{where}: class {code} is served by another bookspin-class on "
                             "this database: stop it, or --new starts another class", 1)

        address, others, unreachable = phones_address(options)
        laptop = teacher_host(options, address)
        names = list(dict.fromkeys([address, laptop, "127.0.0.1", "localhost"]))
        context, ca_file = tls.server_context(folder.path, names)
        # Behind the school's proxy (--public-port) the teacher, as the phones, comes through it.
        teacher_url = (origin(laptop, options.port) if options.public_port is None else
                       origin(address, options.public_port)) + f"/teacher?key={key}"
        folder.write(data_folder.TEACHER_ADDRESS, teacher_url + "\n")
        folder.write(data_folder.TAUGHT, code + "\n")
        if started == "started":
            try:
                db.add_class(code, key)
            except Exception as error:  # the driver's own error (a full disk): one line
                raise StartError(f"{where}: cannot store the new class: "
                                 f"{str(error).strip() or type(error).__name__}", 1) from None

        rate = limits.RateLimit(options.rate, 3 * options.rate)
        limits.HeadDeadlineHandler.head_seconds = options.head_timeout
        server = routes.ClassServer(db, origin(address, options.public_port or options.port),
                                    pathlib.Path(options.page), rate)
        server.ca_file = ca_file
        server.integrity_errors = store.integrity_errors()
        server.max_tosses = options.max_tosses
        server.taught = code
        server.jobs = bool(options.postgres)  # the fits are fit workers' jobs (fit_jobs.py)
        app = web.Application(middlewares=[guard_middleware(options, rate, db)],
                              client_max_size=limits.MAX_BODY)
        routes.add_routes(app, server)
        runner = limits.GuardedRunner(app, keepalive_timeout=15.0, access_log=None)
        try:
            await runner.setup()
            await web.SockSite(runner, sock, ssl_context=context, shutdown_timeout=1.0,
                               backlog=256).start()
        except BaseException:
            if started == "started":
                db.delete_class(code)
            await runner.cleanup()
            raise
    except BaseException:
        sock.close()
        if db is not None:
            db.close()
        raise
    for old in sorted(expired):
        db.delete_class(old)
        print(f"{PROGRAM}: deleted class {old}: older than {options.keep_days:g} days",
              flush=True)
    return runner, server, (code, started, address, others, unreachable)


def client_address(request, proxy):
    """The phone's address, for the rate limit: the connection's, or where the connection is
    the school's reverse proxy's (--proxy) the last address of X-Forwarded-For (the one the
    proxy appended: what came before it the phone may have written itself). A forwarded header
    from any other address is ignored."""
    remote = request.remote or "?"
    if proxy is None:
        return remote
    try:
        if ipaddress.ip_address(remote) != proxy:
            return remote
    except ValueError:
        return remote
    forwarded = request.headers.getall("X-Forwarded-For", [])
    last = ",".join(forwarded).split(",")[-1].strip() if forwarded else ""
    try:
        return str(ipaddress.ip_address(last))
    except ValueError:
        return remote


def guard_middleware(options, rate, db):
    """Every request: the rate limit, errors as {"error": …} (docs/class.md, "The API"), a
    bug as a 500 in one line with the trace on the terminal, and two safe headers. `db` is the
    store, whose errors of the machine's state are named (store.failure)."""
    from aiohttp import web
    from bookspin_class import limits, store

    @web.middleware
    async def guard(request, handler):
        limits.mark_head_seen(request)
        client = client_address(request, options.proxy)
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

    return guard


def open_in_browser(uri):
    """Opens `uri` in this laptop's browser (Python's webbrowser: $BROWSER, else the desktop's);
    False where there is none, or no desktop (a text browser would take the terminal over)."""
    if not any(os.environ.get(name) for name in ("BROWSER", "DISPLAY", "WAYLAND_DISPLAY")):
        return False
    try:
        return webbrowser.open(uri)
    except webbrowser.Error:
        return False


def announce(options, folder, server, chosen):
    """The terminal's lines: everything but the teacher's key, which a projector mirroring the
    laptop's screen would show the class (docs/class.md, "The teacher's steps")."""
    from bookspin_class import data_folder
    code, started, address, others, unreachable = chosen
    address_file = folder.path / data_folder.TEACHER_ADDRESS
    print(f"{PROGRAM}: class {code} {started} ({server.store.description})", flush=True)
    print(f"  phones join:  {server.join_url(code)}", flush=True)
    print(f"  class code:   {code}", flush=True)
    if options.open and open_in_browser(address_file.read_text(encoding="utf-8").strip()):
        print(f"  projector:    opened in this laptop's browser (its address, with the "
              f"teacher's key, is in {address_file})", flush=True)
    else:
        why = "no browser found: " if options.open else ""
        print(f"  projector:    {why}open the address in {address_file} on this laptop (it "
              "holds the teacher's key: not shown here; --open opens it)", flush=True)
    print(f"  certificate:  {server.join_base}/ca.pem  (docs/class.md)", flush=True)
    if options.postgres:
        workers = f"{options.fit_workers} fit worker{'s' * (options.fit_workers != 1)} here" \
            if options.fit_workers else "no fit worker here"
        print(f"  fits:         jobs in the database, taken by {workers} and each "
              "`bookspin-class --fit-worker` on it", flush=True)
    if others:
        listed = ", ".join(f"{a.address} ({a.interface})" for a in others)
        print(f"  other addresses: {listed}: --address ADDR sends phones to one", flush=True)
    if unreachable:
        print(f"{PROGRAM}: NO ADDRESS PHONES CAN REACH: {unreachable}", flush=True)
    print(f"  Ctrl-C stops the server; started again on this store it goes on with class "
          f"{code}", flush=True)


async def serve(options, stop):
    from bookspin_class import data_folder
    folder = data_folder.DataFolder(options.data)
    try:
        runner, server, chosen = await start(options, folder)
    except BaseException:
        folder.undo()
        raise
    announce(options, folder, server, chosen)
    for known in server.store.class_codes():
        server.fit_of(known).request()  # the held tosses fitted again after a restart
    keep_seconds = options.keep_days * 86400.0

    async def daily():
        while True:
            await asyncio.sleep(86400.0)
            for old in await server.db(server.store.delete_older_than, keep_seconds):
                server.fits.pop(old, None)
                print(f"{PROGRAM}: deleted class {old}: older than {options.keep_days:g} "
                      "days", flush=True)

    retention = asyncio.get_running_loop().create_task(daily())
    listening = None
    if options.postgres:  # the other servers' changes on this database (notices.py)
        from bookspin_class import notices
        listening = asyncio.get_running_loop().create_task(notices.listen(
            options.postgres, server.store.instance, server.remote_change, server.refresh))
    working = None
    if options.postgres and options.fit_workers:  # the fit jobs, taken here too (fit_jobs.py)
        from bookspin_class import fit_jobs
        working = asyncio.get_running_loop().create_task(fit_jobs.serve_workers(
            options.postgres, options.fit_workers, options.fit_lease, stop))
    await stop.wait()
    retention.cancel()
    if listening is not None:
        listening.cancel()
    if working is not None:
        await working
    await runner.cleanup()
    server.close()
    server.store.close()


async def fit_worker(options, stop):
    """--fit-worker: no HTTP; the classes' fits taken from the database until stopped (a job
    held then is handed back: docs/class.md, "A school's server")."""
    from bookspin_class import fit_jobs
    db = await asyncio.to_thread(open_store, options)  # the tables, made where missing
    description = db.description
    db.close()
    print(f"{PROGRAM}: fit worker {fit_jobs.worker_name()} takes the classes' fits from "
          f"{description} (lease {options.fit_lease:g} s); Ctrl-C stops it", flush=True)
    await fit_jobs.serve_workers(options.postgres, 1, options.fit_lease, stop)


def main(argv):
    os.umask(0o077)  # the store, keys and addresses readable by the teacher's account alone
    try:
        options = parse_options(argv)
        if not options.list:
            check_imports(options)
    except OptionError as error:
        print(f"{PROGRAM}: error: {error}", file=sys.stderr)
        return 2
    except ImportError as error:
        print(f"{PROGRAM}: error: {import_error_line(error)}", file=sys.stderr)
        return 2
    where = "--postgres" if options.postgres else "--data"
    if options.list:
        try:
            list_classes(options)
        except StoreError as error:
            print(f"{PROGRAM}: error: {where}: cannot open the store: {error}", file=sys.stderr)
            return 1
        return 0

    async def run():
        stop = asyncio.Event()
        loop = asyncio.get_running_loop()
        for sig in (signal.SIGINT, signal.SIGTERM):
            loop.add_signal_handler(sig, stop.set)
        await (fit_worker(options, stop) if options.fit_worker else serve(options, stop))

    try:
        asyncio.run(run())
    except StartError as error:
        print(f"{PROGRAM}: error: {error}", file=sys.stderr)
        return error.status
    except StoreError as error:
        print(f"{PROGRAM}: error: {where}: cannot open the store: {error}", file=sys.stderr)
        return 1
    except OSError as error:
        path = f" {error.filename}" if error.filename else ""
        print(f"{PROGRAM}: error: cannot write{path}: {error.strerror or error}",
              file=sys.stderr)
        return 1
    return 0
