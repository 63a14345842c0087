"""bookspin.exact_motion against the command line's exact motion (flipcheck export, the exact
model through simulate) and against the physics it must obey (docs/physics.md §8)."""
import json
import math
import subprocess
import sys

import numpy as np
import pytest

from conftest import SCENARIO_DIR, numbers, read_csv, run_cli

BOOK = SCENARIO_DIR / "book-intermediate-0.05.toml"


def rotate(q, v):
    """v (N, 3) turned by the unit quaternions q (N, 4) w, x, y, z: q v q^-1, written out."""
    w, u = q[:, :1], q[:, 1:]
    return v + 2.0 * np.cross(u, np.cross(u, v) + w * v)


def exported(tmp_path, scene=BOOK, *sets):
    words = [w for s in sets for w in ("--set", s)]
    run_cli("flipcheck", "export", scene, "-o", tmp_path, *words)
    name = scene.stem
    start = json.loads((tmp_path / f"{name}.json").read_text())
    return start, read_csv(tmp_path / f"{name}-exact.csv")


def test_equals_flipcheck_exports_exact_motion(bookspin, tmp_path):
    start, csv = exported(tmp_path)
    t = numbers(csv["t"])
    got = bookspin.exact_motion(start["principal_moments"], start["omega0_body"], t)
    expected = {
        "q": np.column_stack([numbers(csv[c]) for c in ("qw", "qx", "qy", "qz")]),
        "omega_body": np.column_stack([numbers(csv[c]) for c in ("wx", "wy", "wz")]),
        "omega_world": np.column_stack(
            [numbers(csv[c]) for c in ("wx_world", "wy_world", "wz_world")]),
        "L_world": np.column_stack([numbers(csv[c]) for c in ("Lx", "Ly", "Lz")]),
        "E": numbers(csv["E"]),
    }
    for key, value in expected.items():
        assert got[key].shape == value.shape, key
        assert got[key].dtype == np.float64
        scale = np.max(np.abs(value))
        assert np.max(np.abs(got[key] - value)) <= 1e-12 * scale, key


def test_equals_the_exact_model_of_simulate(bookspin, tmp_path):
    # The exact model (model.kind = "exact") run by `bookspin simulate`, no jiggle: its q, ω and
    # L at every frame's t against exact_motion from the same start.
    sets = ["initial.jiggle=0", "time.duration=40.0", "time.steps_per_frame=7"]
    start, _ = exported(tmp_path, BOOK, *sets)
    run_cli("simulate", BOOK, "--csv", tmp_path / "exact.csv", *[w for s in sets for w in ("--set", s)])
    csv = read_csv(tmp_path / "exact.csv")
    t = numbers(csv["t"])
    got = bookspin.exact_motion(start["principal_moments"], start["omega0_body"], t)
    pairs = {
        "q": ("q_w", "q_x", "q_y", "q_z"),
        "omega_body": ("omega_x", "omega_y", "omega_z"),
        "L_world": ("L_x", "L_y", "L_z"),
    }
    for key, columns in pairs.items():
        value = np.column_stack([numbers(csv[c]) for c in columns])
        assert np.max(np.abs(got[key] - value)) <= 1e-12 * np.max(np.abs(value)), key


@pytest.mark.parametrize("omega0", [[1.0, 0.02, 0.01], [0.03, 0.4, 2.0], [0.5, 1.5, 0.01]])
def test_obeys_the_physics(bookspin, omega0):
    # Independent of bookspin's code: L and E conserved, L = R I ω, ω_world = R ω_body, q of unit
    # length starting at the identity, and Euler's equations and q's kinematics by central
    # differences.
    moments = np.array([0.3, 0.7, 1.0])
    t = np.linspace(0.0, 60.0, 6001)
    m = bookspin.exact_motion(moments, omega0, t)
    q, wb, ww, L, E = m["q"], m["omega_body"], m["omega_world"], m["L_world"], m["E"]
    assert q.shape == (len(t), 4) and wb.shape == ww.shape == L.shape == (len(t), 3)
    np.testing.assert_allclose(q[0], [1, 0, 0, 0], atol=1e-15)
    np.testing.assert_allclose(wb[0], omega0, rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-14)
    assert np.all(q[:, 0] >= 0.0)
    L0 = moments * np.asarray(omega0)
    assert np.max(np.abs(L - L0)) <= 1e-12 * np.linalg.norm(L0)
    np.testing.assert_allclose(np.linalg.norm(L, axis=1), np.linalg.norm(L0), rtol=1e-12)
    E0 = 0.5 * np.dot(omega0, moments * omega0)
    np.testing.assert_allclose(E, E0, rtol=1e-12)
    np.testing.assert_allclose(0.5 * np.sum(wb * moments * wb, axis=1), E0, rtol=1e-12)
    np.testing.assert_allclose(rotate(q, wb), ww, atol=1e-12 * np.linalg.norm(omega0))
    np.testing.assert_allclose(rotate(q, moments * wb), L, atol=1e-12 * np.linalg.norm(L0))
    h = t[1] - t[0]
    dw = (wb[2:] - wb[:-2]) / (2 * h)
    euler = np.cross(moments * wb[1:-1], wb[1:-1]) / moments
    assert np.max(np.abs(dw - euler)) < 1e-4 * np.max(np.abs(euler))
    # q and -q are one orientation (q has w >= 0): made continuous before it is differenced.
    sign = np.cumprod(np.where(np.sum(q[1:] * q[:-1], axis=1) < 0.0, -1.0, 1.0))
    q = q * np.concatenate([[1.0], sign])[:, None]
    dq = (q[2:] - q[:-2]) / (2 * h)
    w, u = q[1:-1, :1], q[1:-1, 1:]
    v = wb[1:-1]
    kinematics = 0.5 * np.column_stack([-np.sum(u * v, axis=1), w * v + np.cross(u, v)])
    assert np.max(np.abs(dq - kinematics)) < 1e-4 * np.linalg.norm(omega0)


def test_any_order_of_t_and_one_time(bookspin):
    moments, omega0 = [1.0, 2.0, 3.0], [0.1, 1.0, 0.1]
    t = np.array([5.0, 0.0, 2.5])
    m = bookspin.exact_motion(moments, omega0, t)
    one = bookspin.exact_motion(moments, omega0, [2.5])
    np.testing.assert_array_equal(m["q"][2], one["q"][0])
    assert bookspin.exact_motion(moments, omega0, []).get("q").shape == (0, 4)


@pytest.mark.parametrize("args, line", [
    (([1, 2], [0, 1, 0], [0.0]), "moments: expected shape (3,), got (2,)"),
    (([1, 2, 3], [0, 1, 0], [[0.0]]), "t: expected shape (N,), got (1, 1)"),
    (([1, -2, 3], [0, 1, 0], [0.0]), "moments[1]: -2 is not a finite positive moment of inertia"),
    (([1, 2, 3], [0, np.nan, 0], [0.0]), "omega0[1]: nan is not a finite angular velocity"),
    (([1, 2, 3], [0, 1, 0], [0.0, np.inf]), "t[1]: inf is not a finite time"),
    (([1, 2, 3], "abc", [0.0]), "omega0: expected an array of numbers (float64), got str"),
    # Round 8: what numpy casts with a loss is refused, not cast; a motion that overflows a
    # double, or an omega0 beyond a scene's range, names its input.
    (([1, 2, 3], [0, 1, 0], np.array([0.0, 1.0]) + 5j),
     "t: expected real numbers (float64), got complex128: the imaginary part would be dropped"),
    (([1, 2, 3], np.array([0, 1, 0], dtype=np.complex64), [0.0]),
     "omega0: expected real numbers (float64), got complex64: the imaginary part would be dropped"),
    (([1, 2, 3], [0, 1, 0], np.array(["0", "1"])),
     "t: expected numbers (float64), got an array of <U1 (numpy casts it to float64 only unsafely)"),
    (([1, 2, 3], [1e200, 1e200, 0], [0, 1]),
     "omega0[0]: 1e+200 is outside the angular velocity's range, ±1e+06 rad per time unit "
     "(a scene's initial.angular_velocity)"),
    # The range is on the magnitude: far below -1e6 as far above.
    (([1, 2, 3], [0, -3e7, 0], [0, 1]),
     "omega0[1]: -3e+07 is outside the angular velocity's range, ±1e+06 rad per time unit "
     "(a scene's initial.angular_velocity)"),
    (([1e300, 2e300, 3e300], [1e6, 1e6, 0], [0, 1]),
     "moments (1e+300, 2e+300, 3e+300) and omega0 (1e+06, 1e+06, 0): the motion's energy "
     "½ ω·Iω, |L| or largest |ω| overflows a double (beyond 1.8e308)"),
])
def test_bad_input_raises_bookspin_error(bookspin, args, line):
    with pytest.raises(bookspin.Error) as raised:
        bookspin.exact_motion(*args)
    assert str(raised.value) == line
    assert isinstance(raised.value, ValueError)
    assert bookspin.exact_motion([1, 2, 3], [0, 1, 0], [0.0])["q"].shape == (1, 4)


def test_an_array_too_large_to_copy_says_its_size(bookspin):
    # 10^11 times broadcast from one value: float64 already, but its C-order copy needs 745 GiB.
    t = np.broadcast_to(np.float64(1.0), (10**11,))
    with pytest.raises(bookspin.Error) as raised:
        bookspin.exact_motion([1, 2, 3], [0, 1, 0], t)
    assert str(raised.value) == ("t: cannot copy the array into memory (100000000000 values, "
                                 "745 GiB as float64): too large for this machine")


def test_a_time_past_the_horizon_is_refused_for_its_phase_not_a_crash(bookspin):
    # It killed the process with SIGSEGV (the table of base points indexed by the phase at
    # t = 1e300), and with other moments was refused as an energy overflow: run in a child so
    # that a crash is a failure here, not the end of the session.
    code = ("import bookspin\n"
            "for moments in ([1, 2, 3], [2, 1, 3]):\n"
            "    try:\n"
            "        bookspin.exact_motion(moments, [0.1, 1, 0.05], [0.0, 1e300])\n"
            "    except bookspin.Error as e:\n"
            "        print(e)\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, (done.returncode, done.stderr)
    lines = done.stdout.splitlines()
    assert len(lines) == 2, done.stdout
    for line in lines:
        assert line.startswith("t[1]: t = 1e+300 is beyond the exact motion's time horizon, "
                               "|t| ≤ "), line
        assert "energy" not in line


def test_any_moments_omega_and_times_give_finite_rows_or_the_true_refusal(bookspin):
    # The door's property over the whole input space, seeded (docs/physics.md §8, "How far in
    # time"; the C++ core's is tests/physics/exact_horizon_test.cpp and tests/fuzz/exact_fuzzer):
    # moments across 1e-300…1e300, near-symmetric bodies, ω0 of either sign down to 1e-300, t
    # across ±1e-300…1e300. Judged apart from the code: |L| and E from the inputs, and every
    # angle's rate between |L|/I_max and |L|/I_min, so a t refused for the horizon has
    # |t| |L|/I_min past 2^40 and a t given has |t| |L|/I_max within it.
    rng = np.random.default_rng(82)
    max_angle = 2.0 ** 40
    refused = given = 0
    for _ in range(400):
        kind = rng.integers(3)
        if kind == 0:
            moments = 10.0 ** rng.uniform(-300, 300, 3)
        elif kind == 1:
            moments = 10.0 ** rng.uniform(-300, 300) * rng.uniform(1, 4, 3)
        else:
            base = 10.0 ** rng.uniform(-300, 300)
            moments = np.array([base, base * (1 + 10.0 ** rng.uniform(-16, -3)),
                                base * rng.uniform(0.5, 4)])
        omega0 = 10.0 ** rng.uniform(-300, 6) * rng.uniform(-1, 1, 3)
        t = np.sign(rng.uniform(-1, 1, 3)) * 10.0 ** rng.uniform(-300, 300, 3)
        I = [float(m) for m in moments]
        # In logarithms: |L| and E may lie beyond a double where the motion's rows do not.
        log_L = log_sum([2 * (math.log(i) + log_abs(w)) for i, w in zip(I, omega0)]) / 2
        log_E = log_sum([math.log(0.5 * i) + 2 * log_abs(w) for i, w in zip(I, omega0)])
        try:
            got = bookspin.exact_motion(moments, omega0, t)
        except bookspin.Error as e:
            refused += 1
            text = str(e)
            if "overflows a double" in text:
                assert max(log_E, log_L) > math.log(1.7e308), (text, I, omega0)
                continue
            assert text.startswith("t["), text
            assert "beyond the exact motion's time horizon" in text and "energy" not in text
            index = int(text[2:text.index("]")])
            assert (log_abs(t[index]) + log_L - math.log(min(I))
                    >= math.log(max_angle) - 1e-9), (text, I, omega0)
            continue
        given += 1
        for key in ("q", "omega_body", "omega_world", "L_world", "E"):
            assert np.isfinite(got[key]).all(), (key, I, omega0, t)
        for time in t:
            assert log_abs(time) + log_L - math.log(max(I)) <= math.log(max_angle) + 1e-9
    assert refused > 50 and given > 50, (refused, given)



def log_abs(x):
    """ln |x|, -inf for 0."""
    return math.log(abs(x)) if x != 0 else -math.inf


def log_sum(logs):
    """ln Σ e^l, scaled by the largest."""
    top = max(logs)
    if top == -math.inf:
        return top
    return top + math.log(sum(math.exp(l - top) for l in logs))
