#!/usr/bin/env python3
"""Validates CityJSON(Seq) files with val3dity and tells morphcut-city's errors from the input's.

usage: check.py [--val3dity BIN] [--report-dir DIR] [--json OUT] [--jobs N] FILE...

val3dity 2.6.0 (the field's reference validator, built outside the source tree by
tools/val3dity/build.sh) runs with its default tolerances on every FILE and writes its JSON
report. Every error in the report is then classified:

  ours   on an object morphcut-city wrote: a BuildingPart whose id has the form
         <buildingid>-mc<levelindex>-<partindex> and that carries the attribute
         `morphcut_level`; a 601 BUILDINGPARTS_OVERLAP error (two ids joined by `&&`) is ours
         when either id is one of our parts; a dataset error (9xx: val3dity could not read the
         file) is ours too, since morphcut-city wrote the file.
  input  every other error: on the input's own geometry, which morphcut-city copies unchanged.
         Listed per code, never a failure.

Prints one summary line per file and a total, then every one of our errors (file, object,
code, description, info). Exit 0 when none of the errors is ours, 1 when some are, 2 on a
usage error or when val3dity cannot be run or writes no report.

Without --val3dity the binary is located (and built once, which takes minutes) by
tools/val3dity/build.sh. Without --report-dir the reports go to a temporary directory that is
removed at the end. .city.jsonl (CityJSONSeq) files are given to val3dity as files: its
`stdin` mode prints only the set of error codes per feature, without the object ids this
classification needs; the file mode reads the same stream and writes the full report.

Note: val3dity tests a Building's parts for overlap (601) only when every geometry of the
Building is valid; the summary counts the buildings with our parts that were not tested for
that reason ("overlap unchecked").
"""

import argparse
import collections
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
OUR_ID = re.compile(r"^.+-mc\d+-\d+$")
# An object id inside an error's `id`: `coid=<object>|geom=<i>|shell=<j>|face=<k>`, or
# `Geometry (Solid) #coid=<object>|geom=<i>` for Solid errors, or two of them joined by `&&`.
COID = re.compile(r"coid=(.*?)(?=\|geom=|\|shell=|\|face=|&&|$)")


class ToolError(Exception):
    """val3dity or the input could not be run/read: exit code 2."""


def our_parts_of(path):
    """Ids of the BuildingParts morphcut-city wrote in a CityJSON or CityJSONSeq file, and the
    ids of their parent Buildings."""
    ours, parents = set(), set()

    def collect(city_objects):
        for oid, obj in city_objects.items():
            if (obj.get("type") == "BuildingPart" and OUR_ID.match(oid)
                    and "morphcut_level" in (obj.get("attributes") or {})):
                ours.add(oid)
                parents.update(obj.get("parents") or [])

    try:
        with open(path, encoding="utf-8") as f:
            if path.endswith(".jsonl"):
                for line in f:
                    if line.strip():
                        collect(json.loads(line).get("CityObjects") or {})
            else:
                collect(json.load(f).get("CityObjects") or {})
    except (OSError, ValueError) as e:
        raise ToolError(f"{path}: cannot read: {e}") from e
    return ours, parents


def object_ids(error):
    """Every object id named by an error (two for a 601 overlap, one otherwise)."""
    ids = COID.findall(str(error.get("id", "")))
    if error.get("code") == 601:
        # 601 names the pair in `id`; look in `info` as well in case a version puts it there.
        ids += [i for i in COID.findall(str(error.get("info", ""))) if i not in ids]
    return ids


def run_val3dity(binary, path, report):
    """Runs val3dity on one file; returns (report JSON, seconds)."""
    log = report[: -len(".json")] + ".log"
    start = time.monotonic()
    with open(log, "w", encoding="utf-8") as out:
        try:
            rc = subprocess.run([binary, path, "--report", report], stdout=out,
                                stderr=subprocess.STDOUT, check=False).returncode
        except OSError as e:
            raise ToolError(f"cannot run {binary}: {e}") from e
    seconds = time.monotonic() - start
    # val3dity exits 0 whether or not the file is valid; anything else is a crash.
    if rc != 0:
        raise ToolError(f"val3dity exited with {rc} on {path}; end of its log:\n{tail(log)}")
    try:
        with open(report, encoding="utf-8") as f:
            return json.load(f), seconds
    except (OSError, ValueError) as e:
        raise ToolError(f"val3dity wrote no readable report for {path} ({e}); end of its log:\n{tail(log)}") from e


def tail(path, lines=10):
    """The last lines of a log, quoted in an error message (the log may be in a removed temp dir)."""
    with open(path, encoding="utf-8", errors="replace") as f:
        return "".join(f.readlines()[-lines:]).rstrip()


def check_file(binary, path, report_dir):
    """Validates one file and classifies its errors; returns the file's summary."""
    ours_ids, our_buildings = our_parts_of(path)
    name = os.path.basename(path)
    report_path = os.path.join(report_dir, name + ".val3dity.json")
    report, seconds = run_val3dity(binary, path, report_path)

    our_errors, input_errors = [], []
    overlap_unchecked = 0
    for feature in report.get("features", []):
        errors = feature.get("errors", [])
        for e in errors:
            ids = object_ids(e) or [feature.get("id", "")]
            entry = {
                "object": " && ".join(ids),
                "feature": feature.get("id"),
                "code": e.get("code"),
                "description": e.get("description"),
                "id": e.get("id"),
                "info": e.get("info"),
            }
            if any(i in ours_ids for i in ids):
                our_errors.append(entry)
            else:
                input_errors.append(entry)
        # A Building with an invalid geometry is not tested for overlapping parts (601).
        if feature.get("id") in our_buildings and errors and not any(e.get("code") == 601 for e in errors):
            overlap_unchecked += 1
    for e in report.get("dataset_errors") or []:
        our_errors.append({"object": "(file)", "feature": None, "code": e.get("code"),
                           "description": e.get("description"), "id": None, "info": e.get("info")})

    overview = report.get("features_overview") or []
    return {
        "file": path,
        "report": report_path,
        "validity": report.get("validity"),
        "features": sum(o.get("total", 0) for o in overview),
        "valid_features": sum(o.get("valid", 0) for o in overview),
        "our_parts": len(ours_ids),
        "our_errors_by_code": by_code(our_errors),
        "input_errors_by_code": by_code(input_errors),
        "overlap_unchecked": overlap_unchecked,
        "seconds": round(seconds, 2),
        "our_errors": our_errors,
        "input_errors": input_errors,
    }


def by_code(errors):
    counts = collections.Counter(e["code"] for e in errors)
    return {str(code): counts[code] for code in sorted(counts)}


def fmt_codes(counts):
    return ",".join(f"{c}:{n}" for c, n in counts.items()) or "-"


def locate_val3dity():
    """The binary built by tools/val3dity/build.sh (which builds it when missing)."""
    script = os.path.join(HERE, "build.sh")
    proc = subprocess.run([script], stdout=subprocess.PIPE, text=True, check=False)
    lines = proc.stdout.strip().splitlines()
    if proc.returncode != 0 or not lines:
        raise ToolError(f"{script} failed (exit {proc.returncode})")
    return lines[-1]


def main():
    ap = argparse.ArgumentParser(
        description="val3dity on CityJSON(Seq) files; errors on morphcut-city's parts vs the input's.")
    ap.add_argument("files", nargs="+", metavar="FILE", help=".city.json or .city.jsonl file")
    ap.add_argument("--val3dity", metavar="BIN", help="val3dity binary (default: tools/val3dity/build.sh)")
    ap.add_argument("--report-dir", metavar="DIR", help="keep val3dity's reports and logs here")
    ap.add_argument("--json", metavar="OUT", help="write the summary (and every error) as JSON")
    ap.add_argument("--jobs", "-j", type=int, default=1, metavar="N",
                    help="files validated in parallel (val3dity uses one core per file)")
    args = ap.parse_args()

    for p in args.files:
        if not os.path.isfile(p):
            ap.error(f"{p}: no such file")
        if not (p.endswith(".json") or p.endswith(".jsonl")):
            ap.error(f"{p}: not a .json/.jsonl file")

    tmp = None
    try:
        binary = args.val3dity or locate_val3dity()
        if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
            raise ToolError(f"{binary}: not an executable")
        if args.report_dir:
            report_dir = args.report_dir
            os.makedirs(report_dir, exist_ok=True)
        else:
            report_dir = tmp = tempfile.mkdtemp(prefix="val3dity-check-")
        if len({os.path.basename(p) for p in args.files}) != len(args.files):
            raise ToolError("two FILEs share a base name; their reports would overwrite each other")
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            results = list(pool.map(lambda p: check_file(binary, p, report_dir), args.files))
    except ToolError as e:
        print(f"check.py: {e}", file=sys.stderr)
        return 2
    finally:
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)

    total_ours, total_input = collections.Counter(), collections.Counter()
    totals = {"features": 0, "valid_features": 0, "our_parts": 0, "overlap_unchecked": 0, "seconds": 0.0}
    for r in results:
        for k in totals:
            totals[k] += r[k]
        total_ours.update({int(c): n for c, n in r["our_errors_by_code"].items()})
        total_input.update({int(c): n for c, n in r["input_errors_by_code"].items()})
        print(f"{r['file']}: {r['features']} features, {r['valid_features']} valid, "
              f"{r['our_parts']} our parts; our errors {sum(r['our_errors_by_code'].values())} "
              f"({fmt_codes(r['our_errors_by_code'])}), input errors "
              f"{sum(r['input_errors_by_code'].values())} ({fmt_codes(r['input_errors_by_code'])}), "
              f"overlap unchecked {r['overlap_unchecked']}; {r['seconds']:.1f} s")
    total = {
        "files": len(results),
        **totals,
        "seconds": round(totals["seconds"], 2),
        "our_errors": sum(total_ours.values()),
        "our_errors_by_code": {str(c): total_ours[c] for c in sorted(total_ours)},
        "input_errors": sum(total_input.values()),
        "input_errors_by_code": {str(c): total_input[c] for c in sorted(total_input)},
    }
    print(f"total: {total['files']} files, {total['features']} features, {total['valid_features']} valid, "
          f"{total['our_parts']} our parts; our errors {total['our_errors']} "
          f"({fmt_codes(total['our_errors_by_code'])}), input errors {total['input_errors']} "
          f"({fmt_codes(total['input_errors_by_code'])}), overlap unchecked {total['overlap_unchecked']}; "
          f"{total['seconds']:.1f} s")
    for r in results:
        for e in r["our_errors"]:
            print(f"OURS {r['file']}: {e['object']}: {e['code']} {e['description']}: {e['info']}")

    if args.json:
        if not args.report_dir:
            for r in results:
                r["report"] = None  # removed with the temporary directory
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump({"total": total, "files": results}, f, indent=1)
            f.write("\n")
    return 1 if total["our_errors"] else 0


if __name__ == "__main__":
    sys.exit(main())
