# Sourced by study.sh and test.sh: creates .venv with the pinned dependencies (skipped when
# python/requirements.lock and pyproject.toml are unchanged since the last install). Every step
# that takes more than a few seconds says what it does on stderr, and how far it is where it can.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="$ROOT/.venv"
PYTHON="${PYTHON:-python3}"

source "$ROOT/scripts/progress.sh"  # say, run_step, CMAKE_STAGES

stamp_now="$(cat "$ROOT/python/requirements.lock" "$ROOT/pyproject.toml" | sha256sum | cut -d' ' -f1)"
if [ ! -x "$VENV/bin/python" ]; then
    say "[1/4] creating the Python environment .venv ($PYTHON -m venv) ..."
    "$PYTHON" -m venv "$VENV"
fi
if [ "$(cat "$VENV/.installed" 2>/dev/null)" != "$stamp_now" ]; then
    packages="$(grep -cE '^[A-Za-z0-9]' "$ROOT/python/requirements.lock" || true)"
    say "[2/4] upgrading pip in .venv ..."
    run_step '/^Successfully installed/ { print; fflush() }' \
        "$VENV/bin/python" -m pip install --upgrade pip
    say "[3/4] installing the $packages pinned packages of python/requirements.lock (minutes the first time) ..."
    run_step "/^Collecting / { k++; printf \"package %d of $packages: %s\\n\", k, \$2; fflush() }
              /^Installing collected packages/ { print \"unpacking them into .venv ...\"; fflush() }" \
        "$VENV/bin/python" -m pip install -r "$ROOT/python/requirements.lock"
    say "[4/4] installing pendulum_fmu (pip install -e .), which is building the FMUs with CMake into build/" \
        "(minutes the first time) ..."
    run_step '/^ *(pendulum-fmu build:|warning: pendulum-fmu)/ { sub(/^ */, ""); print; fflush() }' \
        "$VENV/bin/python" -m pip install -v --no-deps -e "$ROOT"
    echo "$stamp_now" > "$VENV/.installed"
fi
export PATH="$VENV/bin:$PATH"
cd "$ROOT"
