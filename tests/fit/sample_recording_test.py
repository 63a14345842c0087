#!/usr/bin/env python3
"""The sample recording `make figures` fits (recordings/phone-on-book-synthetic/,
recordings/README.md) is what its generator writes, and `bookspin fit` recovers the body the
generator built it from:

  - recordings/make_phone_on_book.py run again into a scratch folder writes the committed files
    byte for byte (the data is the script's, not edited by hand);
  - `bookspin fit` on the committed export keeps one toss per toss of the generator, flags
    the generator's stable toss (about the largest axis) stable and no other;
  - the fitted moment ratios I1/I3 and I2/I3 are within 1 % of the generator's (its RATIOS,
    from the book's sides: an independent number, not bookspin's);
  - the fitted principal axis 2 is within 1° of the generator's (phone x turned 8° about z,
    up to sign).

Usage: sample_recording_test.py BOOKSPIN_EXE SOURCE_DIR BINARY_DIR
"""
import csv
import filecmp
import importlib.util
import math
import pathlib
import shutil
import subprocess
import sys

NAME = "phone-on-book-synthetic"


def main():
    bookspin, source, binary = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    spec = importlib.util.spec_from_file_location(
        "make_phone_on_book", source / "recordings" / "make_phone_on_book.py")
    generator = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(generator)
    scratch = binary / "test-output" / "sample-recording"
    shutil.rmtree(scratch, ignore_errors=True)
    failures = []

    subprocess.run([sys.executable, spec.origin, str(scratch / NAME)], check=True,
                   capture_output=True)
    for file in ("Raw Data.csv", "meta/time.csv", "meta/device.csv"):
        if not filecmp.cmp(scratch / NAME / file, source / "recordings" / NAME / file,
                           shallow=False):
            failures.append(f"the generator does not write the committed {file}")

    run = subprocess.run([bookspin, "fit", str(source / "recordings" / NAME),
                          "-o", str(scratch / "fit")], capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout, run.stderr)
        print(f"FAIL: bookspin fit exited {run.returncode}")
        return 1
    with open(scratch / "fit" / f"{NAME}-fit-body.csv", newline="") as f:
        body = next(csv.DictReader(f))
    with open(scratch / "fit" / f"{NAME}-fit.csv", newline="") as f:
        tosses = list(csv.DictReader(f))
    true_stable = ["yes" if abs(w0[2]) > abs(w0[1]) else "no" for w0, _ in generator.TOSSES]
    fitted_stable = [t["stable"] for t in tosses]
    if fitted_stable != true_stable:
        failures.append(f"tosses kept (stable or not) {fitted_stable}, not {true_stable}")
    for key, truth in (("I1_over_I3", generator.RATIOS[0]), ("I2_over_I3", generator.RATIOS[1])):
        fitted = float(body[key])
        error = abs(fitted / truth - 1)
        print(f"{key}: fitted {fitted:.5f}, true {truth:.5f} ({100 * error:.3f} %)")
        if error > 0.01:
            failures.append(f"{key} fitted {fitted:.5f}, true {truth:.5f}: {100 * error:.2f} % off")
    fitted_axis2 = [float(body[f"axis2_{c}"]) for c in "xyz"]
    true_axis2 = [generator.AXES[r][1] for r in range(3)]
    cosine = abs(sum(a * b for a, b in zip(fitted_axis2, true_axis2)))
    angle = math.degrees(math.acos(min(1.0, cosine)))
    print(f"axis 2: {angle:.4f}° from the generator's")
    if angle > 1.0:
        failures.append(f"the fitted axis 2 is {angle:.3f}° from the generator's")
    for f in failures:
        print("FAIL:", f)
    if failures:
        return 1
    print(f"ok: {len(tosses)} tosses, the generator's ratios and axis 2 recovered")
    return 0


if __name__ == "__main__":
    sys.exit(main())
