#!/usr/bin/env bash
# ctest "python: pip install --no-build-isolation ./python ..." (tests/CMakeLists.txt): installs
# python/ with pip into a fresh venv in WORK_DIR (system site packages, for Debian's numpy), the
# way README "Python" tells users to, then imports freestand from WORK_DIR and calls it. Setuptools
# builds in WORK_DIR too (FREESTAND_BUILD_BASE, python/setup.py), so python/ gains nothing.
# Usage: pip_install_check.sh PYTHON WORK_DIR VERSION
set -euo pipefail
python=$1 work=$2 version=$3
project=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
before=$(ls -A "$project/python")

rm -rf "$work"
mkdir -p "$work"
"$python" -m venv --system-site-packages "$work/venv"
unset PYTHONPATH
FREESTAND_BUILD_BASE="$work/setup" "$work/venv/bin/python" -m pip install --quiet \
  --no-build-isolation --no-index "$project/python"

cd "$work"
"$work/venv/bin/python" - "$work/venv" "$version" <<'PY'
import sys
import freestand

venv, version = sys.argv[1:]
assert freestand.__file__.startswith(venv), f"imported {freestand.__file__}, not the installed one"
assert freestand.__version__ == version, f"__version__ {freestand.__version__!r}, expected {version!r}"
mode = freestand.classify({"b": 0.15, "h": 0.6}, mu=0.4, a_g=0.3)["mode"]
assert mode == "rock", f"classify gave mode {mode!r}, expected 'rock'"
PY

after=$(ls -A "$project/python")
if [ "$before" != "$after" ]; then
  echo "pip install left files in $project/python:" >&2
  diff <(echo "$before") <(echo "$after") >&2 || true
  exit 1
fi
