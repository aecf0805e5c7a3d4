#!/usr/bin/env bash
# Install the Debian packages magnus needs (only the missing ones) and configure + build it.
# Used by scripts/demo.sh and scripts/test.sh; safe to run again.
# scripts/setup.sh --slurm also installs munge and Slurm (slurm-wlm) for ctest -L slurm.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MAGNUS_BUILD_DIR:-$here/build}"

packages=(build-essential cmake pkg-config libeigen3-dev libsuitesparse-dev libopenblas0-pthread
          libhdf5-dev hdf5-tools catch2 libfftw3-dev libarpack2-dev libtomlplusplus-dev libcli11-dev libfmt-dev
          libplplot-dev plplot-driver-cairo libpng-dev libxml2-utils nlohmann-json3-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-h5py python3-matplotlib)
case "${1:-}" in
  "") ;;
  --slurm) packages+=(slurm-wlm munge) ;;
  *) echo "setup.sh: unknown option '$1' (the only one is --slurm)" >&2; exit 2 ;;
esac
source "$here/scripts/install-packages.sh"
install_packages setup "${packages[@]}"

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE="${MAGNUS_BUILD_TYPE:-Release}" ${MAGNUS_CMAKE_ARGS:-} >/dev/null
cmake --build "$build" -j "$(nproc)" >&2
