#!/usr/bin/env bash
# Installs every Debian package morphcut-city needs to build, test and run its demo.
# Idempotent and quiet when everything is present; run as root (or with sudo available).
set -euo pipefail

PKGS=(
  g++ cmake make ccache pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev
  libtbb-dev libembree-dev libgeographiclib-dev libproj-dev
  nlohmann-json3-dev libyaml-cpp-dev libxml2-dev
  python3  # tools/gen_citygml.py: the CityGML streaming-memory test generates its input
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev libspdlog-dev libfmt-dev
  libjemalloc-dev  # the executables' allocator (docs/design.md "The allocator")
  slurm-wlm munge  # tests/slurm: a one-node Slurm cluster on localhost for the job-array test
  clang-format  # tools/format.sh: the sources' style (.clang-format), checked by a test
  clang libclang-rt-14-dev  # tools/fuzz.sh: libFuzzer (libclang_rt.fuzzer) and clang's sanitizers
  libgeos-dev libboost-filesystem-dev  # tools/val3dity/build.sh: val3dity, the reference validator the tests run (with cmake, g++, CGAL, Eigen above)
  chromium  # tests/tools/html_browser_test.mjs: the HTML report in a real (headless) browser
  libgdal-dev gdal-bin python3-networkx  # massing analytics: GeoPackage output (GDAL/OGR, GEOS unions), ogrinfo and networkx in the tests
  python3-matplotlib  # tools/render-parts: PNGs of each building's parts coloured by role (and its test, ctest -R render_parts)
)

missing=()
for p in "${PKGS[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "setup-deps: installing ${missing[*]}" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Optional: a JSON-schema validator for the output-schema tests (npm registry).
# Tests that need it skip with a clear message when it cannot be installed.
if [ "${MC_SKIP_NODE_TOOLS:-0}" != "1" ] && command -v npm >/dev/null 2>&1; then
  here="$(cd "$(dirname "$0")/.." && pwd)"
  if [ ! -x "$here/build/node_tools/node_modules/.bin/ajv" ]; then
    mkdir -p "$here/build/node_tools"
    (cd "$here/build/node_tools" && npm install --silent --no-audit --no-fund ajv-cli@5 ajv-formats@2 >/dev/null 2>&1) \
      || echo "setup-deps: ajv-cli could not be installed; schema tests will be skipped" >&2
  fi
fi
# three.js (the HTML report's 3D view) and playwright-core (its browser test), pinned.
bash "$(dirname "$0")/html/setup.sh"
exit 0
