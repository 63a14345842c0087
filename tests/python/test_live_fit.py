"""bookspin.prepare_recording and bookspin.live_fit (docs/python.md, "The live fit"): the live
estimate of the sample recording's body against bookspin.fit's (`bookspin fit`'s) within its
σ, a live fit started from itself staying there, its rows; a recording the module cannot read
refused with the command line's own line; arguments of the wrong kind named."""
import pytest

from conftest import SOURCE_DIR, assert_same_error

SAMPLE = SOURCE_DIR / "recordings" / "phone-on-book-synthetic"
BAD = SOURCE_DIR / "tests" / "bad_recordings"


def test_the_live_estimate_is_near_the_exact_fit_and_a_fixed_point(bookspin):
    prepared = bookspin.prepare_recording(SAMPLE)
    assert prepared.name == "phone-on-book-synthetic" and prepared.flights > 1
    assert prepared.nbytes > 0
    exact = bookspin.fit(SAMPLE)
    live = bookspin.live_fit([prepared])
    body = live.body
    assert body["recordings"] == 1 and body["tosses"] == prepared.flights
    for ratio, sigma in (("I1_over_I3", "I1_sigma"), ("I2_over_I3", "I2_sigma")):
        assert abs(body[ratio] - exact.body[ratio]) <= exact.body[sigma], (ratio, body, exact.body)
        assert 0.0 < body[sigma]
    assert body["I3_over_I3"] == 1.0
    # Started from itself, it stays there: the same minimum, to the solver's tolerance.
    again = bookspin.live_fit([prepared], start=live)
    assert again.body["I1_over_I3"] == pytest.approx(body["I1_over_I3"], abs=1e-7)
    assert again.body["I2_over_I3"] == pytest.approx(body["I2_over_I3"], abs=1e-7)
    # One row per flight, numbered in the recording and the set, each the exact fit's flight.
    assert [row["flight"] for row in live.tosses] == list(range(1, prepared.flights + 1))
    assert [row["toss"] for row in live.tosses] == list(range(1, prepared.flights + 1))
    assert len(live.tosses) == len(exact.tosses)
    for row, cli in zip(live.tosses, exact.tosses):
        assert row["recording"] == "phone-on-book-synthetic"
        assert abs(row["t_start"] - cli["t_start"]) < 0.15, (row, cli)
        assert row["t_end"] > row["t_start"] and row["residual_rms"] > 0.0
        if cli["half_period_measured"] is not None and row["half_period_measured"] is not None:
            assert row["half_period_measured"] == pytest.approx(cli["half_period_measured"],
                                                                rel=0.05)


@pytest.mark.parametrize("name", ["empty.zip", "bom-then-bad-header.csv", "not-there.csv"])
def test_a_recording_it_cannot_read_is_refused_with_the_commands_line(bookspin, name):
    path = BAD / name
    assert_same_error(bookspin, lambda: bookspin.prepare_recording(path), "fit", path)


def test_arguments_of_the_wrong_kind_are_named(bookspin):
    prepared = bookspin.prepare_recording(SAMPLE)
    with pytest.raises(bookspin.Error, match=r"^recordings: expected bookspin.PreparedRecording"):
        bookspin.live_fit([prepared, 3])
    with pytest.raises(bookspin.Error, match=r"^start: expected a bookspin.LiveFit or None"):
        bookspin.live_fit([prepared], start="last")
    with pytest.raises(bookspin.Error, match=r"given twice$"):
        bookspin.live_fit([prepared, prepared])
    with pytest.raises(bookspin.Error, match=r"^live fit: give one or more"):
        bookspin.live_fit([])
    with pytest.raises(bookspin.Error, match=r"^recording: expected a path, got int"):
        bookspin.prepare_recording(7)
