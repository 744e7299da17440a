#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Installs what is needed, builds, and runs the main job: importance sampling of
# a volume (default: the MRI brain from Debian's mricron-data) into blue-noise
# points, the blue-noise spectrum of a uniform-density run, and two pictures
# (see --help for the files). Arguments go to bluenoise-sample; none are needed.
# Without a DISPLAY the program runs under xvfb-run (a virtual X display) so
# that it can render the pictures off screen.
# Usage: bash scripts/main.sh [VOLUME] [--output DIR] [--points N] [--no-pictures] ...
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build-release.sh"
dir="$root/_build/main"
program=("$dir/bin/bluenoise-sample" "$@")
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null 2>&1; then
  # -a takes the first free display from -n on; a random start keeps two
  # concurrent runs from racing for the same display number.
  exec xvfb-run -a -n $((100 + RANDOM % 800)) -s "-screen 0 1280x1024x24 -noreset" "${program[@]}"
fi
# With a DISPLAY, or without xvfb-run (then the program explains what is missing
# unless --no-pictures is given).
exec "${program[@]}"
