#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Benchmark of the main job's streaming (not run in CI): a generated EDGE^3
# uint8 raw MetaImage (default 1024^3, 1 GiB, in a scratch folder deleted at
# the end) sampled into POINTS points (default 10^6) by bluenoise-sample
#   streamed: z-slabs of --slab-size MiB (the default),
#   whole:    one slab larger than the volume (read whole, then sampled).
# It prints each run's peak resident memory and wall time (/usr/bin/time -v)
# and the ratio of the streamed run's wall time to the sampling alone (the
# whole run's `seconds=`, the sampler on the volume in memory).
# Usage: bash scripts/bench-streaming.sh [EDGE] [POINTS] [BUILD_DIR]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
edge="${1:-1024}"
points="${2:-1000000}"
build="${3:-$root/_build/main}"
program="$build/bin/bluenoise-sample"
[ -x "$program" ] || bash "$root/scripts/build-release.sh"
scratch="$(mktemp -d "${TMPDIR:-/tmp}/bluenoise-bench.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT

# A smooth density: a ball whose value falls off from the center, with a
# gentle ripple along z, so every slab holds a different part of the budget.
/usr/bin/python3 - "$scratch/volume.raw" "$edge" <<'PY'
import sys
import numpy as np
path, n = sys.argv[1], int(sys.argv[2])
c = (n - 1) / 2.0
y, x = np.mgrid[0:n, 0:n].astype(np.float32)
r2 = ((x - c) ** 2 + (y - c) ** 2) / (c * c)
with open(path, 'wb') as f:
    for z in range(n):
        d = np.sqrt(r2 + ((z - c) / c) ** 2)
        v = 255.0 * np.clip(1.0 - d, 0.0, 1.0) * (0.75 + 0.25 * np.sin(z / 16.0))
        f.write(v.astype(np.uint8).tobytes())
PY
cat > "$scratch/volume.mhd" <<MHD
ObjectType = Image
NDims = 3
DimSize = $edge $edge $edge
ElementSpacing = 1 1 1
ElementType = MET_UCHAR
ElementDataFile = volume.raw
MHD

run() {
  local name="$1"
  shift
  /usr/bin/time -v "$program" "$scratch/volume.mhd" --points "$points" --no-pictures \
    --output "$scratch/out-$name" "$@" >"$scratch/$name.out" 2>"$scratch/$name.err" || {
    cat "$scratch/$name.out" "$scratch/$name.err" >&2
    exit 1
  }
  local rss wall seconds
  rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$scratch/$name.err")
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$scratch/$name.err" |
    awk -F: '{ s = 0; for (i = 1; i <= NF; ++i) s = s * 60 + $i; print s }')
  seconds=$(tail -1 "$scratch/$name.out" | sed -n 's/.* seconds=\([^ ]*\).*/\1/p')
  grep '^input:' "$scratch/$name.out"
  echo "$name: peak RSS $((rss / 1024)) MiB, wall ${wall} s, sampling ${seconds} s"
  eval "${name}_wall=$wall ${name}_seconds=$seconds"
}

echo "volume: ${edge}^3 uint8 MetaImage, $points points, $(nproc) cores"
# The file's pages are cached by the generation for both runs alike.
run whole --slab-size 1000000
run streamed
awk -v a="$streamed_wall" -v b="$whole_seconds" \
  'BEGIN { printf "streamed wall time / sampling alone: %.2f\n", a / b }'
