#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Installs what is needed, builds and runs the whole test suite:
#   1. against the ParaView 5.11 SDK (module, plugin, Python, all tests);
#   2. VTK-only (no ParaView plugin) against ParaView's VTK through VTK_DIR;
#   3. VTK-only against a real VTK 9.1 (Debian's, unpacked into _build/);
#   4. the sanitizer builds (scripts/sanitize.sh): clang ASan+UBSan with the whole
#      suite of a VTK-only build and its libFuzzer targets (about a minute each),
#      and ThreadSanitizer on the threaded tests.
# Each stage's wall time is printed at the end.
# Usage: bash scripts/test.sh   (from anywhere; run as root or with sudo rights)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"

paraview_dir=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11
jobs="${BLUENOISE_JOBS:-$(nproc)}"
status=0
timings=()

stage() { # name, command...: runs the command, records its time, keeps going on failure
  local name="$1"; shift
  local start=$SECONDS
  "$@" || status=1
  timings+=("$(printf '%-10s %4d s' "$name" $((SECONDS - start)))")
}

run_suite() { # name, cmake args...
  local name="$1"; shift
  local dir="$root/_build/$name"
  echo "=== $name: configure, build, test ($dir)"
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
  cmake --build "$dir" -j "$jobs"
  (cd "$dir" && ctest --output-on-failure -j "$jobs" --timeout 900)
}

run_vtk91() {
  local vtk91="$root/_build/prefix-vtk-9.1"
  bash "$root/scripts/unpack-vtk91.sh" "$vtk91"
  # The unpacked libraries are not in the loader's paths: their own dependencies
  # among themselves are found through LD_LIBRARY_PATH.
  (
    export LD_LIBRARY_PATH="$vtk91/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
    run_suite vtk-9.1 -DBLUENOISE_VTK_ONLY=ON -DBLUENOISE_WRAP_PYTHON=OFF \
      -DVTK_DIR="$vtk91/usr/lib/x86_64-linux-gnu/cmake/vtk-9.1"
  )
}

stage paraview run_suite paraview -DParaView_DIR="$paraview_dir"
stage vtk-only run_suite vtk-only -DBLUENOISE_VTK_ONLY=ON -DVTK_DIR="$paraview_dir/vtk"
stage vtk-9.1 run_vtk91
stage asan bash "$root/scripts/sanitize.sh" asan
stage tsan bash "$root/scripts/sanitize.sh" tsan
echo "=== stage times"
printf '%s\n' "${timings[@]}"
exit $status
