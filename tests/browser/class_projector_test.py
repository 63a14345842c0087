"""The class's projector in headless Chromium (docs/class.md, "The projector"): a real
bookspin-class on 127.0.0.1 (its own certificate trusted by its public key's hash, nothing
ignored), a class of the real recordings of ../shared/recordings-real/ posted by plain HTTPS
clients, and the teacher's page opened through the printed key at 1920×1080 and 1280×720: the
join screen shows the code and the phones' address and a QR code, the class's body is the
server's pooled fit as the page rounds it, a row per flight with the student's name, no text
under 12 px or past its box, nothing requested from another origin; the teacher leaves a toss
out with a reason through the page and puts it back, and the server holds each. Screenshots
in BINARY_DIR/class-projector-WxH.png (docs/class.md shows them).

    class_projector_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
"""
import base64
import hashlib
import os
import sys
import tempfile
import time
from pathlib import Path

from browser import (fail, find_browser, missing, open_browser, test_arguments, text_problems,
                     wait_for)

bookspin, source, binary = test_arguments(__doc__)
os.environ["BOOKSPIN_SOURCE_DIR"] = str(source)
os.environ["PYTHONPATH"] = os.pathsep.join([str(binary / "python"),
                                            os.environ.get("PYTHONPATH", "")])
sys.path[:0] = [str(source / "tests" / "python"), str(binary / "python")]
try:
    import aiohttp  # noqa: F401
    import segno  # noqa: F401
except ImportError as error:
    missing(f"the class server's packages ({error}): scripts/install-deps.sh")
from class_server import REAL, Server, real_csv  # noqa: E402

if not REAL.is_dir():
    missing(f"no real recordings at {REAL} (../shared/recordings-real/ beside the checkout)")
chromium, driver_path = find_browser()

work = Path(tempfile.mkdtemp(prefix="bookspin-class-browser-"))
page = work / "explorer.html"
page.write_text("<!doctype html><title>explorer</title>\n")
server = Server(work / "data", page).start()
try:
    from cryptography import x509
    from cryptography.hazmat.primitives import serialization
    cert = x509.load_pem_x509_certificate((work / "data" / "tls" / "server.pem").read_bytes())
    spki = cert.public_key().public_bytes(serialization.Encoding.DER,
                                          serialization.PublicFormat.SubjectPublicKeyInfo)
    trust = "--ignore-certificate-errors-spki-list=" + \
        base64.b64encode(hashlib.sha256(spki).digest()).decode()
    names = ["Anna", "Ben", "太郎", "Zoë"]
    recordings = ["12-10-56", "12-13-01", "12-13-51", "12-22-44"]
    for name, recording in zip(names, recordings):
        token = server.join(name)
        status, answer = server.post_toss(token, real_csv(recording), name=recording)
        if status != 201:
            fail(f"posting {recording}: {status} {answer}")
    state = server.fitted_state(4)
    ratios = state["pooled"]["ratios"]
    flights = sum(len(t["flights"]) for s in state["students"] for t in s["tosses"])
    origin = f"https://127.0.0.1:{server.port}"
    for size in ((1920, 1080), (1280, 720)):
        with open_browser(chromium, driver_path, size=size, exact_viewport=True,
                          extra_args=[trust]) as driver:
            driver.get(f"{origin}/teacher?key={server.key}")
            shown = wait_for(driver, "return [document.getElementById('body').textContent, "
                             "document.getElementById('tosses').rows.length, "
                             "document.getElementById('qr').naturalWidth, "
                             "document.getElementById('code').textContent, "
                             "document.getElementById('address').textContent];",
                             lambda r: r[0].startswith("I1") and r[1] == flights and r[2] > 0)
            expected = f"I1 : I2 : I3 = {ratios[0]:.3f}"
            if not shown[0].startswith(expected) or f"{ratios[1]:.3f}" not in shown[0]:
                fail(f"the body shown {shown[0]!r}, the server's ratios {ratios}")
            if shown[1] != flights or shown[2] == 0:
                fail(f"{shown[1]} rows for {flights} flights, QR width {shown[2]}")
            if shown[3] != server.code or shown[4] != state["join_url"]:
                fail(f"join screen shows {shown[3]!r} {shown[4]!r}")
            if server.key in shown[4]:
                fail("the teacher's key is on the join screen")
            text = driver.execute_script("return document.body.innerText;")
            for name in names:
                if name not in text:
                    fail(f"{name} is not on the projector")
            problems = text_problems(driver)
            if problems:
                fail(f"at {size}: " + "; ".join(problems))
            requested = driver.execute_script(
                "return performance.getEntriesByType('resource').map(e => e.name);")
            foreign = [r for r in requested + [driver.current_url] if not r.startswith(origin)]
            if foreign:
                fail(f"the projector asked another origin: {foreign}")
            driver.save_screenshot(str(binary / f"class-projector-{size[0]}x{size[1]}.png"))
            if size == (1920, 1080):
                # Leave the plate's toss out through the page, with a reason, then put it back.
                plate = next(t for s in state["students"] for t in s["tosses"]
                             if t["name"] == "12-22-44")
                driver.execute_script(
                    "const rows = [...document.getElementById('tosses').rows];"
                    "const row = rows.find(r => r.cells[1].textContent.startsWith('12-22-44'));"
                    "row.querySelector('button').click();"
                    "const input = row.querySelector('form.reason input');"
                    "input.value = 'another body (a plate)';"
                    "row.querySelector('form.reason button').click();")
                deadline = time.monotonic() + 30
                while True:
                    held = [t for s in server.state()["students"] for t in s["tosses"]
                            if t["toss"] == plate["toss"]][0]
                    if held["excluded"] == "another body (a plate)":
                        break
                    if time.monotonic() > deadline:
                        fail(f"the page's Leave out did not reach the server: {held}")
                    time.sleep(0.25)
                marked = wait_for(driver, "return document.body.innerText.includes("
                                  "'left out: another body (a plate)');", bool)
                if not marked:
                    fail("the left-out toss does not show its reason")
                server.fitted_state(3)
                wait_for(driver, "return document.getElementById('status').textContent;",
                         lambda status: status == "live")
                time.sleep(0.5)
                driver.save_screenshot(str(binary / "class-projector-1920x1080-left-out.png"))
                driver.execute_script(
                    "const rows = [...document.getElementById('tosses').rows];"
                    "rows.find(r => r.className === 'out').querySelector('button').click();")
                server.fitted_state(4)
    print("the projector shows the class at 1920x1080 and 1280x720; Leave out and Put back "
          "reach the server")
finally:
    server.stop()
