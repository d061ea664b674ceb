#!/usr/bin/env bash
# Submits a tile list to Slurm: a job array (one task per tile, morphcut-array.sbatch) and the
# aggregation job (merge.sbatch) that runs after the whole array, whatever its tasks' outcome.
#
#   tools/slurm/submit.sh TILELIST OUTDIR [--config F] [--cache DIR] [--timeout S] [--retries N]
#                         [--backoff S] [--force] [--cpus N] [--max-parallel M] [--sbatch "ARGS"]
#
# --cpus: CPUs per array task (= morphcut-city --threads), default 2. --max-parallel: at most M
# tasks at once (sbatch's %M). --sbatch: extra sbatch arguments for both jobs (partition, time,
# account...). Prints "<array job id> <merge job id>" on stdout. Outputs: OUTDIR/<stem>.morphcut.*
# per tile, OUTDIR/merged.report.json + OUTDIR/merged.csv, logs in OUTDIR/logs/.
# MORPHCUT_CITY selects the binary (default: build/tools/morphcut-city of this checkout, else PATH).
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
usage() { sed -n '2,13p' "$0" >&2; exit 2; }
[ $# -ge 2 ] || usage
list="$(realpath "$1")" outdir="$2"
shift 2
cpus=2 max_parallel="" extra_sbatch="" tile_opts=()
while [ $# -gt 0 ]; do
  case "$1" in
    --config | --cache) tile_opts+=("$1" "$(realpath "$2")"); shift 2 ;;
    --timeout | --retries | --backoff) tile_opts+=("$1" "$2"); shift 2 ;;
    --force) tile_opts+=("$1"); shift ;;
    --cpus) cpus="$2"; shift 2 ;;
    --max-parallel) max_parallel="%$2"; shift 2 ;;
    --sbatch) extra_sbatch="$2"; shift 2 ;;
    *) usage ;;
  esac
done

bin="${MORPHCUT_CITY:-$here/../../build/tools/morphcut-city}"
[ -x "$bin" ] || bin="$(command -v morphcut-city || true)"
if [ -z "$bin" ] || [ ! -x "$bin" ]; then echo "submit: morphcut-city not found (set MORPHCUT_CITY)" >&2; exit 2; fi
bin="$(realpath "$bin")"
n="$(grep -c -v -E '^[[:space:]]*(#|$)' "$list" || true)"
[ "$n" -gt 0 ] || { echo "submit: no tiles in $list" >&2; exit 2; }
# Outputs are named after the tile's stem: two tiles with one stem would overwrite each other.
dups="$(grep -v -E '^[[:space:]]*(#|$)' "$list" | sed -E -e 's/[[:space:]]*$//' -e 's|.*/||' \
  -e 's/\.(city\.jsonl|city\.json|jsonl|json)$//' | sort | uniq -d)"
if [ -n "$dups" ]; then echo "submit: tiles with the same stem in $list: $dups" >&2; exit 2; fi
mkdir -p "$outdir/logs"
outdir="$(realpath "$outdir")"

export MC_SLURM_DIR="$here" MORPHCUT_CITY="$bin"
# shellcheck disable=SC2086  # extra_sbatch is a list of arguments
array_id="$(sbatch --parsable $extra_sbatch --array="0-$((n - 1))$max_parallel" --cpus-per-task="$cpus" \
  --output="$outdir/logs/tile_%A_%a.log" --export=ALL "$here/morphcut-array.sbatch" "$list" "$outdir" \
  ${tile_opts[@]+"${tile_opts[@]}"})"
array_id="${array_id%%;*}"
# shellcheck disable=SC2086
merge_id="$(sbatch --parsable $extra_sbatch --dependency="afterany:$array_id" --output="$outdir/logs/merge_%j.log" \
  --export=ALL "$here/merge.sbatch" "$list" "$outdir")"
merge_id="${merge_id%%;*}"
echo "submit: $n tiles: array job $array_id, merge job $merge_id -> $outdir/merged.report.json" >&2
echo "$array_id $merge_id"
