#!/usr/bin/env bash
# Installs the Debian packages freestand builds against, only those missing.
# Idempotent and silent when everything is already there. weasyprint (with a font) makes
# `--pdf`; chromium, chromium-driver, python3-selenium, python3-pil and poppler-utils run the
# browser and PDF checks of tests/browser/.
set -euo pipefail
packages=(g++ cmake make ninja-build pkg-config ccache git
  libeigen3-dev libfftw3-dev libboost-dev libboost-program-options-dev libfmt-dev
  catch2 libtomlplusplus-dev libmstch-dev nlohmann-json3-dev
  clang-14 libclang-rt-14-dev
  libopenmpi-dev openmpi-bin
  python3-pytest python3-jsonschema
  pybind11-dev python3-dev python3-numpy python3-matplotlib
  python3-pip python3-venv python3-setuptools python3-wheel
  weasyprint fonts-dejavu-core poppler-utils
  chromium chromium-driver python3-selenium python3-pil)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "freestand setup: installing ${missing[*]}" >&2
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
