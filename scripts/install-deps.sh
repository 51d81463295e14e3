#!/usr/bin/env bash
# Installs caskdem's build and run-time dependencies from Debian 12 packages.
# Idempotent: packages already installed are skipped, so a second run costs a dpkg query.
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libeigen3-dev libxsimd-dev libboost-dev
  libhdf5-dev hdf5-tools
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  libnlopt-cxx-dev librandom123-dev
  libgtest-dev libgmock-dev libbenchmark-dev libmujoco-dev
  libopenmpi-dev openmpi-bin
  python3-matplotlib python3-h5py python3-numpy python3-pandas
  python3-dev python3-pybind11 python3-pytest python3-openturns
  clang libclang-rt-dev libomp-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
