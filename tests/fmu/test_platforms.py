"""The FMU's three platforms: linux64 (glibc floor), win64 (run under wine), darwin64 (universal,
inspected with the llvm tools), and the arm64 code run under qemu as aarch64-linux.

Needs the FMU of ``bash scripts/build-fmu.sh`` (``PENDULUM_PLATFORMS=ON``). A tool that is
missing makes its tests SKIPPED with the install command; a missing binary is a failure.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
from fmpy import supported_platforms

from pendulum_fmu.fmu.build import REPO_ROOT
from platform_runs import (
    AARCH64,
    FMI3_HARNESS,
    HARNESS,
    INSTALL,
    LINUX64,
    WIN64,
    Target,
    build_program,
    extract_fmu,
    fma_errors,
    max_differences,
    results_of,
    run_program,
    zig_win64,
)

sys.path.insert(0, str(REPO_ROOT / "cmake"))
from fat_macho import fat_binary, thin_slice

pytestmark = [pytest.mark.slow, pytest.mark.engines]

AGREEMENT = 1e-13
"""Largest allowed |difference| from the linux64 binary, per value: agreement to 1e-13 across platforms."""
GLIBC_FLOOR = (2, 17)
MACOS_FLOOR = {"x86_64": "10.13", "arm64": "11.0"}
MACHO_LINKER_SYMBOLS = {"__mh_dylib_header", "___dso_handle"}
"""The image-header labels zig's Mach-O linker exports beside ours (lld and Apple's ld64 keep
them private); no function, no code of ours. Any other extra name fails."""
BINARIES = {"linux64": "Pendulum.so", "win64": "Pendulum.dll", "darwin64": "Pendulum.dylib"}


def fmi2_functions() -> set[str]:
    """The functions fmi2_api.h declares exported: the independent list to check against."""
    header = (REPO_ROOT / "fmu_src/fmi2/fmi2_api.h").read_text()
    names = set(re.findall(r"FMI2_EXPORT[^;(]*?\b(fmi2\w+)\s*\(", header))
    assert len(names) == 44, sorted(names)
    return names


def tool(*names: str, package: str) -> str:
    """Path of the first of ``names`` on PATH (also as ``name-<version>``), else skip the test."""
    for name in names:
        found = shutil.which(name) or next(iter(sorted(Path("/usr/bin").glob(f"{name}-[0-9]*"))), None)
        if found:
            return str(found)
    pytest.skip(f"{names[0]} not found: install {package} ({INSTALL})")


def output(*command: str) -> str:
    """stdout of ``command`` (which must succeed)."""
    return subprocess.run(command, capture_output=True, text=True, check=True).stdout


def require(target: Target) -> None:
    """Skip unless ``target``'s compiler and emulator are installed."""
    why_not = target.missing()
    if why_not:
        pytest.skip(why_not)


@pytest.fixture(scope="module")
def unpacked(fmu_path: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The FMU, unpacked once for this module."""
    return extract_fmu(fmu_path, tmp_path_factory.mktemp("platforms"))


@pytest.fixture(scope="module")
def linux64_results(unpacked: Path, tmp_path_factory: pytest.TempPathFactory) -> dict:
    """The seed's runs through the FMU's linux64 binary, run natively: the reference."""
    return results_of(LINUX64, unpacked / "binaries/linux64/Pendulum.so", unpacked / "sources",
                      tmp_path_factory.mktemp("linux64"))


def binary(unpacked: Path, platform: str) -> Path:
    path = unpacked / "binaries" / platform / BINARIES[platform]
    assert path.is_file(), f"no {path.name} for {platform}: build the FMU with bash scripts/build-fmu.sh"
    return path


def cross_library(fmu_path: Path, variant: str) -> Path:
    """A test-only library of the platform build (build/cross/<variant>/Pendulum.so)."""
    path = fmu_path.parent / "cross" / variant / "Pendulum.so"
    assert path.is_file(), f"{path} is missing: build with bash scripts/build-fmu.sh"
    return path


def test_fmu_carries_linux64_win64_darwin64_and_sources(fmu_path: Path) -> None:
    names = set(zipfile.ZipFile(fmu_path).namelist())
    assert {f"binaries/{p}/{b}" for p, b in BINARIES.items()} <= names
    assert not [n for n in names if n.endswith((".pdb", ".lib"))], "debug or import files do not belong in an FMU"
    assert set(supported_platforms(str(fmu_path))) == {"linux64", "win64", "darwin64", "c-code"}


# --- linux64 ---------------------------------------------------------------------------------

def glibc_versions_needed(library: Path) -> set[tuple[int, ...]]:
    """The GLIBC_x.y versions the dynamic loader must provide (.gnu.version_r, via readelf)."""
    text = output(tool("readelf", package="binutils"), "--version-info", "-W", str(library))
    needs = text.split(".gnu.version_r", 1)[-1]
    return {tuple(int(p) for p in v.split(".")) for v in re.findall(r"Name: GLIBC_([0-9.]+)", needs)}


def test_linux64_binary_loads_on_glibc_2_17(unpacked: Path) -> None:
    versions = glibc_versions_needed(binary(unpacked, "linux64"))
    assert versions, "no GLIBC_ version found: not a glibc-linked library?"
    print(f"linux64 highest GLIBC_ version needed: {'.'.join(map(str, max(versions)))}")
    assert max(versions) <= GLIBC_FLOOR


def test_host_build_needs_a_newer_glibc_which_is_why_the_fmu_uses_zig(fmu_path: Path) -> None:
    """The check above can fail: the host gcc build of the same sources needs more."""
    host = fmu_path.parent / "Pendulum.so"
    if not host.is_file():
        pytest.skip(f"{host}: no host build beside the FMU")
    assert max(glibc_versions_needed(host)) > GLIBC_FLOOR


def test_linux64_exports_only_fmi2(unpacked: Path) -> None:
    nm = output(tool("llvm-nm", package="llvm"), "-D", "-g", "--defined-only", str(binary(unpacked, "linux64")))
    assert {line.split()[-1] for line in nm.splitlines()} == fmi2_functions()


def test_linux64_binary_gives_the_host_builds_results_bit_for_bit(fmu_path: Path, unpacked: Path, tmp_path: Path,
                                                                  linux64_results: dict) -> None:
    """zig (clang) at glibc 2.17 against gcc with the build machine's glibc."""
    host = fmu_path.parent / "Pendulum.so"
    if not host.is_file():
        pytest.skip(f"{host}: no host build beside the FMU")
    assert results_of(LINUX64, host, unpacked / "sources", tmp_path) == linux64_results


# --- win64 -----------------------------------------------------------------------------------

def coff_private_headers(dll: Path) -> str:
    return output(tool("llvm-objdump", package="llvm"), "-p", str(dll))


def test_win64_exports_only_fmi2(unpacked: Path) -> None:
    text = coff_private_headers(binary(unpacked, "win64"))
    table = text.split("Export Table:", 1)[1].split("\n\n", 1)[0]
    exported = set(re.findall(r"^\s+\d+\s+0x[0-9a-f]+\s+(\S+)$", table, re.MULTILINE))
    assert exported == fmi2_functions()


def test_win64_dll_needs_only_dlls_every_windows_has(unpacked: Path) -> None:
    """KERNEL32 and the UCRT's api-ms-win-crt-* sets (Windows 10+; an update on 7/8.1): no
    vcruntime, libgcc or winpthread DLL that an importer would have to ship."""
    imported = set(re.findall(r"DLL Name: (\S+)", coff_private_headers(binary(unpacked, "win64"))))
    assert "KERNEL32.dll" in imported
    assert all(n == "KERNEL32.dll" or re.fullmatch(r"api-ms-win-crt-[a-z]+-l1-1-0\.dll", n) for n in imported), imported


def test_win64_fmi_harness_passes_under_wine(unpacked: Path, tmp_path: Path) -> None:
    require(WIN64)
    done = run_program(WIN64, build_program(WIN64, HARNESS, binary(unpacked, "win64"), unpacked / "sources", tmp_path))
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert re.search(r"test_fmi_api: \d+ checks, 0 failed", done.stdout)


def test_win64_results_agree_with_linux64(unpacked: Path, tmp_path: Path, linux64_results: dict) -> None:
    require(WIN64)
    differences = max_differences(linux64_results, results_of(WIN64, binary(unpacked, "win64"),
                                                              unpacked / "sources", tmp_path))
    print(f"win64 under wine vs linux64: {differences}")
    assert all(d <= AGREEMENT for d in differences.values()), differences


def test_win64_fma_is_correctly_rounded(fmu_path: Path, tmp_path: Path) -> None:
    """fma() as the win64 binary gets it (zig's toolchain) against the exactly rounded a*b + c.
    integrator.c needs it for the low part of g/L; mingw-w64's is not (docs/platforms.md)."""
    target = zig_win64(fmu_path.parent / "zig-cache")
    require(target)
    assert fma_errors(target, tmp_path) == 0


# --- arm64 code, as aarch64-linux under qemu ---------------------------------------------------

def test_aarch64_fmi_harness_passes_under_qemu(fmu_path: Path, unpacked: Path, tmp_path: Path) -> None:
    require(AARCH64)
    done = run_program(AARCH64, build_program(AARCH64, HARNESS, cross_library(fmu_path, "aarch64-linux"),
                                              unpacked / "sources", tmp_path))
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert re.search(r"test_fmi_api: \d+ checks, 0 failed", done.stdout)


def test_aarch64_results_agree_with_linux64(fmu_path: Path, unpacked: Path, tmp_path: Path,
                                            linux64_results: dict) -> None:
    require(AARCH64)
    differences = max_differences(linux64_results, results_of(AARCH64, cross_library(fmu_path, "aarch64-linux"),
                                                              unpacked / "sources", tmp_path))
    print(f"aarch64 under qemu vs linux64: {differences}")
    assert all(d <= AGREEMENT for d in differences.values()), differences


def test_contraction_is_what_separates_arm64_from_x86_64(fmu_path: Path, unpacked: Path, tmp_path: Path,
                                                         linux64_results: dict) -> None:
    """The same arm64 build with -ffp-contract=fast (clang's FMA fusion) does not reproduce the
    linux64 results: -ffp-contract=off is what makes the agreement above exact."""
    require(AARCH64)
    fused = results_of(AARCH64, cross_library(fmu_path, "aarch64-linux-contract"), unpacked / "sources", tmp_path)
    assert max(max_differences(linux64_results, fused).values()) > 0.0


def test_the_documented_table_command_prints_every_row(fmu_path: Path) -> None:
    """``python tests/helpers/platform_runs.py FMU``, the command docs/platforms.md and the README give for
    the agreement table, runs to its end: every row measured, the host and arm64 rows exact, the
    win64 row within the bound."""
    for target in (WIN64, AARCH64):
        require(target)
    done = subprocess.run([sys.executable, str(REPO_ROOT / "tests/helpers/platform_runs.py"), str(fmu_path)],
                          capture_output=True, text=True, timeout=900, check=False)
    assert done.returncode == 0 and "Traceback" not in done.stderr, done.stderr[-3000:]
    rows = {}
    for line in done.stdout.splitlines():
        numbers = re.findall(r"\s(\d\.\d\de[+-]\d\d)", line)
        if len(numbers) == 4:
            rows[line[:42].strip()] = [float(n) for n in numbers]
    assert len(rows) == 5, done.stdout
    assert rows["host-gcc build/Pendulum.so (native)"] == [0.0] * 4
    assert rows["aarch64-linux, arm64 flags (qemu)"] == [0.0] * 4
    assert max(rows["win64 Pendulum.dll from the FMU (wine)"]) <= AGREEMENT
    assert re.search(r"fma\(\) of zig .*: 0 of 20000 not correctly rounded", done.stdout), done.stdout


# --- the FMI 3.0 FMU's aarch64-linux and x86_64-windows binaries, run -------------------------------

@pytest.fixture(scope="module")
def unpacked3(fmu3_path: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The FMI 3.0 FMU, unpacked once for this module."""
    return extract_fmu(fmu3_path, tmp_path_factory.mktemp("platforms3"))


def fmi3_binary(unpacked3: Path, folder: str, name: str) -> Path:
    path = unpacked3 / "binaries" / folder / name
    assert path.is_file(), f"no binaries/{folder}/{name} in the FMI 3.0 FMU: build it with bash scripts/build-fmu.sh"
    return path


def run_fmi3_harness(target: Target, library: Path, unpacked3: Path, folder: Path) -> None:
    """tests/c/fmi3/test_fmi3_api.c built for ``target`` against ``library`` (the binary taken
    out of the FMU) and run there; the declarations from the FMU's own sources/ (fmi3_api.h)."""
    program = build_program(target, FMI3_HARNESS, library, unpacked3 / "sources", folder)
    done = run_program(target, program)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert re.search(r"test_fmi3_api: \d+ checks passed", done.stdout), done.stdout[-3000:]


def test_fmi3_aarch64_linux_binary_loads_on_glibc_2_17(unpacked3: Path) -> None:
    versions = glibc_versions_needed(fmi3_binary(unpacked3, "aarch64-linux", "Pendulum.so"))
    assert versions and max(versions) <= GLIBC_FLOOR


def test_fmi3_aarch64_linux_binary_passes_the_fmi3_harness_under_qemu(unpacked3: Path, tmp_path: Path) -> None:
    require(AARCH64)
    run_fmi3_harness(AARCH64, fmi3_binary(unpacked3, "aarch64-linux", "Pendulum.so"), unpacked3, tmp_path)


def test_fmi3_x86_64_windows_dll_passes_the_fmi3_harness_under_wine(unpacked3: Path, tmp_path: Path) -> None:
    require(WIN64)
    run_fmi3_harness(WIN64, fmi3_binary(unpacked3, "x86_64-windows", "Pendulum.dll"), unpacked3, tmp_path)


# --- darwin64, inspected only ----------------------------------------------------------------

def test_darwin64_is_universal_x86_64_and_arm64(unpacked: Path) -> None:
    lipo = tool("llvm-lipo", package="llvm")
    assert set(output(lipo, "-archs", str(binary(unpacked, "darwin64"))).split()) == {"x86_64", "arm64"}


@pytest.mark.parametrize("arch", ["x86_64", "arm64"])
def test_darwin64_floor_install_name_and_dependencies(unpacked: Path, arch: str) -> None:
    text = output(tool("llvm-objdump", package="llvm"), "--macho", "--private-headers", f"--arch={arch}",
                  str(binary(unpacked, "darwin64")))
    floor = re.search(r"cmd (?:LC_VERSION_MIN_MACOSX|LC_BUILD_VERSION)\n(?:.*\n)*?\s+(?:version|minos) (\S+)", text)
    assert floor is not None and floor.group(1) == MACOS_FLOOR[arch]
    assert re.search(r"cmd LC_ID_DYLIB\n.*\n\s+name @rpath/Pendulum\.dylib ", text)
    assert re.findall(r"cmd LC_LOAD_DYLIB\n.*\n\s+name (\S+)", text) == ["/usr/lib/libSystem.B.dylib"]


@pytest.mark.parametrize("arch", ["x86_64", "arm64"])
def test_darwin64_exports_only_fmi2(unpacked: Path, arch: str) -> None:
    """What dyld can bind to is the export trie; its names are the C names with a leading _."""
    text = output(tool("llvm-objdump", package="llvm"), "--macho", "--exports-trie", f"--arch={arch}",
                  str(binary(unpacked, "darwin64")))
    exported = set(re.findall(r"^0x[0-9A-Fa-f]+\s+(\S+)", text, re.MULTILINE))
    assert exported == {f"_{name}" for name in fmi2_functions()} | MACHO_LINKER_SYMBOLS


def test_fat_writer_is_byte_identical_to_llvm_lipo(unpacked: Path, tmp_path: Path) -> None:
    """cmake/fat_macho.py (so the wheel build needs no system llvm) against llvm-lipo -create."""
    lipo = tool("llvm-lipo", package="llvm")
    universal = binary(unpacked, "darwin64")
    thin = []
    for arch in ("arm64", "x86_64"):
        subprocess.run([lipo, str(universal), "-thin", arch, "-output", str(tmp_path / arch)], check=True)
        thin.append(tmp_path / arch)
    subprocess.run([lipo, "-create", *map(str, thin), "-output", str(tmp_path / "lipo")], check=True)
    ours = fat_binary([thin_slice(p.read_bytes(), p.name) for p in thin])
    assert ours == (tmp_path / "lipo").read_bytes() == universal.read_bytes()


def test_fat_writer_refuses_what_is_not_a_64_bit_mach_o(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="not a thin 64-bit"):
        thin_slice(b"\x7fELF" + bytes(60), "elf")
    arm64 = (0xFEEDFACF).to_bytes(4, "little") + (0x0100000C).to_bytes(4, "little") + bytes(24)
    with pytest.raises(ValueError, match="same architecture"):
        fat_binary([thin_slice(arm64, "a"), thin_slice(arm64, "b")])


# --- the wheel -------------------------------------------------------------------------------

def test_wheel_is_py3_none_any_and_carries_all_three_binaries(built_wheel: Path, tmp_path: Path) -> None:
    """The wheel (conftest's ``built_wheel``) is py3-none-any, so it must carry the FMU's three
    binaries and the exact-solution library for each of the same three platforms."""
    assert built_wheel.name.endswith("-py3-none-any.whl")
    with zipfile.ZipFile(built_wheel) as wheel:
        names = wheel.namelist()
        fmu = tmp_path / "Pendulum.fmu"
        fmu.write_bytes(wheel.read("pendulum_fmu/Pendulum.fmu"))
    assert set(supported_platforms(str(fmu))) == {"linux64", "win64", "darwin64", "c-code"}
    for library in ("linux64/libpendulum_exact.so", "win64/pendulum_exact.dll", "darwin64/libpendulum_exact.dylib",
                    "linux64/libpendulum_driver.so", "win64/pendulum_driver.dll", "darwin64/libpendulum_driver.dylib"):
        assert f"pendulum_fmu/lib/{library}" in names
    assert "pendulum_fmu/fmi3/Pendulum.fmu" in names
