"""``study``: the seed's files, and the HTML report's table against the FMU's own outputs."""

from __future__ import annotations

import math
from html.parser import HTMLParser
from pathlib import Path

import pytest
from fmpy import simulate_fmu
from PIL import Image

from fmpy_runs import Interface, Scenario, simulate
from pendulum_fmu.cli.main import main
from pendulum_fmu.study.seed import ME_TOLERANCE, TABLE_HEADER

PERIODS = 2.0


class _Tables(HTMLParser):
    """Collect the cells of every table row, and the images."""

    def __init__(self) -> None:
        super().__init__()
        self.rows: list[list[str]] = []
        self.images: list[str] = []
        self._cell: list[str] | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th"):
            self._cell = []
        elif tag == "img":
            self.images.append(dict(attrs).get("src") or "")

    def handle_data(self, data: str) -> None:
        if self._cell is not None:
            self._cell.append(data)

    def handle_endtag(self, tag: str) -> None:
        if tag in ("td", "th") and self._cell is not None:
            self.rows[-1].append("".join(self._cell))
            self._cell = None


@pytest.fixture(scope="module")
def study_dir(fmu_path: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("study")
    assert main(["study", "--out", str(out), "--fmu", str(fmu_path), "--periods", str(PERIODS)]) == 0
    return out


def _runs_record_every_run(study_dir: Path) -> None:
    """runs.csv's sidecar holds one experiment per run, selected by its interface and amplitude
    (docs/results.md), and each is the run's: its start value and its rows' span."""
    import csv
    import math

    from pendulum_fmu.output.experiment_record import read_runs

    found = read_runs(study_dir / "runs.csv")
    assert found is not None
    runs, _ = found
    with (study_dir / "runs.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    keys = {(row["interface"], row["amplitude_deg"]) for row in rows}
    assert {(s["interface"], s["amplitude_deg"]) for s, _ in runs} == keys and len(runs) == len(keys)
    for select, record in runs:
        times = [float(row["time_s"]) for row in rows
                 if (row["interface"], row["amplitude_deg"]) == (select["interface"], select["amplitude_deg"])]
        assert record.interface == select["interface"] and record.theta0 == math.radians(float(select["amplitude_deg"]))
        assert (record.start_time, record.stop_time) == (times[0], times[-1])


def test_study_writes_the_seed_files_and_the_html_report(study_dir: Path) -> None:
    for name in ("fig3_numeric.png", "fig4_exact.png", "fig5_overlay.png", "period_ratio.png", "speed_vs_error.png"):
        with Image.open(study_dir / name) as image:
            assert image.format == "PNG" and image.size[0] > 800, name
    assert (study_dir / "runs.csv").read_text().startswith("interface,amplitude_deg,time_s,w0t,")
    assert "| 90 | ME |" in (study_dir / "report.md").read_text()
    _runs_record_every_run(study_dir)
    parser = _Tables()
    parser.feed((study_dir / "report.html").read_text())
    # the seed's four figures and the speed-against-error figure
    assert len(parser.images) == 5 and all(src.startswith("data:image/png;base64,") for src in parser.images)


def test_html_table_matches_the_fmu_outputs(study_dir: Path, fmu_path: Path) -> None:
    parser = _Tables()
    parser.feed((study_dir / "report.html").read_text())
    header, *rows = parser.rows[:9]   # the error table comes first (speed and hard cases follow)
    assert tuple(header) == TABLE_HEADER
    assert sorted((float(r[0]), r[1]) for r in rows) == sorted((a, i) for a in (75.0, 80.0, 85.0, 90.0)
                                                                for i in ("CS", "ME"))
    for amplitude, interface, period, measured, ratio, max_error in rows:
        theta0 = math.radians(float(amplitude))
        fmu_period = float(simulate_fmu(str(fmu_path), stop_time=0.1, output_interval=0.1, output=["period"],
                                        start_values={"theta": theta0})["period"][0])
        w0 = math.sqrt(9.81)
        assert float(period) == pytest.approx(fmu_period, abs=1e-9)
        assert float(ratio) == pytest.approx(fmu_period * w0 / (2 * math.pi), abs=1e-6)
        assert float(measured) == pytest.approx(fmu_period, rel=1e-6)
        tolerance = None if interface == "CS" else ME_TOLERANCE
        kind: Interface = "CS" if interface == "CS" else "ME"
        run = simulate(fmu_path, Scenario(amplitude_deg=float(amplitude), periods=PERIODS), kind, tolerance)
        assert float(max_error) == pytest.approx(run.max_error, rel=6e-3)
        assert run.max_error < 1e-6


@pytest.mark.slow
def test_an_interrupted_study_leaves_the_folder_as_it_was(fmu_path: Path, tmp_path: Path,
                                                          monkeypatch: pytest.MonkeyPatch,
                                                          capsys: pytest.CaptureFixture[str]) -> None:
    """Ctrl-C after Figures 3-5 are drawn: no new file in a folder that had a study, no folder where
    there was none; the stages were said on the way."""
    import pendulum_fmu.study.job as job

    def interrupted(*args: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(job, "plot_period_ratio", interrupted)
    fresh = tmp_path / "fresh" / "study"
    assert main(["study", "--out", str(fresh), "--fmu", str(fmu_path), "--periods", "1"]) == 130
    err = capsys.readouterr().err
    assert "study: run 8 of 8" in err and "study: Figure 5 (fig5_overlay.png) ..." in err
    assert "study: the period ratio" in err and err.rstrip().endswith("interrupted")
    assert not (tmp_path / "fresh").exists()  # nor the parent the study created
    kept = tmp_path / "kept"
    kept.mkdir()
    (kept / "fig3_numeric.png").write_bytes(b"the previous study's")
    assert main(["study", "--out", str(kept), "--fmu", str(fmu_path), "--periods", "1"]) == 130
    assert [p.name for p in kept.iterdir()] == ["fig3_numeric.png"]
    assert (kept / "fig3_numeric.png").read_bytes() == b"the previous study's"
