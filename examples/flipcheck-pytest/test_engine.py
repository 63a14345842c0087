"""An engine's own test judged by flipcheck (docs/flipcheck.md, "In your engine's tests")."""
import numpy as np, pytest
from bookspin import flipcheck

def rates(y, I):  # a free rigid body: q' = q (0, w) / 2, I w' = (I w) x w (w in the body frame)
    q, w = y[:4], y[4:]
    return np.r_[-q[1:] @ w / 2, (q[0] * w + np.cross(q[1:], w)) / 2, np.cross(I * w, w) / I]

def euler(y, h, I): return y + h * rates(y, I)

def rk4(y, h, I):
    a = rates(y, I); b = rates(y + h / 2 * a, I); c = rates(y + h / 2 * b, I); d = rates(y + h * c, I)
    return y + h / 6 * (a + 2 * b + 2 * c + d)

def motion(step, scenario="book-intermediate-0.05"):  # the engine run from the scenario's start
    s, _ = flipcheck.export(scenario)
    I, y, rows = np.array(s["principal_moments"]), np.r_[1.0, 0, 0, 0, s["omega0_body"]], []
    for _ in range(s["steps"] + 1):
        q, w = y[:4], y[4:]  # w in the world frame: q (0, w) q*
        rows.append([*q, *(w + 2 * np.cross(q[1:], np.cross(q[1:], w) + q[0] * w))])
        y = step(y, s["dt"], I); y[:4] /= np.linalg.norm(y[:4])
    rows = np.array(rows)
    return scenario, s["dt"] * np.arange(len(rows)), rows[:, :4], rows[:, 4:]

def test_rk4_passes():
    flipcheck.assert_passes(*motion(rk4))

def test_euler_fails_by_gaining_energy():
    with pytest.raises(AssertionError, match=r"FAIL \(energy drift"):
        flipcheck.assert_passes(*motion(euler))
