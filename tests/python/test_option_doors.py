"""One reader per option for every door (src/fit/fit_options.hpp): each value of the table
tests/fit/option_doors.json given to `bookspin fit` (--tosses, --drag, --moments) and to
bookspin.fit (tosses= as the same text and as numbers, drag=, moments=) is accepted by both or
refused by both, and each refusal is the door's own name for the option followed by the same
cause (tests/browser/explorer_lab_test.py gives the same table to the explorer's lab)."""
import json

import pytest

from conftest import SOURCE_DIR, cli_error_line, run_cli

TABLE = json.loads((SOURCE_DIR / "tests" / "fit" / "option_doors.json").read_text())
NAMES = TABLE["names"]
SAMPLE = SOURCE_DIR / "recordings" / "phone-on-book-synthetic" / "Raw Data.csv"
# The option given with a sample's real flights by hand, so that every case but the option's
# own is fitted the same way at each door.
ACCEPTED = [
    {"option": "tosses", "text": "0.5:1.5", "values": [[0.5, 1.5]], "cause": None},
    {"option": "tosses", "text": "", "values": [], "cause": None},
    {"option": "drag", "text": "none", "values": "none", "cause": None},
    {"option": "moments", "text": "1,2,3", "values": [1, 2, 3], "cause": None},
]


def number(v):
    return float(v) if isinstance(v, str) else v


def python_value(case):
    """The case's value as Python's numbers (a str stays a str: drag's names)."""
    values = case["values"]
    if case["option"] == "drag":
        return values
    if case["option"] == "moments":
        return [number(v) for v in values]
    return [(number(a), number(b)) for a, b in values]


def expected(case, door, values=False):
    if case["cause"] is None:
        return None
    cause = case.get("value_cause", case["cause"]) if values else case["cause"]
    return NAMES[door][case["option"]] + cause.replace("{SOURCE}", str(SAMPLE))


def cli_answer(case, tmp_path):
    """None where `bookspin fit` fits it (exit 0), else its one error line (exit 2)."""
    args = ["fit", SAMPLE, "-o", tmp_path / "cli", f"--{case['option']}", case["text"]]
    if case["cause"] is None:
        run_cli(*args)
        return None
    _, stderr = run_cli(*args, expect=2)
    return cli_error_line(stderr)


def python_answer(bookspin, case, value):
    try:
        bookspin.fit(str(SAMPLE), **{case["option"]: value})
    except bookspin.Error as e:
        return str(e)
    return None


@pytest.mark.parametrize("case", TABLE["cases"] + ACCEPTED,
                         ids=lambda c: f"{c['option']}={c['text']!r}")
def test_every_door_accepts_and_refuses_alike_naming_its_own_argument(bookspin, tmp_path, case):
    assert cli_answer(case, tmp_path) == expected(case, "command_line")
    # Python takes --tosses' text as it is, and --moments and --drag's values as numbers and a
    # str: the same answers, named as its arguments.
    if case["option"] == "tosses":
        assert python_answer(bookspin, case, case["text"]) == expected(case, "python")
    if "values" in case:
        assert python_answer(bookspin, case, python_value(case)) == expected(case, "python", True)


def test_the_table_reaches_every_cause_each_door_can_give():
    # Every refusal of the options' readers (fit_options.cpp, hand_flights) is in the table.
    for cause in ("is not a finite time (s)", "is not START:END", "is not a number",
                  "the end is not after the start", "is not none, linear or quadratic",
                  "is not a positive finite number", "is beyond the largest finite number",
                  "is below the smallest positive number",
                  "expected I1,I2,I3",
                  "no rigid body has these principal moments"):
        assert any(cause in c["cause"] + c.get("value_cause", "") for c in TABLE["cases"]), cause


def test_python_only_shapes_are_refused_naming_the_argument(bookspin):
    # What only numbers can get wrong: a range that is not a pair, moments that are not three.
    with pytest.raises(bookspin.Error, match=r"^tosses: expected shape \(2, 2\), got \(2, 3\)$"):
        bookspin.fit(str(SAMPLE), tosses=[(1, 2, 3), (4, 5, 6)])
    with pytest.raises(bookspin.Error, match=r"^moments: expected shape \(3,\), got \(2,\)$"):
        bookspin.fit(str(SAMPLE), moments=[1.0, 2.0])
