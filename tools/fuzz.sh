#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, MC_FUZZ=ON) and fuzzes each for a bounded time, or replays
# the seeds and the committed regression inputs once (--replay).
#
#   tools/fuzz.sh [--seconds N] [--build DIR] [--targets "fuzz_a fuzz_b"] [--replay] [--no-build]
#
# Seeds are generated at run time from small real files (datasets/, tests/io/bad/, small files of
# ../shared/datasets/cityjson/) into DIR/fuzz/seeds/<target>/; the growing corpus lives in
# DIR/fuzz/corpus/<target>/ and crash inputs in DIR/fuzz/artifacts/<target>/. Inputs of crashes
# that were fixed are committed in tests/fuzz/regressions/<target>/.
# Prints one line per target: executions, exec/s, corpus size, crashes. Exit 1 on any crash.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$here/build-fuzz"
seconds=20
targets="fuzz_cityjson fuzz_cityjsonseq fuzz_off_obj fuzz_geometry"
replay=0
do_build=1
while (($#)); do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    --targets) targets="$2"; shift 2 ;;
    --replay) replay=1; shift ;;
    --no-build) do_build=0; shift ;;
    *) echo "fuzz.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
build="$(mkdir -p "$build" && cd "$build" && pwd)"

if ((do_build)); then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    CC=clang CXX=clang++ cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMC_FUZZ=ON \
      -DMC_BUILD_BENCH=OFF >/dev/null
  fi
  # shellcheck disable=SC2086
  cmake --build "$build" -j "$(nproc)" --target $targets
fi

# --- seeds -----------------------------------------------------------------------------------
shared="$here/../shared/datasets/cityjson"
max_seed=65536
seed_files() {  # small files matching the patterns under the given roots
  local pattern="$1"; shift
  for root in "$@"; do
    [ -d "$root" ] && find "$root" -type f -name "$pattern" -size -"$max_seed"c
  done | sort
}
add_seed() {  # add_seed DIR FILE [PREFIX-BYTE]: content-named, so repeated runs do not duplicate
  local dir="$1" file="$2" prefix="${3:-}" tmp
  tmp="$(mktemp)"
  { [ -n "$prefix" ] && printf "$prefix"; cat "$file"; } >"$tmp"
  mv "$tmp" "$dir/$(sha1sum "$tmp" 2>/dev/null | cut -c1-16 || basename "$file")"
}
make_seeds() {
  local t="$1" dir="$build/fuzz/seeds/$1"
  rm -rf "$dir"; mkdir -p "$dir"
  case "$t" in
    fuzz_cityjson)
      for f in $(seed_files '*.json' "$here/datasets" "$here/tests/io/bad" "$shared/cityjson-corpus" \
                   "$shared/val3dity" "$shared/cjio" "$shared/duckdb-cityjson" "$shared/cjseq" "$shared/upgraded-2.0"); do
        add_seed "$dir" "$f"
      done ;;
    fuzz_cityjsonseq)
      for f in $(seed_files '*.jsonl' "$here/datasets" "$here/tests/io/bad" "$shared"); do add_seed "$dir" "$f"; done ;;
    fuzz_off_obj)  # first byte: 0 = OFF, 1 = OBJ
      for f in $(seed_files '*.off' "$here/datasets" "$here/tests/io/bad"); do add_seed "$dir" "$f" '\x00'; done
      printf '\x01# cube with a label, v/vt/vn and negative indices\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvt 0 0\nvn 0 0 1\nusemtl WallSurface\nf 1/1/1 4/1/1 3/1/1 2/1/1\nf 5 6 7 8\nusemtl none\nf -8 -7 -3 -4\nf 2//1 3//1 7//1 6//1\nf 3 4 8 7\nf 4 1 5 8\n' >"$dir/obj_cube"
      printf '\x01v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nv 1 1 0\nv 1 2 0\nv 2 2 0\nf 1 2 3 4\nf 5 6\nf 1 2 99\nv nan 0 0\n' >"$dir/obj_bad" ;;
    fuzz_geometry)  # see fuzz_geometry.cpp for the byte layout
      # A 12-vertex L-shaped prism (8 faces: 6-gon floor and roof, 6 walls).
      { printf '\x08\x07\x00'
        for z in '\x00' '\x0c'; do
          for xy in '\x00\x00' '\x10\x00' '\x10\x08' '\x08\x08' '\x08\x10' '\x00\x10'; do printf "$xy$z"; done
        done
        printf '%b' '\x03\x05\x04\x03\x02\x01\x00' '\x83\x06\x07\x08\x09\x0a\x0b'
        for i in 0 1 2 3 4 5; do
          j=$(((i + 1) % 6)); printf "\\x01\\x$(printf %02x $i)\\x$(printf %02x $j)\\x$(printf %02x $((j + 6)))\\x$(printf %02x $((i + 6)))"
        done; } >"$dir/l_prism"
      # A cube (8 vertices, 6 quads), far from the origin (frame byte 4).
      { printf '\x04\x05\x04'
        for p in 000 800 880 080 008 808 888 088; do
          for c in $(echo "$p" | fold -w1); do [ "$c" = 8 ] && printf '\x08' || printf '\x00'; done
        done
        printf '%b' '\x01\x00\x03\x02\x01' '\x81\x04\x05\x06\x07' '\x01\x00\x01\x05\x04' '\x01\x01\x02\x06\x05' \
               '\x01\x02\x03\x07\x06' '\x01\x03\x00\x04\x07'; } >"$dir/cube_far" ;;
  esac
}

# --- run -------------------------------------------------------------------------------------
status=0
for t in $targets; do
  bin="$build/tests/fuzz/$t"
  [ -x "$bin" ] || { echo "fuzz.sh: $bin not built" >&2; exit 2; }
  make_seeds "$t"
  regress="$here/tests/fuzz/regressions/$t"
  mkdir -p "$regress"
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
  log="$build/fuzz/$t.log"
  if ((replay)); then log="$build/fuzz/$t.replay.log"; fi
  if ((replay)); then
    # Every seed and regression input once; any crash fails.
    if "$bin" -runs=0 -timeout=60 -rss_limit_mb=4096 "$build/fuzz/seeds/$t" "$regress" >"$log" 2>&1; then
      echo "$t: replayed $(ls "$build/fuzz/seeds/$t" | wc -l) seeds + $(ls "$regress" | wc -l) regressions, no crash"
    else
      echo "$t: CRASH on replay (log: $log)"; tail -40 "$log"; status=1
    fi
    continue
  fi
  corpus="$build/fuzz/corpus/$t" artifacts="$build/fuzz/artifacts/$t/"
  mkdir -p "$corpus" "$artifacts"
  rc=0
  "$bin" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$artifacts" "$corpus" "$build/fuzz/seeds/$t" "$regress" >"$log" 2>&1 || rc=$?
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || true)
  speed=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || true)
  crashes=$(find "$artifacts" -type f | wc -l)
  echo "$t: ${execs:-?} executions in ${seconds} s (${speed:-?}/s), corpus $(ls "$corpus" | wc -l) files, crashes $crashes (exit $rc)"
  if ((rc != 0)); then
    status=1
    grep -m1 -E 'ERROR: (AddressSanitizer|libFuzzer|UndefinedBehaviorSanitizer)|runtime error|SUMMARY' "$log" || true
    echo "  log: $log; input: $(ls -t "$artifacts" | head -1)"
  fi
done
exit $status
