#!/usr/bin/env python3
"""Packs the JavaScript engines' bundle (web/build.sh) for the page: one gzip stream, base64,
that the page inflates with the browser's DecompressionStream when it starts
(web/src/engines_packed.js), so that a page written with `bookspin explore --engines` stays
one file that opens from disk, at a third of the bundle's size (docs/explorer.md, "The page").

The bundle carries Rapier's and Havok's WebAssembly as base64 string literals (their packages'
own and esbuild's binary loader). Base64 compresses poorly, so each literal of at least
MIN_BLOB characters is taken out, decoded, and stored as its bytes after the code; the code
keeps a placeholder, BOOKSPIN_BLOB_<i>, which the page replaces with the bytes encoded again.

The stream holds: a 4-byte little-endian length N, N bytes of JSON {"code": bytes of code,
"blobs": [bytes of each blob]}, the code (UTF-8), then each blob. The output is one line of
JavaScript: window.BOOKSPIN_ENGINES_PACKED = "<base64 of the gzip stream>";

Usage: pack_engines.py BUNDLE.js OUT.js
"""
import base64
import gzip
import json
import re
import struct
import sys

MIN_BLOB = 100_000
PLACEHOLDER = "BOOKSPIN_BLOB_{}"


def pack(code):
    """The gzip stream's bytes for the bundle's text `code`."""
    if "BOOKSPIN_BLOB_" in code:
        sys.exit("pack_engines: the bundle already holds a placeholder (BOOKSPIN_BLOB_)")
    blobs = []

    def take(match):
        text = match.group(2)
        try:
            blobs.append(base64.b64decode(text, validate=True))
        except ValueError:
            return match.group(0)  # not base64 after all: left as it is
        if base64.b64encode(blobs[-1]).decode() != text:  # would not come back the same
            blobs.pop()
            return match.group(0)
        return match.group(1) + PLACEHOLDER.format(len(blobs) - 1) + match.group(3)

    pattern = re.compile(r'(["\'])([A-Za-z0-9+/]{%d,}={0,2})(\1)' % MIN_BLOB)
    code_bytes = pattern.sub(take, code).encode("utf-8")
    header = json.dumps({"code": len(code_bytes), "blobs": [len(b) for b in blobs]}).encode()
    stream = struct.pack("<I", len(header)) + header + code_bytes + b"".join(blobs)
    # mtime 0: the same bundle packs to the same bytes (the page's manifest hashes them).
    return gzip.compress(stream, compresslevel=9, mtime=0), len(blobs)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: pack_engines.py BUNDLE.js OUT.js")
    with open(sys.argv[1], encoding="utf-8") as f:
        code = f.read()
    packed, count = pack(code)
    with open(sys.argv[2], "w", encoding="ascii") as f:
        f.write("window.BOOKSPIN_ENGINES_PACKED=\"" + base64.b64encode(packed).decode() + "\";\n")
    print(f"pack_engines: {len(code)} bytes of engines, {count} WebAssembly blobs, packed to "
          f"{len(packed)} bytes ({4 * ((len(packed) + 2) // 3)} in base64)")


if __name__ == "__main__":
    main()
