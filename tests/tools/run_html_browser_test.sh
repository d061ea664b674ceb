#!/usr/bin/env bash
# ctest html_browser: the HTML report in headless Chromium (tests/tools/html_browser_test.mjs).
#   run_html_browser_test.sh BUILD_DIR NODE_MODULES_DIR
# Runs morphcut-city on the first 40 buildings of the 3D BAG demo tile (a few seconds; the whole
# tile takes minutes) and loads the page it writes by default; MC_HTML_TEST_PAGE=PAGE.html tests
# an existing page instead (e.g. build/demo/demo.morphcut.html after `make demo`).
# Artefacts (screenshots, the page, the run's log) stay in BUILD_DIR/html_browser_test/.
# Exit 77 (ctest: skipped) without node, /usr/bin/chromium or the pinned npm packages
# (tools/html/setup.sh), or when the binary was built without three.js.
set -euo pipefail
build="$(cd "$1" && pwd)"
modules="$2"
src="$(cd "$(dirname "$0")/../.." && pwd)"
out="$build/html_browser_test"
skip() { echo "SKIPPED: $*"; exit 77; }
command -v node >/dev/null 2>&1 || skip "node not found"
[ -x /usr/bin/chromium ] || skip "/usr/bin/chromium not installed (Debian package chromium; tools/setup-deps.sh)"
[ -d "$modules/playwright-core" ] || skip "playwright-core not installed in $modules (tools/html/setup.sh)"
rm -rf "$out"
mkdir -p "$out"
if [ -n "${MC_HTML_TEST_PAGE:-}" ]; then
  page="$MC_HTML_TEST_PAGE"
else
  # CityJSONSeq: the header line, then one building per line.
  head -n 41 "$src/datasets/3dbag/3dbag_5910.city.jsonl" > "$out/tile.city.jsonl"
  rc=0
  "$build/tools/morphcut-city" "$out/tile.city.jsonl" -o "$out/tile.morphcut.city.jsonl" --threads 2 \
    2> "$out/run.log" || rc=$?
  cat "$out/run.log"
  [ "$rc" -le 1 ] || { echo "morphcut-city exited with $rc"; exit 1; }
  page="$out/tile.morphcut.html"
  [ -f "$page" ] || { echo "no page written at $page"; exit 1; }
fi
grep -q "var THREE = " "$page" || skip "the page has no three.js (binary built without tools/html/setup.sh's bundle)"
node "$src/tests/tools/html_browser_test.mjs" --page "$page" --out "$out" --node-modules "$modules" \
  --max-interactive-ms "${MC_HTML_MAX_INTERACTIVE_MS:-2000}"
