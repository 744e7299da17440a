#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# The sanitizer builds and their tests (scripts/test.sh runs both):
#
#   asan  clang, AddressSanitizer + UndefinedBehaviorSanitizer on every target
#         (UBSan stops at the first report), VTK-only against ParaView's VTK, with
#         the libFuzzer targets (BLUENOISE_FUZZ): the whole CTest suite of that
#         build, the fuzz tests included (BLUENOISE_FUZZ_SECONDS each, default 60),
#         but for the labels large and benchmark (see below).
#         The C++ tests run with leak detection (but for the main job, see below);
#         the tests that start Python
#         (labels python, applications, install) run with the ASan runtime
#         preloaded and without leak detection (CPython and VTK's wrapping keep
#         objects until exit by design). Without ParaView's plugin, the pvpython,
#         GUI and MPI tests are not part of this build: they run uninstrumented
#         ParaView programs whose only instrumented code would be the module,
#         which the C++ and VTK Python tests already cover.
#   tsan  clang, ThreadSanitizer, the tests labeled `threads` twice: with
#         vtkSMPTools on its STDThread backend (the spectrum's SMP loops and the
#         sampler's parts through vtkSMPTools), and on Sequential, ParaView's
#         default, where the sampler runs its parts on threads of its own
#         (vtkBlueNoiseThreads).
#
# Suppressions (third-party code only) are in Testing/Sanitizers/.
# Usage: bash scripts/sanitize.sh asan|tsan     (needs scripts/install-deps.sh's packages)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
variant="${1:?usage: sanitize.sh asan|tsan}"
source "$root/scripts/common.sh"
paraview_dir="$(bluenoise_paraview_dir)"
# clang-14 on bookworm, clang-19 on trixie (scripts/install-deps.sh)
clang="${BLUENOISE_CLANG_VERSION:-$(bluenoise_clang_version)}"
jobs="${BLUENOISE_JOBS:-$(nproc)}"
dir="$root/_build/$variant"
supp="$root/Testing/Sanitizers"
python_labels='python|applications|install'
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$supp/ubsan.supp"

configure() { # cmake args...
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang-$clang -DCMAKE_CXX_COMPILER=clang++-$clang \
    -DBLUENOISE_VTK_ONLY=ON -DVTK_DIR="$paraview_dir/vtk" "$@"
}

case "$variant" in
  asan)
    configure -DBLUENOISE_FUZZ=ON -DBLUENOISE_FUZZ_SECONDS="${BLUENOISE_FUZZ_SECONDS:-60}"
    cmake --build "$dir" -j "$jobs"
    asan="check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1"
    runtime="$(clang++-$clang -print-file-name=libclang_rt.asan-x86_64.so)"
    # Left out, as they cost minutes under ASan and run in the other builds:
    # label large (2^31 voxels, over 8 minutes here) and benchmark (smoke runs
    # of 256^3 volumes, the module code the tests cover).
    skip='large|benchmark'
    status=0
    # The programs link the runtime themselves (the fuzzers clang's static one).
    (cd "$dir" && ASAN_OPTIONS="$asan" ctest --output-on-failure -j "$jobs" -L fuzz) || status=1
    (cd "$dir" && ASAN_OPTIONS="$asan:detect_leaks=1" \
      LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0" \
      ctest --output-on-failure -j "$jobs" --timeout 900 -LE "$python_labels|fuzz|mainjob|$skip") ||
      status=1
    # The main job draws its pictures with Mesa's software GL driver, which is
    # unloaded before LeakSanitizer looks: its allocations then come from an
    # unknown module that no suppression can name. No leak detection there.
    (cd "$dir" && ASAN_OPTIONS="$asan:detect_leaks=0" \
      ctest --output-on-failure -j "$jobs" --timeout 900 -L mainjob) || status=1
    (cd "$dir" && ASAN_OPTIONS="$asan:detect_leaks=0" LD_PRELOAD="$runtime" \
      ctest --output-on-failure -j "$jobs" --timeout 900 -L "$python_labels" -LE "$skip") || status=1
    exit $status
    ;;
  tsan)
    configure -DBLUENOISE_SANITIZE=thread
    # Only the threaded tests run: build only their programs.
    mapfile -t tests < <(cd "$dir" && ctest -N -L threads | sed -n 's/^ *Test *#[0-9]*: //p')
    cmake --build "$dir" -j "$jobs" --target "${tests[@]}"
    export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$supp/tsan.supp"
    cd "$dir"
    for backend in STDThread Sequential; do
      echo "ThreadSanitizer, vtkSMPTools backend $backend:"
      VTK_SMP_BACKEND_IN_USE=$backend ctest --output-on-failure -j "$jobs" --timeout 900 -L threads
    done
    ;;
  *)
    echo "sanitize.sh: unknown variant '$variant' (asan or tsan)" >&2
    exit 2
    ;;
esac
