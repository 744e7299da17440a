#!/usr/bin/env bash
# Installs what is needed, builds, and runs the main job: importance sampling of
# a volume (default: the MRI brain from Debian's mricron-data) into blue-noise
# points. Arguments go to bluenoise-sample (see --help); none are needed.
# Usage: bash scripts/main.sh [VOLUME] [--output DIR] [--points N] ...
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh" >&2

dir="$root/_build/main"
{
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DParaView_DIR=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11 \
    -DBUILD_TESTING=OFF -DBLUENOISE_BUILD_BENCHMARKS=OFF
  cmake --build "$dir" -j "$(nproc)"
} >&2
exec "$dir/bin/bluenoise-sample" "$@"
