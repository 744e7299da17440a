#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian (bookworm) packages the project builds, tests and runs with.
# Runs as root (or through sudo). Safe to run again: apt-get skips what is there.
set -euo pipefail

packages=(
  # Toolchain and test tools
  build-essential cmake ninja-build pkg-config git xvfb xauth libbenchmark-dev
  # The programs' option parser (header-only)
  libcli11-dev
  # ParaView 5.11 SDK (with its VTK 9.2) and its Python
  paraview paraview-dev python3-paraview
  # What find_package(ParaView) needs besides paraview-dev
  qtbase5-dev qttools5-dev libqt5svg5-dev libqt5x11extras5-dev libqt5opengl5-dev
  qtxmlpatterns5-dev-tools libutfcpp-dev libhdf5-openmpi-dev libnetcdf-dev libexpat1-dev
  libfreetype-dev libjpeg-dev libpng-dev libtiff-dev liblz4-dev liblzma-dev libxml2-dev
  libgl2ps-dev libglew-dev libdouble-conversion-dev libeigen3-dev libjsoncpp-dev
  libtheora-dev libogg-dev libavcodec-dev libavformat-dev libswscale-dev libgdal-dev
  libopenmpi-dev libx11-dev libgl-dev python3-dev python3-mpi4py zlib1g-dev
  libprotobuf-dev libcgns-dev libpugixml-dev
  # mpiexec for the two-process pvbatch test
  openmpi-bin
  # FFTW3 for the spectrum; real MRI volumes for the main job and tests
  libfftw3-dev mricron-data
  # TBB: the headers of Debian's VTK 9.1 (third CI build) include it
  libtbb-dev
  # Python for scripts and reports
  python3-numpy python3-scipy
  # Sanitizer and fuzzer builds (scripts/sanitize.sh): clang with libFuzzer, and
  # llvm-symbolizer (llvm-14) for readable sanitizer reports
  clang-14 libfuzzer-14-dev llvm-14
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages are installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" != 0 ]; then
  SUDO="sudo"
fi
echo "install-deps: installing ${#missing[@]} package(s): ${missing[*]}"
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
