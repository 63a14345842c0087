#!/usr/bin/env python3
"""The gallery that `make figures` writes shows every product it made.

Runs scripts/figures.sh --quick (the same commands `make figures` runs, on the same scenes and
sweeps, each made small) into BINARY_DIR/test-output/figures/ and reads the OUT/index.html it
writes:
  - no section says "not rendered yet",
  - every scene file of scenes/ and sweeps/ has its section, and every section shows media (a
    video, a frame or a chart),
  - every file the page links or shows (src=, href=, relative) exists under OUT,
  - the engines' accuracy report (an accuracy product, not a sweep) shows its four charts,
  - the conformance kit's league table (flipcheck-league.html) is linked, and in it the exact
    motion passes every scenario of scenes/flipcheck/ (docs/flipcheck.md);
  - the phone-toss lab's section shows the sample recording's fit (recordings/README.md): its
    CSV linked, every toss the fit CSV has with its chart (a PNG, its signature checked) and
    its clip shown, and, where the explorer page was made, each toss opened in it.

Usage: figures_test.py SOURCE_DIR BINARY_DIR
"""
import csv
import html.parser
import pathlib
import shutil
import subprocess
import sys


class Page(html.parser.HTMLParser):
    """The sections of the gallery: id → list of (tag, attribute, value) inside it, and every
    text inside them."""

    def __init__(self):
        super().__init__()
        self.sections = {}
        self.current = None
        self.text = []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "section":
            self.current = attrs.get("id")
            self.sections[self.current] = []
        elif self.current is not None:
            for name in ("src", "href", "poster"):
                if name in attrs:
                    self.sections[self.current].append((tag, name, attrs[name]))

    def handle_endtag(self, tag):
        if tag == "section":
            self.current = None

    def handle_data(self, data):
        self.text.append(data)


RECORDING = "phone-on-book-synthetic"


def phone_lab(page, out):
    """What is wrong with the phone-toss lab's section (a list of failures)."""
    if "phone-lab" not in page.sections:
        return ["no phone-toss lab section (id phone-lab)"]
    links = page.sections["phone-lab"]
    failures = []
    hrefs = [v for tag, attr, v in links if tag == "a" and attr == "href"]
    if f"{RECORDING}-fit.csv" not in hrefs:
        failures.append(f"the phone-toss lab does not link {RECORDING}-fit.csv: {hrefs}")
        return failures
    with open(out / f"{RECORDING}-fit.csv", newline="") as f:
        tosses = len(list(csv.DictReader(f)))
    if tosses < 4:
        failures.append(f"the sample recording's fit has {tosses} tosses, not 5")
    images = [v for tag, attr, v in links if tag == "img" and attr == "src"]
    videos = [v for tag, attr, v in links if tag == "video" and attr == "src"]
    explorer = (out / "explorer.html").is_file()
    for n in range(1, tosses + 1):
        chart = f"{RECORDING}-toss{n}.png"
        if chart not in images:
            failures.append(f"the phone-toss lab does not show {chart}: {images}")
        elif (out / chart).read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
            failures.append(f"{chart} is not a PNG")
        if f"{RECORDING}-toss{n}.mp4" not in videos:
            failures.append(f"the phone-toss lab does not show toss {n}'s clip: {videos}")
        scene = f"explorer.html?scene={RECORDING}-toss{n}"
        if explorer and scene not in hrefs:
            failures.append(f"the phone-toss lab does not link {scene}")
    if explorer:
        page_text = (out / "explorer.html").read_text(encoding="utf-8")
        if f"{RECORDING}-toss1" not in page_text:
            failures.append(f"explorer.html does not hold the scene {RECORDING}-toss1")
    return failures


def main():
    source, binary = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    out = binary / "test-output" / "figures"
    shutil.rmtree(out, ignore_errors=True)
    run = subprocess.run(["bash", str(source / "scripts" / "figures.sh"), str(binary), str(out),
                          "--quick"], capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout[-6000:], run.stderr[-6000:], sep="\n")
        print(f"FAIL: scripts/figures.sh --quick exited {run.returncode}")
        return 1
    page = Page()
    page.feed((out / "index.html").read_text(encoding="utf-8"))
    failures = []
    text = "".join(page.text)
    if "not rendered yet" in text:
        failures.append("the page says 'not rendered yet'")
    names = sorted(p.stem for p in (source / "scenes").glob("*.toml")) + \
        sorted(p.stem for p in (source / "sweeps").glob("*.toml"))
    for name in names:
        if name not in page.sections:
            failures.append(f"no section for {name}")
            continue
        media = [v for tag, attr, v in page.sections[name]
                 if tag in ("video", "img") and attr in ("src", "poster")]
        if not media:
            failures.append(f"section {name} shows no video, frame or chart")
    linked = 0
    for name, links in page.sections.items():
        for tag, attr, value in links:
            path = value.split("?")[0].split("#")[0]
            if not path or ":" in path:
                continue  # data: and other absolute addresses
            linked += 1
            if not (out / path).is_file():
                failures.append(f"section {name}: {tag} {attr}={value} names a missing file")
    report = [v for tag, attr, v in page.sections.get("engines-energy-vs-dt", [])
              if tag == "img" and attr == "src"]
    expected = [f"engines-energy-vs-dt{s}.png"
                for s in ("-accuracy", "-work-precision", "-energy-vs-dt", "-turnovers",
                          "-energy")]
    if report != expected:
        failures.append(f"the engines' accuracy report shows {report}, not {expected}")
    league = [v for tag, attr, v in page.sections.get("flipcheck-league", []) if tag == "a"]
    if "flipcheck-league.html" not in league:
        failures.append(f"the gallery does not link the league table (links: {league})")
    else:
        table = (out / "flipcheck-league.html").read_text(encoding="utf-8")
        scenarios = len(list((source / "scenes" / "flipcheck").glob("*.toml")))
        exact = [line for line in table.splitlines() if line.startswith("<tr><th>exact</th>")]
        if not exact or exact[0].count('<td class="pass">') != scenarios:
            failures.append(f"the league table's exact row does not pass all {scenarios} "
                            f"scenarios: {exact}")
    failures += phone_lab(page, out)
    for f in failures:
        print("FAIL:", f)
    if failures:
        return 1
    print(f"ok: {len(page.sections)} sections, {linked} links, every file there, no "
          "'not rendered yet'")
    return 0


if __name__ == "__main__":
    sys.exit(main())
