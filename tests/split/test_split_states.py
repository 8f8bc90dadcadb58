"""FMU states of the split FMUs through fmpy, as an iterating master uses them (docs/split.md).

A coupled Gauss-Seidel run of PendulumBody and PendulumGravity (FMI 2.0 with input
interpolation, FMI 3.0 with hold) saves both FMUs' states, steps on, restores them and steps
the same way again: every output equals the first pass bit for bit. The states serialized
and deserialized into a fresh pair with other start values continue bit for bit too, and
serialize again to the same bytes. A blob cut short, another model's blob and a flipped bit
are refused with an error status (the C test tests/c/test_split_states.c checks each logged
reason).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from pendulum_fmu.spec import InitialValueProblem
from pendulum_fmu.split.pair import ALPHA, OMEGA, OMEGA_EXACT, THETA, THETA_EXACT, Pair

PROBLEM = InitialValueProblem(L=1.5, g=9.81, theta0=2.5, omega0=-0.75)


def gauss_seidel(pair: Pair, first: int, last: int, H: float = 0.03) -> np.ndarray:
    """Macro steps first..last-1 of Gauss-Seidel (FMI 2.0: the output derivatives passed on as
    input derivatives), every output after each step in a row."""
    rows = []
    for k in range(first, last):
        pair.set(pair.gravity, THETA, pair.get(pair.body, THETA))
        if not pair.v3:
            pair.set_derivatives(pair.gravity, THETA, *pair.derivatives(pair.body, THETA))
        pair.set(pair.body, ALPHA, pair.get(pair.gravity, ALPHA))
        if not pair.v3:
            pair.set_derivatives(pair.body, ALPHA, *pair.derivatives(pair.gravity, ALPHA))
        pair.step(pair.body, k * H, H, rollback=True)
        pair.step(pair.gravity, k * H, H, rollback=True)
        rows.append([pair.get(pair.body, vr) for vr in (THETA, OMEGA, THETA_EXACT, OMEGA_EXACT, ALPHA)]
                    + [pair.get(pair.gravity, vr) for vr in (THETA, ALPHA)])
    return np.array(rows)


def serialized(pair: Pair, states: list[Any]) -> list[bytes]:
    return [fmu.serializeFMUState(state) for fmu, state in zip(pair.instances, states, strict=True)]


@pytest.mark.parametrize("version", [2, 3])
def test_rollback_repeats_every_output_bit_for_bit(version: int) -> None:
    with Pair(PROBLEM, version) as pair:
        gauss_seidel(pair, 0, 7)
        states = pair.save()
        first = gauss_seidel(pair, 7, 30)
        pair.restore(states)
        again = gauss_seidel(pair, 7, 30)
        pair.restore(states)
        once_more = gauss_seidel(pair, 7, 30)
        pair.free(states)
    assert first.shape == (23, 7) and np.all(np.isfinite(first))
    assert first.tobytes() == again.tobytes() == once_more.tobytes()
    # the run moved: a rollback that restored nothing would not repeat it
    assert abs(first[-1, 0] - first[0, 0]) > 0.1


@pytest.mark.parametrize("version", [2, 3])
def test_a_serialized_state_continues_in_another_pair(version: int) -> None:
    with Pair(PROBLEM, version) as pair:
        gauss_seidel(pair, 0, 11)
        states = pair.save()
        blobs = serialized(pair, states)
        first = gauss_seidel(pair, 11, 40)
        pair.free(states)
    with Pair(InitialValueProblem(L=1.5, g=9.81, theta0=0.2, omega0=3.0), version) as other:
        restored = [fmu.deserializeFMUState(blob) for fmu, blob in zip(other.instances, blobs, strict=True)]
        assert serialized(other, restored) == blobs
        other.restore(restored)
        again = gauss_seidel(other, 11, 40)
        other.free(restored)
    assert first.tobytes() == again.tobytes()


@pytest.mark.parametrize("version", [2, 3])
def test_blobs_that_are_not_a_state_of_the_fmu_are_refused(version: int) -> None:
    with Pair(PROBLEM, version) as pair:
        states = pair.save()
        body_blob, gravity_blob = serialized(pair, states)
        pair.free(states)
    assert len(body_blob) == len(gravity_blob)
    flipped = bytearray(body_blob)
    flipped[-20] ^= 0x04
    for blob in (body_blob[:-1], body_blob + b"\0", gravity_blob, bytes(flipped)):
        with Pair(PROBLEM, version) as pair, pytest.raises(FMICallException, match="status 3"):
            pair.body.deserializeFMUState(blob)
