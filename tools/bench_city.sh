#!/usr/bin/env bash
# Benchmark of morphcut-city on the 3D BAG tile (432 buildings) as .city.json and .city.jsonl,
# and on the tile replicated N times (ids made unique), to show that the rate holds and memory
# stays flat as the input grows (issue #5: peak RSS < 1 GB, and within 1.2x at 10x the input).
#
# usage: tools/bench_city.sh [--bin PATH] [--threads N] [--replicas N] [--config YAML]
#                            [--work DIR] [--only 1x|Nx] [-- extra morphcut-city args]
# Prints one row per run: input, buildings, wall s, buildings/s, ok/partial/failed/skipped,
# peak RSS (MB, from /usr/bin/time -v, else from the run report's getrusage figure).
set -euo pipefail

here="$(cd "$(dirname "$0")/.." && pwd)"
bin="$here/build/tools/morphcut-city"
[ -x "$bin" ] || bin="$here/build-pipe/tools/morphcut-city"
threads=2
replicas=10
config=""
work="${TMPDIR:-/tmp}/morphcut-bench"
only=""
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --bin) bin="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --replicas) replicas="$2"; shift 2 ;;
    --config) config="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "bench_city: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -x "$bin" ] || { echo "bench_city: $bin not built (cmake --build <dir> --target morphcut_city)" >&2; exit 2; }

# The tile as bundled in datasets/ (a fresh clone has it), else the copy in ../shared.
tile_json="" tile_jsonl=""
for stem in "$here/datasets/3dbag/3dbag_5910" "$here/../shared/datasets/cityjson/upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20"; do
  if [ -f "$stem.city.json" ] && [ -f "$stem.city.jsonl" ]; then tile_json="$stem.city.json"; tile_jsonl="$stem.city.jsonl"; break; fi
done
[ -n "$tile_json" ] || { echo "bench_city: 3D BAG tile not found" >&2; exit 2; }
mkdir -p "$work"

# The tile N times, every object id suffixed with the copy number (also in parents/children).
replicate() {  # in out n
  python3 - "$1" "$2" "$3" <<'PY'
import json, sys
src, dst, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
def rename(objs, k):
    r = lambda i: f"{i}~{k}" if k else i
    out = {}
    for oid, o in objs.items():
        o = json.loads(json.dumps(o))
        for key in ("children", "parents"):
            if key in o: o[key] = [r(c) for c in o[key]]
        out[r(oid)] = o
    return out
def shift(node, base):
    if isinstance(node, list): return [shift(c, base) for c in node]
    return node + base if isinstance(node, int) and node >= 0 else node
if src.endswith(".jsonl"):
    lines = open(src).read().splitlines()
    with open(dst, "w") as f:
        f.write(lines[0] + "\n")
        for k in range(n):
            for line in lines[1:]:
                if not line.strip(): continue
                j = json.loads(line)
                j["id"] = f"{j['id']}~{k}" if k else j["id"]
                j["CityObjects"] = rename(j["CityObjects"], k)
                f.write(json.dumps(j, separators=(",", ":")) + "\n")
else:
    d = json.load(open(src))
    objs, verts = {}, []
    for k in range(n):
        base = len(verts)
        for oid, o in rename(d["CityObjects"], k).items():
            for g in o.get("geometry", []):
                if "boundaries" in g: g["boundaries"] = shift(g["boundaries"], base)
            objs[oid] = o
        verts += d["vertices"]
    d["CityObjects"], d["vertices"] = objs, verts
    json.dump(d, open(dst, "w"), separators=(",", ":"))
PY
}

run_one() {  # input label
  local input="$1" label="$2" out ext
  ext=".city.json"; [[ "$input" == *.jsonl ]] && ext=".city.jsonl"
  out="$work/$label"
  local args=("$input" --threads "$threads" -q -o "$out$ext" --report "$out.report.json" --summary "$out.csv")
  [ -n "$config" ] && args+=(--config "$config")
  args+=("${extra[@]}")
  local rc=0
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -v -o "$out.time" "$bin" "${args[@]}" || rc=$?
  else
    "$bin" "${args[@]}" || rc=$?
  fi
  if [ "$rc" -ge 2 ]; then echo "bench_city: $label failed with exit code $rc" >&2; return; fi
  python3 - "$out.report.json" "$out.time" "$label" <<'PY'
import json, os, re, sys
r = json.load(open(sys.argv[1]))
rss = r.get("peak_rss_mb")
if os.path.exists(sys.argv[2]):
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(sys.argv[2]).read())
    if m: rss = int(m.group(1)) / 1024
c = r["counts"]
print(f"{sys.argv[3]:<22} {r['building_count']:>9} {r['wall_seconds']:>9.1f} {r['buildings_per_second']:>8.2f} "
      f"{c['ok']:>6}/{c['partial']}/{c['failed']}/{c['skipped']:<8} {rss:>10.1f}")
PY
}

printf "%-22s %9s %9s %8s %-17s %10s\n" input buildings wall_s bldg/s ok/part/fail/skip peak_MB
if [ "$only" != "Nx" ]; then
  run_one "$tile_json" "tile.json"
  run_one "$tile_jsonl" "tile.jsonl"
fi
if [ "$only" != "1x" ] && [ "$replicas" -gt 1 ]; then
  replicate "$tile_json" "$work/tile_x$replicas.city.json" "$replicas"
  replicate "$tile_jsonl" "$work/tile_x$replicas.city.jsonl" "$replicas"
  run_one "$work/tile_x$replicas.city.json" "tile_x$replicas.json"
  run_one "$work/tile_x$replicas.city.jsonl" "tile_x$replicas.jsonl"
fi
