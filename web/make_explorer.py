#!/usr/bin/env python3
"""Inlines the explorer into ONE html file that works from disk with the network off:
the page (web/src/index.html), the scene data and face images of bookspin-explorer-data
(as JSON and data: URLs), the physics (emscripten's single-file JS with the wasm inside)
and the esbuild bundle of the app.

Usage: make_explorer.py INDEX_HTML DATA_DIR WASM_JS BUNDLE_JS OUT_HTML
"""
import base64
import json
import os
import sys
from pathlib import Path


def script(text):
    # "</script" inside a script would end it early.
    return "<script>" + text.replace("</script", "<\\/script") + "</script>"


def main(index, data_dir, wasm_js, bundle_js, out):
    data_dir = Path(data_dir)
    scenes = json.loads((data_dir / "explorer-data.json").read_text())
    faces = {}
    for face in ("front", "back", "spine", "pages"):
        png = (data_dir / f"face-{face}.png").read_bytes()
        faces[face] = "data:image/png;base64," + base64.b64encode(png).decode()
    data = ("window.BOOKSPIN_SCENES=" + json.dumps(scenes, separators=(",", ":")) +
            ";window.BOOKSPIN_BOOK_ART=" + json.dumps(faces) + ";")
    html = Path(index).read_text()
    for marker, text in (("<!--BOOKSPIN_DATA-->", data),
                         ("<!--BOOKSPIN_WASM-->", Path(wasm_js).read_text()),
                         ("<!--BOOKSPIN_APP-->", Path(bundle_js).read_text())):
        if marker not in html:
            sys.exit(f"make_explorer: {index}: marker {marker} missing")
        html = html.replace(marker, script(text), 1)
    tmp = Path(out).with_suffix(".html.tmp")
    tmp.write_text(html)
    os.replace(tmp, out)
    print(f"make_explorer: {out} ({Path(out).stat().st_size} bytes)")


if __name__ == "__main__":
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    main(*sys.argv[1:])
