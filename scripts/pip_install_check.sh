#!/usr/bin/env bash
# ctest "python: pip install --no-build-isolation ./python ..." (tests/CMakeLists.txt): installs
# python/ with pip into a fresh venv in WORK_DIR (system site packages, for Debian's numpy), the
# way README "Python" tells users to, then imports freestand from WORK_DIR and calls it.
# CMAKE_DIR and CMAKE_ARGS go to python/setup.py (FREESTAND_CMAKE_BUILD_DIR, FREESTAND_CMAKE_ARGS):
# a folder at the depth of the calling build and that build's flags, so the compiler cache holds
# every object and the install only links. Setuptools builds in CMAKE_DIR, so python/ gains nothing.
# Usage: pip_install_check.sh PYTHON WORK_DIR CMAKE_DIR VERSION [CMAKE_ARGS...]
set -euo pipefail
python=$1 work=$2 cmake_dir=$3 version=$4
shift 4
project=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
before=$(ls -A "$project/python")

rm -rf "$work"
mkdir -p "$work"
# Debian's pip from the system site packages serves the venv: installing pip into it (the README's
# venv) costs the test more than the install it checks.
"$python" -m venv --system-site-packages --without-pip "$work/venv"
unset PYTHONPATH
FREESTAND_CMAKE_BUILD_DIR="$cmake_dir" FREESTAND_CMAKE_ARGS="${*@Q}" \
  "$work/venv/bin/python" -m pip install --quiet --no-build-isolation --no-index "$project/python"

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
