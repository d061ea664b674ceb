#!/usr/bin/env bash
# npm packages of the HTML report (report/html_report.cpp), pinned, into build/node_tools/html:
#   three            the page's 3D view; bundled by tools/html/bundle_three.mjs into one classic
#                    script (three-bundle.js, MIT licence text kept) that CMake embeds into the
#                    binary at build time (report/html/assets.cmake)
#   playwright-core  drives Debian's chromium in tests/tools/html_browser_test.mjs (no browser
#                    download: it uses /usr/bin/chromium)
# Idempotent and quiet when the pinned versions are present. Without npm, or when the registry
# cannot be reached, it warns and exits 0: the page then has no 3D view and the browser test skips.
set -euo pipefail

THREE_VERSION=0.170.0
PLAYWRIGHT_CORE_VERSION=1.65.1

root="$(cd "$(dirname "$0")/../.." && pwd)"
dir="$root/build/node_tools/html"
want="three@$THREE_VERSION playwright-core@$PLAYWRIGHT_CORE_VERSION"

if [ "${MC_SKIP_NODE_TOOLS:-0}" = "1" ] || ! command -v npm >/dev/null 2>&1 || ! command -v node >/dev/null 2>&1; then
  exit 0
fi
if [ -f "$dir/three-bundle.js" ] && [ "$(cat "$dir/.versions" 2>/dev/null)" = "$want" ]; then
  exit 0
fi

mkdir -p "$dir"
cd "$dir"
[ -f package.json ] || echo '{"private": true}' > package.json
if ! npm install --silent --no-audit --no-fund --save-exact "three@$THREE_VERSION" \
    "playwright-core@$PLAYWRIGHT_CORE_VERSION" >/dev/null 2>&1; then
  echo "setup-deps: three/playwright-core could not be installed; the HTML report has no 3D view" >&2
  exit 0
fi
if ! node "$root/tools/html/bundle_three.mjs" node_modules/three three-bundle.js.tmp; then
  rm -f three-bundle.js.tmp
  echo "setup-deps: three.js could not be bundled; the HTML report has no 3D view" >&2
  exit 0
fi
mv -f three-bundle.js.tmp three-bundle.js
echo "$want" > .versions
