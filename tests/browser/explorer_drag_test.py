#!/usr/bin/env python3
"""The explorer page's two "air drag" menus (docs/explorer.md "Air drag" and "Phone-toss lab",
docs/physics.md §21) in headless Chromium, the page opened from disk: each law chosen in a menu
reaches what runs.

Builds the page's program with web/build.sh BINARY_DIR, writes the page of
scenes/exact-unstable-x.toml with `bookspin explore`, and checks:
  - the method's menu offers the three laws, none, linear and quadratic, and is shown with its
    rate for the exact and both rigid models (the rate hidden under none);
  - for each of those models, the law and rate chosen in the menu and the field (not by the
    link) give the damped |L| of the closed form at t = 100 from a start off every axis,
    |L(t)|/|L0| = e^(−rt) (linear, r = 0.01: e^-1), 1/(1 + rt) (quadratic, r = 0.02: 1/3) and
    1 (none), |L| = |I ω| with I the book's principal moments m(b² + c²)/12, … of its edges;
  - the Phone-toss lab's menu, each law chosen by its label, then the sample recording's Raw
    Data.csv given through the file input: the fit the panel shows names that law, and its
    first toss, played, runs under that law (each fit's toss replacing the earlier one's).
About 25 s once the page is built (22 s measured on the 2-core machine, 2026-11-26).

Usage: explorer_drag_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
Skipped (exit 77) where Chromium, chromedriver, selenium, emscripten or npm is missing, except
under CI=true, where that is a failure (browser.py).
"""
import math
import tomllib

from browser import console_errors, fail, find_browser, open_browser, require, run, test_arguments, wait_for
from explorer_test import load

W0 = (0.1, 0.02, 0.3)  # ω0, body frame, off every principal axis
T = 100.0
# The law, its rate, and |L(T)|/|L0| in closed form (docs/physics.md §21).
LAWS = (("linear", 0.01, math.exp(-0.01 * T)), ("quadratic", 0.02, 1 / (1 + 0.02 * T)),
        ("none", 0.0, 1.0))
# The exact motion to round-off; the rigid models' RK4 steps of 0.01 with the drag's exact
# sub-steps (docs/physics.md §21) keep |L| as closely (equal to 12 digits, 2026-11-26).
TOL = {"exact": 1e-9, "rigid-matrix": 1e-8, "rigid-quaternion": 1e-8}


def moments(scene):
    """The book's principal moments about body x, y, z: m(b² + c²)/12, m(a² + c²)/12,
    m(a² + b²)/12 of its edges a, b, c."""
    with open(scene, "rb") as f:
        book = tomllib.load(f)["book"]
    (a, b, c), m = book["size"], book["mass"]
    return [m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12]


def choose(driver, element_id, value):
    """Chooses `value` in the menu or field `element_id` as a person does: the change event."""
    driver.execute_script("""
        const [id, value] = arguments, el = document.getElementById(id);
        el.value = value; el.dispatchEvent(new Event('change'));""", element_id, str(value))


def check_method_menu(driver, page, inertia):
    load(driver, page + "?scene=exact-unstable-x&axis=custom&w=" + ",".join(map(repr, W0)) +
         "&jiggle=0&dt=0.01")
    options = driver.execute_script(
        "return [...document.getElementById('drag').options].map((o) => o.value)")
    if options != ["none", "linear", "quadratic"]:
        fail(f"the air drag menu offers {options}, not none, linear and quadratic")
    L0 = math.sqrt(sum((i * w) ** 2 for i, w in zip(inertia, W0)))
    for model in ("exact", "rigid-matrix", "rigid-quaternion"):
        choose(driver, "model", model)
        if model != "exact":
            choose(driver, "integrator", "rk4")
        for law, rate, want in LAWS:
            choose(driver, "drag", law)
            shown = driver.execute_script(
                "return ['dragRow', 'dragRateRow'].map((id) => !document.getElementById(id).hidden)")
            if shown != [True, law != "none"]:
                fail(f"{model}, {law}: the menu and its rate shown {shown}, expected "
                     f"[True, {law != 'none'}]")
            if law != "none":
                choose(driver, "dragRate", rate)
            state = driver.execute_script("return window.explorer.state()")
            if (state["model"], state["drag"]) != (model, law) or (law != "none" and state["dragRate"] != rate):
                fail(f"the menus set {state['model']}, {state['drag']} {state['dragRate']}, "
                     f"not {model}, {law} {rate}")
            w = driver.execute_script(f"return window.explorer.omegaAt({T!r})")[0]
            got = math.sqrt(sum((i * x) ** 2 for i, x in zip(inertia, w))) / L0
            print(f"{model}, {law} at {rate}: |L({T:g})|/|L0| = {got:.12f}, closed form {want:.12f}")
            if not abs(got - want) <= TOL[model] * want:
                fail(f"{model} with {law} drag at rate {rate} chosen in the menu: |L({T:g})|/|L0| "
                     f"= {got}, the closed form {want}")
    # A model that takes no drag hides the menu.
    choose(driver, "model", "particle")
    if driver.execute_script("return !document.getElementById('dragRow').hidden"):
        fail("the particle model shows the air drag menu, which it does not take")


def check_lab_menu(driver, recording):
    driver.execute_script("document.getElementById('labOpen').click()")
    for law in ("quadratic", "none", "linear"):
        # Chosen by its label, as a person reads the menu.
        found = driver.execute_script("""
            const [law] = arguments, menu = document.getElementById('labDrag');
            const o = [...menu.options].find((x) => x.textContent.trim().startsWith(law));
            if (!o) return false;
            menu.value = o.value; menu.dispatchEvent(new Event('change')); return true;""", law)
        if not found:
            fail(f"the lab's air drag menu has no {law!r}")
        driver.execute_script("document.getElementById('labResult').hidden = true")
        driver.find_element("id", "labFile").send_keys(str(recording))
        if not wait_for(driver, "return !document.getElementById('labResult').hidden", bool, 120):
            fail(f"{law}: the panel showed no fit: {driver.find_element('id', 'labError').text}")
        row = driver.execute_script("""
            return [...document.querySelectorAll('#labBody tr')].map((r) => r.textContent)
              .find((t) => t.startsWith('tosses, drag')) || ''""")
        print(f"lab, {law} chosen: {row!r}")
        if not row.endswith(f", {law}"):
            fail(f"the lab's menu at {law!r}: the fit shown says {row!r}")
        # Its first toss played: the explorer runs that fit's drag (a toss of the same name
        # fitted before under another law is replaced, not played).
        driver.execute_script("document.querySelector('#labTosses button').click()")
        state = driver.execute_script("return window.explorer.state()")
        print(f"lab, {law}: its toss 1 plays {state['scene']} with drag {state['drag']} {state['dragRate']}")
        if state["drag"] != law or (law == "none") != (state["dragRate"] == 0):
            fail(f"the toss fitted under {law} drag plays with {state['drag']} {state['dragRate']}")
        driver.execute_script("document.getElementById('labOpen').click();"
                              "document.getElementById('labFile').value = ''")


def main():
    bookspin, source, binary = test_arguments(__doc__)
    chromium, driver_path = find_browser()
    require("em++", "npm")
    out = binary / "test-output" / "explorer-drag"
    run(["bash", str(source / "web" / "build.sh"), str(binary)])
    scene = source / "scenes" / "exact-unstable-x.toml"
    run([bookspin, "explore", str(scene), "-o", str(out)])
    page = (out / "explorer.html").resolve().as_uri()
    with open_browser(chromium, driver_path, size=(1280, 900)) as driver:
        check_method_menu(driver, page, moments(scene))
        check_lab_menu(driver, (source / "recordings" / "phone-on-book-synthetic" / "Raw Data.csv").resolve())
        errors = console_errors(driver)
        if errors:
            fail(f"console errors: {errors}")
    print("explorer drag menus: OK")


if __name__ == "__main__":
    main()
