#!/usr/bin/env python3
"""Writes the zip fixtures of tests/bad_recordings/ (the CSV ones are committed as written).

Run from the repository root: python3 scripts/make-bad-recordings.py
Fixed timestamps, so that the bytes are the same at every run.
"""
import struct
import zipfile
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "tests" / "bad_recordings"
STAMP = (2026, 1, 1, 0, 0, 0)
RAW = "t,wx,wy,wz\n" + "".join(f"{0.01 * i:.2f},0.1,0.2,0.3\n" for i in range(1, 25))


def write_zip(name: str, entries: list[tuple[str, str]], method=zipfile.ZIP_DEFLATED) -> Path:
    path = OUT / name
    with zipfile.ZipFile(path, "w", method) as z:
        for entry, text in entries:
            z.writestr(zipfile.ZipInfo(entry, STAMP), text, compress_type=method)
    return path


def main() -> None:
    write_zip("empty.zip", [])  # its end record alone, 22 bytes
    (OUT / "empty-file.zip").write_bytes(b"")
    write_zip("two-exports.zip", [("morning/Raw Data.csv", RAW), ("evening/Raw Data.csv", RAW)])
    # phyphox for Android's meta/device.csv whose gyroscope range is no number of rad/s.
    write_zip("device-range-not-a-number.zip",
              [("toss/Raw Data.csv", RAW),
               ("toss/meta/device.csv",
                '"property","value"\n"deviceModel","Pixel"\n"gyroscope Range","2000 dps"\n')])
    # A stored entry whose sizes (local header and central directory) claim 3.75 GiB: a zip
    # bomb's claim, refused before a byte is inflated.
    bomb = write_zip("bomb.zip", [("toss/Raw Data.csv", RAW)], zipfile.ZIP_STORED)
    data = bytearray(bomb.read_bytes())
    claim = struct.pack("<I", 0xF0000000)
    local = data.find(b"PK\x03\x04")
    data[local + 22 : local + 26] = claim  # uncompressed size
    central = data.find(b"PK\x01\x02")
    data[central + 24 : central + 28] = claim
    bomb.write_bytes(bytes(data))


if __name__ == "__main__":
    main()
