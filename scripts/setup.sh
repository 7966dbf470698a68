#!/usr/bin/env bash
# Install what is missing (Debian 12 packages) and configure + build
# signorini in Release mode into ./build. Safe to run again: it only
# installs missing packages and rebuilds what changed (ccache helps).
set -euo pipefail
cd "$(dirname "$0")/.."

# libopenblas0-serial: Debian's optimised BLAS/LAPACK replaces the reference
# one through the alternatives system (MUMPS's factorisations are about twice
# as fast, doc/performance.md). The serial build: MPI ranks and deal.II's
# threads already use the cores, BLAS threads would oversubscribe them.
packages=(cmake make g++ pkg-config ccache libdeal.ii-dev coinor-libipopt-dev
          libopenblas0-serial
          numdiff openmpi-bin gnuplot-nox python3 python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# OpenMPI refuses to run as root unless told otherwise (CI runs as root).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs" --target signorini signorini-test
