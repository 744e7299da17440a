#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Unpacks Debian's VTK 9.1 (libvtk9-dev and the packages its CMake files refer
# to) into a private prefix with dpkg -x, without installing it: Debian cannot
# install it beside python3-paraview. Used to build and test against a real
# VTK 9.1. Usage: bash scripts/unpack-vtk91.sh PREFIX
set -euo pipefail
prefix="$1"
stamp="$prefix/.unpacked"
if [ -f "$stamp" ]; then
  exit 0
fi
packages=(libvtk9.1 libvtk9-dev libvtk9.1-qt python3-vtk9 libvtk9-java vtk9)
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && apt-get download "${packages[@]}" 2>&1 | grep -v "unsandboxed" || true)
count=$(ls "$tmp"/*.deb 2>/dev/null | wc -l)
if [ "$count" -ne ${#packages[@]} ]; then
  echo "unpack-vtk91: downloaded $count of ${#packages[@]} packages" >&2
  exit 1
fi
mkdir -p "$prefix"
for deb in "$tmp"/*.deb; do
  dpkg -x "$deb" "$prefix"
done
touch "$stamp"
echo "unpack-vtk91: VTK 9.1 unpacked in $prefix"
