"""Join thin Mach-O files into one universal ("fat") file, as ``lipo -create`` does.

Usage: ``python fat_macho.py OUTPUT THIN...``. Standard library only, so that the wheel build
needs nothing beyond PyPI (zig has no lipo; llvm-lipo would be a system package).

Layout (<mach-o/fat.h>, all fields big-endian uint32): the header ``FAT_MAGIC, nfat_arch``,
then one ``fat_arch`` per slice ``cputype, cpusubtype, offset, size, align`` (align as a power
of two), then each slice at its aligned offset. Slices are ordered by alignment and aligned
to the page size of their architecture (x86_64 4 KiB, arm64 16 KiB), as llvm-lipo does, so
the output is byte-identical to ``llvm-lipo -create`` (tests/fmu/test_platforms.py checks that).
"""

from __future__ import annotations

import struct
import sys
from pathlib import Path

FAT_MAGIC = 0xCAFEBABE
MH_MAGIC_64 = 0xFEEDFACF
CPU_SUBTYPE_MASK = 0xFF000000
"""Capability bits of cpusubtype (CPU_SUBTYPE_LIB64, ...); lipo drops them from fat_arch."""
PAGE_ALIGN = {0x01000007: 12, 0x0100000C: 14}
"""log2 of the page size per cputype: CPU_TYPE_X86_64 4 KiB, CPU_TYPE_ARM64 16 KiB."""


def thin_slice(data: bytes, name: str) -> tuple[int, int, int, bytes]:
    """Return ``(cputype, cpusubtype, align, data)`` of one little-endian 64-bit Mach-O file."""
    if len(data) < 32 or struct.unpack_from("<I", data)[0] != MH_MAGIC_64:
        raise ValueError(f"{name}: not a thin 64-bit little-endian Mach-O file")
    cputype, cpusubtype = struct.unpack_from("<iI", data, 4)
    if cputype not in PAGE_ALIGN:
        raise ValueError(f"{name}: cputype {cputype:#x} is neither x86_64 nor arm64")
    return cputype, cpusubtype & ~CPU_SUBTYPE_MASK, PAGE_ALIGN[cputype], data


def fat_binary(slices: list[tuple[int, int, int, bytes]]) -> bytes:
    """The universal file holding ``slices`` (each as returned by :func:`thin_slice`)."""
    if len({s[0] for s in slices}) != len(slices):
        raise ValueError("two slices for the same architecture")
    ordered = sorted(slices, key=lambda s: s[2])  # stable: smallest alignment first
    header = struct.pack(">II", FAT_MAGIC, len(ordered))
    entries, body = b"", b""
    offset = len(header) + 20 * len(ordered)
    for cputype, cpusubtype, align, data in ordered:
        start = -(-offset // (1 << align)) * (1 << align)  # round up to 2**align
        body += b"\0" * (start - offset) + data
        entries += struct.pack(">iIIII", cputype, cpusubtype, start, len(data), align)
        offset = start + len(data)
    return header + entries + body


def main(argv: list[str]) -> int:
    """Command line: write ``argv[0]`` from the thin files ``argv[1:]``."""
    if len(argv) < 2:
        print("usage: fat_macho.py OUTPUT THIN...", file=sys.stderr)
        return 2
    try:
        slices = [thin_slice(Path(name).read_bytes(), name) for name in argv[1:]]
        Path(argv[0]).write_bytes(fat_binary(slices))
    except (OSError, ValueError) as error:
        print(f"fat_macho.py: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
