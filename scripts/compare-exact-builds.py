"""Two builds of the exact solution against 50-digit mpmath, over random states of every regime.

Usage (each build's library through ``PENDULUM_EXACT_LIB``, one process per build):

    PENDULUM_EXACT_LIB=old.so python scripts/compare-exact-builds.py eval old.npz [N] [--late]
    PENDULUM_EXACT_LIB=new.so python scripts/compare-exact-builds.py eval new.npz [N] [--late]
    python scripts/compare-exact-builds.py compare old.npz new.npz

The states (seeded, the same for both builds): libration from rest and moving, amplitudes
within 1e-12 of pi, speeds within 1 to 8 ulps and within 1e-16 .. 1e-3 (relative) of the
separatrix on both sides, rotation, angles wound up by up to 1e12 turns, any L and g. Each
state is evaluated at three times in its first three periods and one time 1e2 .. 1e6 periods on;
with ``--late`` at four times 1e8 .. 1e12 periods on instead, where the phase rests on the last
bits of the rate (double-double, ~2^-104) and an output of either build is no longer certain to
be rounded to nearest (``compare`` then prints the late rows alone).
``compare`` prints, per regime and for the early and late times: the largest and the 50th, 99th
percentile errors of theta (rad, relative to |theta| where it exceeds 1) and of omega (relative
to the state's largest |omega|) for both builds, the number of outputs that differ between
them, by how many ulps, and how many of those moved closer to mpmath.
"""
from __future__ import annotations

import sys

import mpmath as mp
import numpy as np

from pendulum_fmu.bench.reference import closed_form, exact_frequency

REGIMES = ("libration", "rest", "near_top", "separatrix_ulps", "separatrix_rel", "rotation", "wound")


def states(n: int) -> dict[str, np.ndarray]:
    """n states per regime: theta0, omega0, L, g, regime index."""
    rng = np.random.default_rng(20261128)
    rows = []
    for index, regime in enumerate(REGIMES):
        for _ in range(n):
            L = float(10.0 ** rng.uniform(-2, 2))
            g = float(10.0 ** rng.uniform(-1, 2))
            w0 = np.sqrt(g / L)
            th = float(rng.uniform(-np.pi, np.pi))
            if regime == "libration":
                omega0 = float(rng.uniform(-1, 1) * 2 * w0 * np.cos(th / 2) * rng.uniform(0, 0.999))
            elif regime == "rest":
                th, omega0 = float(rng.uniform(-np.pi, np.pi)), 0.0
            elif regime == "near_top":
                th = float(rng.choice([-1, 1]) * (np.pi - 10.0 ** rng.uniform(-12, -1)))
                omega0 = float(rng.uniform(-1, 1) * 2 * w0 * np.cos(th / 2) * 0.5)
            elif regime == "separatrix_ulps":
                speed = 2 * w0 * np.cos(th / 2)
                steps = int(rng.integers(-8, 9))
                omega0 = float(speed)
                for _ in range(abs(steps)):
                    omega0 = float(np.nextafter(omega0, np.inf if steps > 0 else 0.0))
                omega0 *= float(rng.choice([-1, 1]))
            elif regime == "separatrix_rel":
                speed = 2 * w0 * np.cos(th / 2)
                omega0 = float(rng.choice([-1, 1]) * speed
                               * (1 + rng.choice([-1, 1]) * 10.0 ** rng.uniform(-16, -3)))
            elif regime == "rotation":
                omega0 = float(rng.choice([-1, 1]) * 2 * w0 * 10.0 ** rng.uniform(0.0005, 3))
            else:   # wound up: any regime, many turns
                omega0 = float(rng.uniform(-3, 3) * w0)
                th = float(th + 2 * np.pi * np.floor(10.0 ** rng.uniform(0, 12)) * rng.choice([-1, 1]))
            rows.append((th, omega0, L, g, index))
    a = np.array(rows)
    return {"theta0": a[:, 0], "omega0": a[:, 1], "L": a[:, 2], "g": a[:, 3], "regime": a[:, 4].astype(int)}


def times_for(theta0: float, omega0: float, L: float, g: float, rng: np.random.Generator,
              late: bool = False) -> list[float]:
    """Three times within about three periods and one 1e2 .. 1e6 periods on (late: four times
    1e8 .. 1e12 periods on)."""
    w0 = float(np.sqrt(g / L))
    unit = 2 * np.pi / max(w0, abs(omega0))
    if late:
        return [float(unit * 10.0 ** rng.uniform(8, 12)) for _ in range(4)]
    early = sorted(float(x) for x in rng.uniform(0, 3 * unit * 4, 3))
    return early + [float(unit * 10.0 ** rng.uniform(2, 6))]


def evaluate(out: str, n: int, late: bool = False) -> None:
    from pendulum_fmu.fmu.library import exact
    s = states(n)
    rng = np.random.default_rng(7)
    t = np.array([times_for(float(s["theta0"][i]), float(s["omega0"][i]), float(s["L"][i]), float(s["g"][i]),
                            rng, late) for i in range(len(s["theta0"]))])
    rep = {k: np.repeat(s[k], 4) for k in ("theta0", "omega0", "L", "g")}
    theta, omega = exact(rep["theta0"], rep["omega0"], rep["L"], rep["g"], t.ravel(), workers=1)
    np.savez(out, theta=theta, omega=omega, t=t.ravel(), regime=np.repeat(s["regime"], 4), late=np.array(late),
             theta0=rep["theta0"], omega0=rep["omega0"], L=rep["L"], g=rep["g"])


def ulps(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """|a - b| in units in the last place of the larger (0 where equal)."""
    return np.where(a == b, 0.0, np.abs(a - b) / np.spacing(np.maximum(np.abs(a), np.abs(b))))


def compare(old_path: str, new_path: str) -> None:
    old, new = np.load(old_path), np.load(new_path)
    assert all(np.array_equal(old[k], new[k]) for k in ("theta0", "omega0", "L", "g", "t"))
    n = len(old["t"])
    err = {name: np.zeros((2, n)) for name in ("old", "new")}
    mp.mp.dps = 50
    for i in range(0, n, 4):
        w0 = exact_frequency(float(old["L"][i]), float(old["g"][i]))
        th_ref, om_ref, _ = closed_form(float(old["theta0"][i]), float(old["omega0"][i]), w0,
                                        [float(x) for x in old["t"][i:i + 4]])
        scale = max(max(abs(float(r)) for r in om_ref), 1e-300)
        for name, data in (("old", old), ("new", new)):
            for j in range(4):
                # theta: absolute for |theta| <= 1, relative beyond (wound-up angles)
                err[name][0, i + j] = float(abs(mp.mpf(float(data["theta"][i + j])) - th_ref[j])
                                            / max(1, abs(th_ref[j])))
                err[name][1, i + j] = float(abs(mp.mpf(float(data["omega"][i + j])) - om_ref[j])) / scale
    late = (np.arange(n) % 4) == 3 if not bool(old.get("late", False)) else np.ones(n, bool)
    print("| regime | times | output | old max | old p50 | old p99 | new max | new p50 | new p99 | changed "
          "| max ulps | closer / farther |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for index, regime in enumerate(REGIMES):
        for when, mask_t in (("early", ~late), ("late", late)):
            mask = (old["regime"] == index) & mask_t
            for row, output in ((0, "theta"), (1, "omega")):
                if not mask.any():
                    continue
                e_old, e_new = err["old"][row, mask], err["new"][row, mask]
                a, b = old[output][mask], new[output][mask]
                changed = a != b
                closer = int(np.sum(e_new[changed] < e_old[changed]))
                farther = int(np.sum(e_new[changed] > e_old[changed]))
                du = ulps(a, b)
                print(f"| {regime} | {when} | {output} | {e_old.max():.2e} | {np.percentile(e_old, 50):.1e} | "
                      f"{np.percentile(e_old, 99):.1e} | {e_new.max():.2e} | {np.percentile(e_new, 50):.1e} | "
                      f"{np.percentile(e_new, 99):.1e} | {int(changed.sum())}/{int(mask.sum())} | "
                      f"{du.max():.0f} | {closer} / {farther} |")
    changed = np.concatenate([old["theta"] != new["theta"], old["omega"] != new["omega"]])
    e_old, e_new = np.concatenate(err["old"]), np.concatenate(err["new"])
    print(f"changed outputs: {int(changed.sum())} of {changed.size}; closer to mpmath "
          f"{int(np.sum(e_new[changed] < e_old[changed]))}, farther {int(np.sum(e_new[changed] > e_old[changed]))}, "
          f"as close {int(np.sum(e_new[changed] == e_old[changed]))}; sum of errors over them: old "
          f"{e_old[changed].sum():.3e}, new {e_new[changed].sum():.3e}")
    for when, mask_t in (("early", ~late), ("all", np.ones(n, bool))):
        if not mask_t.any():
            continue
        for row, output in ((0, "theta"), (1, "omega")):
            print(f"overall {when} {output}: old max {err['old'][row, mask_t].max():.3e}, "
                  f"new max {err['new'][row, mask_t].max():.3e}")
    changed_any = (old["theta"] != new["theta"]) | (old["omega"] != new["omega"])
    print(f"outputs changed: theta {int(np.sum(old['theta'] != new['theta']))}, omega "
          f"{int(np.sum(old['omega'] != new['omega']))} of {n} each; points with any change {int(changed_any.sum())}")


if __name__ == "__main__":
    if sys.argv[1] == "eval":
        numbers = [a for a in sys.argv[3:] if a != "--late"]
        evaluate(sys.argv[2], int(numbers[0]) if numbers else 200, "--late" in sys.argv[3:])
    else:
        compare(sys.argv[2], sys.argv[3])
