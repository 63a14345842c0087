"""What the browser tests share: their arguments, skip-or-fail, running bookspin, headless
Chromium driven by Selenium, a local HTTP server, waiting on the page.

The tests (gallery_test.py, gltf_test.py, explorer_test.py) are run by ctest as
`TEST.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR` with Debian's /usr/bin/python3, which has
python3-selenium. A missing piece (chromium, chromedriver, selenium, node, npm, em++) skips
the test with exit status 77, except under CI=true, where it is a failure: in CI the browser
tests must run. Install the pieces with scripts/install-deps.sh.

    from browser import open_browser, test_arguments
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    with open_browser(chromium, driver_path, webgl=True) as driver:
        ...
"""
import contextlib
import functools
import http.server
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

SKIP = 77


def fail(message):
    """Ends the test as failed (exit 1), the message on stderr."""
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def under_ci():
    return os.environ.get("CI", "").lower() in ("1", "true", "yes")


def missing(what):
    """A missing tool: a failure under CI=true, a skip (exit 77) elsewhere."""
    test = Path(sys.argv[0]).stem
    if under_ci():
        fail(f"{what} (CI=true: {test} must run; install it with scripts/install-deps.sh)")
    print(f"SKIPPED: {what}; install it (scripts/install-deps.sh) to run {test}")
    sys.exit(SKIP)


def require(*programs):
    """The path of each program on PATH, in order; missing() for the first that is not."""
    found = []
    for name in programs:
        path = shutil.which(name)
        if not path:
            missing(f"{name} not found on PATH")
        found.append(path)
    return found


def find_browser():
    """(chromium, chromedriver): the browser and its driver, and selenium importable; a
    missing one is missing()."""
    try:
        import selenium  # noqa: F401
    except ImportError:
        missing(f"python module selenium (python3-selenium) not found by {sys.executable}")
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver") or (
        "/usr/bin/chromedriver" if os.path.exists("/usr/bin/chromedriver") else None)
    if not chromium:
        missing("chromium not found on PATH")
    if not driver:
        missing("chromedriver not found (Debian package chromium-driver)")
    return chromium, driver


def test_arguments(usage):
    """(bookspin, source, binary) from `TEST.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR`, the last
    two as Paths; prints `usage` and exits 2 on any other command line."""
    if len(sys.argv) != 4:
        print(usage, file=sys.stderr)
        sys.exit(2)
    return sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])


def run(cmd, **kw):
    """Runs cmd (any of its parts may be a Path) and returns its stdout and stderr together;
    fail() with that text when it exits non-zero."""
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)
    if r.returncode != 0:
        fail(f"{' '.join(map(str, cmd))} exited {r.returncode}:\n{r.stdout}")
    return r.stdout


def explorer_of_every_scene(bookspin, source, binary, name):
    """The page built (web/build.sh) and written with every scene of scenes/ into
    BINARY_DIR/test-output/<name>: (out, shots, page), `shots` the screenshots' folder
    (BINARY_DIR/test-output/browser), `page` the explorer's file:// address."""
    out = binary / "test-output" / name
    shots = binary / "test-output" / "browser"
    shots.mkdir(parents=True, exist_ok=True)
    out.mkdir(parents=True, exist_ok=True)
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    run([bookspin, "explore", *sorted(str(p) for p in (source / "scenes").glob("*.toml")), "-o", str(out)])
    return out, shots, (out / "explorer.html").resolve().as_uri()


def lab_page_under_test(bookspin, source, binary, name):
    """The page built (web/build.sh) and written with scenes/exact-unstable-x.toml into a fresh
    BINARY_DIR/test-output/<name> (an earlier run's removed), for the lab's tests: (out,
    recordings, shots, page): `recordings` an empty folder in it for the test's recordings,
    `shots` the screenshots' folder (BINARY_DIR/test-output/browser), `page` the explorer's
    file:// address."""
    out = binary / "test-output" / name
    shots = binary / "test-output" / "browser"
    shutil.rmtree(out, ignore_errors=True)
    recordings = out / "recordings"
    for d in (recordings, shots):
        d.mkdir(parents=True, exist_ok=True)
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    run([bookspin, "explore", str(source / "scenes" / "exact-unstable-x.toml"), "-o", str(out)])
    return out, recordings, shots, (out / "explorer.html").resolve().as_uri()


def exact_fig09_motion(bookspin, source, out):
    """fig09's exact motion exported by `bookspin flipcheck export` into OUT/motions: its CSV."""
    run([bookspin, "flipcheck", "export", str(source / "scenes" / "fig09-matrix-unstable-x.toml"),
         "-o", str(out / "motions")])
    return out / "motions" / "fig09-matrix-unstable-x-exact.csv"


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@contextlib.contextmanager
def serve(folder, address="127.0.0.1"):
    """An HTTP server on `address` (127.0.0.1 unless given: another address of the machine
    serves a page that is not a secure context) serving `folder` (file:// pages may not play
    media, nor fetch), for the length of the with block; yields its URL, ending in '/'."""
    handler = functools.partial(_QuietHandler, directory=str(folder))
    server = http.server.ThreadingHTTPServer((address, 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        yield f"http://{address}:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()


@contextlib.contextmanager
def open_browser(chromium, driver_path, *, size=(1280, 1000), webgl=False, media=False,
                 offline=False, exact_viewport=False, profile=None, script_timeout=300,
                 extra_args=()):
    """Headless Chromium for the length of the with block; yields the Selenium driver and
    quits it after.

    size: the window (width, height) in CSS pixels. webgl: WebGL on the CPU, SwiftShader
    through ANGLE (no GPU on the test machines); otherwise the GPU is off. media: sound muted,
    autoplay without a user gesture. offline: every request but those to 127.0.0.1 goes to a
    closed port. exact_viewport: the page's viewport set to `size` exactly through the DevTools
    protocol. profile: the user-data folder (default: a temporary one, removed after).
    extra_args: more of Chromium's command-line switches (the class projector's test trusts
    its certificate; a benchmark's: without GPU rasterization, say). The browser's console
    is kept at every level: see console_errors(). A script the test
    runs in the page may take up to `script_timeout` seconds (Selenium's default, 30 s, is
    too short for a long run of the physics on a loaded 2-core machine)."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    temporary = None
    if profile is None:
        temporary = profile = tempfile.mkdtemp(prefix="bookspin-chromium-")
    args = ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
            "--disable-background-networking", "--disable-component-update", "--disable-sync",
            "--no-first-run", f"--window-size={size[0]},{size[1]}", f"--user-data-dir={profile}"]
    if webgl:
        args += ["--use-angle=swiftshader", "--enable-unsafe-swiftshader"]
    else:
        args += ["--disable-gpu"]
    if media:
        args += ["--mute-audio", "--autoplay-policy=no-user-gesture-required"]
    if offline:
        args += ["--proxy-server=http://127.0.0.1:9", "--proxy-bypass-list=<-loopback>"]
    args += list(extra_args)
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for arg in args:
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(executable_path=driver_path), options=options)
    try:
        driver.set_script_timeout(script_timeout)
        if exact_viewport:
            driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                                   {"width": size[0], "height": size[1], "deviceScaleFactor": 1,
                                    "mobile": False})
        yield driver
    finally:
        driver.quit()
        if temporary:
            shutil.rmtree(temporary, ignore_errors=True)


def console_errors(driver):
    """The SEVERE entries of the browser's console since the last call."""
    return [e for e in driver.get_log("browser") if e.get("level") == "SEVERE"]


def wait_for(driver, script, done, timeout=60):
    """Runs `script` in the page until done(result) or the timeout (seconds); returns the last
    result."""
    deadline = time.monotonic() + timeout
    while True:
        result = driver.execute_script(script)
        if done(result) or time.monotonic() > deadline:
            return result
        time.sleep(0.25)


SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def shown_number(text):
    """A number as the page shows it (web/src/precision.js): plain ("12.67", "-0.000012") or
    with a power of ten ("1.665 × 10⁻¹⁵"), as a float."""
    text = text.strip()
    if " × 10" in text:
        mantissa, power = text.split(" × 10")
        return float(mantissa) * 10.0 ** int(power.translate(SUPERSCRIPT))
    return float(text)


def shown_digits(text):
    """The significant digits a number shown by the page has (its mantissa's, leading zeros
    not counted; an integer's trailing zeros counted)."""
    mantissa = text.strip().split(" × 10")[0].lstrip("-")
    return len(mantissa.replace(".", "").lstrip("0")) or 1


def at_sigma(value, sigma):
    """`value ± sigma` as the page prints it (web/src/precision.js), written again here: σ to
    two significant digits, the value to σ's last decimal place; (value, sigma) as text."""
    rounded = float(f"{sigma:.2g}")
    place = int(f"{rounded:e}".split("e")[1]) - 1
    decimals = max(0, -place)
    if place > 0:
        step = 10 ** place
        return str(int(round(value / step) * step)), str(int(round(sigma / step) * step))
    return f"{value:.{decimals}f}", f"{sigma:.{decimals}f}"


# Every element with text of its own: its computed font size and whether its text runs past
# its box (a horizontal overflow it scrolls or clips, or past the window's right edge).
TEXT_STATE = """
return Array.from(document.querySelectorAll('body *')).filter(e =>
    Array.from(e.childNodes).some(n => n.nodeType === 3 && n.textContent.trim())).map(e => ({
  tag: e.tagName, text: e.textContent.trim().slice(0, 60),
  size: parseFloat(getComputedStyle(e).fontSize),
  overflow: e.scrollWidth > e.clientWidth + 1 && getComputedStyle(e).overflowX !== 'visible'
      || e.getBoundingClientRect().right > document.documentElement.clientWidth + 1}));
"""


def text_problems(driver, unseen=None):
    """What a reader cannot read on the page as shown (docs/outputs.md, "Pictures"): text under
    12 px and text past its box, each as a line; and the element count and smallest size.
    `unseen`: a selector of elements not shown (a screen reader's live region clipped to a
    pixel), left out."""
    texts = driver.execute_script(TEXT_STATE.replace("querySelectorAll('body *')", f"querySelectorAll('body *:not({unseen})')")
                                  if unseen else TEXT_STATE)
    problems = []
    small = [t for t in texts if t["size"] < 12]
    if small:
        problems.append(f"text under 12 px: {small[:5]}")
    over = [t for t in texts if t["overflow"]]
    if over:
        problems.append(f"text past its box: {over[:5]}")
    smallest = min((t["size"] for t in texts), default=0)
    print(f"{len(texts)} text elements, the smallest {smallest} px")
    return problems



# Paper sizes in inches (CDP Page.printToPDF's units): A4 (210×297 mm) and US Letter.
PAPERS = {"A4": (8.27, 11.69), "Letter": (8.5, 11.0)}


def print_to_pdf(driver, path, paper):
    """The page printed as Chromium's Print does by default (the paper's size, portrait, its
    default margins, no background graphics but those a page asks for) to `path`, a PDF, through
    the DevTools protocol's Page.printToPDF; `paper` a key of PAPERS. Returns the path."""
    import base64
    width, height = PAPERS[paper]
    pdf = driver.execute_cdp_cmd("Page.printToPDF", {
        "paperWidth": width, "paperHeight": height, "printBackground": False,
        "preferCSSPageSize": False})
    Path(path).write_bytes(base64.b64decode(pdf["data"]))
    return Path(path)


def pdf_text(path, *options):
    """The text of the PDF at `path` as pdftotext (poppler-utils) reads it back, with
    `options` (e.g. "-raw": in the order the page drew it, a table's cells one after another);
    pdftotext missing is missing()."""
    pdftotext, = require("pdftotext")
    return run([pdftotext, *options, str(path), "-"])


def pdf_pages(path):
    """The number of pages of the PDF at `path` (pdfinfo, poppler-utils)."""
    pdfinfo, = require("pdfinfo")
    for line in run([pdfinfo, str(path)]).splitlines():
        if line.startswith("Pages:"):
            return int(line.split()[1])
    fail(f"pdfinfo names no page count for {path}")


def pdf_to_png(path, prefix, dpi=60):
    """Each page of the PDF at `path` as PREFIX-N.png (pdftoppm, poppler-utils), N from 1 (its
    digits padded by pdftoppm); the PNGs' paths."""
    pdftoppm, = require("pdftoppm")
    run([pdftoppm, "-png", "-r", str(dpi), str(path), str(prefix)])
    prefix = Path(prefix)
    return sorted(prefix.parent.glob(prefix.name + "-*.png"))


def squeezed(text):
    """`text` without its white space: a PDF's text against the page's, wherever either wraps."""
    return "".join(text.split())


# JavaScript: under print media (the caller emulates it), every shown element with text of its
# own: its text, its colour and the colour it is drawn on (the first ancestor's background not
# transparent; the paper's white where none has one) as [r, g, b].
PRINTED_COLOURS = """
  const root = arguments[0] ? document.querySelector(arguments[0]) : document.body;
  const rgb = (c) => (c.match(/[\\d.]+/g) || []).map(Number);
  const under = (e) => {
    for (let x = e; x && x.nodeType === 1; x = x.parentElement) {
      const c = rgb(getComputedStyle(x).backgroundColor);
      if (c.length === 3 || (c.length === 4 && c[3] > 0.5)) return c.slice(0, 3);
    }
    return [255, 255, 255];
  };
  return [...root.querySelectorAll('*')].filter((e) => e.checkVisibility() &&
      [...e.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim())).map((e) =>
    [e.textContent.trim().slice(0, 50), rgb(getComputedStyle(e).color).slice(0, 3), under(e)]);
"""


def luminance(rgb):
    """WCAG's relative luminance of an sRGB colour [r, g, b] in 0..255."""
    def channel(c):
        c /= 255
        return c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4
    r, g, b = map(channel, rgb)
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def pale_print(driver, root=None):
    """Under emulated print media, the texts (of `root`, a selector, or the page) printed pale
    or on a dark ground: a contrast with their ground under 4.5 (WCAG 1.4.3), or text lighter
    than mid-grey, or a ground darker than it (the screen's dark theme on paper); a list of
    [text, colour, ground]. Print media is left on."""
    driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": "print"})
    shown = driver.execute_script(PRINTED_COLOURS, root)
    pale = []
    for text, colour, ground in shown:
        a, b = luminance(colour), luminance(ground)
        contrast = (max(a, b) + 0.05) / (min(a, b) + 0.05)
        if contrast < 4.5 or a > 0.2 or b < 0.5:
            pale.append([text, colour, ground])
    print(f"under print media: {len(shown)} texts, {len(pale)} pale or on a dark ground")
    return pale
