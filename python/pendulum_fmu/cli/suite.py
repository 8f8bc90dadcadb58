"""``pendulum-fmu suite``: the hard cases, run by an importer or engine, judged, reported for CI."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from pendulum_fmu.cli.arguments import output_folder

NAME = "suite"
HELP = "run the hard cases in an importer or engine, judge them, write JUnit XML, HTML and JSON"
DESCRIPTION = """\
The suite: experiments of Pendulum.fmu (FMI 2.0 and 3.0, Co-Simulation and Model Exchange),
each stressing one thing importers get wrong, and the split pendulum's SSP at a sweep of macro
steps. 'suite list' prints them; 'suite run' runs them through a built-in engine (--engine),
an importer's command line (--command TEMPLATE) or takes results made elsewhere (--results DIR),
judges each against the exact solution and writes OUT/junit.xml, OUT/report.html,
OUT/summary.json, and OUT/cases/<case>/ with the experiment, the result and the cross-check
verdict file (passed, failed or rejected). Exit status 0 only when every case passes.
'suite table' runs every built-in engine against every case and writes the compatibility table;
'suite export' writes the Pendulum cases in the FMI cross-check layout.
"""
EPILOG = """\
examples:
  pendulum-fmu suite list
  pendulum-fmu suite run --engine fmpy --out out/suite
  pendulum-fmu suite run --engine libcosim --cases 'cs2-*' --out out/libcosim
  pendulum-fmu suite run --out out/mine --cases 'cs*' \\
      --command 'mytool {fmu} --from {start} --to {stop} --dt {interval} --rtol {tolerance} -o {output} {start_values}'
  pendulum-fmu suite run --results results/ --out out/judged
"""
RUN_DESCRIPTION = """\
Run the cases (default: every case the adapter runs), judge each result, write
OUT/junit.xml, OUT/report.html and OUT/summary.json. Progress goes to stderr, one line a case.
A run that crashes, passes its --timeout or writes nothing is an error with the tail of its
output; the other cases go on. Exit status: 0 every case passed, 1 any failed or errored,
2 a bad argument.

A command TEMPLATE is run by bash once per case with these placeholders, each replaced by
a shell-quoted word: {fmu} the FMU, {fmi_version} 2.0 or 3.0, {interface} cs or me, {start},
{stop}, {interval} (output interval, s), {tolerance} (relative), {output} (the CSV to write:
a header row, then time and the outputs theta, omega, theta_exact, omega_exact, names as the
FMU has them), {start_values} (name=value words: theta, omega, L, g), {experiment} (a JSON
file holding all of them) and {case}; also {interface_type} (CoSimulation or ModelExchange)
and {start_value_pairs} (name value name value ..., as fmpy's --start-values takes them).

--results DIR holds CASE.csv for each case (or one CSV in DIR/CASE/), from a run elsewhere.
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add ``suite list``, ``suite run`` and ``suite table``."""
    actions = parser.add_subparsers(dest="suite_action", metavar="ACTION", title="actions", required=True)
    listing = actions.add_parser("list", help="print the cases, one a line: name, FMI version, interface, what it "
                                              "catches", description="Print the cases, one a line.")
    listing.add_argument("--cases", metavar="PATTERN", help="only the cases matching these comma-separated shell "
                                                            "patterns, e.g. 'cs2-*,me*'")
    listing.set_defaults(subparser=listing)
    run = actions.add_parser("run", help="run, judge and report the cases", description=RUN_DESCRIPTION,
                             formatter_class=argparse.RawDescriptionHelpFormatter)
    how = run.add_mutually_exclusive_group(required=True)
    how.add_argument("--engine", metavar="NAME", help="a built-in engine: fmpy, fmpy-cli, libcosim, ecos, "
                                                      "fmucontainer, fmpy-container")
    how.add_argument("--command", metavar="TEMPLATE", help="an importer's command line with placeholders "
                                                           "(see above)")
    how.add_argument("--results", type=Path, metavar="DIR", help="a folder of results made elsewhere")
    run.add_argument("--out", type=output_folder, required=True, metavar="DIR", help="where the reports go")
    run.add_argument("--cases", metavar="PATTERN", help="comma-separated shell patterns of case names "
                                                        "(default: every case the adapter runs)")
    run.add_argument("--timeout", type=float, default=120.0, metavar="S",
                     help="seconds a case's run may take before it is killed (default 120)")
    run.add_argument("--jobs", type=int, default=2, metavar="N",
                     help="engine runs side by side (default 2; the judging is one at a time)")
    run.add_argument("--master", metavar="NAME", help="for the split cases of --results: the reference master "
                                                      "the engine implements, e.g. jacobi-zoh")
    run.add_argument("--fmu", type=Path, action="append", default=None, metavar="PATH",
                     help="a Pendulum.fmu to run instead of the package's (repeat for FMI 2.0 and 3.0)")
    run.set_defaults(subparser=run)
    table = actions.add_parser("table", help="every built-in engine against every case: the compatibility table "
                                             "in Markdown", description="Run every built-in engine against every "
                                             "case and write the compatibility table (Markdown) with the engines' "
                                             "versions, the machine and each cell's verdict or error.")
    table.add_argument("--out", type=Path, required=True, metavar="FILE", help="the Markdown file to write")
    table.add_argument("--work", type=output_folder, default=None, metavar="DIR",
                       help="where the runs go (default: a temporary folder)")
    table.add_argument("--engines", metavar="NAMES", help="comma-separated engines (default: all)")
    table.add_argument("--timeout", type=float, default=120.0, metavar="S", help="per case (default 120)")
    table.set_defaults(subparser=table)
    export = actions.add_parser("export", help="the Pendulum cases in the FMI cross-check layout "
                                               "(fmus/<version>/<cs|me>/<platform>/PendulumFMU/<version>/<case>/)",
                                description="Write OUT/fmus/... with one model folder per case and platform: "
                                            "CASE.fmu, CASE_ref.opt, CASE_ref.csv and ReadMe.txt (the start values "
                                            "to set). Prints each folder written.")
    export.add_argument("out", type=output_folder, metavar="OUT", help="the folder to write fmus/ into")
    export.add_argument("--cases", metavar="PATTERN", help="comma-separated shell patterns of case names")
    export.add_argument("--fmu", type=Path, action="append", default=None, metavar="PATH",
                        help="a Pendulum.fmu to export instead of the package's (repeat for FMI 2.0 and 3.0)")
    export.set_defaults(subparser=export)


def _progress(k: int, n: int, result: object) -> None:
    from pendulum_fmu.suite.runner import CaseResult

    assert isinstance(result, CaseResult)
    print(f"[{k}/{n}] {result.case.name}: {result.status.upper()} ({result.run_seconds + result.judge_seconds:.1f} s) "
          f"{result.line}", file=sys.stderr, flush=True)


def _fmus(paths: list[Path] | None) -> dict[int, Path]:
    from pendulum_fmu.errors import UsageError
    from pendulum_fmu.fmu.cross_check import describe

    chosen: dict[int, Path] = {}
    for path in paths or []:
        try:
            chosen[int(describe(path).fmi_version[0])] = path
        except (OSError, ValueError, KeyError) as error:
            raise UsageError("fmu", f"{path}: {error}") from None
    return chosen


def _export(args: argparse.Namespace) -> int:
    from pendulum_fmu.errors import UsageError
    from pendulum_fmu.fmu.locate import locate_fmu
    from pendulum_fmu.suite import cases
    from pendulum_fmu.suite.cross_check_layout import export_case
    from pendulum_fmu.suite.session import suite_name

    chosen = cases.select(args.cases, ("pendulum",))
    fmus = _fmus(args.fmu)
    for case in chosen:
        fmu = fmus.get(case.fmi_major) or locate_fmu(None, fmi_version=case.fmi_major)
        try:
            for folder in export_case(case, fmu, args.out, suite_name()):
                print(folder)
        except ValueError as error:
            raise UsageError("fmu", str(error)) from None
    return 0


def run(args: argparse.Namespace) -> int:
    """List, run, tabulate or export."""
    from pendulum_fmu.errors import UsageError
    from pendulum_fmu.suite import adapters, cases

    if args.suite_action == "list":
        for case in cases.select(args.cases):
            print(case.describe())
        return 0
    if args.suite_action == "export":
        return _export(args)
    if args.suite_action == "table":
        from pendulum_fmu.suite.compatibility import write_table

        engines = tuple(e.strip() for e in args.engines.split(",")) if args.engines else adapters.ENGINES
        for name in engines:
            if name not in adapters.ENGINES:
                raise UsageError("engines", f"no engine {name!r} (one of {', '.join(adapters.ENGINES)})")
        write_table(args.out, engines, args.work, args.timeout, lambda line: print(line, file=sys.stderr, flush=True))
        print(args.out)
        return 0
    if not args.timeout > 0:
        raise UsageError("timeout", f"must be > 0, got {args.timeout:g}")
    if args.jobs < 1:
        raise UsageError("jobs", f"must be >= 1, got {args.jobs}")
    if args.engine is not None:
        adapter = adapters.engine(args.engine)
    elif args.command is not None:
        adapter = adapters.command(args.command)
    else:
        if not args.results.is_dir():
            raise UsageError("results", f"no such folder: {str(args.results)!r}")
        adapter = adapters.results(args.results, args.master)
    if args.master is not None:
        from pendulum_fmu.split.masters import master_named

        try:
            master_named(args.master)
        except ValueError as error:
            raise UsageError("master", str(error)) from None
    chosen = cases.select(args.cases, adapter.kinds)
    from pendulum_fmu.suite.session import run_and_report, suite_name

    print(f"{suite_name()}: {len(chosen)} cases with {adapter.version()}", file=sys.stderr, flush=True)
    results = run_and_report(adapter, chosen, args.out, args.timeout, _progress, _fmus(args.fmu), args.jobs)
    passed = sum(r.status == "passed" for r in results)
    print(f"{passed} of {len(results)} cases passed; {args.out / 'junit.xml'}, {args.out / 'report.html'}, "
          f"{args.out / 'summary.json'}")
    return 0 if passed == len(results) else 1
