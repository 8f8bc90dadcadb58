"""``bench``: forwarded benchmarks keep their own options; ``bench sweep`` reports runs/s."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from pendulum_fmu.cli import bench
from pendulum_fmu.cli.main import main


def test_bench_exact_is_forwarded_with_its_own_help(capsys: pytest.CaptureFixture[str]) -> None:
    if "exact" not in bench.available():
        pytest.skip("pendulum_fmu.bench.exact is not installed")
    with pytest.raises(SystemExit) as stop:
        main(["bench", "exact", "--help"])
    assert stop.value.code == 0
    assert capsys.readouterr().out.startswith("usage: pendulum-fmu bench exact")


def test_bench_lists_the_benchmarks_available(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["bench", "--help"])
    out = capsys.readouterr().out
    assert "sweep" in out
    for name in bench.available():
        assert name in out


def test_bench_sweep_prints_runs_per_second(fmu_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["bench", "sweep", "--runs", "24", "--periods", "2", "--workers", "1", "--repeat", "1",
                 "--fmu", str(fmu_path)]) == 0
    out = capsys.readouterr().out
    match = re.search(r"^bench_sweep workers=1 runs=24 rate=([0-9.]+) ", out, re.MULTILINE)
    assert match is not None, out
    assert float(match.group(1)) > 0
