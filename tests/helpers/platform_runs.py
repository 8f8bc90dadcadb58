"""Run the FMU's other-platform binaries here: win64 under wine, the arm64 code under qemu.

The C programs (``tests/c/test_fmi_api.c``, the FMI harness, and ``tests/c/fmu_results.c``,
the seed's runs printed bit for bit) are compiled for each target with that target's Debian
cross compiler and linked against the binary taken out of the FMU (or, for aarch64-linux,
against the library built from the same sources and flags as the arm64 half of the dylib,
``build/cross/aarch64-linux/``). Used by tests/fmu/test_platforms.py; run as a script it prints
the agreement table docs/platforms.md quotes::

    .venv/bin/python tests/helpers/platform_runs.py [build/Pendulum.fmu]
"""

from __future__ import annotations

import os
import re
import shutil
import struct
import subprocess
import sys
import zipfile
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
HARNESS = ROOT / "tests/c/test_fmi_api.c"
FMI3_HARNESS = ROOT / "tests/c/fmi3/test_fmi3_api.c"
RESULTS = ROOT / "tests/c/fmu_results.c"
FMA_CHECK = ROOT / "tests/c/fma_check.c"
VARIABLES = ("theta", "omega", "theta_exact", "omega_exact")
INSTALL = "sudo bash scripts/install-system-packages.sh"
C_FLAGS = ["-std=c11", "-O2", "-ffp-contract=off", "-Wall", "-Wextra", "-Wpedantic"]
"""For the test programs; the library under test keeps the flags it was built with."""

Results = dict[tuple[int, int], tuple[float, ...]]
"""(amplitude in deg, step) -> (theta, omega, theta_exact, omega_exact)."""


@dataclass(frozen=True)
class Target:
    """A platform whose programs are built here and run through an emulator (or natively)."""

    name: str
    compiler: tuple[str, ...]
    runner: tuple[str, ...]
    packages: tuple[str, str]
    """Where the compiler and the runner come from: (compiler's package, runner's package)."""
    env: tuple[tuple[str, str], ...] = ()
    """Extra environment of the compiler."""

    def missing(self) -> str | None:
        """Why this target cannot run here, naming only the tools that are missing and their
        packages (with the install command), or None."""
        tools = [(self.compiler[0], self.packages[0])] + ([(self.runner[0], self.packages[1])] if self.runner else [])
        absent = [(tool, package) for tool, package in tools if shutil.which(tool) is None]
        if not absent:
            return None
        sources = ["python/requirements.lock" if package == "ziglang" else INSTALL for _, package in absent]
        where = "; ".join(dict.fromkeys(sources))
        return (f"{' and '.join(tool for tool, _ in absent)} not found: install "
                f"{' and '.join(package for _, package in absent)} ({where})")

    @property
    def windows(self) -> bool:
        return self.runner[:1] == ("wine",)


WIN64 = Target("win64", ("x86_64-w64-mingw32-gcc",), ("wine",), ("mingw-w64", "wine64"))
AARCH64 = Target("aarch64-linux", ("aarch64-linux-gnu-gcc",), ("qemu-aarch64", "-L", "/usr/aarch64-linux-gnu"),
                 ("gcc-aarch64-linux-gnu libc6-dev-arm64-cross", "qemu-user"))
LINUX64 = Target("linux64", ("gcc",), (), ("gcc", ""))


def zig_win64(zig_cache: Path) -> Target:
    """Programs built like the FMU's win64 binary (zig, UCRT), run under wine. ``zig_cache``:
    the build's zig cache (build/zig-cache), where zig's Windows C runtime is compiled already."""
    try:
        import ziglang
        zig = str(Path(ziglang.__file__).with_name("zig"))
    except ImportError:
        zig = "zig"
    cache = str(zig_cache)
    return Target("win64 (zig)", (zig, "cc", "-target", "x86_64-windows-gnu", "-s"), ("wine",),
                  ("ziglang", "wine64"),
                  (("ZIG_GLOBAL_CACHE_DIR", cache), ("ZIG_LOCAL_CACHE_DIR", cache)))


def extract_fmu(fmu: Path, folder: Path) -> Path:
    """Unpack ``fmu`` into ``folder`` and return it."""
    with zipfile.ZipFile(fmu) as archive:
        archive.extractall(folder)
    return folder


def build_program(target: Target, source: Path, library: Path | None, sources_dir: Path | None,
                  folder: Path, extra_includes: tuple[Path, ...] = ()) -> Path:
    """Compile ``source`` for ``target`` into ``folder``, linked against a copy of ``library``.

    The program lands beside the library, so the loader finds it there (the DLL search order
    on Windows, ``$ORIGIN`` as the run path on Linux). ``extra_includes``: more header
    folders (the FMI 3.0 standard's headers, which the FMU does not ship).
    """
    folder.mkdir(parents=True, exist_ok=True)
    inputs = [str(source)]
    if library is not None:
        if library.parent.resolve() != folder.resolve():
            shutil.copyfile(library, folder / library.name)
        inputs.append(str(folder / library.name))
    includes = ([f"-I{sources_dir}"] if sources_dir else []) + [f"-I{d}" for d in extra_includes]
    program = folder / (source.stem + (".exe" if target.windows else ""))
    rpath = [] if target.windows else ["-Wl,-rpath,$ORIGIN", "-lm"]
    done = subprocess.run([*target.compiler, *C_FLAGS, *includes, *inputs, *rpath, "-o", str(program)],
                          capture_output=True, text=True, env=dict(os.environ, **dict(target.env)), check=False)
    if done.returncode != 0:
        raise RuntimeError(f"compiling {source.name} for {target.name} failed:\n{done.stderr[-3000:]}")
    return program


def run_program(target: Target, program: Path, *args: str) -> subprocess.CompletedProcess[str]:
    """Run ``program`` (through wine or qemu for foreign targets); output as text."""
    env = dict(os.environ, WINEDEBUG="-all")
    return subprocess.run([*target.runner, str(program), *args], capture_output=True, text=True, env=env,
                          timeout=300, check=False)


def parse_results(text: str) -> Results:
    """Read the lines of ``fmu_results``: amplitude, step, then four IEEE 754 bit patterns."""
    results: Results = {}
    for line in text.splitlines():
        fields = line.split()
        if len(fields) != 2 + len(VARIABLES):
            raise ValueError(f"not a fmu_results line: {line!r}")
        values = tuple(struct.unpack(">d", bytes.fromhex(h))[0] for h in fields[2:])
        results[(int(fields[0]), int(fields[1]))] = values
    return results


def results_of(target: Target, library: Path, sources_dir: Path, folder: Path) -> Results:
    """Build ``fmu_results`` for ``target`` against ``library`` in ``folder``, run it, parse it."""
    done = run_program(target, build_program(target, RESULTS, library, sources_dir, folder))
    if done.returncode != 0:
        raise RuntimeError(f"fmu_results on {target.name} failed ({done.returncode}):\n{done.stderr[-2000:]}")
    return parse_results(done.stdout)


def fma_errors(target: Target, folder: Path, cases: int = 20000) -> int:
    """How many of ``cases`` results of ``target``'s fma() differ from the correctly rounded
    a*b + c (exact in rationals, rounded to nearest even by ``float(Fraction)``)."""
    done = run_program(target, build_program(target, FMA_CHECK, None, None, folder), str(cases))
    if done.returncode != 0:
        raise RuntimeError(f"fma_check on {target.name} failed ({done.returncode}):\n{done.stderr[-2000:]}")
    wrong = 0
    lines = done.stdout.splitlines()
    if len(lines) != cases:
        raise RuntimeError(f"fma_check on {target.name}: {len(lines)} lines for {cases} cases")
    for line in lines:
        a, b, c, result = (struct.unpack(">d", bytes.fromhex(h))[0] for h in line.split())
        wrong += result != float(Fraction(a) * Fraction(b) + Fraction(c))
    return wrong


def max_differences(a: Results, b: Results) -> dict[str, float]:
    """Largest absolute difference per variable over all runs and steps (both on the same grid)."""
    if a.keys() != b.keys():
        raise ValueError("the two result sets do not cover the same runs and steps")
    return {name: max(abs(a[key][i] - b[key][i]) for key in a) for i, name in enumerate(VARIABLES)}


def _table(fmu: Path, work: Path) -> list[tuple[str, dict[str, float] | str]]:
    """Every comparison with the linux64 binary of ``fmu``: (what, differences or why not run)."""
    unpacked = extract_fmu(fmu, work / "fmu")
    sources = unpacked / "sources"
    reference = results_of(LINUX64, unpacked / "binaries/linux64/Pendulum.so", sources, work / "linux64")
    cross = fmu.parent / "cross"
    rows: list[tuple[str, dict[str, float] | str]] = []

    def compare(label: str, target: Target, library: Path) -> None:
        why_not = target.missing() or (None if library.is_file() else f"{library} not built")
        if why_not:
            rows.append((label, why_not))
            return
        folder = work / re.sub(r"\W+", "-", label)
        rows.append((label, max_differences(reference, results_of(target, library, sources, folder))))

    compare("host-gcc build/Pendulum.so (native)", LINUX64, fmu.parent / "Pendulum.so")
    compare("win64 Pendulum.dll from the FMU (wine)", WIN64, unpacked / "binaries/win64/Pendulum.dll")
    compare("aarch64-linux, arm64 flags (qemu)", AARCH64, cross / "aarch64-linux/Pendulum.so")
    compare("aarch64-linux -ffp-contract=fast (qemu)", AARCH64, cross / "aarch64-linux-contract/Pendulum.so")
    if "fma" in Path("/proc/cpuinfo").read_text():
        compare("x86_64-v3 -ffp-contract=fast (native)", LINUX64, cross / "x86_64-v3-contract/Pendulum.so")
    return rows


def _fma_rows(fmu: Path, work: Path) -> list[str]:
    """fma() of the two Windows toolchains (run under wine) and of the host."""
    rows = []
    for label, target in (("zig (the FMU's win64 toolchain, UCRT)", zig_win64(fmu.parent / "zig-cache")),
                          ("mingw-w64 gcc (msvcrt)", WIN64), ("host gcc and glibc (native)", LINUX64)):
        why_not = target.missing()
        wrong = why_not or f"{fma_errors(target, work / label.split()[0])} of 20000 not correctly rounded"
        rows.append(f"fma() of {label}: {wrong}")
    return rows


def main(argv: list[str]) -> int:
    """Print the agreement table for the FMU ``argv[0]`` (default build/Pendulum.fmu)."""
    import tempfile

    fmu = Path(argv[0]) if argv else ROOT / "build/Pendulum.fmu"
    if not fmu.is_file():
        print(f"platform_runs.py: no FMU at {fmu}: run bash scripts/build-fmu.sh", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as work:
        rows = _table(fmu, Path(work))
        fma_rows = _fma_rows(fmu, Path(work))
    print(f"max |difference| from the linux64 binary of {fmu}, 75/80/85/90 deg, 10 periods, default solver")
    print(f"{'binary (how run)':42s}" + "".join(f"{name:>13s}" for name in VARIABLES))
    for label, row in rows:
        cells = "".join(f"{row[name]:13.2e}" for name in VARIABLES) if isinstance(row, dict) else f"  skipped: {row}"
        print(f"{label:42s}{cells}")
    print("\n".join(fma_rows))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
