#!/usr/bin/env bash
# Builds val3dity 2.6.0, the field's reference validator (GPL-3), as a separate program in a
# cache directory outside the source tree, and prints the path of its binary as the last line
# on stdout. The project never links or copies val3dity: tools/val3dity/check.py only runs the
# binary on output files, so it stays an independent check of morphcut-city's geometry.
#
# usage: tools/val3dity/build.sh
# env:   MC_VAL3DITY_DIR      cache directory (default ${MC_TOOL_CACHE:-$HOME/.cache/morphcut-city}/val3dity-2.6.0)
#        MC_VAL3DITY_TARBALL  source tarball (default ../shared/peers/val3dity/val3dity-2.6.0-src.tar.gz
#                             relative to the repository root)
#        MC_VAL3DITY_JOBS     parallel compile jobs (default nproc)
#
# Idempotent: when the binary exists it only prints its path (a no-op in milliseconds); a cold
# build takes minutes (CGAL), so it is built once per machine and cache directory. Quiet on
# success: cmake's output goes to build.log in the cache directory, whose tail is printed on
# failure. Needs the Debian packages listed in tools/setup-deps.sh (cmake g++ libcgal-dev
# libeigen3-dev libgeos-dev libboost-filesystem-dev); val3dity ships its other dependencies.
set -euo pipefail

here="$(cd "$(dirname "$0")/../.." && pwd)"
cache="${MC_VAL3DITY_DIR:-${MC_TOOL_CACHE:-$HOME/.cache/morphcut-city}/val3dity-2.6.0}"
tarball="${MC_VAL3DITY_TARBALL:-$here/../shared/peers/val3dity/val3dity-2.6.0-src.tar.gz}"
jobs="${MC_VAL3DITY_JOBS:-$(nproc)}"
bin="$cache/build/val3dity"

if [ -x "$bin" ]; then
  echo "$bin"
  exit 0
fi

[ -f "$tarball" ] || { echo "val3dity/build.sh: source tarball $tarball not found" >&2; exit 2; }
mkdir -p "$cache"
log="$cache/build.log"

# Two test runs (or a test and a person) may ask for val3dity at the same time: the second
# waits for the first build instead of building into the same directory concurrently.
exec 9> "$cache/.lock"
flock 9
if [ -x "$bin" ]; then
  echo "$bin"
  exit 0
fi

fail() {
  echo "val3dity/build.sh: $1 failed; last lines of $log:" >&2
  tail -n 40 "$log" >&2
  exit 2
}

# A fresh source tree and build directory: a half-finished earlier attempt leaves no state
# behind that could make this build differ from a clean one. The tarball has no top folder.
: > "$log"
rm -rf "$cache/src" "$cache/build"
mkdir -p "$cache/src" "$cache/build"
tar -xzf "$tarball" -C "$cache/src" >> "$log" 2>&1 || fail "extracting $tarball"

# ccache makes a rebuild after the cache directory was removed take seconds instead of minutes.
launcher=()
if command -v ccache > /dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi

start=$SECONDS
{
  echo "== cmake configure"
  cmake -S "$cache/src" -B "$cache/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}"
} >> "$log" 2>&1 || fail "cmake configure"
{
  echo "== cmake build (-j $jobs)"
  cmake --build "$cache/build" -j "$jobs"
} >> "$log" 2>&1 || fail "cmake build"
[ -x "$bin" ] || fail "cmake build (no binary at $bin)"
echo "== built $bin in $((SECONDS - start)) s" >> "$log"
echo "$bin"
