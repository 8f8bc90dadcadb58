"""The install-time build step: CMake builds Pendulum.fmu, and a wheel carries it.

All metadata is in pyproject.toml; this file only extends ``build_py``.

Why not scikit-build-core: the package is pure Python that ships one data file (the FMU, a
zip that CMake packs), not a CPython extension module, and the development loop is an
editable install plus ``cmake --build build`` (run by scripts/test.sh and by
``pendulum-fmu study`` anyway). scikit-build-core's editable mode would add a second,
import-hook-driven build of the same tree. So:

- a regular install (``pip install .``, a wheel) runs CMake and puts ``Pendulum.fmu`` into
  the package, where ``pendulum_fmu.fmu.locate.locate_fmu`` finds it first, and the C library
  ``pendulum_exact`` of ``pendulum_fmu.exact`` and the output loop ``pendulum_driver`` of
  ``FmuRunner`` into ``pendulum_fmu/lib/<platform>/``, and the FMI 3.0 FMU into
  ``pendulum_fmu/fmi3/Pendulum.fmu``;
- an editable install (``pip install -e .``) runs CMake into ``build/`` of the checkout,
  where ``locate_fmu`` finds it and rebuilds it whenever a source is newer;
- if CMake is missing or fails, the install goes on with a warning, and the package falls
  back at run time to ``find_fmu()``/``locate_fmu()``, which build or report a missing build.

A regular install or wheel builds the multi-platform FMU (linux64, win64, darwin64; zig
from the ``ziglang`` build requirement, docs/platforms.md) in ``build-wheel/``.

Environment: ``PENDULUM_FMU_SKIP_BUILD=1`` skips the build, ``PENDULUM_ZIG`` names the zig
to cross-build with (default: the ``ziglang`` build requirement's), ``PENDULUM_ZIG_CACHE``
the folder of its caches (default: ``zig-cache/`` in the build folder), ``PENDULUM_FMU_BUILD_DIR``
chooses the CMake build folder (default ``build/`` beside this file, ``build-wheel/`` for a
regular install or a wheel).
"""

from __future__ import annotations

import os
import platform
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent


def working_cmake() -> str | None:
    """The first cmake on PATH that runs here.

    pip's isolated build environment hides the ``cmake`` Python package from the ``cmake``
    script a virtual environment may put first on PATH; that script then fails, and a system
    cmake further down PATH is taken instead.
    """
    for folder in os.environ.get("PATH", "").split(os.pathsep):
        candidate = shutil.which("cmake", path=folder) if folder else None
        if candidate is None:
            continue
        probe = subprocess.run([candidate, "--version"], capture_output=True, text=True, check=False)
        if probe.returncode == 0:
            return candidate
    return None


def zig_path() -> str | None:
    """``$PENDULUM_ZIG``, else the zig of the ``ziglang`` package in this build environment
    (pyproject's requires). A zig at a fixed path keeps zig's cache of the C runtimes valid
    from one build to the next (pip's isolated environment is a new folder every time)."""
    if os.environ.get("PENDULUM_ZIG"):
        return os.environ["PENDULUM_ZIG"]
    try:
        import ziglang  # noqa: PLC0415 (a build requirement, absent in a plain checkout)
    except ImportError:
        return None
    return str(Path(ziglang.__file__).with_name("zig"))


def platform_options() -> list[str]:
    """CMake options for an FMU with linux64, win64 and darwin64 binaries (cross-built with
    zig, docs/platforms.md): what a py3-none-any wheel must carry."""
    zig = zig_path()
    if zig is None:
        print("warning: pendulum-fmu: no ziglang in the build environment: the FMU gets only the "
              "host's binary", file=sys.stderr)
        return []
    options = ["-DPENDULUM_PLATFORMS=ON", f"-DPENDULUM_ZIG={zig}", f"-DPENDULUM_PYTHON={sys.executable}"]
    if os.environ.get("PENDULUM_ZIG_CACHE"):
        options.append(f"-DPENDULUM_ZIG_CACHE={os.environ['PENDULUM_ZIG_CACHE']}")
    return options


def build_fmu(platforms: bool = False) -> Path | None:
    """Configure and build the FMUs and the ``pendulum_exact`` and ``pendulum_driver`` libraries; the build folder, or None
    (with a warning).

    ``platforms``: also the win64 and darwin64 binaries and exact libraries (a wheel); an
    editable install keeps the build folder's own setting (scripts/build-fmu.sh switches it on).
    """
    if os.environ.get("PENDULUM_FMU_SKIP_BUILD"):
        return None
    # A wheel's build gets its own folder: the zig it configures lives in pip's temporary
    # build environment, which must not end up in the cache of the development build/.
    default_dir = ROOT / ("build-wheel" if platforms else "build")
    build_dir = Path(os.environ.get("PENDULUM_FMU_BUILD_DIR") or default_dir)
    cmake = working_cmake()
    if cmake is None or not (ROOT / "CMakeLists.txt").is_file():
        print("warning: pendulum-fmu: no cmake (or no CMakeLists.txt): Pendulum.fmu not built; "
              "it is looked for at run time", file=sys.stderr)
        return None
    options = platform_options() if platforms else []
    # fmu_reference and fmu3_reference: the FMUs as `cmake --build` leaves them, with the
    # FMI-LS-REF reference result, its experiment and manifest under extra/ (the packing
    # targets fmu and fmu3 alone leave them out)
    targets = ["fmu", "fmu3", "fmu_reference", "fmu3_reference", "split_fmi2", "split_fmi3", "pendulum_exact",
               "pendulum_driver"] + (["pendulum_exact_platforms"] if options else [])
    commands = [[cmake, "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release", *options],
                [cmake, "--build", str(build_dir), "--target", *targets, "--parallel", str(os.cpu_count() or 1)]]
    what = "every platform with zig" if options else "the host's binaries"
    say(f"building the FMUs into {build_dir} ({what}; minutes the first time, seconds after)")
    for command in commands:
        returncode, tail = run_saying_stages(command)
        if returncode != 0:
            print(f"warning: pendulum-fmu: {' '.join(command)} failed; Pendulum.fmu is looked for at run time\n"
                  f"{tail}", file=sys.stderr)
            return None
    return build_dir if (build_dir / "Pendulum.fmu").is_file() else None


STAGE = re.compile(r"^\[\s*\d+(?:%|/\d+)\] (?!Building C object|Linking C )")
"""A line of CMake's build output worth a line of progress: a step with a comment (each zig
cross-build per platform, packing an FMU, the reference result) or a target done; not each
object file."""


def say(line: str) -> None:
    """One line of progress on stderr (``pip install -v`` shows it)."""
    print(f"pendulum-fmu build: {line}", file=sys.stderr, flush=True)


def run_saying_stages(command: list[str]) -> tuple[int, str]:
    """Run ``command``, saying each stage of its output as it comes; its exit code and last 4000 characters."""
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    tail = ""
    assert process.stdout is not None
    for line in process.stdout:
        tail = (tail + line)[-4000:]
        if STAGE.match(line):
            say(line.rstrip())
    return process.wait(), tail


def host_library_folder() -> str:
    """The platform folder of the host's ``pendulum_exact`` library (pendulum_fmu.fmu.library's naming)."""
    machine = platform.machine().lower()
    if sys.platform.startswith("win"):
        return "win64"
    if sys.platform == "darwin":
        return "darwin64"
    return "linux64" if machine in ("x86_64", "amd64") else f"linux-{machine}"


class BuildPyWithFmu(build_py):
    """``build_py`` that also builds the FMU and, for a wheel, copies it into the package."""

    def run(self) -> None:
        super().run()
        build_dir = build_fmu(platforms=not self.editable_mode)
        if build_dir is None or self.editable_mode:
            return
        package = Path(self.build_lib) / "pendulum_fmu"
        package.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(build_dir / "Pendulum.fmu", package / "Pendulum.fmu")
        if (build_dir / "fmi3" / "Pendulum.fmu").is_file():  # pendulum_fmu.fmu.build.PACKAGED_FMU3
            (package / "fmi3").mkdir(exist_ok=True)
            shutil.copyfile(build_dir / "fmi3" / "Pendulum.fmu", package / "fmi3" / "Pendulum.fmu")
        # The split pendulum beside them (pendulum_fmu.split.locate: the package's own folder)
        for version in ("", "fmi3"):
            for name in ("PendulumBody.fmu", "PendulumGravity.fmu", "PendulumSplit.ssp"):
                if (build_dir / version / name).is_file():
                    (package / version).mkdir(exist_ok=True)
                    shutil.copyfile(build_dir / version / name, package / version / name)
        # The C libraries: pendulum_exact (pendulum_fmu.exact) and pendulum_driver (FmuRunner's
        # output loop): the host's, and any cross-built ones left in build_dir/exact_lib/<platform>/
        # (platform names as the FMU's binaries/).
        libraries = []
        for stem in ("pendulum_exact", "pendulum_driver"):
            libraries += [(host_library_folder(), path) for path in build_dir.glob(f"*{stem}.*")
                          if path.suffix in (".so", ".dll", ".dylib")]
            libraries += [(path.parent.name, path) for path in build_dir.glob(f"exact_lib/*/*{stem}.*")]
        for folder, path in libraries:
            target = package / "lib" / folder / path.name
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(path, target)


setup(cmdclass={"build_py": BuildPyWithFmu})
