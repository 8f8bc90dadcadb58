"""``pendulum-fmu bench masters``: the table, the orders and the work-precision figure."""

from __future__ import annotations

from pathlib import Path

import pytest

from pendulum_fmu.bench.masters import MasterRun, measure, orders, table
from pendulum_fmu.cli.main import main
from pendulum_fmu.split.masters import MASTERS


def test_bench_masters_prints_the_table_and_draws_the_figure(tmp_path: Path,
                                                             capsys: pytest.CaptureFixture[str]) -> None:
    figure = tmp_path / "masters.png"
    assert main(["bench", "masters", "--steps", "0.02", "0.01", "--stop", "1", "--no-engines",
                 "--plot", str(figure)]) == 0
    out = capsys.readouterr().out
    rows = [line for line in out.splitlines() if any(line.startswith(f"| {m.name} |") for m in MASTERS)]
    assert len(rows) == 2 * len(MASTERS), out
    assert all(line.split("|")[3].strip() == "reference master" for line in rows), rows
    order = {line.split("|")[1].strip(): line.split("|")[5].strip() for line in rows if line.split("|")[5].strip()}
    assert abs(float(order["gauss-seidel-zoh"]) - 1) < 0.2
    assert abs(float(order["gauss-seidel-extrapolation"]) - 2) < 0.2
    assert abs(float(order["gauss-seidel-interpolation"]) - 3) < 0.2
    assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and figure.stat().st_size > 20_000


@pytest.mark.engines
def test_bench_masters_with_one_engine() -> None:
    """Ecos (or whichever engines are installed) joins the masters with its own rows."""
    points = measure((0.02, 0.01), 1.0)
    engines = [p for p in points if p.kind == "engine" and p.note.startswith("conformant; behaves as")]
    assert {p.note for p in engines} >= {"conformant; behaves as Jacobi with zero-order hold"}, table(points)
    assert all(abs(o - 1) < 0.35 for name, found in orders(points).items() if "zoh" in name or "(" in name
               for o in found)


def test_orders_and_table_from_points() -> None:
    points = [MasterRun("m", "master", 0.1, 1e-2, 0.1), MasterRun("m", "master", 0.05, 2.5e-3, 0.2),
              MasterRun("e (FMI 3)", "engine", 0.1, float("nan"), float("nan"), "cannot: no")]
    assert orders(points)["m"] == pytest.approx([2.0])
    lines = table(points)
    assert lines[3] == "| m | 0.05 | reference master | 0.0025 | 2.00 | 0.2 |"
    assert lines[4] == "| e (FMI 3) | 0.1 | cannot: no | | | |"


def test_bench_masters_refuses_bad_arguments(capsys: pytest.CaptureFixture[str]) -> None:
    """Each a single line and exit status 2, before any run."""
    for argv in (["--steps", "0"], ["--steps", "1e-7", "--stop", "1000"]):
        try:
            status = main(["bench", "masters", *argv])
        except SystemExit as stop:
            status = int(stop.code or 0)
        assert status == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and err[0].startswith("pendulum-fmu bench masters: "), err
