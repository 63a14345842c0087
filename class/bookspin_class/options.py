"""`bookspin-class`'s command line (docs/class.md, "The teacher's steps"): the options read
and checked (a bad one: OptionError, one line naming it, nothing written), and what the server
imports, checked with the line that names the missing piece and the command that puts it in
place."""
import argparse
import ipaddress
import os
import pathlib

PROGRAM = "bookspin-class"
# The packages the server imports, by the Debian package that installs each
# (scripts/install-deps.sh).
PACKAGES = {"numpy": "python3-numpy", "aiohttp": "python3-aiohttp", "psycopg": "python3-psycopg",
            "segno": "python3-segno", "cryptography": "python3-cryptography",
            "psutil": "python3-psutil", "idna": "python3-idna"}


class OptionError(Exception):
    pass


class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise OptionError(message)


def page_problem(page):
    """Why `page` is not a page to serve phones (missing, empty, not UTF-8 HTML), or None."""
    if not page.is_file():
        return f"no such file {page}"
    data = page.read_bytes()
    if not data:
        return f"{page} is empty"
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return f"{page} is not an HTML page (not UTF-8 text)"
    if "\0" in text or not text.lstrip().lower().startswith(("<!doctype html", "<html")):
        return f"{page} is not an HTML page (it does not begin with <!doctype html>)"
    return None


def parse_options(argv):
    from bookspin_class import addresses
    parser = Parser(prog=PROGRAM, description="Serve the phone lab to a class and show its "
                    "tosses, fitted as one body, on the projector (docs/class.md).")
    parser.add_argument("--data", default="bookspin-class", metavar="DIR",
                        help="folder of the class's SQLite database, certificates and the "
                             "teacher's address (default: ./bookspin-class)")
    parser.add_argument("--postgres", metavar="URL",
                        help="keep the class in this PostgreSQL database instead of SQLite "
                             "(postgresql://USER@HOST/DB)")
    parser.add_argument("--port", default="8443", metavar="N", help="https port (default 8443)")
    parser.add_argument("--host", default="0.0.0.0", metavar="ADDR",
                        help="address to listen on (default 0.0.0.0: every interface)")
    parser.add_argument("--address", metavar="ADDR",
                        help="the address phones use, a host name or an IP (default: this "
                             "laptop's own on the classroom's network; the others are listed)")
    parser.add_argument("--page", default="out/explorer.html", metavar="FILE",
                        help="the explorer page phones get, as `make class` writes it "
                             "(default out/explorer.html)")
    parser.add_argument("--keep-days", default="7", metavar="N",
                        help="delete classes older than N days, at start and daily (default 7)")
    parser.add_argument("--new", action="store_true",
                        help="start a new class (default: go on with the class taught last)")
    parser.add_argument("--class", dest="class_code", metavar="CODE",
                        help="go on with this class of the store (--list lists them)")
    parser.add_argument("--list", action="store_true",
                        help="list the store's classes and exit")
    parser.add_argument("--open", action="store_true",
                        help="open the projector in this laptop's browser")
    parser.add_argument("--rate", default="20", metavar="R",
                        help="requests a second per phone, on average (default 20; 3R at once)")
    parser.add_argument("--proxy", metavar="ADDR",
                        help="the IP address of the school's reverse proxy: requests from it "
                             "are the phone's named in X-Forwarded-For (docs/class.md, \"A "
                             "school's server\")")
    parser.add_argument("--public-port", metavar="N",
                        help="the port phones and the teacher reach: the school's reverse "
                             "proxy's, in the join address and the QR code (default: --port)")
    parser.add_argument("--max-tosses", default="100", metavar="N",
                        help="tosses one student may have held (default 100)")
    parser.add_argument("--head-timeout", default="10", metavar="S",
                        help="seconds a connection has to send a request's head (default 10)")
    parser.add_argument("--fit-workers", default=None, metavar="N",
                        help="with --postgres: fit workers this server runs itself (default 1; "
                             "0 leaves the classes' fits to `--fit-worker` processes; "
                             "docs/class.md, \"A school's server\")")
    parser.add_argument("--fit-worker", action="store_true",
                        help="with --postgres: serve nothing, take the classes' fits from the "
                             "database until Ctrl-C (run as many as the school's machines "
                             "allow, on any of them)")
    parser.add_argument("--fit-lease", default="30", metavar="S",
                        help="seconds a fit worker holds a job without renewing it: a worker "
                             "killed mid-fit leaves its job to another after this (default 30)")
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
    if options.public_port is not None:
        options.public_port = number("--public-port", options.public_port, int, 1, 65535)
    options.keep_days = number("--keep-days", options.keep_days, float, 0.01, 3650)
    options.rate = number("--rate", options.rate, float, 0.1, 10000)
    options.max_tosses = number("--max-tosses", options.max_tosses, int, 1, 100000)
    options.head_timeout = number("--head-timeout", options.head_timeout, float, 0.1, 600)
    if not options.data:
        raise OptionError("--data: empty: give the class's folder, e.g. --data bookspin-class")
    data = pathlib.Path(options.data)
    if data.exists() and not data.is_dir():
        raise OptionError(f"--data: {data} is not a folder")
    if options.postgres is not None and not options.postgres.startswith(("postgresql:",
                                                                           "postgres:")):
        raise OptionError(f"--postgres: expected a URL postgresql://…, got '{options.postgres}'")
    options.fit_lease = number("--fit-lease", options.fit_lease, float, 1, 3600)
    if options.fit_workers is not None or options.fit_worker:
        if options.postgres is None:
            what = "--fit-worker" if options.fit_worker else "--fit-workers"
            raise OptionError(f"{what}: only with --postgres (the laptop's SQLite store fits "
                              "in the server itself)")
    options.fit_workers = number("--fit-workers", options.fit_workers or "1", int, 0, 64)
    if options.list or options.fit_worker:
        return options
    problem = page_problem(pathlib.Path(options.page))
    if problem:
        raise OptionError(f"--page: {problem} (`make class` writes out/explorer.html, the page "
                          "phones get)")
    if not options.host:
        raise OptionError("--host: empty: give an address of this laptop, e.g. --host 0.0.0.0 "
                          "(every interface)")
    if options.address is not None:
        try:
            options.address = addresses.host_option(options.address)
        except ValueError as error:
            raise OptionError(f"--address: {error}") from None
    if options.proxy is not None:
        try:
            options.proxy = ipaddress.ip_address(options.proxy.strip())
        except ValueError:
            raise OptionError(f"--proxy: expected the reverse proxy's IP address, got "
                              f"'{options.proxy}'") from None
    if options.class_code is not None:
        options.class_code = "".join(options.class_code.split()).upper()
        if not options.class_code:
            raise OptionError("--class: empty: give a class's code (--list lists them)")
        if options.new:
            raise OptionError("--class: a class to go on with, or --new: not both")
    return options


def import_error_line(error):
    """The line that says which piece is missing and the command that puts it in place."""
    top = (error.name or "").split(".")[0]
    build = os.environ.get("BOOKSPIN_CLASS_BUILD")  # set by BUILD/bookspin-class
    if top == "bookspin":
        if not build:
            return ("the bookspin Python module is not on PYTHONPATH: start the server with "
                    "build/bookspin-class, which sets it (`make class` builds it)")
        source = pathlib.Path(__file__).resolve().parents[2]
        make = "make" if source == pathlib.Path.cwd().resolve() else f"make -C {source}"
        make += " class" if pathlib.Path(build).resolve() == source / "build" else \
            f" class BUILD={build}"
        return (f"the bookspin Python module is not built in {build}/python: `{make}` builds it "
                "and the page the phones get")
    if top in PACKAGES:
        return (f"{PACKAGES[top]} is not installed (no module '{error.name}'): "
                "scripts/install-deps.sh installs it")
    return f"the bookspin Python module does not load ({error}): `make class` builds it again"


def check_imports(options):
    """Imports, here on the main thread, what the server needs: the fit (PYTHONPATH=
    BUILD/python, as the launcher sets) and numpy, whose first array would otherwise be imported
    in a worker thread while the event loop starts another (a deadlock on the import lock), and
    the packages. Raises ImportError."""
    import aiohttp  # noqa: F401
    import bookspin  # noqa: F401
    import cryptography  # noqa: F401
    import numpy  # noqa: F401
    import segno  # noqa: F401
    if options.postgres:
        import psycopg  # noqa: F401
