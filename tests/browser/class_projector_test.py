"""The class's projector in headless Chromium (docs/class.md, "The projector"): a real
bookspin-class on 127.0.0.1 (its own certificate trusted by its public key's hash, nothing
ignored), a class of 30 students named in every script a classroom brings (Latin, Cyrillic,
Greek, Arabic, Persian with its zero-width non-joiner, Hebrew, Devanagari, Tamil, Bengali,
Gujarati, Gurmukhi, Thai, CJK, Hangul, emoji with joiners) posting the real recordings of the
bare phone in ../shared/recordings-real/ by plain HTTPS clients (its three recordings each cut
at ten first samples: 30 recordings the fit and the server tell apart), a 31st student's of the
plate, and the teacher's page opened through the printed key, the browser's clock in
Asia/Kolkata:

- before a toss, the join screen: the code, a QR code, the phones' address in type of 24 px or
  more, its lines broken only after a '/' or a '?';
- the class at 1280×720 and 1920×1080: the join screen a strip (shown again and hidden on
  demand), all 30 students' lines seen at once, each one line; the body as the server fitted
  it, "N recordings, M flights" and its time in the browser's local time; one legend naming
  I1 : I2 : I3, T/2, predicted from the others, ± 2σ and within; flights numbered within their
  toss; a line with nothing measured says why; every name drawn from fonts that hold each of
  its characters (no empty boxes: the fonts Chromium reports for it, against fontconfig's) and
  read back by the accessibility tree; no text under 12 px or past its box; nothing requested
  from another origin;
- Leave out: a reason typed while the 31st student joins and sends a toss of the plate, the
  table updating around the form, which keeps its text and focus; Cancel; then the plate's
  toss left out with a reason, held by the server, and put back;
- End, through the page of a second projector: the first (its event stream open) shows that
  the class has ended and what to do next, nothing of the class left; a third, which missed the
  news, shows the same on Download (not the server's JSON); the projector's address after End
  is a page saying so; the store holds nothing of the class.

Screenshots in BINARY_DIR: class-projector-join-1280x720.png, class-projector-WxH.png and
class-projector-ended-1280x720.png (docs/class.md shows them).

    class_projector_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
"""
import contextlib
import datetime
import re
import tempfile
import time
import unicodedata
import uuid
import zoneinfo
from pathlib import Path

from class_browser import RealServer, class_packages
from browser import (fail, find_browser, missing, open_browser, test_arguments, text_problems,
                     wait_for)
from drawn_text import accessible_names, drawn_fonts, undrawn

bookspin, source, binary = test_arguments(__doc__)
class_packages(source, binary)
from class_server import REAL, real_csv  # noqa: E402

if not REAL.is_dir():
    missing(f"no real recordings at {REAL} (../shared/recordings-real/ beside the checkout)")
chromium, driver_path = find_browser()

NAMES = ["Anna Schmidt", "Zoë Ångström", "Юлия Ковалёва", "Дмитрий", "Αθηνά Παππά",
         "فاطمة الزهراء", "مهر\u200cانگیز", "נועה כהן", "प्रिया शर्मा", "अर्जुन", "தமிழ்செல்வி",
         "অর্পিতা", "ગીતા", "ਹਰਪ੍ਰੀਤ", "สมชาย ใจดี", "王芳", "山田太郎", "김지민",
         "Sam 👩🏽\u200d🔬", "❤\ufe0f Lea", "Nguyễn Thị Hoa", "Łukasz", "Oğuz", "Kwame", "Sofía",
         "Mateo", "Chloé", "Tomás", "Aiyana", "Ben"]
LATE = "Lina"  # joins while the teacher types a reason, and tosses the plate
PHONE = ["12-10-56", "12-13-01", "12-13-51"]
PLATE = "12-22-44"
ZONE = "Asia/Kolkata"  # the browser's local time: UTC+05:30, never the server's UTC


def recording(index):
    """(name, CSV text) of the index-th student's toss: a real recording of the phone from its
    `cut`-th sample on (a recording the fit and the server tell apart from the others); the
    31st's (index 30) the plate's."""
    source_name = PLATE if index == 30 else PHONE[index % 3]
    cut = 0 if index == 30 else index // 3
    lines = real_csv(source_name).splitlines(keepends=True)
    return source_name, "".join(lines[:1] + lines[1 + cut:])


def local_clock(iso):
    """The times the browser may show for `iso` in ZONE: 24-hour and 12-hour."""
    at = datetime.datetime.fromisoformat(iso.replace("Z", "+00:00")).astimezone(
        zoneinfo.ZoneInfo(ZONE))
    return {at.strftime("%H:%M"), at.strftime("%I:%M %p")}


LINES_OF = """
const element = document.querySelector(arguments[0]);
const lines = [];
let top = null;
const walker = document.createTreeWalker(element, NodeFilter.SHOW_TEXT);
for (let node = walker.nextNode(); node; node = walker.nextNode()) {
  for (let i = 0; i < node.length; ++i) {
    const range = document.createRange();
    range.setStart(node, i);
    range.setEnd(node, i + 1);
    const rect = range.getClientRects()[0];
    if (!rect) continue;
    if (top === null || rect.top > top + rect.height / 2) { lines.push(""); top = rect.top; }
    lines[lines.length - 1] += node.data[i];
  }
}
return [lines, parseFloat(getComputedStyle(element).fontSize)];
"""

ROWS = """
const rows = [...document.getElementById('tosses').rows];
return [innerHeight, document.scrollingElement.scrollTop, rows.map(r => {
  const box = r.getBoundingClientRect();
  return {cells: [...r.cells].map(c => c.textContent), top: box.top, bottom: box.bottom,
          height: box.height, line: parseFloat(getComputedStyle(r.cells[0]).lineHeight)};
})];
"""


def check_address(driver, selector, url, smallest):
    lines, size = driver.execute_script(LINES_OF, selector)
    if "".join(lines) != url:
        fail(f"{selector} shows {lines}, the phones' address is {url}")
    broken = [line for line in lines[:-1] if not line.endswith(("/", "?"))]
    if broken or any(line.endswith("//") for line in lines):
        fail(f"{selector} breaks inside a word: {lines}")
    if size < smallest:
        fail(f"{selector} in {size} px type, under {smallest} px (read from the back of a room)")
    return lines, size


def check_class(driver, size, state, names):
    """The class's lines at a glance, as the server fitted them, each name drawn."""
    ratios = state["pooled"]["ratios"]
    body = driver.execute_script("return document.getElementById('body').textContent;")
    if not body.startswith(f"I1 : I2 : I3 = {ratios[0]:.3f}") or f"{ratios[1]:.3f}" not in body:
        fail(f"at {size} the body shown {body!r}, the server's ratios {ratios}")
    height, scrolled, rows = driver.execute_script(ROWS)
    tosses = sum(max(1, len(s["tosses"])) for s in state["students"])
    if len(rows) != tosses or scrolled:
        fail(f"at {size}: {len(rows)} lines for {tosses} tosses (scrolled {scrolled})")
    unseen = [r["cells"][0] or r["cells"][1] for r in rows if r["bottom"] > height]
    if unseen:
        fail(f"at {size} {len(unseen)} of {len(rows)} lines are below the screen: {unseen[:5]}")
    tall = [(r["cells"][:2], r["height"]) for r in rows if r["height"] > 1.6 * r["line"]]
    if tall:
        fail(f"at {size} lines of more than one line of text: {tall[:3]}")
    join = driver.execute_script("const r = document.getElementById('join')"
                                 ".getBoundingClientRect(); return r.width * r.height;")
    strip = driver.execute_script("return document.getElementById('strip').offsetHeight;")
    if join or not 0 < strip <= 0.08 * size[1]:
        fail(f"at {size} the joined class's join screen takes {join} px², its strip {strip} px")
    # Flights numbered within their toss; a line with nothing measured says why.
    for row in rows:
        student, toss, flight, measured, predicted, within, why, _ = row["cells"]
        number = re.fullmatch(r"(\d+)(?: of (\d+))?", flight)
        if flight and (not number or int(number[1]) > int(number[2] or 1)):
            fail(f"{toss}: flight {flight!r}, not its place in the toss")
        if measured == "–" and toss != "no toss yet" and not why.strip():
            fail(f"{student or toss}: nothing measured and no word why: {row['cells']}")
        recorded = RECORDED_AT.get(toss.split(" · ")[0])
        if recorded and not any(clock in toss for clock in local_clock(recorded)):
            fail(f"{toss}: the time recorded not in the browser's local time "
                 f"{local_clock(recorded)}")
    text = driver.execute_script("return document.body.innerText;")
    counted = re.findall(r".{0,20}\w\(s\)", text)
    if counted:
        fail(f"a count written with '(s)': {counted}")
    note = driver.execute_script("return document.getElementById('body-note').textContent;")
    pooled = state["pooled"]
    words = (f"{pooled['recordings']} recording{'s' if pooled['recordings'] != 1 else ''}, "
             f"{pooled['tosses']} flight{'s' if pooled['tosses'] != 1 else ''} fitted as one body")
    if not note.startswith(words) or not any(c in note for c in local_clock(pooled["updated"])):
        fail(f"the body's note {note!r}: expected {words!r} at {local_clock(pooled['updated'])}")
    legend = driver.execute_script(
        "const e = document.getElementById('legend'); return [e.textContent.replace(/\\s+/g, ' '),"
        " e.getBoundingClientRect().height / parseFloat(getComputedStyle(e).lineHeight)];")
    terms = ["I1 : I2 : I3", "T/2", "predicted from the others", "± 2σ", "within"]
    if any(term not in legend[0] for term in terms) or legend[1] > 2.2:
        fail(f"the legend {legend} must explain {terms} in a line or two")
    # Every name drawn with real glyphs and read back by the accessibility tree.
    boxes = undrawn(driver, "#tosses td.name")
    if boxes:
        fail(f"at {size} names drawn as empty boxes (no font holds them): {boxes}")
    if size == (1280, 720):
        for name, fonts in drawn_fonts(driver, "#tosses td.name"):
            print(f"{name}: {', '.join(f['familyName'] for f in fonts)}")
    if any(unicodedata.normalize("NFC", n) not in text for n in names):
        fail(f"at {size} names not on the projector: {[n for n in names if n not in text]}")
    read = accessible_names(driver)
    unread = [n for n in names if unicodedata.normalize("NFC", n) not in read]
    if unread:
        fail(f"at {size} the accessibility tree does not read {unread}")
    problems = text_problems(driver)
    if problems:
        fail(f"at {size}: " + "; ".join(problems))


page = Path(tempfile.mkdtemp(prefix="bookspin-class-browser-page-")) / "explorer.html"
page.write_text("<!doctype html><title>explorer</title>\n")
real = RealServer(source, binary, page)
server, trust = real.server, real.trust
RECORDED_AT = {}
browsers = contextlib.ExitStack()
try:
    origin = f"https://127.0.0.1:{server.port}"
    join_url = f"{origin}/explorer.html?class={server.code}#lab"

    def post(token, index, name):
        toss_name, csv = recording(index)
        toss_name = f"{toss_name}-{index:02d}"
        RECORDED_AT[toss_name] = f"2026-11-29T09:{10 + index:02d}:00Z"
        status, answer = server.request(
            "POST", f"/api/class/{server.code}/tosses", {
                "toss": str(uuid.uuid4()), "name": toss_name, "recorded_at": RECORDED_AT[toss_name],
                "csv": csv}, token=token)
        if status != 201:
            fail(f"{name}'s toss {toss_name}: {status} {answer}")
        return toss_name

    def projector(size):
        driver = browsers.enter_context(open_browser(
            chromium, driver_path, size=size, exact_viewport=True, extra_args=[trust]))
        driver.execute_cdp_cmd("Emulation.setTimezoneOverride", {"timezoneId": ZONE})
        driver.get(f"{origin}/teacher?key={server.key}")
        return driver

    driver = projector((1280, 720))
    # Before a toss: the join screen, large, its address broken only after '/' or '?'.
    wait_for(driver, "return [document.getElementById('address').textContent, "
             "document.getElementById('qr').naturalWidth];",
             lambda shown: shown[0] == join_url and shown[1] > 0)
    lines, size = check_address(driver, "#address", join_url, 24)
    print(f"the join screen's address in {size:.0f} px type: {lines}")
    shown = driver.execute_script("return [document.getElementById('qr').naturalWidth, "
                                  "document.getElementById('code').textContent, "
                                  "document.getElementById('joined').textContent];")
    if shown != [shown[0] or 1, server.code, "0 students joined"] or not shown[0]:
        fail(f"the join screen shows QR width {shown[0]}, code {shown[1]!r}, {shown[2]!r}")
    if server.key in driver.execute_script("return document.body.innerText;"):
        fail("the teacher's key is on the join screen")
    problems = text_problems(driver)
    if problems:
        fail("the join screen: " + "; ".join(problems))
    driver.save_screenshot(str(binary / "class-projector-join-1280x720.png"))

    tokens = {}
    for index, name in enumerate(NAMES):
        tokens[name] = server.join(name)
        post(tokens[name], index, name)
    started = time.monotonic()
    state = server.fitted_state(len(NAMES))
    print(f"the pooled fit of {len(NAMES)} recordings: {time.monotonic() - started:.0f} s")
    wait_for(driver, "return [document.getElementById('status').textContent, "
             "document.getElementById('body').textContent];",
             lambda r: r[0] == "live" and r[1].startswith("I1"))
    driver.save_screenshot(str(binary / "class-projector-1280x720.png"))  # seen if it fails
    check_class(driver, (1280, 720), state, NAMES)
    check_address(driver, "#strip-address", join_url, 17)
    # The join screen again on demand, and hidden again.
    driver.execute_script("document.getElementById('join-show').click();")
    shown = driver.execute_script("const j = document.getElementById('join');"
                                  "return [j.offsetWidth, document.getElementById('qr').offsetWidth,"
                                  " document.getElementById('strip').offsetHeight];")
    if shown[0] < 300 or shown[1] < 200 or shown[2] != 0:
        fail(f"Show the join screen: join {shown[0]} px wide, QR {shown[1]} px, strip {shown[2]}")
    check_address(driver, "#address", join_url, 24)
    driver.execute_script("document.getElementById('join-hide').click();")

    # Leave out: the reason typed while a student joins and sends a toss.
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    last = state["students"][-1]["tosses"][0]
    row_of = ("return [...document.getElementById('tosses').rows]"
              f".find(r => r.cells[1].textContent.startsWith('{last['name']}'));")
    driver.execute_script(row_of.replace("return ", "const row = ") +
                          "row.querySelector('button').click();")
    reason = driver.execute_script(row_of).find_element(By.CSS_SELECTOR, "form.reason input")
    driver.execute_script("arguments[0].dataset.opened = 'first';", reason)
    reason.send_keys("drop")
    late = server.join(LATE)
    late_toss = post(late, 30, LATE)
    shown = wait_for(driver, "return document.body.innerText;",
                     lambda text: late_toss in text, timeout=60)
    if late_toss not in shown:
        fail("the table did not update while a reason was typed")
    kept = driver.execute_script(
        "const e = document.activeElement; return [e.dataset.opened || '', e.value];")
    if kept != ["first", "drop"]:
        fail(f"the reason's form was not kept while the table updated: focus on {kept}")
    reason.send_keys("ped")
    driver.execute_script(row_of.replace("return ", "const row = ") +
                          "[...row.querySelectorAll('form.reason button')]"
                          ".find(b => b.textContent === 'Cancel').click();")
    after = driver.execute_script(row_of.replace("return ", "const row = ") +
                                  "return [row.querySelectorAll('form').length, "
                                  "row.querySelector('button').textContent];")
    if after != [0, "Leave out"]:
        fail(f"Cancel left {after}")
    time.sleep(0.5)
    if any(t["excluded"] for s in server.state()["students"] for t in s["tosses"]):
        fail("Cancel left a toss out")
    # The plate among 30 phones, judged (docs/class.md, "A toss that does not fit the others'
    # body"): its line alone is singled out; no phone's line is flagged.
    deadline = time.monotonic() + 300
    while True:
        judged = {t["name"]: t.get("judgement") for s in server.state()["students"]
                  for t in s["tosses"]}
        if all(judged.values()):
            break
        if time.monotonic() > deadline:
            fail(f"the class's tosses were not judged: {judged}")
        time.sleep(1)
    if not judged[late_toss]["outlier"] or any(j["outlier"] for n, j in judged.items()
                                                if n != late_toss):
        fail(f"the plate alone must be judged an outlier: {judged}")
    lines = wait_for(driver, "return [...document.getElementById('tosses').rows].map(r => "
                     "[r.cells[1].textContent, r.cells[6].textContent]);",
                     lambda rows: any(n.startswith(late_toss) and "outlier" in w
                                      for n, w in rows), timeout=60)
    flagged = [(n, w) for n, w in lines if not n.startswith(late_toss) and
               ("flag:" in w or w.startswith("outlier") or "flexes" in w)]
    if flagged or not any(n.startswith(late_toss) and w.startswith("outlier") for n, w in lines):
        fail(f"the plate's line alone must say outlier: flagged {flagged[:3]}, lines {lines[-2:]}")
    plate = next(t for s in server.state()["students"] for t in s["tosses"]
                 if t["name"] == late_toss)
    row_of = ("return [...document.getElementById('tosses').rows]"
              f".find(r => r.cells[1].textContent.startsWith('{late_toss}'));")
    driver.execute_script(row_of.replace("return ", "const row = ") +
                          "row.querySelector('button').click();")
    reason = driver.execute_script(row_of).find_element(By.CSS_SELECTOR, "form.reason input")
    reason.send_keys("another body (a plate)", Keys.ENTER)
    deadline = time.monotonic() + 30
    while True:
        held = [t for s in server.state()["students"] for t in s["tosses"]
                if t["toss"] == plate["toss"]][0]
        if held["excluded"] == "another body (a plate)":
            break
        if time.monotonic() > deadline:
            fail(f"the page's Leave out did not reach the server: {held}")
        time.sleep(0.25)
    state = server.fitted_state(len(NAMES))  # 31 tosses held, one left out
    wait_for(driver, "return [document.getElementById('status').textContent, "
             "document.body.innerText.includes('left out: another body (a plate)')];",
             lambda r: r == ["live", True])
    time.sleep(0.5)
    names = NAMES + [LATE]
    driver.save_screenshot(str(binary / "class-projector-1280x720.png"))
    check_class(driver, (1280, 720), state, names)
    requested = driver.execute_script(
        "return performance.getEntriesByType('resource').map(e => e.name);")
    foreign = [r for r in requested + [driver.current_url] if not r.startswith(origin)]
    if foreign:
        fail(f"the projector asked another origin: {foreign}")

    wide = projector((1920, 1080))
    wait_for(wide, "return [document.getElementById('status').textContent, "
             "document.getElementById('tosses').rows.length];",
             lambda r: r[0] == "live" and r[1] == len(names))
    wide.save_screenshot(str(binary / "class-projector-1920x1080.png"))
    check_class(wide, (1920, 1080), state, names)
    # Put back through the page, held by the server.
    wide.execute_script("[...document.getElementById('tosses').rows].find(r => r.className === "
                        "'out').querySelector('button').click();")
    state = server.fitted_state(len(names))
    if any(t["excluded"] for s in state["students"] for t in s["tosses"]):
        fail("Put back did not reach the server")

    # End: through the wide projector's page; the small one hears it on its event stream; a
    # third, which missed it, learns it on Download.
    late_page = projector((1280, 720))
    wait_for(late_page, "return document.getElementById('tosses').rows.length;",
             lambda n: n == len(names))
    late_page.execute_script("events.close();")
    wide.execute_script("window.confirm = () => true; document.getElementById('end').click();")
    for who, page_driver in (("the page that ended it", wide), ("the event stream", driver)):
        ended = wait_for(page_driver, "return document.body.innerText;",
                         lambda text: "This class has ended" in text)
        if "This class has ended; its data is deleted." not in ended or \
                "build/bookspin-class --new" not in ended:
            fail(f"after End ({who}) the projector shows {ended[:300]!r}")
    late_page.execute_script("document.getElementById('download').click();")
    ended = wait_for(late_page, "return document.body.innerText;",
                     lambda text: "This class has ended" in text)
    if "This class has ended; its data is deleted." not in ended or \
            not late_page.current_url.startswith(f"{origin}/projector"):
        fail(f"Download after End: {late_page.current_url} shows {ended[:300]!r}")
    for page_driver in (driver, late_page):
        left = page_driver.execute_script(
            "return [document.body.innerText, document.getElementById('join').offsetWidth, "
            "document.getElementById('strip').offsetWidth, "
            "document.getElementById('tosses').rows.length];")
        stale = [n for n in names + [server.code, "I1 :", "joined"] if n in left[0]]
        if stale or left[1] or left[2] or left[3]:
            fail(f"after End the projector still shows {stale}, join {left[1]} px, strip "
                 f"{left[2]} px, {left[3]} lines")
    driver.save_screenshot(str(binary / "class-projector-ended-1280x720.png"))
    problems = text_problems(driver)
    if problems:
        fail("after End: " + "; ".join(problems))
    driver.get(f"{origin}/projector?class={server.code}")
    again = driver.execute_script("return document.body.innerText;")
    if "has ended" not in again or "--new" not in again or '"error"' in again:
        fail(f"the projector's address after End shows {again[:300]!r}")
    if server.counts() != {"classes": 0, "students": 0, "tosses": 0}:
        fail(f"End the class left {server.counts()}")
    print(f"the projector shows a class of {len(names)} at 1280x720 and 1920x1080, each name "
          "drawn; Leave out keeps its form while the class updates; End says what is next")
finally:
    browsers.close()
    real.close()
