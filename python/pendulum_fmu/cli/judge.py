"""``pendulum-fmu judge``: is an importer's result of Pendulum.fmu right, and if not, what is wrong."""

from __future__ import annotations

import argparse
import sys

from pendulum_fmu.cli.arguments import fmu_file, output_file, output_folder, positive

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
The experiment (start time, tolerance, step, interface) is read from the cross-check
<Model>_ref.opt when the result sits in a cross-check folder (beside it, or the exporter's
fmus/ folder for an importer's results/ folder), else from the FMU's FMI-LS-REF experiment
(extra/org.fmi-standard.fmi-ls-ref/Pendulum.exp, the default experiment); --start, --step
and --interface say otherwise. --cross-check-verdict DIR writes DIR/passed, DIR/failed or
DIR/rejected (unreadable result), the file the cross-check rules ask an importer to publish.
One line per check, then the verdict. Exit status 0 pass, 1 fail, 2 unreadable input.
"""
EPILOG = """\
examples:
  pendulum-fmu judge fmpy_cs.csv
  pendulum-fmu judge result.csv --interface ME --start tolerance=1e-6
  pendulum-fmu judge ecos.csv --start theta=80deg --start L=2 --json verdict.json --plot errors.png
  pendulum-fmu judge container.csv --instance pend2
  pendulum-fmu judge coupled.csv --system split --master gauss-seidel-zoh
  pendulum-fmu judge results/2.0/me/linux64/MyTool/1.0/PendulumFMU/0.1.0/Pendulum/Pendulum_out.csv \
      --cross-check-verdict results/2.0/me/linux64/MyTool/1.0/PendulumFMU/0.1.0/Pendulum
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``judge``."""
    parser.add_argument("result", metavar="RESULT", help="the result file: CSV or Parquet")
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
                             "PendulumGravity (PendulumSplit.ssp), judged against the reference masters "
                             "(docs/masters.md)")
    parser.add_argument("--master", metavar="NAME",
                        help="with --system split: the reference master the run implements, e.g. gauss-seidel-zoh "
                             "(jacobi|gauss-seidel)-(zoh|extrapolation|interpolation); the bound is 4 times its error")
    parser.add_argument("--cross-check-verdict", type=output_folder, metavar="DIR",
                        help="also write DIR/passed, DIR/failed or DIR/rejected (empty, the cross-check "
                             "rules' verdict file; the other two are removed)")


def run(args: argparse.Namespace) -> int:
    """Run ``judge`` with parsed arguments: print the checks and the verdict, return 0/1/2."""
    if args.system == "split" or args.master:
        from pendulum_fmu.judge import ReadError
        from pendulum_fmu.split.judge import judge_split

        try:
            split = judge_split(args.result, start=args.start, master=args.master, instance=args.instance)
        except (ReadError, ValueError) as error:
            print(f"pendulum-fmu judge: {'unreadable: ' if isinstance(error, ReadError) else ''}{error}",
                  file=sys.stderr)
            return 2
        print("\n".join(split.lines))
        return split.exit_code
    from pendulum_fmu.judge import ReadError
    from pendulum_fmu.judge.report import lines, write_json, write_plot
    from pendulum_fmu.judge.standard_files import judge_with_experiment, outcome, write_verdict_file

    try:
        verdict, settings = judge_with_experiment(args.result, start=args.start, interface=args.interface,
                                                  instance=args.instance, step=args.step, fmu=args.fmu)
    except ReadError as error:
        print(f"pendulum-fmu judge: unreadable: {error}", file=sys.stderr)
        if args.cross_check_verdict:
            write_verdict_file(args.cross_check_verdict, outcome(None))
        return 2
    if settings is not None:
        print(f"{'experiment file':<16s}{'INFO':<6s}{settings.describe()}")
    print("\n".join(lines(verdict)))
    if args.cross_check_verdict:
        write_verdict_file(args.cross_check_verdict, outcome(verdict))
    if args.json:
        write_json(verdict, args.json)
    if args.plot:
        write_plot(verdict, args.result, args.plot)
    return verdict.exit_code
