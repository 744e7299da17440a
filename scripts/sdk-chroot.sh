#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Builds and tests the project against the ParaView SDK of a newer Debian
# release in a chroot of that release (its C library is newer than the host's):
#   trixie  Debian 13: ParaView 5.13, VTK 9.3, Qt 6
#   sid     Debian unstable: ParaView 6.1, VTK 9.6, Qt 6
# The chroot is made with mmdebstrap under /var/cache/bluenoise-sdk/RELEASE and
# reused when it is there: its packages come from scripts/install-deps.sh
# --sdk, and a stamp keyed on that list (and on this script's set-up steps)
# tells whether they must be installed again. /proc, /dev and /sys are mounted
# in it and the source tree is bind-mounted at its own path; all are unmounted
# on exit. Then the whole CTest suite runs (module, plugin, Python, GUI and
# pvpython tests) in _build/sdk-RELEASE; the sanitizer and fuzz stages are the
# host's (scripts/sanitize.sh).
# Usage: bash scripts/sdk-chroot.sh trixie|sid [--setup-only] [--shell]
#   Runs as root. BLUENOISE_SDK_CACHE moves the chroots; BLUENOISE_MIRROR
#   names the Debian mirror (default http://deb.debian.org/debian).
set -euo pipefail
# All in a function: bash reads it whole before running it, so an edit of
# this file during a run (minutes) does not change the run.
main() {
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  release="${1:?usage: sdk-chroot.sh trixie|sid [--setup-only] [--shell]}"
  mode="${2:-test}"
  case "$release" in
    trixie | sid) ;;
    *) echo "sdk-chroot: unsupported release '$release' (trixie or sid)" >&2; exit 2 ;;
  esac
  cache="${BLUENOISE_SDK_CACHE:-/var/cache/bluenoise-sdk}"
  mirror="${BLUENOISE_MIRROR:-http://deb.debian.org/debian}"
  chroot_dir="$cache/$release"
  jobs="${BLUENOISE_JOBS:-$(nproc)}"
  if [ "$(id -u)" != 0 ]; then
    echo "sdk-chroot: run as root (chroot, mount)" >&2
    exit 1
  fi
  mkdir -p "$cache"
  # One set-up or run per release at a time.
  exec 9>"$cache/$release.lock"
  flock 9

  mounts=()
  cleanup() {
    local i
    for ((i = ${#mounts[@]} - 1; i >= 0; i--)); do
      umount -R "${mounts[i]}" 2>/dev/null || umount -l "${mounts[i]}" 2>/dev/null || true
    done
  }
  trap cleanup EXIT
  mount_in() { # kind, source, target inside the chroot
    local target="$chroot_dir$3"
    mkdir -p "$target"
    case "$1" in
      proc) mount -t proc proc "$target" ;;
      # rslave: unmounting the chroot's copy never unmounts the host's submounts
      rbind) mount --rbind "$2" "$target" && mount --make-rslave "$target" ;;
      bind) mount --bind "$2" "$target" ;;
    esac
    mounts+=("$target")
  }
  in_chroot() { # command...
    chroot "$chroot_dir" /usr/bin/env -i HOME=/root TERM="${TERM:-dumb}" LANG=C.UTF-8 \
      PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin "$@"
  }

  # The Python module-name workaround below; a change to it changes the stamp.
  python_module_links() {
    # Debian's ParaView and VTK CMake files name the Python modules
    # .../dist-packages/<package>/X.so (vtkmodules, paraview/modules,
    # paraview/incubator) while the packages ship X.cpython-3NN-<triplet>.so:
    # find_package(ParaView) stops on the missing files. A link X.so ->
    # X.cpython-...so for each file the CMake files name and miss.
    in_chroot bash -c '
      n=0
      for want in $(sed -n "s|.*\"\${_IMPORT_PREFIX}\(/lib/python3/dist-packages/[^\"]*\.so\)\".*|/usr\1|p" \
                      /usr/lib/*/cmake/*/*targets-*.cmake /usr/lib/*/cmake/*/*/*targets-*.cmake 2>/dev/null | sort -u); do
        [ -e "$want" ] && continue
        have="$(ls "${want%.so}".cpython-*.so 2>/dev/null | head -n 1)"
        [ -n "$have" ] || continue
        ln -s "$(basename "$have")" "$want"
        n=$((n + 1))
      done
      echo "sdk-chroot: $n Python module link(s) made"'
  }

  start=$SECONDS
  stamp_value="$(
    {
      bash "$root/scripts/install-deps.sh" --release "$release" --sdk --list
      declare -f python_module_links
    } | sha256sum | cut -d' ' -f1
  )"
  stamp="$chroot_dir/.bluenoise-sdk-stamp"
  if [ ! -f "$chroot_dir/.bluenoise-sdk-bootstrapped" ]; then
    command -v mmdebstrap >/dev/null || {
      apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends mmdebstrap
    }
    echo "=== sdk-chroot: bootstrapping $release in $chroot_dir"
    # Never remove through a mount left by a killed run (the source tree is
    # bind-mounted in the chroot).
    if awk -v d="$chroot_dir/" 'index($2, d) == 1 { found = 1 } END { exit !found }' /proc/mounts; then
      echo "sdk-chroot: mounts left under $chroot_dir; unmount them first" >&2
      exit 1
    fi
    rm -rf --one-file-system "$chroot_dir"
    # No documentation in the chroot, and dpkg without fsync (the tree is a
    # cache): smaller and quicker to set up. The
    # archive's Release files are accepted past their Valid-Until (sid's expire
    # within days; a mirror or a machine clock that lags or leads would fail).
    # The system PATH: its python3 for mmdebstrap's helpers, not a user's shim.
    PATH=/usr/sbin:/usr/bin:/sbin:/bin mmdebstrap --variant=apt --components=main \
      --aptopt='Acquire::Check-Valid-Until "false"' \
      --dpkgopt='path-exclude=/usr/share/man/*' --dpkgopt='path-exclude=/usr/share/doc/*' \
      --dpkgopt='path-include=/usr/share/doc/*/copyright' --dpkgopt='path-exclude=/usr/share/locale/*' \
      --dpkgopt='force-unsafe-io' \
      "$release" "$chroot_dir" "$mirror"
    touch "$chroot_dir/.bluenoise-sdk-bootstrapped"
  fi

  mount_in proc proc /proc
  mount_in rbind /dev /dev
  mount_in rbind /sys /sys
  mount_in bind "$root" "$root"
  cp /etc/resolv.conf "$chroot_dir/etc/resolv.conf" 2>/dev/null || true

  if [ "$(cat "$stamp" 2>/dev/null)" != "$stamp_value" ]; then
    echo "=== sdk-chroot: installing the packages of $release"
    # Without documentation, maintainer scripts that link into the man pages'
    # folders (update-alternatives of openjdk, pulled in by sid's VTK) need
    # them; an installation cut short before is finished first.
    in_chroot mkdir -p /usr/share/man/man1 /usr/share/man/man7
    in_chroot dpkg --configure -a
    in_chroot bash "$root/scripts/install-deps.sh" --release "$release" --sdk
    in_chroot apt-get clean
    python_module_links
    echo "$stamp_value" >"$stamp"
  fi
  echo "=== sdk-chroot: $release ready in $((SECONDS - start)) s"

  case "$mode" in
    --setup-only) exit 0 ;;
    --shell) in_chroot bash; exit $? ;;
  esac

  build="$root/_build/sdk-$release"
  start=$SECONDS
  in_chroot bash -c '
    set -euo pipefail
    root="$1" build="$2" jobs="$3"
    # The ParaView CMake directory of the release, whatever its version
    paraview_dir="$(ls -d /usr/lib/*/cmake/paraview-* | sort -V | tail -n 1)"
    echo "=== sdk-chroot: configure and build against $paraview_dir ($build)"
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DParaView_DIR="$paraview_dir"
    cmake --build "$build" -j "$jobs"' _ "$root" "$build" "$jobs"
  echo "=== sdk-chroot: $release build in $((SECONDS - start)) s"
  start=$SECONDS
  status=0
  in_chroot bash -c 'cd "$1" && ctest --output-on-failure -j "$2" --timeout 900' _ "$build" "$jobs" ||
    status=$?
  echo "=== sdk-chroot: $release tests in $((SECONDS - start)) s"
  exit $status
}
main "$@"
