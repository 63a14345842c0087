"""bookspin.read_gyro_csv (docs/python.md), the reader the class server judges a posted
recording with, against the command line's: every bad recording of the catalogue
(tests/bad_recordings/, whose .expected lines are `bookspin fit`'s) refused with the command's
very line, a lone surrogate named as bookspin.fit names one, and the real recordings read to the
samples `bookspin fit` fits."""
import json
import pathlib

import numpy as np
import pytest

from conftest import SOURCE_DIR

CATALOGUE = SOURCE_DIR / "tests" / "bad_recordings"
REAL = SOURCE_DIR.parent / "shared" / "recordings-real" / "dvarkian-2022-05-03"


def catalogue_cases():
    """The catalogue's CSV cases given alone (no .args), as (path, expected line)."""
    cases = []
    for path in sorted(CATALOGUE.glob("*.csv")):
        if path.with_suffix(".args").exists():
            continue
        expected = path.with_suffix(".expected").read_text(encoding="utf-8").strip()
        cases.append((path, expected.replace("{FILE}", path.name)))
    return cases


@pytest.mark.parametrize("path,expected", catalogue_cases(), ids=lambda v: getattr(v, "stem", ""))
def test_each_bad_recording_is_refused_with_the_commands_line(bookspin, path, expected):
    with pytest.raises(bookspin.Error) as raised:
        bookspin.read_gyro_csv(path.read_bytes().decode("utf-8"), path.name)
    assert str(raised.value) == expected


def test_the_real_recordings_read_as_the_fit_reads_them(bookspin):
    if not REAL.is_dir():
        pytest.skip(f"no real recordings at {REAL}")
    for folder in sorted(p for p in REAL.iterdir() if p.is_dir()):
        raw = folder / "Raw Data.csv"
        csv = raw if raw.is_file() else sorted(folder.glob("*.csv"))[0]
        read = bookspin.read_gyro_csv(csv.read_text(encoding="utf-8"), csv.name)
        t, omega = read["t"], read["omega"]
        assert t.shape == (omega.shape[0],) and omega.shape[1] == 3
        assert np.all(np.diff(t) > 0) and np.all(np.isfinite(omega))
        # The fit's chart of each toss holds the recording's own samples: found in these.
        fit = bookspin.fit(str(csv))
        for chart in fit.charts:
            rows = np.searchsorted(t, chart["t"])
            assert np.array_equal(t[rows], chart["t"]), folder.name


def test_a_lone_surrogate_is_named_as_bookspin_fit_names_it(bookspin):
    # pybind11's cast refused it with a TypeError naming no argument ("incompatible function
    # arguments"); bookspin.fit, the page and the npm package say this line.
    good = "t,wx,wy,wz\n" + "".join(f"{0.01 * i},1,2,3\n" for i in range(12))
    text = good + "m\ud800x"
    with pytest.raises(bookspin.Error) as raised:
        bookspin.read_gyro_csv(text)
    assert str(raised.value) == ("text: " + json.dumps(text) + " holds a lone surrogate (U+D800) at "
                                 f"character {len(good) + 2}: no UTF-8 text holds one")
    with pytest.raises(bookspin.Error) as raised:
        bookspin.read_gyro_csv(good, "m\ud800x.csv")
    assert str(raised.value) == ('file: "m\\ud800x.csv" holds a lone surrogate (U+D800) at '
                                 'character 2: no UTF-8 text holds one')
    with pytest.raises(bookspin.Error, match=r"^text: expected a str, got int$"):
        bookspin.read_gyro_csv(3)
    # Bytes are a file's bytes, read as `bookspin fit` reads them.
    assert bookspin.read_gyro_csv(good.encode())["t"].shape == (12,)
