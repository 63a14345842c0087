"""Whether text on a page is drawn with real glyphs, and what a screen reader reads of it, through
headless Chromium's DevTools protocol (the Selenium driver's session): the fonts Chromium drew
each element's text with (CSS.getPlatformFontsForNode) against what those fonts hold
(fontconfig's fc-list), and the names of the accessibility tree (Accessibility.getFullAXTree).

A character no font drawn for it holds is drawn as the first font's .notdef glyph (an empty
box): Chromium still names that font, so a name is drawn only where the fonts named for its
element hold each of its characters."""
import subprocess
import unicodedata

from browser import missing, require


def font_coverage():
    """{font name: set of code points} of every font fontconfig knows, by family and by
    PostScript name (Chromium reports either), each face's characters joined."""
    fc_list, = require("fc-list")
    listed = subprocess.run([fc_list, "--format", "%{family}|%{postscriptname}|%{charset}\n"],
                            capture_output=True, text=True, check=True).stdout
    coverage = {}
    for line in listed.splitlines():
        families, postscript, charset = (line.split("|") + ["", ""])[:3]
        points = set()
        for part in charset.split():
            first, _, last = part.partition("-")
            points.update(range(int(first, 16), int(last or first, 16) + 1))
        for name in families.split(",") + [postscript]:
            if name:
                coverage.setdefault(name, set()).update(points)
    if not coverage:
        missing("fontconfig lists no font (fc-list)")
    return coverage


def drawn_characters(text):
    """The characters of `text` that a font must hold to draw it: all but spaces and the
    invisible format characters (joiners, a flag's tags) and variation selectors, which shape
    the characters beside them."""
    return {ch for ch in text if unicodedata.category(ch) not in ("Cf", "Zs")
            and not 0xFE00 <= ord(ch) <= 0xFE0F}


def drawn_fonts(driver, selector):
    """[(text, [font objects Chromium drew it with: familyName, postScriptName, glyphCount])] of
    each element matching `selector` that holds text."""
    driver.execute_cdp_cmd("DOM.enable", {})
    driver.execute_cdp_cmd("CSS.enable", {})
    root = driver.execute_cdp_cmd("DOM.getDocument", {"depth": 0})["root"]["nodeId"]
    nodes = driver.execute_cdp_cmd("DOM.querySelectorAll",
                                   {"nodeId": root, "selector": selector})["nodeIds"]
    texts = driver.execute_script(
        "return [...document.querySelectorAll(arguments[0])].map(e => e.textContent);", selector)
    return [(text, driver.execute_cdp_cmd("CSS.getPlatformFontsForNode",
                                          {"nodeId": node})["fonts"])
            for node, text in zip(nodes, texts) if text.strip()]


def undrawn(driver, selector):
    """[(text, fonts, characters no drawn font holds)] of each element matching `selector`
    whose text is not all drawn with real glyphs (or reports no font); [] when every character
    of every element is."""
    coverage = font_coverage()
    problems = []
    for text, fonts in drawn_fonts(driver, selector):
        names = [f.get("postScriptName") or f["familyName"] for f in fonts]
        held = set()
        for font in fonts:
            for name in (font.get("postScriptName"), font["familyName"]):
                held |= {chr(c) for c in coverage.get(name, ())}
        lacking = sorted(drawn_characters(text) - held)
        if not fonts or lacking:
            problems.append((text, names, [f"U+{ord(c):04X}" for c in lacking]))
    return problems


def accessible_names(driver):
    """The names of every node of the page's accessibility tree (what a screen reader reads)."""
    driver.execute_cdp_cmd("Accessibility.enable", {})
    nodes = driver.execute_cdp_cmd("Accessibility.getFullAXTree", {})["nodes"]
    return {n["name"]["value"] for n in nodes if n.get("name") and n["name"].get("value")}
