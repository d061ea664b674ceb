#!/usr/bin/env bash
# Runs morphcut-city on every public real CityJSON file with buildings in
# ../shared/datasets/cityjson (from its MANIFEST.tsv; the synthetic conformance snippets and the
# schemas are left out), validates each output with `morphcut-city validate`, and prints per file
# and in total the share of output parts that pass (issue #6: target 100%).
#
# usage: tools/validate_tiles.sh [--bin PATH] [--threads N] [--config YAML] [--work DIR] [--only SUBSTRING]
# Outputs, the validation JSON reports and failures.txt (every error of an invalid object) are
# kept in the work directory (default $TMPDIR/morphcut-validate).
set -euo pipefail

here="$(cd "$(dirname "$0")/.." && pwd)"
bin="$here/build/tools/morphcut-city"
threads=2
config=""
work="${TMPDIR:-/tmp}/morphcut-validate"
only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --bin) bin="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --config) config="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "validate_tiles: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -x "$bin" ] || { echo "validate_tiles: $bin not built (cmake --build <dir> --target morphcut_city)" >&2; exit 2; }
data="$here/../shared/datasets/cityjson"
[ -f "$data/MANIFEST.tsv" ] || { echo "validate_tiles: $data/MANIFEST.tsv not found" >&2; exit 2; }
mkdir -p "$work"
: > "$work/failures.txt"

# Columns of MANIFEST.tsv: path ... n_building (7th).
mapfile -t files < <(awk -F'\t' 'NR > 1 && $7 > 0 && $1 !~ /^(cityjson-corpus|schemas)\// { print $1 }' "$data/MANIFEST.tsv")

count() { grep -o "\"$1\":[0-9.e+-]*" "$2" | tail -1 | cut -d: -f2; }

printf '%-58s %6s %-24s %6s %6s %7s %8s %8s %s\n' file bldgs "ok/partial/failed/skip" parts valid invalid share exact maxdev
tot_parts=0; tot_valid=0; tot_invalid_bldg=0; bad_files=0
for rel in "${files[@]}"; do
  [ -z "$only" ] || [[ "$rel" == *"$only"* ]] || continue
  name="$(echo "$rel" | tr '/' '_')"
  ext=".city.json"; [[ "$rel" == *.jsonl ]] && ext=".city.jsonl"
  out="$work/${name%.*}.morphcut$ext"
  args=("$data/$rel" -o "$out" --threads "$threads" --no-report --no-summary)
  [ -z "$config" ] || args+=(--config "$config")
  set +e
  "$bin" "${args[@]}" 2> "$work/${name}.run.log"
  rc=$?
  set -e
  if [ "$rc" -gt 1 ]; then
    printf '%-58s run failed (exit %d): %s\n' "$rel" "$rc" "$(tail -1 "$work/${name}.run.log")"
    bad_files=$((bad_files + 1)); continue
  fi
  statuses="$(grep -o '[0-9]* ok, [0-9]* partial, [0-9]* failed, [0-9]* skipped' "$work/${name}.run.log" | tail -1 |
              awk '{ print $1 "/" $3 "/" $5 "/" $7 }')"
  set +e
  "$bin" validate "$out" --json "$work/${name}.validate.json" > "$work/${name}.validate.txt"
  vrc=$?
  set -e
  grep -v -e '^VALID$' -e '^INVALID$' -e "^$out: " "$work/${name}.validate.txt" | sed "s|^|$rel: |" >> "$work/failures.txt" || true
  if [ "$vrc" -gt 1 ]; then
    printf '%-58s validate failed (exit %d)\n' "$rel" "$vrc"
    bad_files=$((bad_files + 1)); continue
  fi
  j="$work/${name}.validate.json"
  parts=$(count parts "$j"); valid=$(count valid_parts "$j"); invalid=$(count invalid_parts "$j")
  share="-"; [ "$parts" -gt 0 ] && share="$(awk -v v="$valid" -v p="$parts" 'BEGIN { printf "%.2f%%", 100 * v / p }')"
  printf '%-58s %6s %-24s %6s %6s %7s %8s %8s %s\n' "$rel" "$(count buildings "$j")" "$statuses" "$parts" "$valid" \
    "$invalid" "$share" "$(count overlap_tests "$j")" "$(count max_volume_deviation "$j")"
  tot_parts=$((tot_parts + parts)); tot_valid=$((tot_valid + valid))
  tot_invalid_bldg=$((tot_invalid_bldg + $(count invalid_buildings "$j")))
done
share="-"; [ "$tot_parts" -gt 0 ] && share="$(awk -v v="$tot_valid" -v p="$tot_parts" 'BEGIN { printf "%.2f%%", 100 * v / p }')"
echo "total: $tot_valid of $tot_parts output parts valid ($share); $tot_invalid_bldg buildings with tiling errors;" \
     "$bad_files files not processed; errors in $work/failures.txt"
