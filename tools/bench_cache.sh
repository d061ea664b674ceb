#!/usr/bin/env bash
# Incremental reprocessing with the per-building cache (morphcut-city --cache) on the 3D BAG tile:
#   cold    empty cache: every building computed and stored
#   warm    the same tile again: every complete building a hit (outputs must be byte-identical)
#   5%      a copy of the tile with every 20th building moved 1 m east: those miss, the rest hit
# Prints wall times, hits/misses and the speed-ups cold/warm and cold/5%.
# Usage: tools/bench_cache.sh [BUILD_DIR] [INPUT.city.json]
set -euo pipefail

here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
input="${2:-$here/datasets/3dbag/3dbag_5910.city.json}"
bin="$build/tools/morphcut-city"
[ -x "$bin" ] || { echo "bench_cache: $bin not built" >&2; exit 2; }
threads="${THREADS:-2}"

work="$(mktemp -d "${TMPDIR:-/tmp}/mc_bench_cache.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# Every 20th Building (sorted ids) gets its own copies of its vertices, 1 m further east; the
# other buildings and the vertex list they use are untouched.
python3 - "$input" "$work/changed.city.json" <<'EOF'
import json, sys
doc = json.load(open(sys.argv[1]))
objs, verts = doc["CityObjects"], doc["vertices"]
east = round(1.0 / doc["transform"]["scale"][0]) if "transform" in doc else 1.0
tops = sorted(k for k, o in objs.items() if o["type"] == "Building" and not o.get("parents"))
changed = tops[::20]
def shift(node, remap):
    if isinstance(node, list):
        return [shift(c, remap) for c in node]
    if node not in remap:
        x, y, z = verts[node]
        remap[node] = len(verts)
        verts.append([x + east, y, z])
    return remap[node]
for b in changed:
    remap = {}
    for oid in [b] + objs[b].get("children", []):
        for g in objs[oid].get("geometry", []):
            g["boundaries"] = shift(g["boundaries"], remap)
json.dump(doc, open(sys.argv[2], "w"), separators=(",", ":"))
print(f"changed {len(changed)} of {len(tops)} buildings", file=sys.stderr)
EOF

run() {  # name input -> "wall cpu" seconds on stdout (cpu = user + system, robust to a busy machine)
  local name="$1" in="$2" t
  t="$( { TIMEFORMAT='%R %U %S'; time "$bin" "$in" --cache "$work/cache" --threads "$threads" -q \
    -o "$work/$name.city.json" --report "$work/$name.report.json" --summary "$work/$name.csv" \
    || [ $? -eq 1 ]; } 2>&1 >/dev/null | tail -n 1)"
  awk '{ printf "%.2f %.2f\n", $1, $2 + $3 }' <<<"$t"
}
cache_counts() {
  python3 -c 'import json,sys; c=json.load(open(sys.argv[1]))["cache"]; print(c["hits"], "hits /", c["misses"], "misses")' "$1"
}

read -r cold cold_cpu < <(run cold "$input")
read -r warm warm_cpu < <(run warm "$input")
read -r changed changed_cpu < <(run changed "$work/changed.city.json")

cmp -s "$work/cold.city.json" "$work/warm.city.json" || { echo "bench_cache: warm output differs from cold" >&2; exit 1; }
cmp -s "$work/cold.csv" "$work/warm.csv" || { echo "bench_cache: warm CSV differs from cold" >&2; exit 1; }

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1fx", a / b }'; }
printf '%-22s %9s %9s  %s\n' run "wall (s)" "CPU (s)" "cache"
printf '%-22s %9.2f %9.2f  %s\n' "cold (empty cache)" "$cold" "$cold_cpu" "$(cache_counts "$work/cold.report.json")"
printf '%-22s %9.2f %9.2f  %s\n' "warm (unchanged)" "$warm" "$warm_cpu" "$(cache_counts "$work/warm.report.json")"
printf '%-22s %9.2f %9.2f  %s\n' "5% buildings changed" "$changed" "$changed_cpu" "$(cache_counts "$work/changed.report.json")"
echo "speed-up warm: $(ratio "$cold" "$warm") wall, $(ratio "$cold_cpu" "$warm_cpu") CPU;" \
  "5% changed: $(ratio "$cold" "$changed") wall, $(ratio "$cold_cpu" "$changed_cpu") CPU" \
  "(threads $threads; load average $(cut -d' ' -f1 /proc/loadavg); warm output byte-identical to cold)"
