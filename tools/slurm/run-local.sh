#!/usr/bin/env bash
# The Slurm path without Slurm: every tile of the list in turn (process-tile.sh, same outputs,
# same skipping of up-to-date tiles, same retries), then merge-reports.
#
#   tools/slurm/run-local.sh TILELIST OUTDIR [--threads N] [--config F] [--cache DIR] [--timeout S]
#                            [--retries N] [--backoff S] [--force]
#
# Exits 0 when every tile ran clean and merged; otherwise the highest exit code seen (1: some
# buildings partial/failed or a tile missing from the merge; 2 and above: a tile failed).
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
[ $# -ge 2 ] || { sed -n '2,9p' "$0" >&2; exit 2; }
list="$1" outdir="$2"
shift 2
threads="$(nproc)"
opts=()
while [ $# -gt 0 ]; do
  case "$1" in
    --threads) threads="$2"; shift 2 ;;
    --force) opts+=("$1"); shift ;;
    *) [ $# -ge 2 ] || { echo "run-local: $1 needs a value" >&2; exit 2; }; opts+=("$1" "$2"); shift 2 ;;
  esac
done
bin="${MORPHCUT_CITY:-$here/../../build/tools/morphcut-city}"
[ -x "$bin" ] || bin="$(command -v morphcut-city || true)"
if [ -z "$bin" ] || [ ! -x "$bin" ]; then echo "run-local: morphcut-city not found (set MORPHCUT_CITY)" >&2; exit 2; fi
MORPHCUT_CITY="$(realpath "$bin")"
export MORPHCUT_CITY

# Outputs are named after the tile's stem: two tiles with one stem would overwrite each other.
dups="$(grep -v -E '^[[:space:]]*(#|$)' "$list" | sed -E -e 's/[[:space:]]*$//' -e 's|.*/||' \
  -e 's/\.(city\.jsonl|city\.json|jsonl|json)$//' | sort | uniq -d)"
if [ -n "$dups" ]; then echo "run-local: tiles with the same stem in $list: $dups" >&2; exit 2; fi
worst=0
while IFS= read -r tile; do
  code=0
  "$here/process-tile.sh" "$tile" "$outdir" --threads "$threads" ${opts[@]+"${opts[@]}"} || code=$?
  [ "$code" -gt "$worst" ] && worst=$code
done < <(grep -v -E '^[[:space:]]*(#|$)' "$list" | sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//')

code=0
"$MORPHCUT_CITY" merge-reports --tiles "$list" --dir "$outdir" -o "$outdir/merged.report.json" --csv "$outdir/merged.csv" || code=$?
[ "$code" -gt "$worst" ] && worst=$code
exit "$worst"
