#!/usr/bin/env bash
# Installs everything Paddy needs to build, test and benchmark on Debian 12.
# Idempotent: packages already present are skipped by apt. Run as root (or with sudo).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev liblua5.4-dev lua5.4
  libcgal-dev libgmp-dev libmpfr-dev
  libhdf5-dev hdf5-tools
  catch2 libcli11-dev libboost-math-dev libboost-dev nlohmann-json3-dev libfmt-dev
  libnlopt-cxx-dev libnlopt-dev
  libssl-dev
  gnuplot-nox
  libxml2-utils
  # Sanitizer runs and fuzzing (scripts/sanitize.sh, scripts/fuzz.sh, docs/reliability.md):
  # clang with its sanitizer and libFuzzer runtimes, LLVM's OpenMP runtime with the Archer tool.
  clang libclang-rt-dev libomp-dev
  # The real clients of the outputs (tests/clients, label "clients", docs/reliability.md): the
  # HTML reports in headless Chromium; the XDMF + HDF5 snapshots in ParaView's pvpython, which
  # renders offscreen under xvfb-run.
  chromium xvfb python3-paraview paraview
)
# Optional: comparison codes for bench/ (not needed to build or test).
if [ "${PADDY_BENCH_DEPS:-0}" = "1" ]; then
  packages+=(lammps liggghts)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
