#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Installs what is needed, builds and runs the whole test suite:
#   1. against the host's ParaView SDK (module, plugin, Python, all tests);
#   2. VTK-only (no ParaView plugin) against ParaView's VTK through VTK_DIR,
#      with the plain code paths of processors without SSE2 (BLUENOISE_SSE2=OFF);
#   3. VTK-only against a real VTK 9.1 (Debian 12's, unpacked into _build/;
#      on a Debian 12 host only);
#   4. the sanitizer builds (scripts/sanitize.sh): clang ASan+UBSan with the whole
#      suite of a VTK-only build and its libFuzzer targets (about a minute each),
#      and ThreadSanitizer on the threaded tests;
#   5. the whole suite against the SDK of each newer Debian release, in a chroot
#      of it (scripts/sdk-chroot.sh, made on first use and then reused): Debian
#      13 (ParaView 5.13) and unstable (ParaView 6.1) from a Debian 12 host.
#      BLUENOISE_SDKS names them instead (e.g. "sid", or "" for none). The
#      chroots are set up in the background during stages 1-4; a stage's time
#      counts what it waited for its chroot.
# Each stage's wall time is printed at the end.
# Usage: bash scripts/test.sh   (from anywhere; run as root or with sudo rights)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/common.sh"
bash "$root/scripts/install-deps.sh"

paraview_dir="$(bluenoise_paraview_dir)"
host="$(bash "$root/scripts/install-deps.sh" --release-name)"
case "$host" in
  bookworm) default_sdks="trixie sid" ;;
  trixie) default_sdks="sid" ;;
  *) default_sdks="" ;;
esac
sdks="${BLUENOISE_SDKS-$default_sdks}"
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

# The chroots of the newer SDKs are made (or brought up to date) in the
# background while the host's stages run: mostly downloads and unpacking,
# which the compiler-bound stages leave room for.
declare -A sdk_setup
for sdk in $sdks; do
  mkdir -p "$root/_build"
  bash "$root/scripts/sdk-chroot.sh" "$sdk" --setup-only >"$root/_build/sdk-$sdk-setup.log" 2>&1 &
  sdk_setup[$sdk]=$!
done
run_sdk() { # release: waits for its chroot, then builds and tests in it
  local ok=0
  wait "${sdk_setup[$1]}" || ok=$?
  echo "=== sdk-$1: chroot set-up ($root/_build/sdk-$1-setup.log)"
  tail -n 5 "$root/_build/sdk-$1-setup.log"
  [ "$ok" = 0 ] || return "$ok"
  bash "$root/scripts/sdk-chroot.sh" "$1"
}

stage paraview run_suite paraview -DParaView_DIR="$paraview_dir"
stage vtk-only run_suite vtk-only -DBLUENOISE_VTK_ONLY=ON -DBLUENOISE_SSE2=OFF \
  -DVTK_DIR="$paraview_dir/vtk"
if [ "$host" = bookworm ]; then
  stage vtk-9.1 run_vtk91 # Debian 12's packages
fi
stage asan bash "$root/scripts/sanitize.sh" asan
stage tsan bash "$root/scripts/sanitize.sh" tsan
for sdk in $sdks; do
  stage "sdk-$sdk" run_sdk "$sdk"
done
echo "=== stage times"
printf '%s\n' "${timings[@]}"
exit $status
