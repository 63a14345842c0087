"""bookspin.flipcheck against `bookspin flipcheck export` and `judge` on the same input: the
scenarios, their start and exact motion, and the judgement of the exact motion, of perturbed
motions, of two integrators written here in numpy (explicit Euler fails, RK4 passes), and of
the JavaScript engines' motions as `make figures` writes them (web/flipcheck-engines.mjs)."""
import hashlib
import json
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest

from conftest import (SCENARIO_DIR, SOURCE_DIR, cli_error_line, interrupted_child, numbers, read_csv,
                      run_cli, write_motion_csv)

SCENARIOS = sorted(p.stem for p in SCENARIO_DIR.glob("*.toml"))
NUMERIC = ("start_error", "energy_drift", "L_drift", "first_flip", "first_flip_exact",
           "first_flip_error", "orientation_error", "L_direction_error", "tumble_time",
           "separatrix_ratio_drift",
           "separatrix_approach")
WHOLE = ("stride", "last_step", "flips", "flips_exact", "stable_spin", "orientation_error_step",
         "L_direction_error_step")


def test_scenarios_are_the_folders_files(bookspin, tmp_path):
    assert bookspin.flipcheck.scenarios() == SCENARIOS
    # the copy the module carries beside itself, not the source tree's folder
    carried = pathlib.Path(bookspin.flipcheck.scenario_dir)
    assert carried == pathlib.Path(bookspin.__file__).parent / "bookspin-scenarios"
    assert {p.name: p.read_bytes() for p in carried.iterdir()} == \
           {p.name: p.read_bytes() for p in SCENARIO_DIR.glob("*.toml")}
    (tmp_path / "b.toml").write_text("")
    (tmp_path / "a.toml").write_text("")
    (tmp_path / "notes.txt").write_text("")
    assert bookspin.flipcheck.scenarios(tmp_path) == ["a", "b"]


@pytest.mark.parametrize("name", SCENARIOS)
def test_export_equals_the_command_line(bookspin, tmp_path, name):
    run_cli("flipcheck", "export", SCENARIO_DIR / f"{name}.toml", "-o", tmp_path)
    start, arrays = bookspin.flipcheck.export(name)
    assert start == json.loads((tmp_path / f"{name}.json").read_text())
    csv = read_csv(tmp_path / f"{name}-exact.csv")
    columns = {"t": ["t"], "q": ["qw", "qx", "qy", "qz"], "omega_body": ["wx", "wy", "wz"],
               "omega_world": ["wx_world", "wy_world", "wz_world"],
               "L_world": ["Lx", "Ly", "Lz"], "E": ["E"]}
    assert sorted(arrays) == sorted(columns)
    for key, names in columns.items():
        expected = np.column_stack([numbers(csv[c]) for c in names])
        if len(names) == 1:
            expected = expected[:, 0]
        np.testing.assert_array_equal(arrays[key], expected, err_msg=key)


# --- integrators written here, in numpy, outside the project: Euler's equations I ω̇ = (I ω) × ω
# in the body frame (docs/physics.md §8) and q̇ = ½ q ⊗ (0, ω_body) (§4) ---

def quaternion_rate(q, w):
    return 0.5 * np.array([-q[1:] @ w, *(q[0] * w + np.cross(q[1:], w))])


def rates(state, moments):
    q, w = state[:4], state[4:]
    return np.concatenate([quaternion_rate(q, w), np.cross(moments * w, w) / moments])


def euler_step(state, moments, dt):
    return state + dt * rates(state, moments)


def rk4_step(state, moments, dt):
    k1 = rates(state, moments)
    k2 = rates(state + 0.5 * dt * k1, moments)
    k3 = rates(state + 0.5 * dt * k2, moments)
    k4 = rates(state + dt * k3, moments)
    out = state + dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
    out[:4] /= np.linalg.norm(out[:4])
    return out


def to_world(q, w):
    u = q[:, 1:]
    return w + 2.0 * np.cross(u, np.cross(u, w) + q[:, :1] * w)


def integrate(start, step, stride=1):
    moments = np.array(start["principal_moments"])
    dt, steps = start["dt"], start["steps"]
    state = np.concatenate([[1.0, 0.0, 0.0, 0.0], start["omega0_body"]])
    rows = [state]
    for n in range(1, steps + 1):
        state = step(state, moments, dt)
        if n % stride == 0:
            rows.append(state)
    rows = np.array(rows)
    t = np.arange(len(rows)) * stride * dt
    return t, rows[:, :4], to_world(rows[:, :4] / np.linalg.norm(rows[:, :4], axis=1)[:, None],
                                    rows[:, 4:])


def cli_judgement(tmp_path, scenario, t, q, omega_world, file="motion.csv"):
    write_motion_csv(tmp_path / file, t, q, omega_world)
    out, _ = run_cli("flipcheck", "judge", SCENARIO_DIR / f"{scenario}.toml", tmp_path / file,
                     "-o", tmp_path / "out", "--force", expect=(0, 3))
    row = {k: v[0] for k, v in read_csv(tmp_path / "out" / f"{scenario}-judge.csv").items()}
    assert (": FAIL (" in out) == (row["verdict"] == "fail")
    return row


def assert_same_judgement(got, cli):
    assert list(got) == list(cli)  # every column, in the CSV's order
    for column, cell in cli.items():
        if column == "motion":
            continue  # the file's name there, the motion argument here
        value = got[column]
        if column in NUMERIC:
            if cell == "":
                assert value is None, column
            else:
                assert value == pytest.approx(float(cell), rel=1e-9, abs=0.0), column
        elif column in WHOLE:
            assert value == int(cell), column
        else:
            assert value == cell, column


def motions_of(name, arrays, start):
    """The exact motion every stride steps, and two perturbed copies of it."""
    # A stride that divides the steps, so that the motion reaches the last one (complete).
    stride = next(k for k in range(max(1, start["steps"] // 3000), 0, -1) if start["steps"] % k == 0)
    t, q, w = arrays["t"][::stride], arrays["q"][::stride], arrays["omega_world"][::stride]
    ramp = t / t[-1]
    noisy_q = q + 1e-3 * np.sin(7.0 * t)[:, None] * np.array([0.0, 1.0, -0.5, 0.25])
    scaled_w = w * (1.0 + 0.02 * ramp)[:, None]  # spins up by 2 %: energy and L drift
    return [("exact", t, q, w), ("noisy-q", t, -noisy_q, w), ("spun-up", t, q, scaled_w)]


@pytest.mark.parametrize("name", SCENARIOS)
def test_judge_equals_the_command_line_in_every_scenario(bookspin, tmp_path, name):
    start, arrays = bookspin.flipcheck.export(name)
    for label, t, q, w in motions_of(name, arrays, start):
        cli = cli_judgement(tmp_path, name, t, q, w)
        got = bookspin.flipcheck.judge(name, t, q, w, motion=label)
        assert got["motion"] == label
        assert_same_judgement(got, cli)
    assert bookspin.flipcheck.judge(name, *motions_of(name, arrays, start)[0][1:])["verdict"] == "pass"


def test_a_judgement_records_the_version_and_the_scenarios_sha256(bookspin, tmp_path):
    """docs/flipcheck.md, "Versions": VERSION's version, and the SHA-256 of the scenario's JSON
    as `bookspin flipcheck export` writes it, whichever way the scenario is named."""
    version = next(line.split()[1] for line in (SOURCE_DIR / "VERSION").read_text().splitlines()
                   if line.startswith("version "))
    assert bookspin.__version__ == version
    name = "mujoco-test-box"
    run_cli("flipcheck", "export", SCENARIO_DIR / f"{name}.toml", "-o", tmp_path)
    sha = hashlib.sha256((tmp_path / f"{name}.json").read_bytes()).hexdigest()
    start, arrays = bookspin.flipcheck.export(name)
    _, t, q, w = motions_of(name, arrays, start)[0]
    for scenario in (name, SCENARIO_DIR / f"{name}.toml"):
        got = bookspin.flipcheck.judge(scenario, t, q, w)
        assert (got["version"], got["scenario_sha256"]) == (version, sha)
        assert list(got)[-2:] == ["version", "scenario_sha256"]


def test_numpy_euler_fails_and_rk4_passes(bookspin, tmp_path):
    name = "book-intermediate-0.05"
    start, _ = bookspin.flipcheck.export(name)
    verdicts = {}
    for label, step in (("euler", euler_step), ("rk4", rk4_step)):
        t, q, w = integrate(start, step)
        got = bookspin.flipcheck.judge(name, t, q, w, motion=label)
        assert_same_judgement(got, cli_judgement(tmp_path, name, t, q, w, f"{label}.csv"))
        verdicts[label] = got
    assert verdicts["euler"]["verdict"] == "fail"
    assert "energy" in verdicts["euler"]["failures"]
    assert verdicts["rk4"]["verdict"] == "pass", verdicts["rk4"]["failures"]
    assert verdicts["rk4"]["flips"] == verdicts["rk4"]["flips_exact"] > 0


def test_assert_passes_raises_the_command_lines_line(bookspin, tmp_path):
    name = "book-intermediate-0.05"
    start, arrays = bookspin.flipcheck.export(name)
    t, q, w = arrays["t"], arrays["q"], arrays["omega_world"]
    assert bookspin.flipcheck.assert_passes(name, t, q, w) == bookspin.flipcheck.judge(name, t, q, w)
    t, q, w = integrate(start, euler_step)
    write_motion_csv(tmp_path / "euler.csv", t, q, w)
    out, _ = run_cli("flipcheck", "judge", SCENARIO_DIR / f"{name}.toml", tmp_path / "euler.csv",
                     "-o", tmp_path / "out", expect=3)
    line = next(l for l in out.splitlines() if "FAIL" in l)
    with pytest.raises(AssertionError) as raised:
        bookspin.flipcheck.assert_passes(name, t, q, w, motion="euler")
    assert str(raised.value) == line.replace(str(tmp_path / "euler.csv"), "euler")
    assert str(raised.value).startswith(f"{name} euler: FAIL (energy drift 0.48")
    with pytest.raises(bookspin.Error, match="omega_world"):
        bookspin.flipcheck.assert_passes(name, t, q, w[:, :2])


def test_a_scenario_by_path_and_from_another_folder(bookspin, tmp_path):
    path = SCENARIO_DIR / "symmetric-top.toml"
    (tmp_path / "top.toml").write_text(path.read_text())
    a, _ = bookspin.flipcheck.export(path)
    b, _ = bookspin.flipcheck.export("top", directory=tmp_path)
    assert {k: v for k, v in a.items() if k not in ("scenario", "exact_motion")} == \
           {k: v for k, v in b.items() if k not in ("scenario", "exact_motion")}


def test_bad_motions_raise_the_rows_line(bookspin, tmp_path):
    name = "book-intermediate-0.05"
    start, arrays = bookspin.flipcheck.export(name)
    t, q, w = arrays["t"][:50].copy(), arrays["q"][:50].copy(), arrays["omega_world"][:50].copy()
    bad_t = t.copy()
    bad_t[3] += 0.3 * start["dt"]
    t3 = repr(float(bad_t[3]))
    cases = [
        ((bad_t, q, w), f"flipcheck.judge: t[3]: t = {t3} is not a whole number of steps of dt = 0.05"),
        ((t[1:], q[1:], w[1:]), "flipcheck.judge: t[0]: the first row must be t = 0"),
        ((t, q[:-1], w), "q: 49 rows, but t and omega_world have 50: one row of each per time"),
        ((t[:10], q, w), "t: 10 rows, but q and omega_world have 50: one row of each per time"),
        ((t, q + 0j, w), "q: expected real numbers (float64), got complex128: the imaginary part "
                         "would be dropped"),
        ((t, q, w[:, :2]), "omega_world: expected shape (50, 3), got (50, 2)"),
        ((t, np.zeros_like(q), w), "flipcheck.judge: q[0]: q is zero (qw = qx = qy = qz = 0): no orientation"),
        ((t[:0], q[:0], w[:0]), "flipcheck.judge: no rows (t is empty)"),
    ]
    for args, line in cases:
        with pytest.raises(bookspin.Error) as raised:
            bookspin.flipcheck.judge(name, *args)
        assert str(raised.value) == line
    nan_w = w.copy()
    nan_w[5, 1] = math.nan
    with pytest.raises(bookspin.Error, match=r"omega_world\[5\]: nan is not a finite number"):
        bookspin.flipcheck.judge(name, t, q, nan_w)
    with pytest.raises(bookspin.Error, match='no scenario "nosuch" in'):
        bookspin.flipcheck.judge("nosuch", t, q, w)
    # The command line refuses the same misplaced row, on its line of the file.
    write_motion_csv(tmp_path / "bad.csv", bad_t, q, w)
    _, stderr = run_cli("flipcheck", "judge", SCENARIO_DIR / f"{name}.toml", tmp_path / "bad.csv",
                        "-o", tmp_path, expect=2)
    assert cli_error_line(stderr).endswith(f": t: t = {t3} is not a whole number of steps of dt = 0.05")


def test_judge_equals_the_command_line_on_the_engines_motions(bookspin, tmp_path):
    """Every scenario's motion from two of the JavaScript engines (the two `make figures
    --quick` runs), each CSV judged by the command line as it is and by the module from its
    columns."""
    runner = SOURCE_DIR / "web" / "flipcheck-engines.mjs"
    ready = shutil.which("node") and os.environ.get("FLIPCHECK_PACKAGE") and subprocess.run(
        ["node", runner, "--check"], cwd=SOURCE_DIR, capture_output=True).returncode == 0
    if not ready:
        assert os.environ.get("CI") != "true", \
            "node, the engines' npm packages or FLIPCHECK_PACKAGE (the runner's reader) are missing"
        pytest.skip("node, the engines' npm packages (scripts/install-deps.sh) or FLIPCHECK_PACKAGE "
                    "(make npm: BUILD/npm/package, the runner's scenario reader) are missing")
    run_cli("flipcheck", "export", *sorted(SCENARIO_DIR.glob("*.toml")), "-o", tmp_path / "ex")
    subprocess.run(["node", runner, "--only", "cannon-es,babylonjs-havok", tmp_path / "motions",
                    *sorted((tmp_path / "ex").glob("*.json"))], cwd=SOURCE_DIR, check=True,
                   capture_output=True)
    motions = sorted((tmp_path / "motions").glob("*.csv"))
    assert len(motions) == 2 * len(SCENARIOS)
    for motion in motions:
        name = next(n for n in SCENARIOS if motion.name.startswith(n + "-"))
        run_cli("flipcheck", "judge", SCENARIO_DIR / f"{name}.toml", motion, "-o",
                tmp_path / "out", "--force", expect=(0, 3))
        cli = {k: v[0] for k, v in read_csv(tmp_path / "out" / f"{name}-judge.csv").items()}
        columns = read_csv(motion)
        t = numbers(columns["t"])
        q = np.stack([numbers(columns[c]) for c in ("qw", "qx", "qy", "qz")], axis=1)
        w = np.stack([numbers(columns[c]) for c in ("wx_world", "wy_world", "wz_world")], axis=1)
        assert_same_judgement(bookspin.flipcheck.judge(name, t, q, w), cli)


def test_the_whole_motion_is_judged_and_coarse_rows_are_refused(bookspin):
    """The exact motion turned 90° about world z between its ends fails on its orientation and
    L's direction, each failure with its limit; written every 1000th step it is refused as too
    coarse (never "0 turn-overs"), and every 50th step passes."""
    name = "book-intermediate-0.05"
    _, arrays = bookspin.flipcheck.export(name)
    t, q, w = arrays["t"], arrays["q"].copy(), arrays["omega_world"].copy()
    c, s = math.cos(math.pi / 4), math.sin(math.pi / 4)  # q_turn = (c, 0, 0, s): 90° about z
    inner = slice(1, len(t) - 1)
    qw, qx, qy, qz = q[inner].T.copy()
    q[inner] = np.stack([c * qw - s * qz, c * qx - s * qy, c * qy + s * qx, c * qz + s * qw], axis=1)
    wx, wy = w[inner, 0].copy(), w[inner, 1].copy()
    w[inner, 0], w[inner, 1] = -wy, wx
    judged = bookspin.flipcheck.judge(name, t, q, w)
    assert judged["verdict"] == "fail"
    assert judged["orientation_error"] == pytest.approx(math.pi / 2, abs=1e-9)
    assert judged["L_direction_error"] == pytest.approx(math.pi / 2, abs=1e-6)
    with pytest.raises(AssertionError) as raised:
        bookspin.flipcheck.assert_passes(name, t, q, w)
    assert re.search(r"orientation error 1.57 rad at step \d+ \(limit 0.1; past it from step 1\)",
                     str(raised.value))
    assert "(limit 0.01; past it from step 1)" in str(raised.value)
    t, q, w = arrays["t"], arrays["q"], arrays["omega_world"]
    with pytest.raises(bookspin.Error, match="rows every 1000 steps .* too far apart"):
        bookspin.flipcheck.judge(name, t[::1000], q[::1000], w[::1000])
    assert bookspin.flipcheck.judge(name, t[::50], q[::50], w[::50])["verdict"] == "pass"


def test_bad_arguments_raise_bookspin_error_naming_them(bookspin, tmp_path):
    name = "mujoco-test-box"
    _, arrays = bookspin.flipcheck.export(name)
    t, q, w = arrays["t"], arrays["q"], arrays["omega_world"]
    with pytest.raises(bookspin.Error, match="motion: expected a name \\(str\\), got int"):
        bookspin.flipcheck.judge(name, t, q, w, motion=3)
    with pytest.raises(bookspin.Error, match="motion: a name holds a NUL byte"):
        bookspin.flipcheck.judge(name, t, q, w, motion="a\0b")
    with pytest.raises(bookspin.Error, match=r"q: expected shape \(501, 4\), N = len\(t\) rows, "
                                              r"got \(4, 501\).*give q.T"):
        bookspin.flipcheck.judge(name, t, q.T, w)
    with pytest.raises(bookspin.Error, match=r"omega_world: expected shape \(501, 3\)"):
        bookspin.flipcheck.judge(name, t, q, w.T)
    # a scene at its limits: 99999 frames of 100000 steps (it gave "exact -2147483647")
    huge = tmp_path / "huge.toml"
    huge.write_text((SCENARIO_DIR / f"{name}.toml").read_text().replace("frames = 51", "frames = 100000")
                    .replace("steps_per_frame = 10", "steps_per_frame = 100000"))
    with pytest.raises(bookspin.Error, match=r"steps: 9999900000: must be from 1 to 10\^7"):
        bookspin.flipcheck.judge(huge, t, q, w)
    with pytest.raises(bookspin.Error, match="scenario: holds a NUL byte at character 8"):
        bookspin.flipcheck.judge("mujoco-\0test-box", t, q, w)


def test_ctrl_c_stops_a_long_judgement(tmp_path):
    """SIGINT 0.3 s into the judgement of 10^6 rows (2 s on the 2-core machine) raises
    KeyboardInterrupt from the judge within the next poll (it came when the judgement was done):
    sooner than half the same judgement takes uninterrupted, timed first in the same process (a
    ratio, not a wall-clock bound: a loaded machine slows both)."""
    scene = tmp_path / "long.toml"
    scene.write_text((SCENARIO_DIR / "mujoco-test-box.toml").read_text()
                     .replace("frames = 51", "frames = 2").replace("steps_per_frame = 10",
                                                                    "steps_per_frame = 1000000"))
    script = f"""
        import time, numpy as np, bookspin
        n = 1000001
        t, q, w = np.arange(n) * 0.01, np.tile([1.0, 0, 0, 0], (n, 1)), np.tile([1.0, 2, 3], (n, 1))
        start = time.monotonic()
        bookspin.flipcheck.judge({str(scene)!r}, t, q, w)
        whole = time.monotonic() - start
        print("judging", flush=True)
        try:
            bookspin.flipcheck.judge({str(scene)!r}, t, q, w)
            print("finished", time.monotonic(), flush=True)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic(), whole, flush=True)
    """
    lines, stderr, returncode, sent = interrupted_child(script, "judging", 0.3)
    assert lines and lines[0].startswith("interrupted"), (lines, stderr)
    _, when, whole = lines[0].split()
    assert float(when) - sent < 0.5 * float(whole), lines
    assert returncode == 0, stderr


def random_scene(rng, k, folder):
    """A random scenario as a scene file: the book's size in [0.5, 3] per axis, ω0 of 0.5 to 3
    rad per time unit in a random direction (every third one near the intermediate axis), dt in
    [0.005, 0.05], 40 to 100 time units."""
    size = rng.uniform(0.5, 3.0, 3)
    direction = rng.uniform(-0.5, 0.5, 3)
    if k % 3 == 0:  # near the intermediate axis: I_i ~ the sum of the other two sizes squared
        moments = [size[1] ** 2 + size[2] ** 2, size[0] ** 2 + size[2] ** 2, size[0] ** 2 + size[1] ** 2]
        direction = 0.05 * direction + np.eye(3)[int(np.argsort(moments)[1])]
    dt = float(rng.uniform(0.005, 0.05))
    frames = int(rng.uniform(40, 100) / dt)
    path = folder / f"random-{k}.toml"
    omega = rng.uniform(0.5, 3.0) * direction / np.linalg.norm(direction)
    path.write_text(f'[model]\nkind = "exact"\n[book]\nsize = [{size[0]}, {size[1]}, {size[2]}]\n'
                    f'mass = 1.0\n[initial]\nangular_velocity = [{omega[0]}, {omega[1]}, {omega[2]}]\n'
                    f'[time]\ndt = {dt}\nsteps_per_frame = 1\nframes = {frames + 1}\n')
    return path


def test_a_seeded_property_of_the_judge_at_the_python_door(bookspin, tmp_path):
    """The exact motion, q negated on random rows and every thinning the rules allow pass (or
    the thinning is refused as too coarse); rows turned, a time shift, ω scaled, q in x, y, z, w
    order and a dropped row never pass (docs/flipcheck.md, "Thresholds")."""
    rng = np.random.default_rng(8181)
    flipping = 0
    for k in range(6):
        scene = random_scene(rng, k, tmp_path)
        start, a = bookspin.flipcheck.export(scene)
        t, q, w = a["t"], a["q"], a["omega_world"]
        exact = bookspin.flipcheck.judge(scene, t, q, w)
        assert exact["verdict"] == "pass", scene.read_text()
        flipping += exact["flips_exact"] > 0
        negated = q * np.where(rng.random(len(t)) < 0.5, -1.0, 1.0)[:, None]
        assert bookspin.flipcheck.judge(scene, t, negated, w)["verdict"] == "pass"
        steps = start["steps"]
        for stride in [d for d in (2, 3, 5, 10, 50, 200, 1000) if steps % d == 0]:
            try:
                judged = bookspin.flipcheck.judge(scene, t[::stride], q[::stride], w[::stride])
                assert judged["verdict"] == "pass", (stride, judged["failures"])
            except bookspin.Error as e:
                assert "too far apart to judge the turn-overs" in str(e), str(e)
        moments, omega0 = np.array(start["principal_moments"]), np.array(start["omega0_body"])
        shift = rng.uniform(0.3, 1.0) / np.linalg.norm(omega0)
        shifted = bookspin.exact_motion(moments, omega0, t + shift)
        turned = q.copy()
        first = 1 + int(rng.integers(len(t) - 30))
        rows = slice(first, first + 20)  # a run of rows in the middle: not the last
        angle = rng.uniform(0.2, 3.0)
        turned[rows] = np.stack([np.cos(angle / 2) * q[rows, 0] - np.sin(angle / 2) * q[rows, 3],
                                 np.cos(angle / 2) * q[rows, 1] - np.sin(angle / 2) * q[rows, 2],
                                 np.cos(angle / 2) * q[rows, 2] + np.sin(angle / 2) * q[rows, 1],
                                 np.cos(angle / 2) * q[rows, 3] + np.sin(angle / 2) * q[rows, 0]], axis=1)
        drop = 1 + int(rng.integers(len(t) - 3))
        for what, motion in [
                ("rows turned about z", (t, turned, w)),
                ("shifted", (t, shifted["q"], shifted["omega_world"])),
                ("omega scaled", (t, q, w * rng.choice([0.9, 1.1]))),
                ("q as x, y, z, w", (t, q[:, [1, 2, 3, 0]], w)),
                ("a row dropped", tuple(np.delete(x, drop, axis=0) for x in (t, q, w)))]:
            try:
                assert bookspin.flipcheck.judge(scene, *motion)["verdict"] == "fail", what
            except bookspin.Error:
                pass  # refused with its reason: never a pass
    assert flipping >= 2  # not an empty claim: some of the scenarios turn over


def turned_from(csv_text, step):
    """The exact motion's CSV with every row from `step` on turned (qx negated): a broken engine
    whose motion leaves the exact one there."""
    lines = csv_text.splitlines()
    header = lines[0].split(",")
    qx = header.index("qx")
    for i in range(1 + step, len(lines)):
        cells = lines[i].split(",")
        cells[qx] = cells[qx][1:] if cells[qx].startswith("-") else "-" + cells[qx]
        lines[i] = ",".join(cells)
    return "\n".join(lines) + "\n"


def test_the_ci_example_passes_the_exact_motion_and_fails_a_broken_one(bookspin, tmp_path):
    """docs/flipcheck.md, "In a CI job": examples/flipcheck-ci/test_motion.py run by pytest as
    an engine's CI runs it, on the exported exact motion (passes) and on it turned from step 100
    on (fails, pytest's exit status 1, the judge's FAIL line in its report)."""
    name = "book-intermediate-0.05"
    run_cli("flipcheck", "export", SCENARIO_DIR / f"{name}.toml", "-o", tmp_path / "kit")
    exact = tmp_path / "kit" / f"{name}-exact.csv"
    broken = tmp_path / "broken.csv"
    broken.write_text(turned_from(exact.read_text(), 100))
    project = tmp_path / "project"
    shutil.copytree(SOURCE_DIR / "examples" / "flipcheck-ci", project)
    for motion, status in ((exact, 0), (broken, 1)):
        done = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                               "test_motion.py"], cwd=project, capture_output=True, text=True,
                              env={**os.environ, "MOTION": str(motion), "PYTHONPATH":
                                   str(pathlib.Path(bookspin.__file__).resolve().parent)},
                              timeout=300)
        assert done.returncode == status, done.stdout + done.stderr
        if status:
            assert f"AssertionError: {name} broken.csv: FAIL (" in done.stdout, done.stdout


def test_judge_reads_the_scenario_json_export_wrote(bookspin, tmp_path):
    """A scenario JSON as `export` wrote it is a scenario judge takes, as the command line and
    npm do: the same judgement as by name; JSON null in it is said so."""
    name = "mujoco-test-box"
    run_cli("flipcheck", "export", SCENARIO_DIR / f"{name}.toml", "-o", tmp_path)
    _, arrays = bookspin.flipcheck.export(name)
    t, q, w = arrays["t"], arrays["q"], arrays["omega_world"]
    by_json = bookspin.flipcheck.judge(str(tmp_path / f"{name}.json"), t, q, w)
    assert by_json == bookspin.flipcheck.judge(name, t, q, w)
    assert by_json["verdict"] == "pass"
    (tmp_path / "null.json").write_text("null\n")
    with pytest.raises(bookspin.Error, match=r"null.json: holds JSON null, not a scenario"):
        bookspin.flipcheck.judge(str(tmp_path / "null.json"), t, q, w)


def test_a_scenario_json_saved_as_utf16_or_nested_too_deep_is_said_so_as_the_command_line_says(
        bookspin, tmp_path):
    """A scenario JSON saved as UTF-16 is "saved as UTF-16" (as a scene or a recording is, not
    "a control character at line 1, column 2"), and one nested past 64 levels "nested more than
    64 deep" at its line and column (valid JSON, not "not valid JSON"): the command line's line,
    word for word."""
    name = "mujoco-test-box"
    run_cli("flipcheck", "export", SCENARIO_DIR / f"{name}.toml", "-o", tmp_path / "kit")
    text = (tmp_path / "kit" / f"{name}.json").read_text()
    motion = tmp_path / "kit" / f"{name}-exact.csv"
    _, arrays = bookspin.flipcheck.export(name)
    t, q, w = arrays["t"], arrays["q"], arrays["omega_world"]
    (tmp_path / "le.json").write_bytes(text.encode("utf-16"))  # with its byte-order mark
    (tmp_path / "be.json").write_bytes(b"\xfe\xff" + text.encode("utf-16-be"))
    (tmp_path / "deep.json").write_text('{"extra": ' + "[" * 70 + "]" * 70 + "}\n")
    for file, said in (("le.json", "NUL byte at line 1 (not a text file: a binary file, or text "
                                    "saved as UTF-16)"),
                       ("be.json", "NUL byte at line 1 (not a text file: a binary file, or text "
                                    "saved as UTF-16)"),
                       ("deep.json", "nested more than 64 deep at line 1, column 75")):
        path = str(tmp_path / file)
        _, err = run_cli("flipcheck", "judge", path, motion, "-o", tmp_path / "out", expect=2)
        assert cli_error_line(err) == f"{path}: {said}"
        with pytest.raises(bookspin.Error) as raised:
            bookspin.flipcheck.judge(path, t, q, w)
        assert str(raised.value) == f"{path}: {said}"
    assert not (tmp_path / "out").exists()


def test_a_scenario_file_is_read_by_its_extension_in_any_case(bookspin, tmp_path, monkeypatch):
    """One route per file (docs/flipcheck.md, "What a scenario may be"): a scenario JSON saved as
    scen.JSON is judged as the same file named .json (not read as TOML), and a scene file saved
    as NAME.TOML is read as a scene, as the command line reads both."""
    name = "mujoco-test-box"
    run_cli("flipcheck", "export", SCENARIO_DIR / f"{name}.toml", "-o", tmp_path)
    _, arrays = bookspin.flipcheck.export(name)
    t, q, w = arrays["t"], arrays["q"], arrays["omega_world"]
    want = bookspin.flipcheck.judge(str(tmp_path / f"{name}.json"), t, q, w)
    for spelled in ("scen.JSON", "scen.Json"):
        shutil.copy(tmp_path / f"{name}.json", tmp_path / spelled)
        assert bookspin.flipcheck.judge(str(tmp_path / spelled), t, q, w) == want
    shutil.copy(SCENARIO_DIR / f"{name}.toml", tmp_path / f"{name}.TOML")
    monkeypatch.chdir(tmp_path)
    assert bookspin.flipcheck.judge(f"{name}.TOML", t, q, w) == bookspin.flipcheck.judge(name, t, q, w)


def test_a_ragged_list_is_named(bookspin):
    """q given as a list whose rows differ in length: named, with the shape expected (it was
    numpy's ValueError, naming no argument)."""
    name = "mujoco-test-box"
    _, arrays = bookspin.flipcheck.export(name)
    t, w = arrays["t"][:3], arrays["omega_world"][:3]
    ragged = [[1.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]]
    with pytest.raises(bookspin.Error) as raised:
        bookspin.flipcheck.judge(name, t, ragged, w)
    assert str(raised.value) == ("q: its rows are of different lengths (a ragged list): expected "
                                 "shape (3, 4), N = len(t) rows of 4 numbers each")
