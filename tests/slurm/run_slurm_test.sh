#!/usr/bin/env bash
# The Slurm path for real: a one-node cluster on localhost (munged, slurmctld, slurmd with a
# generated slurm.conf, everything under a temp dir), tools/slurm/submit.sh over 3 small tiles
# cut from datasets/3dbag/3dbag_5910.city.jsonl, then checks of the merged report and CSV. A
# second submission adds a broken tile: the good tiles are skipped as up to date, the broken one
# is retried and fails, and the merge job lists it as missing and exits 1.
# Needs root (slurmd) and Debian's slurm-wlm + munge (tools/setup-deps.sh installs them);
# without them it prints SKIPPED and exits 77 (ctest's skip code). The daemons are stopped on
# every exit path.
#
#   tests/slurm/run_slurm_test.sh BUILD_DIR
set -euo pipefail

src="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$src/build}")"
bin="$build/tools/morphcut-city"
data="$src/datasets/3dbag/3dbag_5910.city.jsonl"

skip() { echo "SKIPPED: $*"; exit 77; }
for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol; do
  command -v "$tool" >/dev/null 2>&1 || skip "$tool not found (apt-get install slurm-wlm munge; tools/setup-deps.sh does)"
done
[ "$(id -u)" -eq 0 ] || skip "slurmd must run as root to start jobs"
[ -x "$bin" ] || { echo "FAIL: $bin not built"; exit 1; }
[ -r "$data" ] || { echo "FAIL: $data not found"; exit 1; }

tmp="$(mktemp -d /tmp/mc_slurm_test.XXXXXX)"
pids=()
cleanup() {
  local code=$?
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill "${pids[i]}" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  if [ "$code" -ne 0 ] && [ "$code" -ne 77 ]; then
    for f in "$tmp"/log/*.log "$tmp"/out*/logs/*.log; do
      [ -f "$f" ] && { echo "---- $f (tail)"; tail -n 25 "$f"; }
    done
  fi
  rm -rf "$tmp"
  exit "$code"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
fail() { echo "FAIL: $*"; exit 1; }

mkdir -p "$tmp"/{munge,state,spool,log,tiles}
chmod 700 "$tmp/munge"

# munge: a fresh key, our own socket.
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
socket="$tmp/munge/munge.socket"
munged -F --force --key-file="$tmp/munge/munge.key" --socket="$socket" --pid-file="$tmp/munge/munged.pid" \
  --log-file="$tmp/log/munged.log" --seed-file="$tmp/munge/munged.seed" >"$tmp/log/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$socket" ] && break; sleep 0.1; done
[ -S "$socket" ] || fail "munged did not start"

# slurm.conf for this machine (slurmd -C), on ports of our own so a second cluster cannot clash.
hw="$(slurmd -C | head -n 1 | sed -e 's/^NodeName=[^ ]* //')"
port=$((20000 + ($$ % 20000)))
cat >"$tmp/slurm.conf" <<EOF
ClusterName=mctest
SlurmctldHost=localhost
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
MinJobAge=600
NodeName=localhost NodeAddr=127.0.0.1 $hw State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$tmp/slurm.conf"
slurmctld -D -c -f "$SLURM_CONF" >"$tmp/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N localhost -f "$SLURM_CONF" >"$tmp/log/slurmd.out" 2>&1 &
pids+=($!)
state=""
for _ in $(seq 120); do
  state="$(sinfo -h -N -o %T 2>/dev/null | head -n 1 || true)"
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || fail "the node did not become idle (state '$state')"
echo "cluster up: $(sinfo -h -N -o '%N %T cpus=%c mem=%m')"

# Three tiles of 10 buildings each (CityJSONSeq: the header line, then features).
python3 - "$data" "$tmp/tiles" <<'EOF'
import sys
lines = open(sys.argv[1]).read().splitlines()
for t in range(3):
    with open(f"{sys.argv[2]}/tile{t}.city.jsonl", "w") as f:
        f.write("\n".join([lines[0]] + lines[1 + 10 * t: 11 + 10 * t]) + "\n")
EOF
printf '%s\n' "# three tiles" "$tmp/tiles/tile0.city.jsonl" "$tmp/tiles/tile1.city.jsonl" "" \
  "$tmp/tiles/tile2.city.jsonl" >"$tmp/tiles.txt"

# Waits until both jobs have left the queue (bounded), then prints the merge job's exit code.
wait_jobs() {
  local array="$1" merge="$2" deadline=$((SECONDS + 300))
  while squeue -h -j "$array,$merge" 2>/dev/null | grep -q .; do
    [ "$SECONDS" -lt "$deadline" ] || fail "jobs $array/$merge still queued after 300 s: $(squeue -h)"
    sleep 0.5
  done
  scontrol -o show job "$merge" | sed -n 's/.*JobState=\([A-Z]*\).* ExitCode=\([0-9]*\):.*/\1 \2/p' | head -n 1
}
task_states() { scontrol -o show job "$1" | sed -n 's/.*ArrayTaskId=\([0-9]*\) .*JobState=\([A-Z]*\).* ExitCode=\([0-9]*\):.*/\1:\2:\3/p' | sort; }

# 1. The array over three tiles (1 CPU per task: two tasks at a time on this node) with a cache
#    shared by the tasks, and the dependent merge.
export MORPHCUT_CITY="$bin"
t0_ns=$(date +%s%N)
read -r array merge < <("$src/tools/slurm/submit.sh" "$tmp/tiles.txt" "$tmp/out" --cpus 1 --cache "$tmp/cache")
result="$(wait_jobs "$array" "$merge")"
wall="$(awk -v a="$t0_ns" -v b="$(date +%s%N)" 'BEGIN { printf "%.1f", (b - a) / 1e9 }')"
echo "array $array + merge $merge: $result, wall ${wall} s (submit to merged)"
[ "$result" = "COMPLETED 0" ] || fail "merge job: $result"
tasks="$(task_states "$array")"
echo "array tasks (id:state:exit): $(echo "$tasks" | tr '\n' ' ')"
[ "$(echo "$tasks" | grep -c -E ':(COMPLETED:0|FAILED:1)$')" -eq 3 ] || fail "not every tile task completed"

python3 - "$tmp/out" "$tmp/tiles" <<'EOF'
import csv, json, sys
out, tiles = sys.argv[1], sys.argv[2]
m = json.load(open(f"{out}/merged.report.json"))
expect = {f"tile{t}": len(open(f"{tiles}/tile{t}.city.jsonl").read().splitlines()) - 1 for t in range(3)}
t = m["totals"]
assert t["tiles"] == 3 and t["merged"] == 3 and t["missing"] == 0, t
assert [x["tile"] for x in m["tiles"]] == ["tile0", "tile1", "tile2"], m["tiles"]
assert t["building_count"] == sum(expect.values()) == len(m["buildings"]), t
assert sum(t["counts"].values()) == t["building_count"], t["counts"]
assert t["cache"]["misses"] == t["building_count"] and t["cache"]["hits"] == 0, t["cache"]
for x in m["tiles"]:
    assert x["building_count"] == expect[x["tile"]], x
    assert x["report_sha256"] and x["input_sha256"], x
rows = list(csv.reader(open(f"{out}/merged.csv", newline="")))
assert rows[0][:3] == ["tile", "id", "status"], rows[0]
assert len(rows) == 1 + t["building_count"], len(rows)
for name, n in expect.items():
    assert sum(1 for r in rows[1:] if r[0] == name) == n, name
ids = {(b["tile"], b["id"]) for b in m["buildings"]}
assert ids == {(r[0], r[1]) for r in rows[1:]}, "report and CSV disagree"
print(f"merged report: {t['tiles']} tiles, {t['building_count']} buildings, counts {t['counts']}, "
      f"cache {t['cache']}, duplicates {t['duplicate_ids']}, {len(rows) - 1} CSV rows")
EOF

# 2. The same list plus a broken tile: the three are up to date (skipped), the broken one is
#    retried once and fails, the merge still runs (afterany), lists it and exits 1.
printf '{"type":"CityJSON","version":"2.0","CityObjects":{' >"$tmp/tiles/broken.city.json"
cp "$tmp/tiles.txt" "$tmp/tiles2.txt"
echo "$tmp/tiles/broken.city.json" >>"$tmp/tiles2.txt"
before="$(stat -c %Y "$tmp/out/tile0.morphcut.report.json")"
read -r array2 merge2 < <("$src/tools/slurm/submit.sh" "$tmp/tiles2.txt" "$tmp/out" --cpus 1 --retries 1 --backoff 1)
result2="$(wait_jobs "$array2" "$merge2")"
echo "second array $array2 + merge $merge2: $result2"
[ "$result2" = "COMPLETED 1" ] || [ "$result2" = "FAILED 1" ] || fail "merge job with a broken tile: $result2 (want exit 1)"
tasks2="$(task_states "$array2")"
echo "array tasks (id:state:exit): $(echo "$tasks2" | tr '\n' ' ')"
echo "$tasks2" | grep -q '^3:FAILED:2$' || fail "the broken tile's task should fail with exit 2"
[ "$(echo "$tasks2" | grep -c -E '^[012]:COMPLETED:0$')" -eq 3 ] || fail "the up-to-date tiles should complete"
grep -q "up to date, skipped" "$tmp"/out/logs/tile_"${array2}"_0.log || fail "tile0 was not skipped as up to date"
grep -q "retrying" "$tmp"/out/logs/tile_"${array2}"_3.log || fail "the broken tile was not retried"
[ "$(stat -c %Y "$tmp/out/tile0.morphcut.report.json")" = "$before" ] || fail "an up-to-date tile was rewritten"
python3 - "$tmp/out/merged.report.json" <<'EOF'
import json, sys
m = json.load(open(sys.argv[1]))
assert [x["tile"] for x in m["missing_tiles"]] == ["broken"], m["missing_tiles"]
assert m["totals"]["merged"] == 3 and m["totals"]["tiles"] == 4, m["totals"]
print("second run: broken tile listed as missing:", m["missing_tiles"][0]["reason"])
EOF
echo "PASS: slurm array over 3 tiles in ${wall} s (wall, submit to merged report)"
