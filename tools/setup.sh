#!/usr/bin/env bash
# Installs the Debian packages tubemesh needs: build, tests, outside readers, benchmark peers.
# Silent and fast when everything is present; `apt-get update` only when something is missing.
set -euo pipefail

packages=(
  # build
  build-essential cmake ninja-build ccache pkg-config
  libocct-data-exchange-dev libtbb-dev libeigen3-dev libnanoflann-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev
  # the Python module and the HTML report (three.js and Chart.js are inlined at build time)
  pybind11-dev python3-dev libjs-three libjs-chart.js
  # batch: catalogue, hashes, the MPI driver (built only when MPI is found)
  libsqlite3-dev libssl-dev libopenmpi-dev openmpi-bin
  # install: `pip install .` in a venv (offline with Debian's setuptools, wheel and numpy) and
  # `cpack -G DEB` (dpkg-shlibdeps, file)
  python3-venv python3-setuptools python3-wheel dpkg-dev file
  # tests
  libgtest-dev libgmock-dev libgmp-dev libbenchmark-dev
  python3 python3-gmsh python3-meshio python3-numpy python3-vtk9 calculix-ccx python3-pytest
  # the HTML report in a browser: headless Chromium, screenshots read with Pillow
  chromium python3-pil
  # fuzzing (libFuzzer) and the interrupt tests' file-size limit (prlimit)
  clang libclang-rt-14-dev util-linux
  # benchmark peers
  gmsh tetgen valgrind time
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "setup: installing ${#missing[@]} missing package(s): ${missing[*]}" >&2
sudo_cmd=()
[[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq >/dev/null
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done" >&2
