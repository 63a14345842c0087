#!/usr/bin/env python3
"""Writes the binary fixtures of tests/bad_meshes/ (the text ones are committed as written).

Run from the repository root: python3 scripts/make-bad-meshes.py
A binary STL is an 80-byte header, a little-endian uint32 triangle count and 50 bytes per
triangle (normal, three corners as float32, a uint16 attribute).
"""
import struct
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "tests" / "bad_meshes"

# A closed tetrahedron, wound outward.
CORNERS = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def header(text: str, count: int) -> bytes:
    return text.encode().ljust(80, b" ") + struct.pack("<I", count)


def triangle(face) -> bytes:
    data = struct.pack("<3f", 0.0, 0.0, 0.0)
    for k in face:
        data += struct.pack("<3f", *CORNERS[k])
    return data + struct.pack("<H", 0)


def main() -> None:
    body = b"".join(triangle(f) for f in FACES)
    # Claims 12 triangles, holds four and a bit: cut short in the middle of a triangle.
    (OUT / "truncated.stl").write_bytes(header("binary STL cut short", 12) + body + body[:20])
    # Claims 100 million triangles (5 GB) on a 284-byte file.
    (OUT / "huge-claim.stl").write_bytes(header("binary STL claiming 5 GB", 100_000_000) + body)
    # Claims 2^31 + 2 triangles on a 184-byte file: 84 + 50 * count wraps around to 184 in
    # 32-bit arithmetic, so a reader checking the size that way would take it as well formed.
    (OUT / "overflow-claim.stl").write_bytes(
        header("binary STL whose size check wraps", 2**31 + 2) + body[: 2 * 50])


if __name__ == "__main__":
    main()
