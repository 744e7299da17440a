# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Sourced by the scripts: what differs between the supported Debian releases
# (scripts/install-deps.sh lists their packages).

# The ParaView CMake directory of the installed SDK, whatever its version
# (paraview-5.11 on bookworm, 5.13 on trixie, 6.1 on sid).
bluenoise_paraview_dir() {
  local dir
  dir="$(ls -d /usr/lib/*/cmake/paraview-* 2>/dev/null | sort -V | tail -n 1)"
  if [ -z "$dir" ]; then
    echo "no ParaView CMake directory in /usr/lib/*/cmake (scripts/install-deps.sh)" >&2
    return 1
  fi
  echo "$dir"
}

# The version suffix of the newest clang++-N installed (14 on bookworm, 19 on
# trixie): the sanitizer builds' compiler.
bluenoise_clang_version() {
  local v
  v="$(compgen -c clang++- | sed -n 's/^clang++-\([0-9][0-9]*\)$/\1/p' | sort -n | tail -n 1)"
  if [ -z "$v" ]; then
    echo "no clang++-N installed (scripts/install-deps.sh)" >&2
    return 1
  fi
  echo "$v"
}
