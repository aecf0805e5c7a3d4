#!/usr/bin/env bash
# Install the Debian packages magnus needs (only the missing ones) and configure + build it.
# Used by scripts/demo.sh and scripts/test.sh; safe to run again.
# Options (any of them, together):
#   --slurm    also munge and Slurm (slurm-wlm), for ctest -L slurm
#   --viewers  also ParaView (pvpython) and meshio, for ctest -L viewers
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MAGNUS_BUILD_DIR:-$here/build}"

packages=(build-essential cmake pkg-config libeigen3-dev libsuitesparse-dev libopenblas0-pthread
          libhdf5-dev hdf5-tools catch2 libfftw3-dev libarpack2-dev libtomlplusplus-dev libcli11-dev libfmt-dev
          libplplot-dev plplot-driver-cairo libpng-dev libxml2-utils nlohmann-json3-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-h5py python3-matplotlib
          python3-xarray python3-h5netcdf ffmpeg python3-build python3-venv python3-setuptools
          python3-nbclient python3-nbformat python3-ipykernel)
for option in "$@"; do
  case "$option" in
    --slurm) packages+=(slurm-wlm munge) ;;
    # without recommends, paraview has no pvpython: python3-paraview brings it (xarray is in the list above)
    --viewers) packages+=(paraview python3-paraview python3-meshio) ;;
    *) echo "setup.sh: unknown option '$option' (the options are --slurm and --viewers)" >&2; exit 2 ;;
  esac
done
source "$here/scripts/install-packages.sh"
install_packages setup "${packages[@]}"

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE="${MAGNUS_BUILD_TYPE:-Release}" ${MAGNUS_CMAKE_ARGS:-} >/dev/null
cmake --build "$build" -j "$(nproc)" >&2
