"""The class's projector on every screen a school has, by keyboard alone and on paper (docs/class.md,
"The projector"), in headless Chromium against a real bookspin-class on 127.0.0.1 (its own
certificate trusted by its public key's hash), a class of twelve named in several scripts
posting the real recordings of the bare phone in ../shared/recordings-real/ (each cut at a few
first samples: twelve recordings the fit and the server tell apart):

- an old projector at 800×600, a tablet both ways (1024×768, 768×1024), 1280×720 at 200 % and
  1920×1080 at 400 % (a teacher's zoom for the back of the room: the CSS viewport a half and a
  quarter, the device pixel ratio 2 and 4): every student's name and the class's body on the
  page, nothing wider than the screen (no sideways scrolling), no text under 12 px or past its
  box, the legend whole;
- by keyboard alone (Tab, Enter, typing): a toss left out with a reason and put back, each held
  by the server;
- printed to PDF (A4, as Chromium's Print does by default): every name, the body and the
  legend on paper, none of the teacher's buttons or forms.

Screenshots in BINARY_DIR: class-projector-screen-WxH@Z.png and class-projector-print-1.png.

    class_projector_screens_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
"""
import contextlib
import tempfile
import time
import unicodedata
import uuid
from pathlib import Path

from class_browser import RealServer, class_packages
from browser import (fail, find_browser, missing, open_browser, pdf_text, pdf_to_png, print_to_pdf,
                     test_arguments, text_problems, wait_for)

bookspin, source, binary = test_arguments(__doc__)
class_packages(source, binary)
from class_server import REAL, real_csv  # noqa: E402

if not REAL.is_dir():
    missing(f"no real recordings at {REAL} (../shared/recordings-real/ beside the checkout)")
chromium, driver_path = find_browser()

NAMES = ["Anna Schmidt", "Юлия Ковалёва", "Αθηνά Παππά", "فاطمة الزهراء", "נועה כהן",
         "प्रिया शर्मा", "தமிழ்செல்வி", "สมชาย ใจดี", "王芳", "김지민", "Nguyễn Thị Hoa",
         "Sam 👩🏽\u200d🔬"]
PHONE = ["12-10-56", "12-13-01", "12-13-51"]
# (CSS width, CSS height, device pixel ratio): the screen's pixels over the zoom.
SCREENS = [(800, 600, 1), (1024, 768, 1), (768, 1024, 1), (640, 360, 2), (480, 270, 4)]

LAYOUT = """
const page = document.scrollingElement;
return {wide: page.scrollWidth - innerWidth, text: document.body.innerText,
        legend: document.getElementById('legend').textContent.replace(/\\s+/g, ' '),
        body: document.getElementById('body').textContent};
"""


def recording(index):
    """The index-th student's toss: a real recording of the phone from its (index // 3)-th
    sample on."""
    lines = real_csv(PHONE[index % 3]).splitlines(keepends=True)
    return "".join(lines[:1] + lines[1 + index // 3:])


def tab_to(driver, keys, text, limit=80):
    """Presses Tab until the focused element is a button whose text is `text` (at most `limit`
    times); its row's first cell, or fails."""
    for _ in range(limit):
        driver.switch_to.active_element.send_keys(keys.TAB)
        found = driver.execute_script(
            "const e = document.activeElement; return e && e.tagName === 'BUTTON' && "
            "e.textContent === arguments[0] ? (e.closest('tr') || {cells: [{}]}).cells[1]"
            ".textContent || '' : null;", text)
        if found is not None:
            return found
    fail(f"by keyboard: no '{text}' button within {limit} Tabs")


page = Path(tempfile.mkdtemp(prefix="bookspin-class-screens-page-")) / "explorer.html"
page.write_text("<!doctype html><title>explorer</title>\n")
real = RealServer(source, binary, page)
server, trust = real.server, real.trust
browsers = contextlib.ExitStack()
try:
    origin = f"https://127.0.0.1:{server.port}"
    for index, name in enumerate(NAMES):
        status, answer = server.request(
            "POST", f"/api/class/{server.code}/tosses",
            {"toss": str(uuid.uuid4()), "name": f"{PHONE[index % 3]}-{index:02d}",
             "recorded_at": f"2026-11-29T09:{10 + index:02d}:00Z", "csv": recording(index)},
            token=server.join(name))
        if status != 201:
            fail(f"{name}'s toss: {status} {answer}")
    state = server.fitted_state(len(NAMES))
    names = [unicodedata.normalize("NFC", n) for n in NAMES]

    def projector(width, height, ratio):
        driver = browsers.enter_context(open_browser(
            chromium, driver_path, size=(width, height), extra_args=[trust]))
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
            "width": width, "height": height, "deviceScaleFactor": ratio, "mobile": False})
        driver.get(f"{origin}/teacher?key={server.key}")
        wait_for(driver, "return document.getElementById('body').textContent;",
                 lambda body: body.startswith("I1"))
        return driver

    for width, height, ratio in SCREENS:
        driver = projector(width, height, ratio)
        screen = f"{width * ratio}x{height * ratio}@{100 * ratio}"
        driver.save_screenshot(str(binary / f"class-projector-screen-{screen}.png"))
        shown = driver.execute_script(LAYOUT)
        text = unicodedata.normalize("NFC", shown["text"])
        problems = [f"{shown['wide']} px wider than the screen"] if shown["wide"] > 0 else []
        problems += [f"{n} not shown" for n in names if n not in text]
        problems += [f"the legend lacks {term}" for term in ("I1 : I2 : I3", "T/2", "± 2σ")
                     if term not in shown["legend"]]
        problems += text_problems(driver)
        if problems:
            fail(f"at {screen} ({width}×{height} CSS px): " + "; ".join(problems))
        print(f"{screen}: every name, the body ({shown['body'][:40]}…) and the legend shown")
        browsers.close()

    # By keyboard alone: a toss left out with a reason, then put back.
    from selenium.webdriver.common.keys import Keys
    driver = projector(1280, 720, 1)
    driver.find_element("tag name", "body").click()
    first = tab_to(driver, Keys, "Leave out")
    driver.switch_to.active_element.send_keys(Keys.ENTER)
    focused = driver.execute_script("return document.activeElement.tagName;")
    if focused != "INPUT":
        fail(f"Leave out by keyboard puts the focus on {focused}, not its reason's field")
    driver.switch_to.active_element.send_keys("caught early" + Keys.ENTER)
    held = None
    for _ in range(60):
        held = [t for s in server.state()["students"] for t in s["tosses"]
                if t["excluded"] is not None]
        if held:
            break
        time.sleep(0.5)
    if not held or held[0]["excluded"] != "caught early" or not first.startswith(held[0]["name"]):
        fail(f"by keyboard: left out {held}, the row was {first!r}")
    tab_to(driver, Keys, "Put back")
    driver.switch_to.active_element.send_keys(Keys.ENTER)
    for _ in range(60):
        if not any(t["excluded"] is not None for s in server.state()["students"]
                   for t in s["tosses"]):
            break
        time.sleep(0.5)
    else:
        fail("by keyboard: Put back did not put the toss back")
    print(f"by keyboard: {held[0]['name']} left out ('caught early') and put back")

    # On paper.
    pdf = print_to_pdf(driver, real.work / "projector.pdf", "A4")
    paper = unicodedata.normalize("NFC", pdf_text(pdf))
    flat = " ".join(paper.split())
    # (pdftotext reads no text back from an emoji's colour glyphs: letters and marks compared)
    letters = [" ".join("".join(c for c in n if unicodedata.category(c)[0] in "LMZ").split())
               for n in names]
    missing_names = [n for n in letters if n not in flat]
    buttons = [b for b in ("Leave out", "Download the class's set", "End the class",
                           "Show the QR code") if b in flat]
    if missing_names or "I1" not in flat or "± 2σ" not in flat or buttons:
        fail(f"on paper: names missing {missing_names}, buttons printed {buttons}:\n{paper[:800]}")
    pngs = pdf_to_png(pdf, real.work / "print")
    (binary / "class-projector-print-1.png").write_bytes(pngs[0].read_bytes())
    print(f"on paper: {len(pngs)} page(s), every name and the body, no button")
finally:
    browsers.close()
    real.close()
print("PASS")
