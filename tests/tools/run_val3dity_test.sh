#!/usr/bin/env bash
# val3dity (the field's reference validator, built outside the source tree by
# tools/val3dity/build.sh) as an independent check of morphcut-city's output geometry.
#
# usage: tests/tools/run_val3dity_test.sh BUILD_DIR selftest|demo|tiles|crosscheck
#   selftest  tools/val3dity/check.py on hand-made CityJSON and CityJSONSeq files: an error on
#             a morphcut part (and an overlap of two morphcut parts) is ours and fails (exit 1);
#             errors on the input's own BuildingParts, also one with a morphcut-like id but no
#             `morphcut_level`, are listed as input; a file with valid parts passes (exit 0).
#   demo      morphcut-city on the bundled 3D BAG tile and on an open building of it
#             (tests/pipeline/data), then check.py on every CityJSON file the runs wrote (the main
#             output and one file per level): fails on any error on our parts, whatever the
#             input's own geometry has.
#   tiles     tools/validate_tiles.sh --val3dity on every public real file with buildings: every
#             part valid for `morphcut-city validate` and no val3dity error on any of our parts.
#   crosscheck  tools/val3dity/crosscheck.py: `morphcut-city validate` and val3dity must say the
#             same about every part of the hand-made files of tools/val3dity/handmade_parts.py
#             (one per way they could read a part differently, valid or not) and of every file
#             morphcut-city writes for the 3D BAG tile.
# Exit 0 pass, 1 fail, 77 skipped (the val3dity source tarball is not available).
set -euo pipefail

build="$(cd "${1:?usage: $0 BUILD_DIR selftest|demo|tiles|crosscheck}" && pwd)"
mode="${2:?usage: $0 BUILD_DIR selftest|demo|tiles|crosscheck}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
check="$root/tools/val3dity/check.py"

tarball="${MC_VAL3DITY_TARBALL:-$root/../shared/peers/val3dity/val3dity-2.6.0-src.tar.gz}"
if [ ! -f "$tarball" ]; then
  echo "SKIPPED: val3dity source $tarball not found"
  exit 77
fi
# Built once per machine (minutes); later runs only print the path.
v3="$("$root/tools/val3dity/build.sh" | tail -n 1)" || { echo "FAIL: val3dity could not be built"; exit 1; }

tmp="$(mktemp -d "${TMPDIR:-/tmp}/mc-val3dity-$mode.XXXXXX")"
# The work directory stays for inspection when the test fails.
trap 'rc=$?; if [ "$rc" -eq 0 ]; then rm -rf "$tmp"; else echo "work directory kept: $tmp"; fi' EXIT

case "$mode" in
selftest)
  # Unit cubes (scale 0.001: 1000 = 1 m) at x offsets; outward faces. A cube without its top
  # face is not closed (302); one with a raised top corner has a non-planar face (203).
  python3 - "$tmp" <<'EOF'
import json, sys
tmp = sys.argv[1]
verts = []

def cube(x0, top=True, raised=False):
    b = len(verts)
    for z in (0, 1000):
        for x, y in ((0, 0), (1000, 0), (1000, 1000), (0, 1000)):
            verts.append([x0 + x, y, z + (500 if raised and z and (x, y) == (1000, 1000) else 0)])
    faces = [[0, 3, 2, 1], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    if top:
        faces.append([4, 5, 6, 7])
    return [{"type": "Solid", "lod": "2.2", "boundaries": [[[[b + i for i in f]] for f in faces]]}]

def part(pid, parent, geom, level=None):
    attrs = {} if level is None else {"morphcut_level": level}
    return pid, {"type": "BuildingPart", "parents": [parent], "attributes": attrs, "geometry": geom}

def city(parts):
    cos = {}
    for pid, obj in parts:
        parent = obj["parents"][0]
        cos.setdefault(parent, {"type": "Building", "geometry": [], "children": []})["children"].append(pid)
        cos[pid] = obj
    return {"type": "CityJSON", "version": "2.0",
            "transform": {"scale": [0.001, 0.001, 0.001], "translate": [0, 0, 0]},
            "CityObjects": cos, "vertices": verts}

broken = city([
    part("b1-0", "b1", cube(0, raised=True)),             # input part, non-planar: input 203
    part("b1-mc0-0", "b1", cube(3000, top=False), 0.1),   # our part, not closed: ours 302
    part("b1-mc0-1", "b1", cube(6000, top=False)),        # morphcut-like id, no attribute: input 302
    part("b2-mc0-0", "b2", cube(10000), 0.1),             # our parts overlapping: ours 601
    part("b2-mc0-1", "b2", cube(10500), 0.1),
    part("b3-0", "b3", cube(20000)),                      # input parts overlapping: input 601
    part("b3-1", "b3", cube(20500)),
])
json.dump(broken, open(f"{tmp}/broken.city.json", "w"))
# The same as CityJSONSeq: a header line, then one CityJSONFeature per Building (each with all
# the vertices, which only makes some of them unused).
with open(f"{tmp}/broken.city.jsonl", "w") as f:
    header = {k: v for k, v in broken.items() if k not in ("CityObjects", "vertices")}
    f.write(json.dumps({**header, "CityObjects": {}, "vertices": []}) + "\n")
    for bid, b in broken["CityObjects"].items():
        if b["type"] == "Building":
            cos = {bid: b, **{c: broken["CityObjects"][c] for c in b["children"]}}
            f.write(json.dumps({"type": "CityJSONFeature", "id": bid, "CityObjects": cos,
                                "vertices": broken["vertices"]}) + "\n")
verts.clear()
valid = city([part("b1-mc0-0", "b1", cube(0), 0.1), part("b1-mc0-1", "b1", cube(1000), 0.1)])
json.dump(valid, open(f"{tmp}/valid.city.json", "w"))
EOF
  set +e
  python3 "$check" --val3dity "$v3" --report-dir "$tmp/reports" --json "$tmp/broken.json" \
    "$tmp/broken.city.json" "$tmp/broken.city.jsonl"
  rc=$?
  set -e
  [ "$rc" -eq 1 ] || { echo "FAIL: check.py exited $rc on a file with a broken morphcut part (expected 1)"; exit 1; }
  python3 - "$tmp/broken.json" <<'EOF'
import json, sys
want_ours = [("b1-mc0-0", 302), ("b2-mc0-0 && b2-mc0-1", 601)]
want_inputs = [("b1-0", 203), ("b1-mc0-1", 302), ("b3-0 && b3-1", 601)]
ok = True
for r in json.load(open(sys.argv[1]))["files"]:
    ours = sorted((e["object"], e["code"]) for e in r["our_errors"])
    inputs = sorted((e["object"], e["code"]) for e in r["input_errors"])
    if ours != want_ours:
        print(f"FAIL: {r['file']}: our errors {ours}, expected {want_ours}"); ok = False
    if sorted(set(inputs)) != want_inputs:
        print(f"FAIL: {r['file']}: input errors {inputs}, expected {want_inputs}"); ok = False
sys.exit(0 if ok else 1)
EOF
  set +e
  python3 "$check" --val3dity "$v3" "$tmp/valid.city.json"
  rc=$?
  set -e
  [ "$rc" -eq 0 ] || { echo "FAIL: check.py exited $rc on a file with valid morphcut parts (expected 0)"; exit 1; }
  echo "PASS: check.py names only the morphcut parts' errors as ours"
  ;;
demo)
  out="$tmp/demo.morphcut.city.json"
  set +e
  "$build/tools/morphcut-city" "$root/datasets/3dbag/3dbag_5910.city.json" -o "$out" --threads 2
  rc=$?
  set -e
  # 1 = some buildings partial or failed, still written: their parts are checked all the same.
  [ "$rc" -le 1 ] || { echo "FAIL: morphcut-city exited $rc"; exit 1; }
  # A building with its party walls removed whose repaired parts once left a shared face written
  # differently in a neighbour (tests/pipeline/data; a 601 overlap at three levels).
  set +e
  "$build/tools/morphcut-city" "$root/tests/pipeline/data/3dbag_party_walls_removed_32917.city.json" \
    -o "$tmp/open.morphcut.city.json" --threads 2 --no-html --no-gpkg
  rc=$?
  set -e
  [ "$rc" -le 1 ] || { echo "FAIL: morphcut-city exited $rc on the open building"; exit 1; }
  files=("$tmp"/demo.morphcut*.city.json "$tmp"/open.morphcut*.city.json)
  [ -f "${files[0]}" ] || { echo "FAIL: morphcut-city wrote no CityJSON file"; exit 1; }
  set +e
  python3 "$check" --val3dity "$v3" --report-dir "$tmp/val3dity" --json "$tmp/val3dity.json" \
    --jobs "$(nproc)" "${files[@]}"
  rc=$?
  set -e
  case "$rc" in
    0) echo "PASS: val3dity finds no error on morphcut-city's parts in ${#files[@]} file(s)" ;;
    1) echo "FAIL: val3dity finds errors on morphcut-city's parts (listed above; reports in $tmp/val3dity)"; exit 1 ;;
    *) echo "FAIL: check.py could not run val3dity (exit $rc)"; exit 1 ;;
  esac
  ;;
tiles)
  # Every public real CityJSON file with buildings (tools/validate_tiles.sh): every part valid for
  # morphcut-city validate, and no val3dity error on any part in any file the runs wrote.
  set +e
  bash "$root/tools/validate_tiles.sh" --bin "$build/tools/morphcut-city" --work "$tmp" --val3dity | tee "$tmp/tiles.txt"
  rc=$?
  set -e
  [ "$rc" -eq 0 ] || { echo "FAIL: validate_tiles.sh exited $rc"; exit 1; }
  total="$(grep '^total: ' "$tmp/tiles.txt" || true)"
  v3="$(grep '^val3dity: ' "$tmp/tiles.txt" || true)"
  read -r valid parts < <(echo "$total" | sed -E 's/^total: ([0-9]+) of ([0-9]+) .*/\1 \2/')
  fail=0
  [ -n "$total" ] && [ "$parts" -gt 0 ] && [ "$valid" = "$parts" ] || { echo "FAIL: not every part valid: $total"; fail=1; }
  echo "$total" | grep -q ' 0 buildings with tiling errors; 0 files not processed' || { echo "FAIL: $total"; fail=1; }
  echo "$v3" | grep -q '^val3dity: 0 errors on our parts' || { echo "FAIL: $v3 (listed in $tmp/failures.txt)"; fail=1; }
  echo "$v3" | grep -q ' 0 files val3dity could not check' || { echo "FAIL: $v3"; fail=1; }
  [ "$fail" = 0 ] || exit 1
  echo "PASS: $total; $v3"
  ;;
crosscheck)
  python3 "$root/tools/val3dity/handmade_parts.py" "$tmp/handmade" || { echo "FAIL: handmade_parts.py"; exit 1; }
  out="$tmp/demo/demo.morphcut.city.json"
  mkdir -p "$tmp/demo"
  set +e
  "$build/tools/morphcut-city" "$root/datasets/3dbag/3dbag_5910.city.json" -o "$out" --threads 2 --no-html --no-gpkg
  rc=$?
  set -e
  [ "$rc" -le 1 ] || { echo "FAIL: morphcut-city exited $rc"; exit 1; }
  set +e
  python3 "$root/tools/val3dity/crosscheck.py" --bin "$build/tools/morphcut-city" --val3dity "$v3" \
    --keep "$tmp/reports" --json "$tmp/crosscheck.json" --jobs "$(nproc)" --dir "$tmp/handmade" --dir "$tmp/demo"
  rc=$?
  set -e
  case "$rc" in
    0) echo "PASS: morphcut-city validate and val3dity agree on every part" ;;
    1) echo "FAIL: morphcut-city validate and val3dity disagree (listed above; reports in $tmp/reports)"; exit 1 ;;
    *) echo "FAIL: crosscheck.py could not run the validators (exit $rc)"; exit 1 ;;
  esac
  ;;
*)
  echo "usage: $0 BUILD_DIR selftest|demo|tiles|crosscheck" >&2; exit 2 ;;
esac
