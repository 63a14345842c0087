#!/usr/bin/env python3
"""Inlines the explorer's program into the page's shell: the physics (emscripten's single-file
JS with the WebAssembly inside) and the esbuild bundle of the app go into web/src/index.html.
The scenes' data marker stays: `bookspin explore` fills it (src/products/explorer.hpp).

Usage: make_explorer.py INDEX_HTML WASM_JS BUNDLE_JS OUT_HTML
"""
import os
import sys
from pathlib import Path


def script(text, element_id=None):
    # "</script" inside a script would end it early.
    opening = f'<script id="{element_id}">' if element_id else "<script>"
    return opening + text.replace("</script", "<\\/script") + "</script>"


def main(index, wasm_js, bundle_js, out):
    html = Path(index).read_text()
    if "<!--BOOKSPIN_DATA-->" not in html:
        sys.exit(f"make_explorer: {index}: marker <!--BOOKSPIN_DATA--> missing")
    for marker, text, element_id in (("<!--BOOKSPIN_WASM-->", Path(wasm_js).read_text(), None),
                                     ("<!--BOOKSPIN_APP-->", Path(bundle_js).read_text(), None)):
        if marker not in html:
            sys.exit(f"make_explorer: {index}: marker {marker} missing")
        html = html.replace(marker, script(text, element_id), 1)
    tmp = Path(out).with_suffix(".html.tmp")
    tmp.write_text(html)
    os.replace(tmp, out)
    print(f"make_explorer: {out} ({Path(out).stat().st_size} bytes)")


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    main(*sys.argv[1:])
