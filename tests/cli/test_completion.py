"""``pendulum-fmu completion bash``: a script from the parser's tree that bash really completes with."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from pendulum_fmu.cli.completion import bash_script
from pendulum_fmu.cli.main import build_parser, main

COMPLETE = """\
source "$1"; shift
COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1))
_pendulum_fmu
printf '%s\\n' "${COMPREPLY[@]}"
"""
"""Source the script, complete the words given (the last is the one being typed), print the candidates."""


@pytest.fixture(scope="module")
def script(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The script, written as the command prints it."""
    path = tmp_path_factory.mktemp("completion") / "pendulum-fmu.bash"
    path.write_text(bash_script(build_parser()))
    return path


def complete(script: Path, *words: str) -> list[str]:
    """The candidates bash offers for the last of ``words``."""
    bash = shutil.which("bash")
    if bash is None:
        pytest.skip("bash not found: apt-get install bash")
    done = subprocess.run([bash, "-c", COMPLETE, "complete", str(script), "pendulum-fmu", *words],
                          capture_output=True, text=True, timeout=30, check=False)
    assert done.returncode == 0 and done.stderr == "", done.stderr
    return done.stdout.split()


def test_the_command_prints_the_script(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["completion", "bash"]) == 0
    out = capsys.readouterr().out
    assert out == bash_script(build_parser())
    assert out.rstrip().endswith("complete -o filenames -F _pendulum_fmu pendulum-fmu")


@pytest.mark.parametrize(("words", "expected"), [
    (("si",), ["simulate"]),
    (("",), ["simulate", "compare", "study", "animate", "sweep", "bench", "judge", "cross-check", "suite",
             "completion"]),
    (("bench", "e"), ["exact"]),
    (("bench", "exact", "--am"), ["--amplitudes"]),
    (("simulate", "--solver", "r"), ["rk4", "rkn"]),
    (("simulate", "-a", "80", "--inter"), ["--interface"]),
    (("completion", ""), ["bash"]),
])
def test_bash_completes_subcommands_options_and_choices(script: Path, words: tuple[str, ...],
                                                        expected: list[str]) -> None:
    assert complete(script, *words) == expected


def test_an_option_the_subcommand_lacks_is_not_offered(script: Path) -> None:
    assert complete(script, "study", "--sol") == []
    assert "--amplitudes" not in complete(script, "simulate", "--")
