#!/usr/bin/env python3
"""Open-model benchmark (docs/design.md, open models): morphcut-city on open variants of the public files and on their
closed originals, compared building by building. Python 3 standard library only.

    tools/bench_open_models.py [--bin PATH] [--work DIR] [--threads N] [--variants a,b,c,d,e]
                               [--files 3dbag,rotterdam,dh] [--no-synthetic] [--json OUT]
                               [--base-bin PATH]

For each file (the 3D BAG tile 5910, the Rotterdam subset, DH_01_subs; ../shared/datasets/cityjson)
it generates the variants with tools/gen_open_variants.py --seed 19 (once, into WORK/variants),
runs the binary on the closed original and on every variant (WORK/runs/<tag>/), and prints per
file and variant:

  ok%        share of buildings with geometry whose status is ok (partial and failed are not ok)
  failed     failed buildings, and how many of them with "no interior"
  flagged    buildings carrying morphcut_volume_check (a cell/estimate disagreement kept as ok)
  vol med    median of cell volume / the closed original's cell volume (buildings with both)
  <=2% <=5%  share of those buildings within 2 % / 5 % of the original's volume
  parts=     share with the same part count at level 0.01 as the original
  cpu s      CPU seconds of the run (user + sys of the child), and vs the original

and the synthetic open models of datasets/open_models (each against its .closed reference).
With --base-bin the closed originals are also run with that binary and compared (statuses,
volumes, parts at 0.01): "closed originals unchanged or differences explained".
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(ROOT, "..", "shared", "datasets", "cityjson")
FILES = {
    "3dbag": os.path.join(SHARED, "upgraded-2.0", "3dbag_v210908_fd2cee53_5910.v20.city.json"),
    "rotterdam": os.path.join(SHARED, "cjio", "rotterdam", "rotterdam_subset.json"),
    "dh": os.path.join(SHARED, "upgraded-2.0", "DH_01_subs.v20.city.json"),
}
SYNTHETIC = ["terraced_row", "gable_roof_only", "l_shape_roof_only", "tower_inclined_prisms"]


def stem(path):
    b = os.path.basename(path)
    for suf in (".city.json", ".json"):
        if b.endswith(suf):
            return b[: -len(suf)]
    return b


def run(binary, inp, outdir, threads):
    """Runs morphcut-city; returns (cpu seconds, wall seconds, per-building dict)."""
    os.makedirs(outdir, exist_ok=True)
    out = os.path.join(outdir, "out.city.json")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    p = subprocess.run([binary, inp, "-o", out, "-j", str(threads), "-q", "--no-html"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wall = time.time() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if p.returncode not in (0, 1):
        sys.stderr.write(f"bench_open_models: {binary} {inp} exited {p.returncode}\n{p.stderr[-2000:]}\n")
        return cpu, wall, {}
    with open(out) as f:
        city = json.load(f)
    res = {}
    for oid, o in city["CityObjects"].items():
        a = o.get("attributes") or {}
        if "morphcut_status" not in a:
            continue
        levels = a.get("morphcut_levels") or []
        parts = a.get("morphcut_parts") or []
        p01 = None
        for t, n in zip(levels, parts):
            if abs(float(t) - 0.01) < 1e-12:
                p01 = n
        res[oid] = {
            "status": a["morphcut_status"],
            "reason": a.get("morphcut_reason") or "",
            "volume": a.get("morphcut_cell_volume"),
            "parts01": p01,
            "check": a.get("morphcut_volume_check"),
        }
    return cpu, wall, res


def compare(ref, var):
    """Statistics of a run `var` against the reference run `ref` (dicts from run())."""
    ids = [k for k, v in var.items() if v["status"] != "skipped"]
    n = len(ids)
    ok = sum(1 for k in ids if var[k]["status"] == "ok")
    failed = [k for k in ids if var[k]["status"] == "failed"]
    no_int = sum(1 for k in failed if "no interior" in var[k]["reason"])
    flagged = sum(1 for k in ids if var[k].get("check"))
    ratios, same = [], 0
    both = 0
    for k in ids:
        r = ref.get(k)
        if not r or not r.get("volume") or var[k].get("volume") is None:
            continue
        both += 1
        ratios.append(var[k]["volume"] / r["volume"])
        if r.get("parts01") is not None and r["parts01"] == var[k].get("parts01"):
            same += 1
    within = lambda e: sum(1 for x in ratios if abs(x - 1) <= e) / len(ratios) if ratios else float("nan")
    return {
        "buildings": n,
        "ok_pct": 100.0 * ok / n if n else float("nan"),
        "partial": sum(1 for k in ids if var[k]["status"] == "partial"),
        "failed": len(failed),
        "no_interior": no_int,
        "flagged": flagged,
        "compared": both,
        "vol_median": statistics.median(ratios) if ratios else float("nan"),
        "vol_min": min(ratios) if ratios else float("nan"),
        "within2_pct": 100 * within(0.02),
        "within5_pct": 100 * within(0.05),
        "same_parts01_pct": 100.0 * same / both if both else float("nan"),
    }


def row(name, s, cpu, cpu_ref):
    rel = f"{100 * (cpu / cpu_ref - 1):+.0f}%" if cpu_ref else ""
    return (f"{name:<34} {s['buildings']:>4} {s['ok_pct']:>6.1f} {s['failed']:>4} ({s['no_interior']:>3}) "
            f"{s['flagged']:>4} {s['vol_median']:>7.4f} {s['vol_min']:>6.3f} {s['within2_pct']:>6.1f} "
            f"{s['within5_pct']:>6.1f} {s['same_parts01_pct']:>6.1f} {cpu:>7.1f} {rel:>6}")


HEADER = (f"{'file / variant':<34} {'n':>4} {'ok%':>6} {'fail':>4} {'(noi)':>5} {'flag':>4} {'volmed':>7} "
          f"{'volmin':>6} {'<=2%':>6} {'<=5%':>6} {'parts=':>6} {'cpu s':>7} {'vs':>6}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "tools", "morphcut-city"))
    ap.add_argument("--base-bin", help="a second binary run on the closed originals (before/after)")
    ap.add_argument("--work", default=os.path.join(os.environ.get("TMPDIR", "/tmp"), "morphcut-open-bench"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--variants", default="a,b,c,d,e")
    ap.add_argument("--files", default="3dbag,rotterdam,dh")
    ap.add_argument("--no-synthetic", action="store_true")
    ap.add_argument("--json", help="write every number as JSON")
    args = ap.parse_args()
    binary = os.path.abspath(args.bin)
    if not os.access(binary, os.X_OK):
        sys.exit(f"bench_open_models: {binary} not built")
    variants = [v for v in args.variants.split(",") if v]
    vdir = os.path.join(args.work, "variants")
    os.makedirs(vdir, exist_ok=True)
    out = {"binary": binary, "files": {}, "synthetic": {}}
    print(HEADER)
    for key in [f for f in args.files.split(",") if f]:
        src = FILES[key]
        s = stem(src)
        missing = [v for v in variants if not os.path.exists(os.path.join(vdir, f"{s}.{v}.city.json"))]
        if missing:
            subprocess.run([sys.executable, os.path.join(HERE, "gen_open_variants.py"), src, vdir, "--seed", "19",
                            "--variants", ",".join(missing)], check=True, stdout=subprocess.DEVNULL)
        cpu_ref, _, ref = run(binary, src, os.path.join(args.work, "runs", key, "orig"), args.threads)
        sref = compare(ref, ref)
        print(row(f"{key} closed", sref, cpu_ref, 0))
        fo = {"closed": dict(sref, cpu=cpu_ref), "variants": {}}
        if args.base_bin:
            cpu_b, _, base = run(os.path.abspath(args.base_bin), src, os.path.join(args.work, "runs", key, "orig-base"),
                                 args.threads)
            sb = compare(base, ref)
            changed = [k for k in ref if k in base and (ref[k]["status"] != base[k]["status"] or
                       ref[k]["volume"] != base[k]["volume"] or ref[k]["parts01"] != base[k]["parts01"])]
            print(row(f"{key} closed vs --base-bin", sb, cpu_ref, cpu_b) + f"  changed {len(changed)}")
            fo["closed_vs_base"] = dict(sb, cpu_base=cpu_b, changed=changed)
        for v in variants:
            cpu, _, res = run(binary, os.path.join(vdir, f"{s}.{v}.city.json"),
                              os.path.join(args.work, "runs", key, v), args.threads)
            st = compare(ref, res)
            print(row(f"{key} {v}", st, cpu, cpu_ref))
            fo["variants"][v] = dict(st, cpu=cpu)
        out["files"][key] = fo
    if not args.no_synthetic:
        sdir = os.path.join(ROOT, "datasets", "open_models")
        for name in SYNTHETIC:
            cpu_r, _, ref = run(binary, os.path.join(sdir, f"{name}.closed.city.json"),
                                os.path.join(args.work, "runs", "synthetic", name + ".closed"), 1)
            cpu, _, res = run(binary, os.path.join(sdir, f"{name}.city.json"),
                              os.path.join(args.work, "runs", "synthetic", name), 1)
            st = compare(ref, res)
            print(row(f"synthetic {name}", st, cpu, cpu_r))
            out["synthetic"][name] = st
    if args.json:
        with open(args.json, "w") as f:
            json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
