#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Installs the packages and builds the programs (no tests) in _build/main; the
# build output goes to stderr. Used by main.sh and quality-report.sh.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/common.sh"
{
  bash "$root/scripts/install-deps.sh"
  cmake -S "$root" -B "$root/_build/main" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DParaView_DIR="$(bluenoise_paraview_dir)" \
    -DBUILD_TESTING=OFF -DBLUENOISE_BUILD_BENCHMARKS=OFF
  cmake --build "$root/_build/main" -j "$(nproc)"
} >&2
