#!/usr/bin/env bash
# tools/slurm/run-local.sh (the Slurm path without Slurm) on two small tiles: merged outputs,
# re-runs that skip up-to-date tiles and redo only a changed one, and a forced re-run served from
# the cache with byte-identical outputs.
#
#   tests/slurm/run_local_test.sh BUILD_DIR
set -euo pipefail

src="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$src/build}")"
export MORPHCUT_CITY="$build/tools/morphcut-city"
[ -x "$MORPHCUT_CITY" ] || { echo "FAIL: $MORPHCUT_CITY not built"; exit 1; }
tmp="$(mktemp -d /tmp/mc_run_local_test.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cd "$tmp"

head -n 6 "$src/datasets/3dbag/3dbag_5910.city.jsonl" >a.city.jsonl  # 5 buildings
cp "$src/datasets/3dbag/3dbag_b2.city.json" b.city.json             # 2 buildings
printf '%s\n' a.city.jsonl "# a comment" b.city.json >tiles.txt
run() { "$src/tools/slurm/run-local.sh" tiles.txt out --threads 2 --cache cache "$@" 2>"log.$runs"; }

runs=1
run || fail "first run exited $?: $(cat log.1)"
python3 - <<'EOF'
import csv, json
m = json.load(open("out/merged.report.json"))
t = m["totals"]
assert [x["tile"] for x in m["tiles"]] == ["a", "b"], m["tiles"]
assert t["merged"] == 2 and t["building_count"] == 7 == len(m["buildings"]), t
rows = list(csv.reader(open("out/merged.csv", newline="")))
assert rows[0][0] == "tile" and len(rows) == 8 and {r[0] for r in rows[1:]} == {"a", "b"}, rows[:2]
EOF
cp out/a.morphcut.city.jsonl first_a.city.jsonl

runs=2
run || fail "second run exited $?"
[ "$(grep -c 'up to date, skipped' log.2)" -eq 2 ] || fail "an unchanged tile was redone: $(cat log.2)"

touch b.city.json  # a changed input: only its tile is redone
runs=3
run || fail "third run exited $?"
grep -q '\[a.city.jsonl\]: up to date' log.3 || fail "tile a should be skipped: $(cat log.3)"
grep -q '\[b.city.json\]: done' log.3 || fail "tile b should be redone: $(cat log.3)"

runs=4
run --force || fail "forced run exited $?"
python3 - <<'EOF'
import json
for tile, n in (("a", 5), ("b", 2)):
    c = json.load(open(f"out/{tile}.morphcut.report.json"))["cache"]
    assert c["hits"] == n and c["misses"] == 0, (tile, c)
EOF
cmp -s first_a.city.jsonl out/a.morphcut.city.jsonl || fail "the cached re-run wrote different bytes"
echo "PASS: run-local: merged 2 tiles / 7 buildings; up-to-date tiles skipped, a touched tile redone, forced re-run all cache hits with identical output"
