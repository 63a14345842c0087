#!/usr/bin/env python3
"""A phone's lesson from the student's side, to its end (web/src/class_join.js,
web/src/fit_failure.js, web/src/modal.js askFirst; docs/phone-lab.md "In a class", docs/class.md
"A phone"): headless Chromium as a touch phone (390x844, and its screenshots again at 320x568)
against the real class server (class/bookspin_class, started by class/tests/class_server.py's
Server over https, its certificate trusted by its key's hash) and real recordings
(../shared/recordings-real/dvarkian-2022-05-03, fed sample by sample at their own rate through the
sensor override; a failure under CI=true where that folder is absent, a skip elsewhere):
  - the bare address typed by hand (https://ADDRESS:PORT/): the lab with its join form;
  - the class's page typed by hand without its class (https://ADDRESS:PORT/explorer.html#lab):
    the lab offers "Join a class" with a code field, not a lab without a class box;
  - a toss recorded turning too slowly (before joining): the lab's fit fails in one sentence
    saying what to do ("record again, spinning the phone faster … at least 2 rad/s", the finder's
    number), the fit's whole line one tap away in a closed <details>; said in the live region;
  - the code typed in lower case with a space and a dash joins (the projector's code);
  - the slow turn sent to the class by its row's button: the class's fit of it alone fails, and
    the phone says so in one sentence (the server's own where it gives one), not "not fitted
    yet"; the teacher leaves it out;
  - two real tosses held by the class; Remove on a held one asks first, saying the class keeps
    its copy and to ask the teacher; "Keep it" keeps the row; "Remove from this phone" removes
    it from the phone alone: the server still holds all three tosses;
  - the teacher ends the class (DELETE, as the projector's End does): the phone says the class
    is over at its next reading of the results, shows the join form, and asks the server
    nothing more (no reading of the results in the 17 s after, where it read them every 15 s);
    a reload does not claim the class again.
Screenshots (BINARY_DIR/test-output/browser/explorer-phone-class-{join,fit-failed,class-failed,
list,results,remove,ended}-WxH.png) at 390x844 and 320x568 (docs/class.md's, "A phone"); none of their text
under 12 px or past its box.

Usage: explorer_phone_class_end_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import math
import time

from browser import fail, text_problems, wait_for
from explorer_phone_in_class_test import (ROW_BUTTON, phone_lesson, record, row_state, rows,
                                          state_of, type_into, wait_row)
from explorer_records_gyro_test import override, tap

SIZES = [(390, 844), (320, 568)]
TOSSES = ["12-13-01", "12-13-51"]
NAME = "Ана Lima"


def phone(driver, size):
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
        "width": size[0], "height": size[1], "deviceScaleFactor": 1, "mobile": True})


def screenshots(driver, shots, stem, element_id):
    """The page at each phone size, `element_id` scrolled to the top: saved, its text checked."""
    for size in SIZES:
        phone(driver, size)
        time.sleep(0.5)
        driver.execute_script("const e = document.getElementById(arguments[0]);"
                              "if (e && !e.closest('dialog:not([open])')) e.scrollIntoView({block: 'start'})", element_id)
        time.sleep(0.3)
        path = shots / f"explorer-phone-class-{stem}-{size[0]}x{size[1]}.png"
        driver.save_screenshot(str(path))
        problems = text_problems(driver, unseen='.unseen, #spoken, dialog:not([open]) *')
        if problems:
            fail(f"{stem} at {size[0]}x{size[1]}: {'; '.join(problems)} ({path})")
        print(f"screenshot {path}")
    phone(driver, SIZES[0])


def slow_turn():
    """3 s of a phone turned slowly in the hand (0.9 rad/s, wobbling), at 50 Hz: no flight."""
    t = [k / 50 for k in range(150)]
    return t, [(0.9 + 0.1 * math.sin(3 * s), 0.2 * math.cos(2 * s), 0.1) for s in t]


def tap_remove(driver, name):
    """A tap on the Remove button of recording `name`'s row."""
    point = driver.execute_script("""const li = [...document.querySelectorAll('#labRecordList li')]
          .find((r) => r.dataset.name === arguments[0]);
        const b = li && [...li.querySelectorAll('button')].find((x) => x.textContent === 'Remove');
        if (!b) return null;
        b.scrollIntoView({block: 'center'}); const r = b.getBoundingClientRect();
        return {x: r.left + r.width / 2, y: r.top + r.height / 2};""", name)
    if point is None:
        fail(f"the row of {name} has no Remove button: {rows(driver)}")
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [point]})
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})


def question(driver):
    return driver.execute_script("""const d = document.getElementById('question');
        return d && d.open ? [document.getElementById('questionText').textContent,
          document.getElementById('questionDetail').textContent, document.activeElement.id] : null;""")


def results_read(driver):
    """How many times the page has asked the server for the student's results (GET me)."""
    return driver.execute_script("return performance.getEntriesByType('resource')"
                                 ".filter((e) => /\\/api\\/class\\/[^/]+\\/me$/.test(e.name)).length")


def main():
    phone_lesson(__doc__, "explorer-phone-class-end", SIZES[0], TOSSES, lesson)


def lesson(driver, server, shots, recordings):
    code = server.code
    # The bare address typed by a student who cannot scan: the lab's join form (its code filled
    # in where the server sends the class's address instead).
    driver.get(server.url)
    if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
        fail(f"the page never became ready: {driver.get_log('browser')}")
    shown = wait_for(driver, """return [!document.getElementById('lab').hidden, !document.getElementById('classBox').hidden,
        !document.getElementById('classJoin').hidden, document.getElementById('classCode').value]""",
                     lambda s: s[0] and s[1], 15)
    if shown[:3] != [True, True, True] or shown[3] not in ("", code):
        fail(f"the bare address {server.url}: the lab open, a class box, the join form, the code: {shown}")
    print(f"the bare address: {shown} ({driver.current_url})")
    # The class's page typed without its class: the join form all the same.
    driver.get(f"{server.url}explorer.html#lab")
    if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
        fail(f"the page never became ready: {driver.get_log('browser')}")
    override(driver, True)
    shown = wait_for(driver, """return [!document.getElementById('lab').hidden, !document.getElementById('classBox').hidden,
        document.getElementById('classTitle').textContent, document.getElementById('classCode').value,
        !document.getElementById('classJoin').hidden]""", lambda s: s[1], 15)
    if shown != [True, True, "Join a class", "", True]:
        fail(f"the class's page without ?class=: the lab open, a class box, its title, an empty code, the "
             f"join form: {shown}")
    print(f"explorer.html#lab on the class's server: {shown}")

    # A toss turned too slowly, before joining: the fit fails in one sentence saying what to do.
    driver.execute_script("""window.saidLines = [];
        new MutationObserver(() => window.saidLines.push(document.getElementById('labSpoken').textContent))
          .observe(document.getElementById('labSpoken'), {childList: true, characterData: true, subtree: true});""")
    slow = record(driver, "a slow turn", *slow_turn())
    failure = wait_for(driver, """const e = document.getElementById('labError'); const d = e.querySelector('details');
        return [(e.querySelector('.failureSentence') || e).textContent, d ? d.open : null,
          d ? d.querySelector('summary').textContent : '', d ? d.querySelector('p').textContent : '']""",
                       lambda f: f[0].startswith("error:"), 60)
    sentence = ("error: No flight in this recording: record again, spinning the phone faster as you throw it "
                "(at least 2 rad/s, a turn in 3.1 s).")
    if failure[0] != sentence or failure[1] is not False or "no free flight found" not in failure[3]:
        fail(f"a recording with no flight: the lab shows {failure[0]!r} (wanted {sentence!r}), its detail "
             f"{'open' if failure[1] else 'closed' if failure[1] is False else 'absent'}: {failure[3][:200]!r}")
    if sentence not in driver.execute_script("return window.saidLines"):
        fail(f"the failure's sentence was not said: {driver.execute_script('return window.saidLines')}")
    print(f"no flight: {failure[0]!r}; the fit's words one tap away ({len(failure[3])} characters)")
    screenshots(driver, shots, "fit-failed", "labError")

    # The code typed in lower case, with a space and a dash: joined.
    typed = f"{code[:2].lower()} {code[2:4].lower()}-{code[4:].lower()}"
    type_into(driver, "classCode", typed)
    type_into(driver, "className", NAME)
    driver.execute_script("document.activeElement.blur()")
    screenshots(driver, shots, "join", "classBox")
    tap(driver, "classJoinButton")
    said = wait_for(driver, "return document.getElementById('classState').textContent",
                    lambda s: s.startswith("In class") or "error" in s, 20)
    if not said.startswith(f"In class {code} as {NAME}") or server.students() != [NAME]:
        fail(f"the code typed {typed!r}: the page says {said!r}; the server's students {server.students()}")
    if f"class={code}" not in driver.current_url:
        fail(f"joined: the address {driver.current_url} does not carry class={code}")
    print(f"typed {typed!r}: {said}")
    if row_state(driver, slow):
        fail(f"the slow turn kept before joining was sent: {row_state(driver, slow)!r}")

    # The slow turn sent to the class by its row's button: the class's fit of it alone fails,
    # and the phone says so in one sentence (not "not fitted yet"); the teacher leaves it out.
    point = driver.execute_script(ROW_BUTTON + "b.scrollIntoView({block: 'center'}); const r = b.getBoundingClientRect();"
                                  "return {x: r.left + r.width / 2, y: r.top + r.height / 2};", slow)
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [point]})
    driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
    wait_row(driver, slow, f"held by class {code}", 30, "the slow turn sent")
    failed = None
    for _ in range(60):
        tap(driver, "classRefresh")
        failed = wait_for(driver, """const e = document.getElementById('classPooledError'); const d = e.querySelector('details');
            return [e.hidden, (e.querySelector('.failureSentence') || e).textContent, d ? d.open : null,
              document.getElementById('classPooled').textContent]""", lambda f: not f[0], 2)
        if not failed[0]:
            break
    if failed[0] or not failed[1] or len(failed[1]) > 300 or failed[2] or failed[3] != "The class's body: not fitted":
        fail(f"the class's fit of a recording with no flight: the phone shows {failed} (hidden, its sentence, "
             "its detail open, the body's line)")
    print(f"the class's fit failed: {failed[1]!r}")
    screenshots(driver, shots, "class-failed", "classBox")
    toss = driver.execute_script("return window.explorer.labTossIds()")[slow]
    origin = {"Origin": server.url.rstrip("/")}
    answer = server.server.request("POST", f"/api/class/{code}/tosses/{toss}/exclude", {"reason": "no flight"},
                                   token=server.server.key, headers=origin)
    if answer[0] != 200:
        fail(f"leaving the slow turn out: {answer}")

    # Two real tosses, held by the class; the class's results.
    names = []
    for k, (t, omega) in enumerate(recordings):
        names.append(record(driver, f"toss {k + 1}", t, omega))
        wait_row(driver, names[-1], f"held by class {code}", 30, f"toss {k + 1}")
    tap(driver, "classRefresh")
    pooled = wait_for(driver, "return document.getElementById('classPooled').textContent",
                      lambda s: "pooled from" in s, 120)
    if "pooled from" not in pooled:
        fail(f"the class's results: {pooled!r}")
    screenshots(driver, shots, "list", "labRecordings")
    screenshots(driver, shots, "results", "classBox")

    # Remove on a held toss: asked first, told the class keeps its copy.
    tap_remove(driver, names[0])
    asked = wait_for(driver, "return document.getElementById('question').open ? true : null", bool, 5) and question(driver)
    want = [f"Remove {names[0]} from this phone?", f"Class {code} keeps its copy", "ask your teacher"]
    if not asked or asked[0] != want[0] or want[1] not in asked[1] or want[2] not in asked[1] or asked[2] != "questionNo":
        fail(f"Remove on a toss the class holds: the question {asked} (wanted {want}, focus on Keep it); "
             f"the rows {rows(driver)}")
    print(f"Remove asks: {asked[0]} {asked[1]}")
    screenshots(driver, shots, "remove", "question")
    tap(driver, "questionNo")
    if question(driver) or names[0] not in dict(rows(driver)):
        fail(f"Keep it: the question {question(driver)}, the rows {rows(driver)}")
    tap_remove(driver, names[0])
    wait_for(driver, "return document.getElementById('question').open ? true : null", bool, 5)
    tap(driver, "questionYes")
    gone = wait_for(driver, "return [...document.querySelectorAll('#labRecordList li')].map((li) => li.dataset.name)",
                    lambda r: names[0] not in r, 5)
    outbox = [i["toss"] for i in driver.execute_script("return window.explorer.classOutbox()")]
    held = [b["name"] for b in server.held()]
    if names[0] in gone or held != [slow, *names] or len(outbox) != 2:
        fail(f"removed from the phone: its rows {gone}, its outbox {outbox}; the server holds {held}, not "
             f"{[slow, *names]}")
    print(f"removed from this phone; the class still holds {held}")

    # The teacher ends the class: the phone says so once, and asks nothing more.
    answer = server.server.request("DELETE", f"/api/class/{code}", token=server.server.key, headers=origin)
    if answer[0] != 200:
        fail(f"ending the class: {answer}")
    tap(driver, "classRefresh")
    said = wait_for(driver, "return document.getElementById('classState').textContent",
                    lambda s: s.startswith(f"Class {code} is over"), 30)
    shown = driver.execute_script("""return [document.getElementById('classMe').hidden,
        !document.getElementById('classJoin').hidden, document.getElementById('classCode').value]""")
    if not said.startswith(f"Class {code} is over") or shown != [True, True, ""]:
        fail(f"after End: the phone says {said!r}; results hidden, join form shown, code: {shown}")
    print(f"after End: {said}")
    screenshots(driver, shots, "ended", "classBox")
    before = results_read(driver)
    time.sleep(17)
    if results_read(driver) != before or not state_of(driver).startswith(f"Class {code} is over"):
        fail(f"after End the phone read the results {results_read(driver) - before} more times; it says "
             f"{state_of(driver)!r}")
    driver.refresh()
    if not wait_for(driver, "return !!(window.explorer && window.explorer.ready)", bool, 60):
        fail("the page never became ready after the reload")
    time.sleep(2)
    if state_of(driver).startswith("In class") or not driver.execute_script("return document.getElementById('classMe').hidden"):
        fail(f"reloaded after End: the phone says {state_of(driver)!r}")
    print(f"reloaded after End: {state_of(driver)!r}")


if __name__ == "__main__":
    main()
