#!/usr/bin/env bash
# Debian packages the tests need beyond Python, cmake and gcc (run as root; CI calls it):
# valgrind (memcheck of the FMI harness), clang + libFuzzer runtime (the fuzz target),
# mingw-w64 + wine64 (the win64 binary, built and run), gcc-aarch64 + qemu-user (the arm64
# code, built and run), llvm (llvm-lipo/llvm-nm/llvm-objdump to inspect the macOS binary),
# libgsl-dev (GSL, timed beside the exact port by tests/c/bench_exact), chromium (headless
# screenshots of every documentation page, tests/package/test_docs_render.py) and fonts-dejavu-extra
# (DejaVu Math TeX Gyre: a font with a MATH table, with which Chromium stretches brackets).
set -euo pipefail
packages=(cmake gcc python3-venv valgrind clang lld libclang-rt-14-dev llvm libgsl-dev
          mingw-w64 wine wine64 qemu-user gcc-aarch64-linux-gnu libc6-dev-arm64-cross chromium
          fonts-dejavu-extra)
apt-get update -q
# With the recommended packages, as installed on the machine the tests were measured on
# (`wine`, the command that runs 64-bit programs, is only a recommendation of wine64).
DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${packages[@]}"
