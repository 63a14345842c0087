#!/usr/bin/env python3
"""Writes recordings/phone-on-book-synthetic/, a synthetic phyphox export of a phone taped on a
book tossed five times (recordings/README.md). Deterministic: run again, the same bytes.

The body: a 17 × 24 × 3.5 cm book (uniform box; the phone's mass left out), the phone on its
cover turned 8° in the cover's plane. Its principal axes 1 < 2 < 3 are the book's long side,
its short side (across the cover) and its thickness, in the phone frame about phone y, x and
−z. The flights are in air: Euler's equations with a drag torque −c·(a ⊙ L) (docs/physics.md
§21; c = 0.17 /s, a = (1, 1, 1): isotropic, |L| falls 16 % a second, as real tosses do)
integrated here by RK4 at 1e-4 s steps (not bookspin's exact motion; `--drag C` and
`--anisotropy A1,A2,A3` change them, e.g. `--anisotropy 1.6,0.7,1` for a drag the isotropic
model cannot fit); around them the hand: rest with a slow wobble of
0.03 rad/s, a 0.15 s throw (a ramp to ω0 with spikes of 4 rad/s), a 0.12 s catch (spikes of
6 rad/s), then rest. Sampled at 100 Hz with ±10 % jitter, noise 0.01 rad/s, a constant bias,
one pause (PAUSE/START in meta/time.csv) after the second toss. Python 3, standard library
only.

Usage: python3 recordings/make_phone_on_book.py [OUT_DIR] [--drag C] [--anisotropy A1,A2,A3]
       (default: beside this script, c = 0.17 /s, isotropic)
"""
import argparse
import math
import pathlib
import random
import sys

# The book's sides (cm) along the phone's x, y, z before the 8° turn.
SIDES = (17.0, 24.0, 3.5)
# Principal moments 1 < 2 < 3 (box, mass 1, cm²): about the long side (phone y), across the
# cover (phone x), through the cover (phone z).
MOMENTS = ((SIDES[0] ** 2 + SIDES[2] ** 2) / 12, (SIDES[1] ** 2 + SIDES[2] ** 2) / 12,
           (SIDES[0] ** 2 + SIDES[1] ** 2) / 12)
# The moment ratios the fit reports (the largest is 1).
RATIOS = (MOMENTS[0] / MOMENTS[2], MOMENTS[1] / MOMENTS[2], 1.0)
TURN_DEG = 8.0  # the phone turned in the cover's plane
# Each toss: ω0 (rad/s) about principal axes 1, 2, 3 at release, and its free flight (s).
# Four about the intermediate axis (2), 8–22 % off it (|ω1, ω3| / |ω2|); the last about the largest (3): stable.
TOSSES = (((2.5, 17.0, 1.8), 1.4),
          ((1.2, 18.0, -2.8), 1.3),
          ((-3.2, 16.0, 1.4), 1.3),
          ((1.0, -17.0, 0.9), 1.5),
          ((0.9, 0.7, 11.0), 1.0))
RATE, JITTER, NOISE = 100.0, 0.1, 0.01  # Hz, fraction of a sample interval, rad/s
BIAS = (0.018, -0.012, 0.009)  # rad/s, phone frame
REST, THROW, CATCH, AFTER = 1.5, 0.15, 0.12, 1.2  # s
SEED = 2026
DRAG = 0.17  # 1/s: the air's linear drag rate (|L| ∝ e^(−c t) when isotropic)
ANISOTROPY = (1.0, 1.0, 1.0)  # the torque −c (a ⊙ L) about principal axes 1, 2, 3


def matmul(a, b):
    return [[sum(a[r][k] * b[k][c] for k in range(3)) for c in range(3)] for r in range(3)]


def rotation_z(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]


# Columns: principal axes 1, 2, 3 in the phone frame: phone y, x, −z (a right-handed frame:
# Euler's equations run backwards in a mirrored one), turned 8° about z.
AXES = matmul(rotation_z(TURN_DEG), [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])


def to_phone(w):
    return [sum(AXES[r][c] * w[c] for c in range(3)) for r in range(3)]


def euler_rate(w):
    """ω̇ (principal) of Euler's equations with the drag torque −c (a ⊙ L): I ω̇ = (I ω) × ω − c a ⊙ I ω."""
    I1, I2, I3 = MOMENTS
    c, a = DRAG, ANISOTROPY
    return ((I2 - I3) / I1 * w[1] * w[2] - c * a[0] * w[0],
            (I3 - I1) / I2 * w[2] * w[0] - c * a[1] * w[1],
            (I1 - I2) / I3 * w[0] * w[1] - c * a[2] * w[2])


def flight(w0, time):
    """ω (principal) after `time` s from `w0`: RK4, steps of at most 1e-4 s."""
    steps = max(1, math.ceil(time / 1e-4))
    h, w = time / steps, list(w0)
    for _ in range(steps):
        k1 = euler_rate(w)
        k2 = euler_rate([w[i] + 0.5 * h * k1[i] for i in range(3)])
        k3 = euler_rate([w[i] + 0.5 * h * k2[i] for i in range(3)])
        k4 = euler_rate([w[i] + h * k3[i] for i in range(3)])
        w = [w[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(3)]
    return w


def pieces():
    """(t0, t1, kind, a, b) over the recording: rest, then per toss throw, flight, catch, rest."""
    out, now = [(0.0, REST, "rest", None, None)], REST
    for w0, length in TOSSES:
        out.append((now, now + THROW, "throw", None, to_phone(w0)))
        now += THROW
        out.append((now, now + length, "flight", w0, None))
        now += length
        out.append((now, now + CATCH, "catch", to_phone(flight(w0, length)), None))
        now += CATCH
        out.append((now, now + AFTER, "rest", None, None))
        now += AFTER
    return out


def main():
    global DRAG, ANISOTROPY
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out_dir", nargs="?", default=None)
    parser.add_argument("--drag", type=float, default=DRAG, help="linear drag rate c, 1/s")
    parser.add_argument("--anisotropy", default=",".join(str(x) for x in ANISOTROPY),
                        help="a1,a2,a3: the torque −c (a ⊙ L) about principal axes 1, 2, 3")
    args = parser.parse_args()
    DRAG = args.drag
    ANISOTROPY = tuple(float(x) for x in args.anisotropy.split(","))
    folder = pathlib.Path(args.out_dir) if args.out_dir else \
        pathlib.Path(__file__).resolve().parent / "phone-on-book-synthetic"
    rng = random.Random(SEED)
    parts = pieces()
    end = parts[-1][1]
    pause = parts[8][1] - AFTER / 2  # mid-rest after the second toss
    rows, t, p, state = [], 0.0, 0, None
    while t < end:
        while p + 1 < len(parts) and t >= parts[p][1]:
            p += 1
        t0, t1, kind, a, b = parts[p]
        s = (t - t0) / (t1 - t0)
        if kind == "rest":
            w = [0.03 * math.sin(3.1 * t), 0.03 * math.sin(2.3 * t + 1), 0.03 * math.sin(1.7 * t + 2)]
        elif kind == "throw":
            w = [s * b[i] + 4.0 * rng.gauss(0, 1) for i in range(3)]
        elif kind == "flight":
            # From the last sample of this flight (or its release), not from the release.
            if state is None or state[2] != t0:
                state = (t0, a, t0)  # (time, principal ω, this flight's release)
            state = (t, flight(state[1], t - state[0]), t0)
            w = to_phone(state[1])
        else:
            w = [(1 - s) * a[i] + 6.0 * rng.gauss(0, 1) for i in range(3)]
        w = [w[i] + BIAS[i] + rng.gauss(0, NOISE) for i in range(3)]
        rows.append((t, *w, math.sqrt(sum(x * x for x in w))))
        t += (1 + JITTER * rng.uniform(-1, 1)) / RATE
    (folder / "meta").mkdir(parents=True, exist_ok=True)
    with open(folder / "Raw Data.csv", "w", newline="\n") as f:
        f.write('"Time (s)","Gyroscope x (rad/s)","Gyroscope y (rad/s)","Gyroscope z (rad/s)",'
                '"Absolute (rad/s)"\n')
        for row in rows:
            f.write(",".join(f"{x:.9E}" for x in row) + "\n")
    with open(folder / "meta" / "time.csv", "w", newline="\n") as f:
        f.write('"event","experiment time","system time","system time text"\n')
        f.write('"START",0.000000000E0,1.764028800E9,"2025-11-25 00:00:00.000 UTC+00:00"\n')
        f.write(f'"PAUSE",{pause:.9E},1.764028900E9,"2025-11-25 00:01:40.000 UTC+00:00"\n')
        f.write(f'"START",{pause:.9E},1.764029000E9,"2025-11-25 00:03:20.000 UTC+00:00"\n')
    with open(folder / "meta" / "device.csv", "w", newline="\n") as f:
        f.write('"property","value"\n"deviceModel","synthetic (recordings/make_phone_on_book.py)"\n')
    print(f"{folder}: {len(rows)} samples, {end:.2f} s, ratios "
          f"{RATIOS[0]:.4f} : {RATIOS[1]:.4f} : 1")


if __name__ == "__main__":
    main()
