#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian packages the project builds, tests and runs with: the one
# place that lists them, per supported release:
#   bookworm  Debian 12: ParaView 5.11 (VTK 9.2), Qt 5
#   trixie    Debian 13: ParaView 5.13 (VTK 9.3), Qt 6
#   sid       Debian unstable: ParaView 6.1 (VTK 9.6), Qt 6
# The release is taken from /etc/os-release (a "*/sid" /etc/debian_version is
# sid) unless given. Runs as root (or through sudo). Safe to run again:
# apt-get skips what is there.
# Usage: bash scripts/install-deps.sh [--release R] [--sdk] [--list | --release-name]
#   --sdk           leave out what only the host's CI stages need (the sanitizer
#                   toolchain, mmdebstrap): the set-up of scripts/sdk-chroot.sh
#   --list          print the package list and install nothing
#   --release-name  print the release and install nothing
set -euo pipefail

release=""
sdk=0
list=0
name=0
while [ $# -gt 0 ]; do
  case "$1" in
    --release) release="$2"; shift 2 ;;
    --sdk) sdk=1; shift ;;
    --list) list=1; shift ;;
    --release-name) name=1; shift ;;
    *) echo "install-deps: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ -z "$release" ]; then
  if grep -q '/sid$' /etc/debian_version 2>/dev/null; then
    release=sid
  else
    release="$(. /etc/os-release && echo "${VERSION_CODENAME:-}")"
  fi
fi
if [ "$name" = 1 ]; then
  echo "$release"
  exit 0
fi

# Common to every release
packages=(
  # Toolchain and test tools
  build-essential cmake ninja-build pkg-config git xvfb xauth libbenchmark-dev
  # The programs' option parser (header-only)
  libcli11-dev
  # The ParaView SDK (with its VTK) and its Python
  paraview paraview-dev python3-paraview
  # What find_package(ParaView) needs besides paraview-dev
  libutfcpp-dev libhdf5-openmpi-dev libnetcdf-dev libexpat1-dev
  libfreetype-dev libjpeg-dev libpng-dev libtiff-dev liblz4-dev liblzma-dev libxml2-dev
  libgl2ps-dev libglew-dev libdouble-conversion-dev libeigen3-dev libjsoncpp-dev
  libtheora-dev libogg-dev libavcodec-dev libavformat-dev libswscale-dev libgdal-dev
  libopenmpi-dev libx11-dev libgl-dev python3-dev python3-mpi4py zlib1g-dev
  libprotobuf-dev libcgns-dev libpugixml-dev
  # mpiexec for the two-process pvbatch test
  openmpi-bin
  # FFTW3 for the spectrum; real MRI volumes for the main job and tests
  libfftw3-dev mricron-data
  # TBB: the headers of Debian's VTK include it
  libtbb-dev
  # Python for scripts and reports
  python3-numpy python3-scipy
)
# Per release: the Qt of its ParaView, what else its ParaView CMake files need,
# and the clang of the sanitizer builds (scripts/sanitize.sh; host stages only).
case "$release" in
  bookworm)
    packages+=(qtbase5-dev qttools5-dev libqt5svg5-dev libqt5x11extras5-dev libqt5opengl5-dev
      qtxmlpatterns5-dev-tools)
    sanitizer=(clang-14 libfuzzer-14-dev llvm-14)
    ;;
  trixie | sid)
    packages+=(qt6-base-dev qt6-tools-dev qt6-svg-dev qt6-5compat-dev
      # ParaView's CMake files run xsltproc on Qt 6 (Qt 5's xmlpatterns is gone)
      xsltproc)
    if [ "$release" = sid ]; then
      # paraview-dev does not depend on it there, but its CMake files use it
      packages+=(libvtk9-dev)
    fi
    sanitizer=(clang-19 libclang-rt-19-dev libfuzzer-19-dev llvm-19)
    [ "$release" = sid ] && sanitizer=(clang libclang-rt-dev libfuzzer-dev llvm)
    ;;
  *)
    echo "install-deps: unsupported release '$release' (bookworm, trixie or sid)" >&2
    exit 2
    ;;
esac
if [ "$sdk" = 0 ]; then
  # The sanitizer builds and the chroots of the newer SDKs (scripts/sdk-chroot.sh)
  packages+=("${sanitizer[@]}" mmdebstrap)
fi

if [ "$list" = 1 ]; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps ($release): all ${#packages[@]} packages are installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" != 0 ]; then
  SUDO="sudo"
fi
echo "install-deps ($release): installing ${#missing[@]} package(s): ${missing[*]}"
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
