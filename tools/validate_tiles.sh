#!/usr/bin/env bash
# Runs morphcut-city on every public real CityJSON file with buildings in
# ../shared/datasets/cityjson (from its MANIFEST.tsv; the synthetic conformance snippets and the
# schemas are left out), validates each output with `morphcut-city validate`, and prints per file
# and in total the share of output parts that pass.
#
# usage: tools/validate_tiles.sh [--bin PATH] [--threads N] [--config YAML] [--work DIR] [--only SUBSTRING] [--val3dity]
# Outputs, the validation JSON reports and failures.txt (every error of an invalid object) are
# kept in the work directory (default $TMPDIR/morphcut-validate).
# --val3dity also runs val3dity, the independent reference validator (tools/val3dity/check.py;
# built once by tools/val3dity/build.sh), on every CityJSON file the run wrote (the main output
# and one file per level) and adds three columns: val3dity errors on our parts, how many of them
# are 601 (overlapping parts), errors on the input's own geometry (not ours, listed only).
# Its summaries and reports are kept as <file>.val3dity.json and <file>.val3dity/.
set -euo pipefail

here="$(cd "$(dirname "$0")/.." && pwd)"
bin="$here/build/tools/morphcut-city"
threads=2
config=""
work="${TMPDIR:-/tmp}/morphcut-validate"
only=""
val3dity=0
while [ $# -gt 0 ]; do
  case "$1" in
    --bin) bin="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --config) config="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --val3dity) val3dity=1; shift ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "validate_tiles: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -x "$bin" ] || { echo "validate_tiles: $bin not built (cmake --build <dir> --target morphcut_city)" >&2; exit 2; }
data="$here/../shared/datasets/cityjson"
[ -f "$data/MANIFEST.tsv" ] || { echo "validate_tiles: $data/MANIFEST.tsv not found" >&2; exit 2; }
mkdir -p "$work"
: > "$work/failures.txt"
if [ "$val3dity" = 1 ]; then
  # Built before the loop so that its first (minutes-long) build is not charged to a file.
  v3bin="$("$here/tools/val3dity/build.sh" | tail -n 1)" || { echo "validate_tiles: val3dity could not be built" >&2; exit 2; }
fi

# Columns of MANIFEST.tsv: path ... n_building (7th).
mapfile -t files < <(awk -F'\t' 'NR > 1 && $7 > 0 && $1 !~ /^(cityjson-corpus|schemas)\// { print $1 }' "$data/MANIFEST.tsv")

count() { grep -o "\"$1\":[0-9.e+-]*" "$2" | tail -1 | cut -d: -f2; }

# One file's val3dity columns: our errors, of them 601, input errors ("err" when val3dity failed).
v3_columns() {
  python3 -c 'import json, sys
t = json.load(open(sys.argv[1]))["total"]
print(t["our_errors"], t["our_errors_by_code"].get("601", 0), t["input_errors"])' "$1"
}

v3_header=""; row='%-58s %6s %-24s %6s %6s %7s %8s %8s %s%s\n'
if [ "$val3dity" = 1 ]; then
  v3_header="$(printf ' %7s %7s %8s' v3_ours of_601 v3_input)"; row='%-58s %6s %-24s %6s %6s %7s %8s %8s %8s%s\n'
fi
# shellcheck disable=SC2059  # the row format is chosen above
printf "$row" file bldgs "ok/partial/failed/skip" parts valid invalid share exact maxdev \
  "$(printf ' %8s %6s %8s' repaired grid fallback)$v3_header"
tot_parts=0; tot_valid=0; tot_invalid_bldg=0; bad_files=0; tot_rep=0; tot_grid=0; tot_fb=0
tot_v3_ours=0; tot_v3_601=0; tot_v3_input=0; v3_failed=0
for rel in "${files[@]}"; do
  [ -z "$only" ] || [[ "$rel" == *"$only"* ]] || continue
  name="$(echo "$rel" | tr '/' '_')"
  ext=".city.json"; [[ "$rel" == *.jsonl ]] && ext=".city.jsonl"
  out="$work/${name%.*}.morphcut$ext"
  args=("$data/$rel" -o "$out" --threads "$threads" --report "$work/${name}.report.json" --no-summary --no-html)
  # Level files of an earlier run would otherwise be validated again with this run's output.
  rm -f "${out%"$ext"}".level-*"$ext"
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
  # Every file the run wrote: the annotated input and one city per level (docs/output-format.md).
  outs=("$out")
  for f in "${out%"$ext"}".level-*"$ext"; do [ -f "$f" ] && outs+=("$f"); done
  parts=0; valid=0; invalid=0; vfail=0; overlap_tests=0; maxdev=0; invalid_bldg=0
  for o in "${outs[@]}"; do
    vj="$work/$(basename "$o").validate.json"
    set +e
    "$bin" validate "$o" --json "$vj" > "$work/$(basename "$o").validate.txt"
    vrc=$?
    set -e
    grep -v -e '^VALID$' -e '^INVALID$' -e "^$o: " "$work/$(basename "$o").validate.txt" | sed "s|^|$rel: |" >> "$work/failures.txt" || true
    if [ "$vrc" -gt 1 ]; then vfail=1; continue; fi
    parts=$((parts + $(count parts "$vj"))); valid=$((valid + $(count valid_parts "$vj")))
    invalid=$((invalid + $(count invalid_parts "$vj"))); overlap_tests=$((overlap_tests + $(count overlap_tests "$vj")))
    invalid_bldg=$((invalid_bldg + $(count invalid_buildings "$vj")))
    maxdev="$(awk -v a="$maxdev" -v b="$(count max_volume_deviation "$vj")" 'BEGIN { print (b > a ? b : a) }')"
    [ "$o" = "$out" ] && j="$vj"
  done
  if [ "$vfail" = 1 ]; then
    printf '%-58s validate failed\n' "$rel"
    bad_files=$((bad_files + 1)); continue
  fi
  # Repairs on the output grid, from the run report: parts repaired, levels that needed vertex
  # clustering or non-conforming meshes, levels that fell back.
  read -r rep_parts grid_levels fallbacks < <(python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
b = [x for x in r["buildings"] if "sizes" in x]
print(sum(x["sizes"].get("parts_repaired", 0) for x in b),
      sum(1 for x in b for l in x.get("levels", []) if l.get("grid_repair")),
      sum(1 for x in b for l in x.get("levels", []) if l.get("fallback")))' "$work/${name}.report.json")
  tot_rep=$((tot_rep + rep_parts)); tot_grid=$((tot_grid + grid_levels)); tot_fb=$((tot_fb + fallbacks))
  share="-"; [ "$parts" -gt 0 ] && share="$(awk -v v="$valid" -v p="$parts" 'BEGIN { printf "%.2f%%", 100 * v / p }')"
  v3_cols=""
  if [ "$val3dity" = 1 ]; then
    set +e
    python3 "$here/tools/val3dity/check.py" --val3dity "$v3bin" --jobs "$threads" --report-dir "$work/${name}.val3dity" \
      --json "$work/${name}.val3dity.json" "${outs[@]}" > "$work/${name}.val3dity.txt" 2>&1
    v3rc=$?
    set -e
    if [ "$v3rc" -le 1 ]; then
      read -r v3o v3s v3i < <(v3_columns "$work/${name}.val3dity.json")
      grep '^OURS ' "$work/${name}.val3dity.txt" | sed "s|^|$rel: val3dity |" >> "$work/failures.txt" || true
      tot_v3_ours=$((tot_v3_ours + v3o)); tot_v3_601=$((tot_v3_601 + v3s)); tot_v3_input=$((tot_v3_input + v3i))
    else
      v3o=err; v3s=err; v3i=err; v3_failed=$((v3_failed + 1))
      echo "$rel: val3dity failed (exit $v3rc): $(tail -1 "$work/${name}.val3dity.txt")" >> "$work/failures.txt"
    fi
    v3_cols="$(printf ' %7s %7s %8s' "$v3o" "$v3s" "$v3i")"
  fi
  # shellcheck disable=SC2059
  printf "$row" "$rel" "$(count buildings "$j")" "$statuses" "$parts" "$valid" \
    "$invalid" "$share" "$overlap_tests" "$maxdev" "$(printf ' %8s %6s %8s' "$rep_parts" "$grid_levels" "$fallbacks")$v3_cols"
  tot_parts=$((tot_parts + parts)); tot_valid=$((tot_valid + valid))
  tot_invalid_bldg=$((tot_invalid_bldg + invalid_bldg))
done
share="-"; [ "$tot_parts" -gt 0 ] && share="$(awk -v v="$tot_valid" -v p="$tot_parts" 'BEGIN { printf "%.2f%%", 100 * v / p }')"
echo "total: $tot_valid of $tot_parts output parts valid ($share); $tot_invalid_bldg buildings with tiling errors;" \
     "$bad_files files not processed; errors in $work/failures.txt"
echo "repairs: $tot_rep parts repaired on the output grid; $tot_grid levels needed clustering or non-conforming meshes;" \
     "$tot_fb levels fell back"
if [ "$val3dity" = 1 ]; then
  echo "val3dity: $tot_v3_ours errors on our parts ($tot_v3_601 of them 601 overlaps), $tot_v3_input on the input's" \
       "own geometry; $v3_failed files val3dity could not check"
fi
