"""bookspin.fit against `bookspin fit` on the same recording: every body column and every toss
row, for the three drag laws, on the sample recording and on a recording made here from the
exact motion (given as arrays, and written as the t,wx,wy,wz CSV the command reads); the
summary lines; the chart arrays against the CSV's residual; the command line's error lines;
Ctrl-C during a long fit."""
import csv
import math
import os
import zipfile

import numpy as np
import pytest

from conftest import SOURCE_DIR, assert_same_error, interrupted_child, run_cli

SAMPLE = SOURCE_DIR / "recordings" / "phone-on-book-synthetic"


def cell_value(cell):
    """A CSV cell as the module presents it: None, a float or a str."""
    if cell == "":
        return None
    try:
        return float(cell)
    except ValueError:
        return cell


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return [{name: cell_value(row[i]) for i, name in enumerate(rows[0])} for row in rows[1:]]


def assert_rows_equal(got, expected, what):
    assert len(got) == len(expected), what
    for k, (g, e) in enumerate(zip(got, expected)):
        assert list(g) == list(e), (what, k)  # every column, in the CSV's order
        for column in e:
            a, b = g[column], e[column]
            if isinstance(b, float):
                assert isinstance(a, float), (what, k, column, a)
                assert a == pytest.approx(b, rel=1e-9, abs=0.0) or (math.isnan(a) and math.isnan(b)), \
                    (what, k, column, a, b)
            else:
                assert a == b, (what, k, column, a, b)


def cli_fit(tmp_path, recording, *options):
    out = tmp_path / "cli"
    stdout, _ = run_cli("fit", recording, "-o", out, *options)
    name = sorted(p.name for p in out.glob("*-fit-body.csv"))[0][: -len("-fit-body.csv")]
    lines = stdout.splitlines()
    summary = lines[: next(i for i, l in enumerate(lines) if l.startswith("wrote "))]
    return (read_rows(out / f"{name}-fit-body.csv"), read_rows(out / f"{name}-fit.csv"),
            summary)


def assert_fit_equals_cli(fitted, cli):
    body, tosses, summary = cli
    assert_rows_equal(fitted.bodies, body, "body")
    assert fitted.body == fitted.bodies[0]
    assert_rows_equal(fitted.tosses, tosses, "tosses")
    assert list(fitted.summary) == summary


@pytest.mark.parametrize("drag", ["none", "linear", "quadratic"])
def test_the_sample_recording_fits_as_the_command_fits_it(bookspin, tmp_path, drag):
    fitted = bookspin.fit(SAMPLE, drag=drag)
    assert fitted.recording == SAMPLE.name
    assert fitted.body["drag"] == drag
    assert_fit_equals_cli(fitted, cli_fit(tmp_path, SAMPLE, "--drag", drag))


def made_recording(bookspin, seed=3):
    """Two tosses of a phone-like body (moments 1 : 2.6 : 3.4), each near its intermediate axis,
    made with the exact motion (bookspin.exact_motion, docs/physics.md §8) and sampled at 200 Hz
    with a bias and noise, between rests of 0.6 s: t (N,) s and omega (N, 3) rad/s."""
    rng = np.random.default_rng(seed)
    rate, bias = 200.0, np.array([0.012, -0.008, 0.02])
    pieces_t, pieces_w, now = [], [], 0.0

    def rest(seconds):
        nonlocal now
        t = now + np.arange(int(seconds * rate)) / rate
        pieces_t.append(t)
        pieces_w.append(np.zeros((len(t), 3)))
        now = t[-1] + 1 / rate

    rest(0.6)
    for omega0 in ([0.4, 14.0, 0.5], [-0.6, 12.5, 0.3]):
        t = np.arange(int(1.3 * rate)) / rate
        pieces_t.append(now + t)
        pieces_w.append(bookspin.exact_motion([1.0, 2.6, 3.4], omega0, t)["omega_body"])
        now += t[-1] + 1 / rate
        rest(0.6)
    t = np.concatenate(pieces_t)
    omega = np.concatenate(pieces_w) + bias + rng.normal(0.0, 0.01, (len(t), 3))
    return t, omega


def write_recording(path, t, omega):
    with open(path, "w") as f:
        f.write("t,wx,wy,wz\n")
        for i in range(len(t)):
            f.write(",".join(repr(float(v)) for v in (t[i], *omega[i])) + "\n")


@pytest.mark.parametrize("drag", ["none", "linear", "quadratic"])
def test_arrays_fit_as_the_command_fits_their_csv(bookspin, tmp_path, drag):
    t, omega = made_recording(bookspin)
    path = tmp_path / "recording.csv"
    write_recording(path, t, omega)
    from_arrays = bookspin.fit((t, omega), drag=drag)
    assert from_arrays.recording == "recording"
    assert len(from_arrays.tosses) == 2
    assert_fit_equals_cli(from_arrays, cli_fit(tmp_path, path, "--drag", drag))
    # The body made here: I1/I3 = 1/3.4, I2/I3 = 2.6/3.4 within 1 % (an independent number).
    assert from_arrays.body["I1_over_I3"] == pytest.approx(1 / 3.4, rel=0.01)
    assert from_arrays.body["I2_over_I3"] == pytest.approx(2.6 / 3.4, rel=0.01)


def test_a_list_of_recordings_fits_as_one_body_as_the_command_fits_them(bookspin, tmp_path):
    t, omega = made_recording(bookspin)
    first, second = tmp_path / "first.csv", tmp_path / "second.csv"
    write_recording(first, t[t < 2.2], omega[t < 2.2])
    write_recording(second, t[t >= 2.2], omega[t >= 2.2])
    pooled = bookspin.fit([first, str(second)])
    assert pooled.recording == "first-and-1-more"
    assert [row["recording"] for row in pooled.tosses] == ["first", "second"]
    assert_fit_equals_cli(pooled, cli_fit(tmp_path, first, second))
    assert pooled.body["I1_over_I3"] == pytest.approx(1 / 3.4, rel=0.01)
    assert pooled.body["I2_over_I3"] == pytest.approx(2.6 / 3.4, rel=0.01)


def test_names_in_any_alphabet_as_the_command_names_them(bookspin, tmp_path):
    # docs/phone-lab.md, "Names": each file's name in its own alphabet, NFC (the German written
    # decomposed, as a Mac names it), in the module's values as in the command's files.
    names = {"太郎": "太郎", "Αθηνά": "Αθηνά", "Юлия": "Юлия",
             "Wurf u\u0308ber dem Bett": "Wurf \u00fcber dem Bett", "تجربة": "تجربة",
             "🎲 würfel": "🎲 würfel", "anna b": "anna b", "anna:b": "anna-b", "anna*b": "anna-b-2"}
    paths = []
    for seed, stem in enumerate(names):
        t, omega = made_recording(bookspin, seed=10 + seed)
        path = tmp_path / f"{stem}.csv"
        write_recording(path, t[t < 2.2], omega[t < 2.2])
        paths.append(path)
    pooled = bookspin.fit(paths)
    expected = sorted(names.values())  # the canonical order: by name, as bytes
    assert pooled.recording == f"{expected[0]}-and-{len(names) - 1}-more"
    assert sorted(row["recording"] for row in pooled.tosses) == expected
    assert_fit_equals_cli(pooled, cli_fit(tmp_path, *paths))
    assert (tmp_path / "cli" / f"{pooled.recording}-fit.csv").exists()


def test_one_recording_given_twice_however_spelled_is_refused(bookspin, tmp_path):
    # A relative and an absolute path, a symlink: one file; a copy, and an export beside its
    # own zip: the same samples. Each would predict a toss partly from its own copy.
    t, omega = made_recording(bookspin)
    first = tmp_path / "first.csv"
    write_recording(first, t, omega)
    (tmp_path / "link.csv").symlink_to(first)
    (tmp_path / "copy.csv").write_bytes(first.read_bytes())
    export = tmp_path / "export"
    export.mkdir()
    (export / "Raw Data.csv").write_bytes(first.read_bytes())
    with zipfile.ZipFile(tmp_path / "export.zip", "w") as z:
        z.write(export / "Raw Data.csv", "Raw Data.csv")
    cases = [
        ([first, "first.csv"], "first.csv: the same file as {0}/first.csv, given twice"),
        ([first, "link.csv"], "link.csv: the same file as {0}/first.csv, given twice"),
        ([first, "copy.csv"], "copy.csv: the same samples as {0}/first.csv (an export beside its "
                              "own zip, or a copy), given twice"),
        (["export", "export.zip"], "export.zip:Raw Data.csv: the same samples as export/Raw Data.csv "
                                   "(an export beside its own zip, or a copy), given twice"),
    ]
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        for recordings, line in cases:
            with pytest.raises(bookspin.Error) as raised:
                bookspin.fit(recordings)
            assert str(raised.value) == line.format(tmp_path)
        assert_same_error(bookspin, lambda: bookspin.fit([first, tmp_path / "link.csv"]),
                          "fit", first, tmp_path / "link.csv", "-o", tmp_path / "out")
    finally:
        os.chdir(here)


def test_tosses_and_moments_by_hand_as_the_command_takes_them(bookspin, tmp_path):
    t, omega = made_recording(bookspin)
    path = tmp_path / "recording.csv"
    write_recording(path, t, omega)
    tosses = [(0.65, 1.85), (2.55, 3.75)]
    fitted = bookspin.fit(path, tosses=tosses, moments=[1.0, 2.6, 3.4])
    assert fitted.body["moments"] == "given"
    assert [(row["t_start"], row["t_end"]) for row in fitted.tosses] == \
        pytest.approx([(t[t >= a][0], t[t <= b][-1]) for a, b in tosses])
    assert_fit_equals_cli(fitted, cli_fit(tmp_path, path, "--tosses", "0.65:1.85,2.55:3.75",
                                          "--moments", "1.0,2.6,3.4"))


def test_the_charts_hold_what_the_residual_was_computed_from(bookspin):
    fitted = bookspin.fit(SAMPLE)
    assert len(fitted.charts) == len(fitted.tosses)
    for chart, row in zip(fitted.charts, fitted.tosses):
        n = len(chart["t"])
        assert chart["measured"].shape == chart["fitted"].shape == (n, 3)
        assert chart["t"][0] == row["t_start"] and chart["t"][-1] == row["t_end"]
        rms = math.sqrt(np.mean(np.sum((chart["measured"] - chart["fitted"]) ** 2, axis=1)))
        assert rms == pytest.approx(row["residual_rms"], rel=1e-3)
        assert chart["curve"].shape == (len(chart["curve_t"]), 3)
        assert np.all(np.diff(chart["curve_t"]) == pytest.approx(0.001))
        # Each flip lies where the fitted omega's component about axis 2 changes sign.
        axis2 = np.array([fitted.body[f"axis2_{c}"] for c in "xyz"])
        along = chart["curve"] @ axis2
        for when in chart["flips"]:
            i = np.searchsorted(chart["curve_t"], when)
            assert np.sign(along[i - 1]) != np.sign(along[i])


def test_bad_input_raises_the_command_lines_error(bookspin, tmp_path):
    for recording in (tmp_path / "missing.csv",
                      SOURCE_DIR / "tests" / "bad_recordings" / "header-not-gyroscope.csv"):
        assert_same_error(bookspin, lambda: bookspin.fit(recording),
                          "fit", recording, "-o", tmp_path / "out")
    t = np.arange(20) * 0.01
    omega = np.zeros((20, 3))
    t[7] = t[6]
    with pytest.raises(bookspin.Error, match=r"^recording: t\[7\]: time does not increase$"):
        bookspin.fit((t, omega))
    with pytest.raises(bookspin.Error, match=r"^omega: expected shape \(20, 3\), got \(20, 2\)$"):
        bookspin.fit((t, omega[:, :2]))
    with pytest.raises(bookspin.Error, match=r"^omega: 19 rows, but t has 20: one row of each per time$"):
        bookspin.fit((t, omega[:-1]))
    with pytest.raises(bookspin.Error, match=r"^omega: expected real numbers \(float64\), got complex128"):
        bookspin.fit((np.arange(20) * 0.01, omega.astype(complex)))
    with pytest.raises(bookspin.Error, match="drag"):
        bookspin.fit(SAMPLE, drag="cubic")
    with pytest.raises(bookspin.Error, match=r"^moments: \"-2\" is not a positive finite number$"):
        bookspin.fit(SAMPLE, moments=[1.0, -2.0, 3.0])
    with pytest.raises(bookspin.Error, match="no free flight found"):
        bookspin.fit((np.arange(50) * 0.01, np.zeros((50, 3))))
    assert bookspin.fit(SAMPLE).tosses  # the interpreter goes on


def test_ctrl_c_one_second_into_a_long_fit():
    # Sixty tosses at 1000 samples/s, a fit of several seconds: KeyboardInterrupt within a
    # second of SIGINT (the solver asks at every iteration), and the interpreter goes on.
    script = """
        import time
        import numpy as np
        import bookspin
        rate, t, w, now = 1000.0, [], [], 0.0
        for k in range(60):
            flight = np.arange(1300) / rate
            rest = np.arange(600) / rate
            t += [now + rest, now + 0.6 + flight]
            w += [np.zeros((600, 3)), bookspin.exact_motion([1.0, 2.6, 3.4], [0.4, 14.0, 0.5],
                                                            flight)["omega_body"]]
            now += 1.9
        t, w = np.concatenate(t), np.concatenate(w)
        w += np.random.default_rng(1).normal(0.0, 0.01, w.shape)
        print("fitting", flush=True)
        try:
            bookspin.fit((t, w))
            print("finished", flush=True)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic(), flush=True)
            print(len(bookspin.fit((t[:4000], w[:4000])).tosses), flush=True)
    """
    lines, stderr, returncode, sent = interrupted_child(script, "fitting", 1.0)
    assert lines[0].startswith("interrupted"), (lines, stderr)
    assert float(lines[0].split()[1]) - sent < 1.0
    assert lines[1] == "2"  # the next fit runs
    assert returncode == 0, stderr
