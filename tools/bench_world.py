#!/usr/bin/env python3
"""Inputs from the rest of the world, measured: every public file with buildings, the geographic
twins and output-grid stress variants of the 3D BAG tile and the Rotterdam subset
(tools/gen_world_variants.py), and a PLATEAU-like CityGML file; per file the statuses, the
failures by reason, the levels that fell back or needed a grid repair, `morphcut-city validate`,
optionally val3dity on our parts, wall and CPU time; the twins also against their originals.

usage: tools/bench_world.py [--bin B] [--work DIR] [--threads N] [--val3dity] [--only SUBSTRING]
                            [--skip-public] [--seed S]

Geographic outputs are reprojected to UTM 31N at 1e-5 m (`morphcut-city reproject`) for
val3dity, whose tolerances are in the file's units. Prints one table; exit 1 when a building
failed for a grid reason or val3dity found an error on our parts."""
import argparse, collections, csv, json, os, re, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(ROOT, "..", "shared", "datasets")


def public_files():
    out = []
    manifest = os.path.join(SHARED, "cityjson", "MANIFEST.tsv")
    for row in csv.DictReader(open(manifest), delimiter="\t"):
        if int(row["n_building"] or 0) > 0 and not row["path"].startswith(("cityjson-corpus/", "schemas/")):
            out.append(os.path.join(SHARED, "cityjson", row["path"]))
    gml = os.path.join(SHARED, "citygml")
    out += sorted(os.path.join(gml, f) for f in os.listdir(gml) if f.endswith(".gml"))
    return out


def run(args, cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def process(args, path, name):
    ext = ".city.jsonl" if path.endswith(".jsonl") else ".city.json"
    out = os.path.join(args.work, name + ".morphcut" + ext)
    report = os.path.join(args.work, name + ".report.json")
    for f in os.listdir(args.work):
        if f.startswith(name + ".morphcut.level-"):
            os.remove(os.path.join(args.work, f))
    t0 = time.monotonic()
    r = run(args, [args.bin, path, "-o", out, "--report", report, "--threads", str(args.threads), "-q",
                   "--no-html", "--no-gpkg", "--no-graph", "--no-summary"])
    wall = time.monotonic() - t0
    if r.returncode > 1:
        return {"name": name, "error": (r.stderr or r.stdout).strip().splitlines()[-1:]}
    rep = json.load(open(report))
    b = rep["buildings"]
    row = {"name": name, "out": out, "report": rep, "wall": wall, "cpu": rep.get("cpu_seconds", 0),
           "buildings": len(b), "counts": rep["counts"], "geographic": "degrees" in rep["coordinates"]["input_units"]}
    reasons = collections.Counter()
    for x in b:
        if x["status"] in ("failed", "partial"):
            reasons[re.sub(r"[0-9.e+-]{3,}", "#", (x.get("reason") or "")[:70])] += 1
    row["reasons"] = reasons
    levels = [l for x in b for l in x.get("levels", [])]
    row["fallbacks"] = sum(1 for l in levels if l.get("fallback"))
    row["grid_repairs"] = collections.Counter((l.get("grid_repair") or "").split(",")[0].split(" ")[0]
                                              for l in levels if l.get("grid_repair"))
    row["grid_failed"] = sum(1 for x in b if x["status"] == "failed" and "output grid" in (x.get("reason") or ""))
    outs = [out] + sorted(os.path.join(args.work, f) for f in os.listdir(args.work)
                          if f.startswith(name + ".morphcut.level-"))
    invalid = 0
    for o in outs:
        v = run(args, [args.bin, "validate", o, "--json", o + ".validate.json"])
        try:
            invalid += json.load(open(o + ".validate.json"))["counts"]["invalid_parts"]
        except Exception:
            invalid = "err"
            break
    row["invalid"] = invalid
    if args.val3dity:
        files = outs
        if row["geographic"]:  # val3dity's tolerances are in file units: check a metric copy
            files = []
            for o in outs:
                m = o.replace(ext, ".utm" + ext)
                run(args, [args.bin, "reproject", o, "-o", m, "--to", "EPSG:32631", "--scale", "1e-5"])
                files.append(m)
        j = os.path.join(args.work, name + ".val3dity.json")
        v = run(args, [sys.executable, os.path.join(HERE, "val3dity", "check.py"), "--jobs", str(args.threads),
                       "--json", j] + files)
        try:
            row["v3_ours"] = json.load(open(j))["total"]["our_errors"]
        except Exception:
            row["v3_ours"] = "err"
    return row


def compare(a, b):
    """Twin b against original a: same status, same part counts at every level, volume ratio."""
    ra = {x["id"]: x for x in a["report"]["buildings"]}
    rb = {x["id"]: x for x in b["report"]["buildings"]}
    n = same_status = same_parts = 0
    dv = []
    for k, x in ra.items():
        y = rb.get(k)
        if not y:
            continue
        n += 1
        same_status += x["status"] == y["status"]
        if [l["parts"] for l in x.get("levels", [])] == [l["parts"] for l in y.get("levels", [])]:
            same_parts += 1
        vx = (x.get("volume_check") or {}).get("cell")
        vy = (y.get("volume_check") or {}).get("cell")
        if vx and vy:
            dv.append(abs(vy / vx - 1))
    dv.sort()
    return (f"same status {same_status}/{n}, same parts {same_parts}/{n} ({100 * same_parts / max(n, 1):.1f} %), "
            f"volume |diff| median {dv[len(dv) // 2] if dv else 0:.1e} max {dv[-1] if dv else 0:.1e}, "
            f"> 0.1 %: {sum(v > 1e-3 for v in dv)}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "tools", "morphcut-city"))
    ap.add_argument("--work", default=os.path.join(os.environ.get("TMPDIR", "/tmp"), "morphcut-world"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--val3dity", action="store_true")
    ap.add_argument("--only", default="")
    ap.add_argument("--skip-public", action="store_true")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    var = os.path.join(args.work, "variants")
    os.makedirs(var, exist_ok=True)
    gen = [sys.executable, os.path.join(HERE, "gen_world_variants.py")]
    tile = os.path.join(SHARED, "cityjson", "3dbag", "3dbag_v210908_fd2cee53_5910.city.json")
    rotterdam = os.path.join(SHARED, "cityjson", "cjio", "rotterdam", "rotterdam_subset.json")
    def name_of(p):  # unique: the path under datasets/, dots and slashes as underscores
        return os.path.relpath(p, SHARED).replace("/", "_").replace(".", "_")

    inputs = [] if args.skip_public else [(p, name_of(p), None) for p in public_files()]
    # (cjio's Rotterdam subset lost its CRS; rotterdam_one, from the same data, says EPSG:7415)
    for src, stem, crs in ((tile, "3dbag_v210908_fd2cee53_5910", ""), (rotterdam, "rotterdam_subset", "EPSG:7415")):
        original = name_of(src)
        run(args, gen + ["geographic", src, var, "--bin", args.bin] + (["--from", crs] if crs else []), check=True)
        run(args, gen + ["stress", src, var, "--seed", str(args.seed)], check=True)
        for tag in ("epsg4979", "epsg6697"):
            inputs.append((os.path.join(var, f"{stem}.{tag}.city.json"), f"{stem}.{tag}", original))
        for tag in ("rot", "cm", "jitter", "all"):
            inputs.append((os.path.join(var, f"{stem}.{tag}.city.json"), f"{stem}.{tag}", None))
    plateau = os.path.join(var, "plateau_like.gml")
    run(args, gen + ["plateau", tile, plateau, "--bin", args.bin], check=True)
    inputs.append((plateau, "plateau_like", None))
    rows, by_name, bad = [], {}, 0
    hdr = f"{'file':44} {'bldgs':>5} {'ok/partial/failed/skip':>22} {'fallbk':>6} {'grid repairs':>24} {'invalid':>7}"
    hdr += f" {'v3':>4}" if args.val3dity else ""
    print(hdr + f" {'wall s':>7} {'cpu s':>7}")
    for path, name, original in inputs:
        if args.only and args.only not in name:
            continue
        row = process(args, path, name)
        by_name[name] = row
        if "error" in row:
            print(f"{name:44} run failed: {row['error']}")
            bad += 1
            continue
        c = row["counts"]
        gr = ", ".join(f"{k} {v}" for k, v in sorted(row["grid_repairs"].items())) or "-"
        line = (f"{name:44} {row['buildings']:5} {c['ok']:>5}/{c['partial']}/{c['failed']}/{c['skipped']:<8} "
                f"{row['fallbacks']:6} {gr:>24} {row['invalid']!s:>7}")
        if args.val3dity:
            line += f" {row['v3_ours']!s:>4}"
            bad += row["v3_ours"] != 0
        print(line + f" {row['wall']:7.1f} {row['cpu']:7.1f}")
        for reason, n in row["reasons"].most_common(4):
            print(f"{'':8}{n} x {reason}")
        bad += row["grid_failed"] > 0
        if original and original in by_name and "error" not in by_name[original]:
            print(f"{'':8}vs {original}: {compare(by_name[original], row)}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
