"""``pendulum-fmu judge``: is an importer's result of Pendulum.fmu right, and if not, what is wrong."""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import replace
from pathlib import Path

from pendulum_fmu.cli.arguments import fmu_file, output_file, output_folder, positive
from pendulum_fmu.spec import InitialValueProblem

NAME = "judge"
HELP = "judge any importer's result file against the exact solution (exit 0 pass, 1 fail, 2 unreadable)"
DESCRIPTION = """\
Read the result of any importer (CSV as fmpy, fmusim, fmuCheck, FMI4j, libcosim, Ecos or the
fmi-cross-check write it, or Parquet) and check it against the exact solution: the time grid
(monotone, step, drift from k h), the theta_exact/omega_exact columns against
pendulum_fmu.exact at the file's own times, theta and omega against the exact solution (largest
error, where, growth), isolated mangled values, and the bound: in CS the certificate's
100 tol max(1, |theta_e|) (omega: max(w0, |omega_e|)); in ME 300 tol of local error per
natural period, propagated by the pendulum's linearised flow and summed (docs/importers.md). When
it fails the judge says what fits: other parameters or start values, a fixed-step method,
another tolerance. The check "fmpy band" reports what fmpy's cross-check validation (a band
of 10 % of each signal's range) says of the same file; it never decides.
The experiment is read from the result's own record when this package wrote it (start
values, parameters, solver, interface, tolerance, step: FILE.csv.experiment.json beside a CSV,
a Parquet file's metadata; docs/results.md), else from the cross-check <Model>_ref.opt when
the result sits in a cross-check folder (beside it, or the exporter's fmus/ folder for an
importer's results/ folder: start time, tolerance, step, interface), else from the FMU's
FMI-LS-REF experiment (extra/org.fmi-standard.fmi-ls-ref/Pendulum.exp, the default
experiment); --start, --step and --interface say otherwise, and the first line names the file.
A gzipped CSV (run.csv.gz) is read as the CSV. --cross-check-verdict DIR writes DIR/passed, DIR/failed or
DIR/rejected (unreadable result), the file the cross-check rules ask an importer to publish.
One line per check, then the verdict. Exit status 0 pass, 1 fail, 2 unreadable input.
"""
EPILOG = """\
examples:
  pendulum-fmu judge fmpy_cs.csv
  pendulum-fmu judge result.csv --interface ME --start tolerance=1e-6
  pendulum-fmu judge ecos.csv --start theta=80deg --start L=2 --json verdict.json --plot errors.png
  pendulum-fmu judge container.csv --instance pend2
  pendulum-fmu judge coupled.csv --system split
  pendulum-fmu judge runs/ --system split --order 1 --json runs.json --plot runs.png
  pendulum-fmu judge coupled.csv --system split --max-error 1e-3 --master gauss-seidel-zoh
  pendulum-fmu judge results/2.0/me/linux64/MyTool/1.0/PendulumFMU/0.1.0/Pendulum/Pendulum_out.csv \
      --cross-check-verdict results/2.0/me/linux64/MyTool/1.0/PendulumFMU/0.1.0/Pendulum
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``judge``."""
    parser.add_argument("result", metavar="RESULT", nargs="+",
                        help="the result file: CSV (also gzipped) or Parquet; with --system split several files or "
                             "folders of CSV files: runs of one master at different H (the observed order over them)")
    parser.add_argument("--start", action="append", default=[], metavar="NAME=VALUE",
                        help="a value the run set: theta (rad, or e.g. 80deg), omega, L, g, solver, tolerance; "
                             "repeat for several (the rest: the model description's defaults)")
    parser.add_argument("--interface", choices=("CS", "ME"), default=None,
                        help="Co-Simulation or Model Exchange (default: a cross-check folder's cs/me, else CS)")
    parser.add_argument("--instance", metavar="NAME", help="whose columns, when the file has several instances")
    parser.add_argument("--step", type=positive("s"), metavar="H",
                        help="the communication step the run asked for (default: read from the times)")
    parser.add_argument("--json", type=output_file(".json"), metavar="FILE.json", help="also write the verdict as JSON")
    parser.add_argument("--plot", type=output_file(".png"), metavar="FILE.png",
                        help="also draw the error over time with the bound")
    parser.add_argument("--fmu", type=fmu_file, metavar="PATH",
                        help="the FMU whose model description and FMI-LS-REF experiment give the defaults "
                             "(default: as for simulate)")
    parser.add_argument("--system", choices=("pendulum", "split"), default="pendulum",
                        help="pendulum: a run of Pendulum.fmu (default); split: a coupled run of PendulumBody and "
                             "PendulumGravity (PendulumSplit.ssp): conformance (each defect named), which reference "
                             "master it reproduces, its accuracy (docs/masters.md)")
    parser.add_argument("--master", metavar="NAME",
                        help="with --system split: the reference master the run implements, e.g. gauss-seidel-zoh "
                             "(jacobi|gauss-seidel)-(zoh|extrapolation|interpolation): fail unless the run reproduces "
                             "it")
    parser.add_argument("--max-error", type=positive("rad"), metavar="E",
                        help="with --system split: fail when the largest |theta - theta_exact| is above E")
    parser.add_argument("--order", type=positive(""), metavar="P",
                        help="with --system split and runs at two H or more: fail when the observed order is below "
                             "P - 0.2")
    parser.add_argument("--cross-check-verdict", type=output_folder, metavar="DIR",
                        help="also write DIR/passed, DIR/failed or DIR/rejected (empty, the cross-check "
                             "rules' verdict file; the other two are removed)")


def run(args: argparse.Namespace) -> int:
    """Run ``judge`` with parsed arguments: print the checks and the verdict, return 0/1/2."""
    if args.system == "split" or args.master or args.max_error is not None or args.order is not None:
        return _run_split(args)
    if len(args.result) > 1:
        print(f"pendulum-fmu judge: {len(args.result)} results given: judge one at a time (several only with "
              "--system split)", file=sys.stderr)
        return 2
    from pendulum_fmu.judge import ReadError, judge
    from pendulum_fmu.judge.cross_check_verdict import outcome, write_verdict_file
    from pendulum_fmu.judge.report import lines, write_json, write_plot

    start = start_values(args.start)
    try:
        verdict = judge(args.result[0], start=start, interface=args.interface, instance=args.instance,
                        step=args.step, fmu=args.fmu)
    except ReadError as error:
        print(f"pendulum-fmu judge: unreadable: {error}", file=sys.stderr)
        if args.cross_check_verdict:
            write_verdict_file(args.cross_check_verdict, outcome(None))
        return 2
    if verdict.experiment_file is not None:
        print(f"{'experiment file':<16s}{'INFO':<6s}{verdict.experiment_file.describe()}")
    print("\n".join(lines(verdict)))
    if args.cross_check_verdict:
        write_verdict_file(args.cross_check_verdict, outcome(verdict))
    if args.json:
        write_json(verdict, args.json)
    if args.plot:
        write_plot(verdict, args.plot)
    return verdict.exit_code


def start_values(pairs: list[str]) -> dict[str, float | str]:
    """``--start NAME=VALUE`` as the judge's typed start values: ``theta=80deg`` in radians.

    The pairs are split here, degrees turned into radians, and the names and values checked by
    the judge's own :func:`~pendulum_fmu.judge.experiment.check_start`, so a bad value is
    reported with the text the user typed.

    Raises
    ------
    UsageError
        A pair without ``=``, an unknown name, a value that is not a number or is out of range
        (naming ``start``).
    """
    from pendulum_fmu.errors import UsageError
    from pendulum_fmu.judge.experiment import check_start

    typed: dict[str, float | str] = {}
    for pair in pairs:
        name, sep, raw = (part.strip() for part in pair.partition("="))
        if not sep:
            raise UsageError("start", f"expected NAME=VALUE, got {pair!r}")
        typed[name] = raw
        if name == "theta" and raw.endswith("deg"):
            try:
                typed[name] = math.radians(float(raw[:-3]))
            except ValueError:
                raise UsageError("start", f"{name}={raw!r} is not a number") from None
    return check_start(typed)


def split_problem(pairs: list[str]) -> InitialValueProblem | None:
    """``--start NAME=VALUE`` of the split system (theta, omega, L, g) over the SSP's problem.

    Returns
    -------
    InitialValueProblem or None
        None when no pair is given (the judge then takes the SSP's problem as unstated).

    Raises
    ------
    UsageError
        A pair :func:`start_values` refuses, or a name the split system has no use for.
    """
    from pendulum_fmu.errors import UsageError
    from pendulum_fmu.split.pair import DEFAULT_PROBLEM

    fields = {"theta": "theta0", "omega": "omega0", "L": "L", "g": "g"}
    for pair in pairs:
        name, sep, _ = (part.strip() for part in pair.partition("="))
        if sep and name not in fields:
            raise UsageError("start", f"unknown name {name!r}: the split system takes theta, omega, L and g")
    values = start_values(pairs)
    return replace(DEFAULT_PROBLEM, **{fields[name]: float(value) for name, value in values.items()}) if pairs else None


def _split_sources(items: list[str]) -> list[Path]:
    """The files named, a folder standing for its CSV files (sorted); ValueError when none."""
    sources: list[Path] = []
    for item in items:
        path = Path(item)
        if path.is_dir():
            found = sorted(p for p in path.iterdir() if p.suffix.lower() in (".csv", ".parquet"))
            if not found:
                raise ValueError(f"{item}: a folder without CSV or Parquet files")
            sources += found
        else:
            sources.append(path)
    return sources


def _run_split(args: argparse.Namespace) -> int:
    """``judge --system split``: one run or several; print the three answers, write JSON and figure."""
    from pendulum_fmu.judge import ReadError
    from pendulum_fmu.split.judge import judge_runs, judge_split
    from pendulum_fmu.split.report import runs_dict, verdict_dict, write_json, write_plot

    for name in ("interface", "fmu", "cross_check_verdict"):
        if getattr(args, name):
            print(f"pendulum-fmu judge: --{name.replace('_', '-')} is for --system pendulum; the split system has "
                  "its SSP", file=sys.stderr)
            return 2
    problem = split_problem(args.start)
    try:
        sources = _split_sources(args.result)
        if len(sources) == 1 and args.order is None:
            verdict = judge_split(sources[0], problem=problem, master=args.master, instance=args.instance,
                                  step=args.step, max_error=args.max_error)
            print("\n".join(verdict.lines))
            verdicts, data, code = [verdict], verdict_dict(verdict), verdict.exit_code
        else:
            runs = judge_runs(sources, problem=problem, master=args.master, instance=args.instance,
                              step=args.step, max_error=args.max_error, order=args.order)
            print("\n".join(runs.lines))
            verdicts, data, code = runs.verdicts, runs_dict(runs), runs.exit_code
    except (ReadError, ValueError) as error:
        print(f"pendulum-fmu judge: {'unreadable: ' if isinstance(error, ReadError) else ''}{error}", file=sys.stderr)
        return 2
    if args.json:
        write_json(data, args.json)
    if args.plot:
        write_plot([v.source for v in verdicts], verdicts, args.plot)
    return code
