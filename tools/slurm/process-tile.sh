#!/usr/bin/env bash
# One tile through morphcut-city, idempotently: the unit of work of both the Slurm array
# (morphcut-array.sbatch) and run-local.sh.
#
#   process-tile.sh TILE OUTDIR [--config F] [--cache DIR] [--threads N] [--timeout S]
#                   [--retries N] [--backoff S] [--force]
#
# Outputs, named after the input's stem (as morphcut-city names them), so a re-run overwrites:
#   OUTDIR/<stem>.morphcut.city.json (.city.jsonl for CityJSONSeq input): the annotated input
#   OUTDIR/<stem>.morphcut.level-<t>.city.json[l]: one city per level (docs/output-format.md)
#   OUTDIR/<stem>.morphcut.report.json, OUTDIR/<stem>.morphcut.csv
# The tile is skipped when all three exist and are newer than the input, the config file and the
# morphcut-city binary (--force redoes it). morphcut-city writes atomically, so a tile killed
# half-way leaves no output and is redone by the next run.
# A run that exits 0 (all ok) or 1 (some buildings partial/failed, outputs complete) is final;
# any other exit (read/write error, crash, signal) is retried up to --retries times with
# exponential backoff (--backoff, 2x each time). The script exits with morphcut-city's last code.
# A building that crashes morphcut-city is recorded in <output>.crashed (pipeline/crash_guard),
# so the retry writes it through as failed and completes the tile instead of crashing again.
set -euo pipefail

usage() { echo "usage: process-tile.sh TILE OUTDIR [--config F] [--cache DIR] [--threads N] [--timeout S] [--retries N] [--backoff S] [--force]" >&2; exit 2; }
[ $# -ge 2 ] || usage
tile="$1" outdir="$2"
shift 2
config="" cache="" threads=0 timeout="" retries=2 backoff=5 force=0
while [ $# -gt 0 ]; do
  case "$1" in
    --config) config="$2"; shift 2 ;;
    --cache) cache="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --timeout) timeout="$2"; shift 2 ;;
    --retries) retries="$2"; shift 2 ;;
    --backoff) backoff="$2"; shift 2 ;;
    --force) force=1; shift ;;
    *) usage ;;
  esac
done

bin="${MORPHCUT_CITY:-$(command -v morphcut-city || true)}"
if [ -z "$bin" ] || [ ! -x "$bin" ]; then echo "process-tile: morphcut-city not found (set MORPHCUT_CITY)" >&2; exit 2; fi
[ -r "$tile" ] || { echo "process-tile: cannot read tile $tile" >&2; exit 2; }
log() { echo "$(date -u +%FT%TZ) process-tile [$(basename "$tile")]: $*" >&2; }

# The stem rule of morphcut-city (tools/morphcut_city.cpp, report/merge_reports.cpp).
name="$(basename "$tile")"
stem="$name"
for ext in .city.jsonl .city.json .jsonl .json; do
  if [ "${name%"$ext"}" != "$name" ] && [ -n "${name%"$ext"}" ]; then stem="${name%"$ext"}"; break; fi
done
case "$name" in *.jsonl) out="$outdir/$stem.morphcut.city.jsonl" ;; *) out="$outdir/$stem.morphcut.city.json" ;; esac
report="$outdir/$stem.morphcut.report.json"
csv="$outdir/$stem.morphcut.csv"
mkdir -p "$outdir"

up_to_date() {
  local f dep
  # The level files (docs/output-format.md), as the report lists them; the report is written last.
  local levels=()
  [ -f "$report" ] && mapfile -t levels < <(python3 -c '
import json, sys
for l in json.load(open(sys.argv[1]))["outputs"].get("levels", []): print(l["cityjson"])' "$report" 2>/dev/null)
  for f in "$out" "$report" "$csv" "${levels[@]}"; do
    [ -f "$f" ] || return 1
    for dep in "$tile" ${config:+"$config"} "$bin"; do
      [ "$f" -nt "$dep" ] || return 1
    done
  done
}
if [ "$force" = 0 ] && up_to_date; then
  log "up to date, skipped ($report)"
  exit 0
fi

args=("$tile" -o "$out" --report "$report" --summary "$csv" --threads "$threads" -q)
[ -n "$config" ] && args+=(--config "$config")
[ -n "$cache" ] && args+=(--cache "$cache")
[ -n "$timeout" ] && args+=(--timeout "$timeout")

attempt=0
while :; do
  attempt=$((attempt + 1))
  code=0
  "$bin" "${args[@]}" || code=$?
  if [ "$code" -eq 0 ] || [ "$code" -eq 1 ]; then
    log "done (exit $code, attempt $attempt)"
    exit "$code"
  fi
  if [ "$attempt" -gt "$retries" ]; then
    log "FAILED after $attempt attempts (exit $code)"
    exit "$code"
  fi
  wait_s=$((backoff * (1 << (attempt - 1))))
  log "exit $code on attempt $attempt; retrying in ${wait_s}s"
  sleep "$wait_s"
done
