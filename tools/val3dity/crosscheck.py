#!/usr/bin/env python3
"""Compares `morphcut-city validate` with val3dity, part by part, on morphcut-city's output files.

usage: crosscheck.py [--bin MORPHCUT_CITY] [--val3dity BIN] [--dir DIR] [--json OUT] [--jobs N] [FILE...]

Both validators run on every FILE (and every .city.json / .city.jsonl file under --dir). For each
morphcut part (check.py's rule: a BuildingPart with an id <building>-mc<level>-<index> and the
attribute `morphcut_level`) the error codes of the two are compared:

  solid codes  val3dity stops at the first stage of its checks that fails (faces 1xx/2xx except
               204; 204; 301; the polyhedron's construction 303/307; 302/305; 306; the Solid's
               orientation 405), so only our codes of the first stage that has any are compared
               with its codes. A part valid for one and not the other always disagrees.
  601 overlaps compared per pair of parts, and only in Buildings where val3dity tested them (it
               skips a Building with any invalid geometry).

The input's own geometry is not compared (check.py lists it). Prints every part on which they
disagree (id, our codes, val3dity's codes), a line per file and a total. Exit 0 when they agree
on every part, 1 on any disagreement, 2 when a validator cannot be run.
"""

import argparse
import collections
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import check  # noqa: E402  (tools/val3dity/check.py: runs val3dity, tells our parts from the input's)

ROOT = os.path.dirname(os.path.dirname(HERE))
# val3dity 2.6's order of checks for one Solid: the first stage with an error ends its checks.
STAGES = [{101, 102, 103, 104, 105, 201, 202, 203, 205, 206, 207, 208}, {204}, {301}, {300, 303, 307},
          {302, 305}, {306}, {405}]
OVERLAP = 601


def first_stage(codes):
    """The codes of the first stage of val3dity's checks that has any (codes of no stage kept)."""
    for stage in STAGES:
        if codes & stage:
            return (codes & stage) | (codes - set().union(*STAGES))
    return set(codes)


def ours(binary, path, out_json):
    """`morphcut-city validate`: {part: solid codes}, {frozenset pair} of 601 between parts."""
    proc = subprocess.run([binary, "validate", path, "--json", out_json, "--quiet"], check=False)
    if proc.returncode > 1:
        raise check.ToolError(f"morphcut-city validate exited {proc.returncode} on {path}")
    with open(out_json, encoding="utf-8") as f:
        report = json.load(f)
    parts = {o["id"]: o for o in report["objects"] if "morphcut_level" in o}
    codes, pairs = {}, set()
    for pid, o in parts.items():
        codes[pid] = {e["code"] for e in o["errors"] if e["code"] != OVERLAP}
        for e in o["errors"]:
            if e["code"] == OVERLAP:
                # "overlaps <other part>: ..." (output/validate.cpp)
                other = next((q for q in parts if e["message"].startswith(f"overlaps {q}:")), None)
                if other:
                    pairs.add(frozenset((pid, other)))
    return codes, pairs


def theirs(binary, path, report_dir):
    """val3dity through check.py: {part: codes}, 601 pairs, Buildings whose overlaps it tested."""
    r = check.check_file(binary, path, report_dir)
    codes, pairs = collections.defaultdict(set), set()
    for e in r["our_errors"]:
        ids = [i.strip() for i in e["object"].split("&&")]
        if e["code"] == OVERLAP:
            if len(ids) == 2:
                pairs.add(frozenset(ids))
        else:
            for i in ids:
                codes[i].add(e["code"])
    with open(r["report"], encoding="utf-8") as f:
        report = json.load(f)
    # A Building with an invalid geometry (ours or the input's) is not tested for overlaps.
    tested = {ft["id"] for ft in report.get("features", [])
              if not any(e.get("code") != OVERLAP for e in ft.get("errors", []))}
    return codes, pairs, tested


def compare(binary, v3, path, work):
    name = os.path.basename(path)
    our_codes, our_pairs = ours(binary, path, os.path.join(work, name + ".validate.json"))
    v3_codes, v3_pairs, tested = theirs(v3, path, work)
    part_ids, _ = check.our_parts_of(path)
    parent = {}
    for pid in part_ids:
        parent[pid] = pid.rsplit("-mc", 1)[0]
    rows = []
    for pid in sorted(part_ids):
        mine = our_codes.get(pid, set())
        v3c = v3_codes.get(pid, set())
        mine_cmp = first_stage(mine)
        if mine_cmp != v3c:
            rows.append({"part": pid, "ours": sorted(mine), "val3dity": sorted(v3c)})
    for pair in sorted(our_pairs ^ v3_pairs, key=sorted):
        a, b = sorted(pair)
        if parent.get(a) in tested and parent.get(b) in tested:
            rows.append({"part": f"{a} && {b}", "ours": [OVERLAP] if pair in our_pairs else [],
                         "val3dity": [OVERLAP] if pair in v3_pairs else []})
    return {"file": path, "parts": len(part_ids),
            "invalid_ours": sum(1 for p in part_ids if our_codes.get(p)),
            "invalid_val3dity": sum(1 for p in part_ids if v3_codes.get(p)),
            "overlaps_ours": len(our_pairs), "overlaps_val3dity": len(v3_pairs),
            "disagreements": rows}


def main():
    ap = argparse.ArgumentParser(description="morphcut-city validate vs val3dity on every morphcut part")
    ap.add_argument("files", nargs="*", metavar="FILE", help=".city.json or .city.jsonl output file")
    ap.add_argument("--dir", action="append", default=[], help="every .city.json(l) file under DIR")
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "tools", "morphcut-city"),
                    help="morphcut-city binary (default build/tools/morphcut-city)")
    ap.add_argument("--val3dity", metavar="BIN", help="val3dity binary (default: tools/val3dity/build.sh)")
    ap.add_argument("--json", metavar="OUT", help="write the results as JSON")
    ap.add_argument("--keep", metavar="DIR", help="keep both validators' reports here")
    ap.add_argument("--jobs", "-j", type=int, default=1, metavar="N", help="files checked in parallel")
    args = ap.parse_args()
    files = list(args.files)
    for d in args.dir:
        for root, _, names in sorted(os.walk(d)):
            files += [os.path.join(root, n) for n in sorted(names) if n.endswith((".city.json", ".city.jsonl"))]
    if not files:
        ap.error("no FILE and no file under --dir")
    if not os.access(args.bin, os.X_OK):
        ap.error(f"{args.bin}: not an executable (build the morphcut_city target, or pass --bin)")
    if len({os.path.basename(p) for p in files}) != len(files):
        ap.error("two files share a base name; their reports would overwrite each other")

    tmp = None
    try:
        v3 = args.val3dity or check.locate_val3dity()
        if args.keep:
            work = args.keep
            os.makedirs(work, exist_ok=True)
        else:
            work = tmp = tempfile.mkdtemp(prefix="crosscheck-")
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            results = list(pool.map(lambda p: compare(args.bin, v3, p, work), files))
    except (check.ToolError, OSError, ValueError) as e:
        print(f"crosscheck.py: {e}", file=sys.stderr)
        return 2
    finally:
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)

    total = collections.Counter()
    for r in results:
        n = len(r["disagreements"])
        total.update(files=1, parts=r["parts"], disagreements=n, invalid_ours=r["invalid_ours"],
                     invalid_val3dity=r["invalid_val3dity"], overlaps_ours=r["overlaps_ours"],
                     overlaps_val3dity=r["overlaps_val3dity"])
        print(f"{r['file']}: {r['parts']} parts; invalid {r['invalid_ours']} ours, {r['invalid_val3dity']} "
              f"val3dity; 601 pairs {r['overlaps_ours']} ours, {r['overlaps_val3dity']} val3dity; "
              f"{n} disagreements")
        for d in r["disagreements"]:
            print(f"  DIFF {d['part']}: ours {d['ours'] or 'valid'}, val3dity {d['val3dity'] or 'valid'}")
    print(f"total: {total['files']} files, {total['parts']} parts; invalid {total['invalid_ours']} ours, "
          f"{total['invalid_val3dity']} val3dity; 601 pairs {total['overlaps_ours']} ours, "
          f"{total['overlaps_val3dity']} val3dity; {total['disagreements']} disagreements")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump({"total": dict(total), "files": results}, f, indent=1)
            f.write("\n")
    return 1 if total["disagreements"] else 0


if __name__ == "__main__":
    sys.exit(main())
