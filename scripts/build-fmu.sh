#!/usr/bin/env bash
# The one command for the multi-platform FMU: build/Pendulum.fmu with binaries/linux64
# (glibc 2.17), binaries/win64 and binaries/darwin64 (universal x86_64 + arm64), all
# cross-built with zig from PyPI (ziglang, pinned in python/requirements.lock), plus the
# host build and the C tests. study.sh and test.sh run it first; the wheel build does the same.
source "$(dirname "${BASH_SOURCE[0]}")/setup-env.sh"
zig="$(python -c 'import pathlib, ziglang; print(pathlib.Path(ziglang.__file__).with_name("zig"))')"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPENDULUM_PLATFORMS=ON \
      -DPENDULUM_ZIG="$zig" -DPENDULUM_PYTHON="$VENV/bin/python" > /dev/null
cmake --build build --parallel "$(nproc)"
python -c 'import zipfile; print("build/Pendulum.fmu:", *(n for n in zipfile.ZipFile("build/Pendulum.fmu").namelist() if n.startswith("binaries/") and not n.endswith("/")))'
