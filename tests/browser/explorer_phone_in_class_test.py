#!/usr/bin/env python3
"""A phone in a class (web/src/class_join.js, web/src/class_outbox.js, docs/phone-lab.md "In a
class"; the server's API: docs/class.md): headless Chromium at a phone's size (390x844, touch:
every button tapped through the DevTools protocol's touch events) opens the class's address
(explorer.html?class=CODE#lab, as its QR code gives it) from a class server on 127.0.0.1, joins
under a name in two alphabets, and records real tosses (../shared/recordings-real/dvarkian-
2022-05-03, each fed sample by sample at its own rate through the sensor override, as
explorer_records_gyro_test does; a failure under CI=true where that folder is absent, a skip
elsewhere):
  - the join form: the code prefilled from the address; a name the project's rule refuses (a
    '/') refused by the page with the rule's words, nothing asked of the server; a wrong code
    refused with the server's reason;
  - toss 1 kept online: held by the class (its row says so in words), the server holds it
    under the id the page stored with the recording, its CSV the one the row's Download gives;
  - the network off (Network.emulateNetworkConditions offline): toss 2 kept, its row "waiting",
    said in the lab's live region, the server holds nothing new; the network back just as a
    wait of 8 s or more begins: held within 4 s (the browser's online event), once;
  - the class's address unreachable while the page is (Network.setBlockedURLs on /api/): toss 3
    kept, waiting; the page reloaded: still waiting (the outbox in the phone's storage), and
    once the address answers again, held by the retry alone (no online event), once;
  - a toss kept before joining (12-38-00) not sent on its own: its row offers "Send to class
    CODE", which sends it;
  - every held toss posted again under its id (a lost answer's resend): answered 200, the
    server still holds each once; at the end the server holds exactly the four tosses, each
    once, in the order sent, each with the bytes of its recording;
  - the class's results as the server gives them (GET me): its pooled body and each of the
    student's tosses shown.
The server: the real class server (class/bookspin_class, started by tests/python/
class_server.py's Server over https, its certificate trusted by its key's hash), what it holds
read from its SQLite store beside it; its packages missing, the test skips (fails under CI).
Screenshots (BINARY_DIR/test-output/browser/explorer-phone-in-class-{join,list,results}-WxH.png)
at 390x844 and 1280x720: the join form, the list with held and waiting rows, the class's
results; none of their text under 12 px or past its box.

Usage: explorer_phone_in_class_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import re
import time

from browser import (at_sigma, console_errors, fail, find_browser, lab_page_under_test,
                     open_browser, require, test_arguments, text_problems, wait_for)
from class_browser import RealServer
from explorer_records_gyro_test import (feed, feed_at_own_rate, override, readings, real_recording,
                                        tap)

SIZE = (390, 844)
FOLDER = "dvarkian-2022-05-03"
TOSSES = ["12-13-01", "12-13-51", "12-22-44", "12-38-00"]
NAME = "太郎 Ωmega"
UUID = re.compile(r"^[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}$")


def state_of(driver):
    return driver.execute_script("return document.getElementById('classState').textContent")


def rows(driver):
    """Each row of the lab's list: [its recording's name, the class's state in words]."""
    return driver.execute_script("""return [...document.querySelectorAll('#labRecordList li')].map((li) =>
        [li.dataset.name, (li.querySelector('.classState') || {}).textContent || '']);""")


def type_into(driver, element_id, text):
    driver.execute_script("const e = document.getElementById(arguments[0]); e.value = ''; e.focus();", element_id)
    driver.find_element("id", element_id).send_keys(text)


def record(driver, where, t, omega):
    """One toss recorded: Record tapped with a first reading given, the recording fed at its own
    rate, Stop tapped; waits until the lab is idle again (its fit ended). Its kept name."""
    before = len(driver.execute_script("return window.explorer.labRecordings()"))
    time.sleep(0.7)
    feed(driver, omega[0])
    tap(driver, "labRecord")
    said = wait_for(driver, "return document.getElementById('labRecordState').textContent",
                    lambda s: s.startswith(("recording", "error")), 30)
    if not said.startswith("recording"):
        fail(f"{where}: the recording did not start: {said!r}")
    feed_at_own_rate(driver, t, omega)
    tap(driver, "labRecord")
    kept = wait_for(driver, "return [window.explorer.labRecordings(), window.explorer.labRecorderPhase()]",
                    lambda r: len(r[0]) > before and r[1] == "idle", 300)
    if len(kept[0]) <= before:
        state = driver.execute_script("return document.getElementById('labRecordState').textContent")
        fail(f"{where}: no recording kept: {state!r}")
    return kept[0][-1]["name"]


# JavaScript: `b`, the "Send to class" button of the row of recording arguments[0] (or null).
ROW_BUTTON = ("const li = [...document.querySelectorAll('#labRecordList li')].find((r) => r.dataset.name === arguments[0]);"
              "const b = li && li.querySelector('.classSend');")


def row_state(driver, name):
    return dict(rows(driver)).get(name, "")


def wait_row(driver, name, words, timeout, where):
    """The row of recording `name` says `words`: fail() after `timeout` s otherwise."""
    said = wait_for(driver, "return [...document.querySelectorAll('#labRecordList li')].map((li) => "
                    "[li.dataset.name, (li.querySelector('.classState') || {}).textContent || ''])",
                    lambda r: words in dict(r).get(name, ""), timeout)
    if words not in dict(said).get(name, ""):
        fail(f"{where}: the row of {name} says {dict(said).get(name, '')!r}, not {words!r}; "
             f"the outbox {driver.execute_script('return window.explorer.classOutbox()')}")


def network(driver, offline):
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": offline, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1})


def block_api(driver, blocked):
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.setBlockedURLs", {"urls": ["*/api/class/*"] if blocked else []})


def open_class_page(driver, url):
    driver.get(url)
    if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
        fail(f"the page never became ready: {driver.get_log('browser')}")
    override(driver, True)


def check_server_holds(server, names_and_ids, texts, where):
    """fail() unless the server holds exactly these tosses, each once, in this order, each with
    its recording's bytes."""
    held = server.held()
    got = [(b["toss"], b["name"]) for b in held]
    want = [(toss, name) for name, toss in names_and_ids]
    if got != want:
        fail(f"{where}: the server holds {got}, not each toss once in the order kept {want}")
    for b in held:
        if b["csv"] != texts[b["name"]]:
            fail(f"{where}: the server holds other bytes for {b['name']} than the recording's download")


def screenshots(driver, shots, stem):
    for size in (SIZE, (1280, 720)):
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
            "width": size[0], "height": size[1], "deviceScaleFactor": 1, "mobile": size == SIZE})
        time.sleep(0.5)
        driver.execute_script("document.getElementById(arguments[0]).scrollIntoView({block: 'start'})",
                              "labRecordings" if stem == "list" else "classBox")
        time.sleep(0.3)
        path = shots / f"explorer-phone-in-class-{stem}-{size[0]}x{size[1]}.png"
        driver.save_screenshot(str(path))
        problems = text_problems(driver, unseen='.unseen, #spoken')
        if problems:
            fail(f"{stem} at {size[0]}x{size[1]}: {'; '.join(problems)} ({path})")
        print(f"screenshot {path}")
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
        "width": SIZE[0], "height": SIZE[1], "deviceScaleFactor": 1, "mobile": True})


def downloads(driver):
    """Each row's name and the text its Download serves."""
    return dict(driver.execute_async_script("""const done = arguments[0];
        Promise.all([...document.querySelectorAll('#labRecordList li')].map((li) =>
          fetch(li.querySelector('a[download]').href).then((r) => r.text()).then((t) => [li.dataset.name, t]))).then(done);"""))


def phone_lesson(doc, name, size, tosses, lesson):
    """A phone's lesson against the real class server (this test and the class's end test): the
    lab's page built as `name`, the server started on it, the real recordings `tosses` read,
    Chromium at `size` (a touch phone), `lesson(driver, server, shots, recordings)` run; no
    console error but the favicon's and the class API's answers."""
    bookspin, source, binary = test_arguments(doc)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    recordings = [readings(real_recording(source, f"{FOLDER}/{t}")) for t in tosses]
    out, _, shots, _ = lab_page_under_test(bookspin, source, binary, name)
    server = RealServer(source, binary, out / "explorer.html")
    print(f"the server: bookspin_class at {server.url}, class {server.code}")
    try:
        with open_browser(chromium, driver_path, size=size, exact_viewport=True, extra_args=[server.trust]) as driver:
            driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
                "width": size[0], "height": size[1], "deviceScaleFactor": 1, "mobile": True})
            driver.execute_cdp_cmd("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 5})
            lesson(driver, server, shots, recordings)
            errors = [e for e in console_errors(driver)
                      if "favicon" not in e.get("message", "") and "/api/class/" not in e.get("message", "")]
            if errors:
                fail(f"console errors: {errors[:3]}")
    finally:
        server.close()
    print("ok")


def main():
    phone_lesson(__doc__, "explorer-phone-in-class", SIZE, TOSSES, run_class)


def run_class(driver, server, shots, recordings):
    code = server.code
    open_class_page(driver, f"{server.url}explorer.html?class={code}#lab")
    # The join form, its code from the address.
    shown = driver.execute_script("""return [!document.getElementById('lab').hidden, !document.getElementById('classBox').hidden,
        document.getElementById('classCode').value, !document.getElementById('classJoin').hidden]""")
    if shown != [True, True, code, True]:
        fail(f"the class's address: the lab open, the class box, its code, the form: {shown}")
    screenshots(driver, shots, "join")
    # A toss kept before joining: not sent on its own.
    early = record(driver, "before joining", *recordings[3])
    # A name the project's rule refuses: said by the page, the server not asked.
    type_into(driver, "className", "a/b")
    tap(driver, "classJoinButton")
    said = wait_for(driver, "return document.getElementById('classState').textContent", lambda s: "error" in s, 10)
    if "your name: it must not hold /" not in said or server.students():
        fail(f"a name with '/': the page says {said!r}; the server's students {server.students()}")
    # A wrong code: the server's reason.
    type_into(driver, "classCode", "NOPE42")
    type_into(driver, "className", NAME)
    tap(driver, "classJoinButton")
    said = wait_for(driver, "return document.getElementById('classState').textContent", lambda s: "refused" in s, 20)
    if "no class with code NOPE42" not in said:
        fail(f"a wrong code: the page says {said!r}")
    type_into(driver, "classCode", code)
    tap(driver, "classJoinButton")
    said = wait_for(driver, "return document.getElementById('classState').textContent", lambda s: s.startswith("In class"), 20)
    if not said.startswith(f"In class {code} as {NAME}") or server.students() != [NAME]:
        fail(f"joined: the page says {said!r}; the server's students {server.students()}")
    print(f"joined: {said}")

    # The toss kept before joining: its row offers to send it, and nothing was sent.
    offer = driver.execute_script(ROW_BUTTON + "return b ? b.textContent : null;", early)
    if offer != f"Send to class {code}" or row_state(driver, early) or server.held():
        fail(f"a toss kept before joining: its row offers {offer!r}, says {row_state(driver, early)!r}; "
             f"the server holds {len(server.held())}")
    kept = []  # (name, toss id) in the order kept
    # Toss 1, online: held.
    name = record(driver, "toss 1", *recordings[0])
    ids = driver.execute_script("return window.explorer.labTossIds()")
    if not UUID.match(ids.get(name) or ""):
        fail(f"toss 1: the recording's toss id {ids.get(name)!r} is not a UUID v4")
    kept.append((name, ids[name]))
    wait_row(driver, name, f"held by class {code}", 30, "toss 1 online")
    print(f"toss 1 online: {row_state(driver, name)}")

    # Toss 2 with the network off: waiting, said; back online: held.
    driver.execute_script("""window.saidLines = [];
        new MutationObserver(() => window.saidLines.push(document.getElementById('labSpoken').textContent))
          .observe(document.getElementById('labSpoken'), {childList: true, characterData: true, subtree: true});""")
    network(driver, True)
    name = record(driver, "toss 2", *recordings[1])
    kept.append((name, driver.execute_script("return window.explorer.labTossIds()")[name]))
    wait_row(driver, name, "waiting to be sent", 20, "toss 2 offline")
    print(f"toss 2 offline: {row_state(driver, name)}")
    if len(server.held()) != 1:
        fail(f"offline: the server holds {len(server.held())} tosses")
    time.sleep(3)
    if len(server.held()) != 1 or "waiting" not in row_state(driver, name):
        fail(f"offline 3 s on: the server holds {len(server.held())}, the row says {row_state(driver, name)!r}")
    screenshots(driver, shots, "list")
    # Back online just as a wait of 8 s or more begins (the row's "next try in N s" changed):
    # held within 4 s is the browser's online event's doing, not the timer's (at least 6.4 s).
    seen, deadline = row_state(driver, name), time.monotonic() + 90
    while time.monotonic() < deadline:
        now = row_state(driver, name)
        wait = re.search(r"next try in (\d+) s", now)
        if now != seen and wait and int(wait.group(1)) >= 8:
            break
        seen = now
        time.sleep(0.1)
    else:
        fail(f"offline: no wait of 8 s or more began within 90 s: the row says {row_state(driver, name)!r}")
    network(driver, False)
    wait_row(driver, name, f"held by class {code}", 4, f"toss 2 back online ({now!r} before)")
    print(f"toss 2 back online: {row_state(driver, name)}")
    said = driver.execute_script("return window.saidLines")
    for words in ("waiting to be sent", "held by class"):
        if not any(l.startswith(name) and words in l for l in said):
            fail(f"toss 2: the live region never said {name}: …{words}…: {said}")

    # Toss 3 with the class's address blocked, the page reloaded meanwhile: still waiting;
    # the address back: held by the retry alone.
    block_api(driver, True)
    name = record(driver, "toss 3", *recordings[2])
    kept.append((name, driver.execute_script("return window.explorer.labTossIds()")[name]))
    wait_row(driver, name, "waiting to be sent", 20, "toss 3 blocked")
    driver.refresh()
    if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
        fail("the page never became ready after the reload")
    wait_row(driver, name, "waiting to be sent", 30, "toss 3 after a reload")
    for earlier, _ in kept[:2]:
        wait_row(driver, earlier, f"held by class {code}", 10, "the held tosses after a reload")
    print(f"toss 3 after a reload: {row_state(driver, name)}")
    if len(server.held()) != 2:
        fail(f"blocked: the server holds {len(server.held())} tosses")
    block_api(driver, False)
    wait_row(driver, name, f"held by class {code}", 40, "toss 3 unblocked")
    print(f"toss 3 unblocked: {row_state(driver, name)}")

    # The toss kept before joining, sent by its row's button: held, after the others.
    point = driver.execute_script(ROW_BUTTON + "b.scrollIntoView({block: 'center'}); const r = b.getBoundingClientRect();"
                                  "return {x: r.left + r.width / 2, y: r.top + r.height / 2};", early)
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [point]})
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
    wait_row(driver, early, f"held by class {code}", 30, "the toss kept before joining, sent")
    kept.append((early, driver.execute_script("return window.explorer.labTossIds()")[early]))

    texts = downloads(driver)
    check_server_holds(server, kept, texts, "after the four tosses")
    # Every held toss posted again under its id: 200, none stored twice.
    again = driver.execute_async_script("window.explorer.classResendHeld().then(arguments[0])")
    if sorted(s for _, s in again) != [200] * 4:
        fail(f"the held tosses posted again: answered {again}")
    check_server_holds(server, kept, texts, "after every held toss was posted again")
    print(f"the server holds {len(server.held())} tosses, each once, in the order kept; posted again: {again}")

    # The class's results (GET me): the server's pooled body as the page rounds it, and this
    # student's four tosses.
    pooled = server.pooled(4)
    tap(driver, "classRefresh")
    if pooled["ratios"]:
        want = " : ".join(" ± ".join(at_sigma(r, s)) for r, s in zip(pooled["ratios"][:2], pooled["sigma"][:2]))
        want = (f"pooled from {pooled['tosses']} toss{'' if pooled['tosses'] == 1 else 'es'} in {pooled['recordings']} "
                f"recording{'' if pooled['recordings'] == 1 else 's'}: I1 : I2 : I3 = {want} : 1")
    else:
        want = "not fitted yet"
    me = wait_for(driver, "return [document.getElementById('classPooled').textContent, "
                  "document.querySelectorAll('#classMine tr').length - 1]", lambda r: want in r[0] and r[1] == 4, 30)
    if want not in me[0] or me[1] != 4:
        fail(f"the class's results: the page shows {me}, the server's pooled fit {pooled} ({want!r})")
    print(f"the class's results: {me[0]}; {me[1]} tosses of the student's")
    screenshots(driver, shots, "results")

if __name__ == "__main__":
    main()
