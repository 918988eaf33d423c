#!/usr/bin/env bash
# Installs what milldyn needs from Debian 12's packages, and nothing else.
# Idempotent: installs only what is missing, and touches apt only then.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libsimbody-dev libeigen3-dev libyaml-cpp-dev nlohmann-json3-dev libcli11-dev
  ninja-build dpkg-dev liblapack-dev libblas-dev   # the Release engine's build (scripts/build-engine.sh)
  googletest libgtest-dev
  gnuplot-nox fonts-dejavu-core
  openmpi-bin libopenmpi-dev
  chromium python3   # the validation report's render test (tests/report/render_check.sh)
  librsvg2-bin       # rsvg-convert: PNG copies of `run --schematic` (docs/schematic.md)
  pybind11-dev python3-dev python3-numpy python3-pytest   # the Python module (docs/python.md)
  python3-pandas python3-matplotlib                      # its to_pandas() and worked study
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
