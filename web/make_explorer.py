#!/usr/bin/env python3
"""Inlines the explorer's program into the page's shell: the physics (emscripten's single-file
JS) and the esbuild bundle of the app go into web/src/index.html. The WebAssembly that
emscripten inlines as base64 is taken out and stored packed instead, as base64 of its gzip
(window.BOOKSPIN_WASM_PACKED, a script of its own), which the page inflates with the browser's
DecompressionStream and hands to the module as its wasmBinary (web/src/packed.js): 0.8 MB in
place of 2.3 MB. The physics' script has the id "bookspinPhysics": the lab's fit worker is made
of its text (web/src/fit_worker.js).
The scenes' data marker stays: `bookspin explore` fills it (src/products/explorer.hpp).

Usage: make_explorer.py INDEX_HTML WASM_JS BUNDLE_JS OUT_HTML
"""
import base64
import gzip
import os
import re
import sys
from pathlib import Path


def script(text, element_id=None):
    # "</script" inside a script would end it early.
    opening = f'<script id="{element_id}">' if element_id else "<script>"
    return opening + text.replace("</script", "<\\/script") + "</script>"


DATA_URI = re.compile(r'(["\'])data:application/octet-stream;base64,([A-Za-z0-9+/]+={0,2})\1')


def packed_physics(text, where):
    """emscripten's single-file JS `text` with its WebAssembly taken out of its data URI (left
    empty): (the script setting window.BOOKSPIN_WASM_PACKED, base64 of its gzip, the JS left)."""
    found = DATA_URI.findall(text)
    if len(found) != 1:
        sys.exit(f"make_explorer: {where}: {len(found)} inlined WebAssembly modules, not one")
    wasm = base64.b64decode(found[0][1], validate=True)
    if wasm[:4] != b"\0asm":
        sys.exit(f"make_explorer: {where}: the inlined data is not WebAssembly")
    # mtime 0: the same module packs to the same bytes (the page's manifest hashes them).
    packed = base64.b64encode(gzip.compress(wasm, compresslevel=9, mtime=0)).decode()
    text = DATA_URI.sub(lambda m: m.group(1) + "data:application/octet-stream;base64," + m.group(1),
                        text, count=1)
    return f'window.BOOKSPIN_WASM_PACKED="{packed}";', text


def main(index, wasm_js, bundle_js, out):
    html = Path(index).read_text()
    if "<!--BOOKSPIN_DATA-->" not in html:
        sys.exit(f"make_explorer: {index}: marker <!--BOOKSPIN_DATA--> missing")
    packed, physics = packed_physics(Path(wasm_js).read_text(), wasm_js)
    # The packed WebAssembly, then the physics' script by its id: the lab's fit worker is made of
    # its text (web/src/fit_worker.js); then the app.
    for marker, text in (("<!--BOOKSPIN_WASM-->", script(packed) + script(physics, "bookspinPhysics")),
                         ("<!--BOOKSPIN_APP-->", script(Path(bundle_js).read_text()))):
        if marker not in html:
            sys.exit(f"make_explorer: {index}: marker {marker} missing")
        html = html.replace(marker, text, 1)
    tmp = Path(out).with_suffix(".html.tmp")
    tmp.write_text(html)
    os.replace(tmp, out)
    print(f"make_explorer: {out} ({Path(out).stat().st_size} bytes)")


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    main(*sys.argv[1:])
