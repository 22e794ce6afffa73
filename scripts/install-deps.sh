#!/usr/bin/env bash
# Installs the Debian packages rbcal needs, only those missing (idempotent).
# Needs root (or sudo) and access to Debian's package registry.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libceres-dev libboost-math-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev
  gnuplot-nox
  libnetcdf-dev  # the reports' ArviZ posterior files (NetCDF-4)
  openmpi-bin  # only mpirun, for the test of `mpirun -np K rbcal library generate`; rbcal links no MPI
  # the Python module (python/) and its tests; emcee for the side-by-side sampler benchmark
  pybind11-dev python3-dev python3-numpy python3-pytest python3-emcee
  python3-netcdf4 python3-xarray  # the test that reads the posterior files back as ArviZ does
  chromium  # the test that renders report.html headless
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
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
