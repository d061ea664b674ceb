#!/usr/bin/env python3
"""Mean surface deviation of open-model runs from their closed originals (docs/benchmarks.md,
"Open models"). Python 3 standard library; the distances come from `morphcut hausdorff`.

    tools/open_models_deviation.py REF_RUN VAR_RUN [VAR_RUN ...] [--morphcut PATH] [--level T]
                                   [--json OUT]

A run directory is one written by tools/bench_open_models.py (WORK/runs/<tag>/: out.city.json
and out.level-<t>.city.json). For every Building that is `ok` in the reference run (the closed
original) and in a variant run, the singleton cell of each run is rebuilt from the level file's
parts (the parts of a level tile the cell: a face two parts share is dropped, what is left is the
cell's surface), written as OFF, and `morphcut hausdorff REF.off VAR.off` measures the two
surfaces (sampled exact closest points; the mean of the two one-sided mean distances is the
mean surface deviation, the maximum the Hausdorff distance). Printed per variant: buildings
compared, median and mean of the mean deviation, share with mean deviation <= 0.1 m, the
largest, and the median Hausdorff distance.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def level_file(run, level):
    path = os.path.join(run, f"out.level-{level:g}.city.json")
    if not os.path.exists(path):
        sys.exit(f"open_models_deviation: {path} is missing (run tools/bench_open_models.py first)")
    return path


def cells(run, level):
    """Building id -> list of faces (each a list of (x, y, z)) of its singleton cell."""
    with open(level_file(run, level)) as f:
        city = json.load(f)
    t = city.get("transform", {"scale": [1, 1, 1], "translate": [0, 0, 0]})
    verts = city["vertices"]

    def xyz(i):
        v = verts[i]
        return tuple(round(v[k] * t["scale"][k] + t["translate"][k], 6) for k in range(3))

    out = {}
    objs = city["CityObjects"]
    for oid, o in objs.items():
        if o.get("type") != "Building" or (o.get("attributes") or {}).get("morphcut_status") != "ok":
            continue
        seen = {}  # face key -> [face, count]
        for child in o.get("children", []):
            part = objs.get(child, {})
            if "morphcut_level" not in (part.get("attributes") or {}):
                continue
            for g in part.get("geometry", []):
                if g.get("type") != "Solid":
                    continue
                for shell in g["boundaries"]:
                    for surface in shell:
                        ring = [xyz(i) for i in surface[0]]
                        key = tuple(sorted(ring))
                        seen.setdefault(key, [ring, 0])[1] += 1
        faces = [ring for ring, n in seen.values() if n == 1]  # shared faces appear twice
        if faces:
            out[oid] = faces
    return out


def write_off(path, faces, origin):
    index, pts, polys = {}, [], []
    for ring in faces:
        poly = []
        for p in ring:
            if p not in index:
                index[p] = len(pts)
                pts.append(p)
            poly.append(index[p])
        polys.append(poly)
    with open(path, "w") as f:
        f.write(f"OFF\n{len(pts)} {len(polys)} 0\n")
        for p in pts:
            f.write(f"{p[0] - origin[0]:.6f} {p[1] - origin[1]:.6f} {p[2] - origin[2]:.6f}\n")
        for poly in polys:
            f.write(f"{len(poly)} " + " ".join(map(str, poly)) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ref")
    ap.add_argument("variants", nargs="+")
    ap.add_argument("--morphcut", default=os.path.join(ROOT, "build", "tools", "morphcut"))
    ap.add_argument("--level", type=float, default=0.1, help="the level file whose parts give the cell (any level tiles it)")
    ap.add_argument("--json", help="write every building's numbers here")
    a = ap.parse_args()
    ref = cells(a.ref, a.level)
    results = {}
    print(f"{'variant':28} {'compared':>8} {'mean dev med':>12} {'mean':>8} {'<=0.1 m':>8} {'max':>8} {'hausdorff med':>13}")
    with tempfile.TemporaryDirectory() as tmp:
        for run in a.variants:
            var = cells(run, a.level)
            rows = {}
            for oid in sorted(set(ref) & set(var)):
                origin = ref[oid][0][0]
                ra, rb = os.path.join(tmp, "ref.off"), os.path.join(tmp, "var.off")
                write_off(ra, ref[oid], origin)
                write_off(rb, var[oid], origin)
                p = subprocess.run([a.morphcut, "hausdorff", ra, rb], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
                if p.returncode != 0:
                    print(f"  {oid}: morphcut hausdorff failed: {p.stderr.strip()[:200]}", file=sys.stderr)
                    continue
                h = json.loads(p.stdout)
                rows[oid] = {"mean": h["mean_symmetric"], "hausdorff": h["symmetric"]}
            means = [r["mean"] for r in rows.values()]
            name = os.path.basename(os.path.normpath(run))
            if means:
                print(f"{name:28} {len(means):8d} {statistics.median(means):12.4f} {statistics.mean(means):8.4f} "
                      f"{100 * sum(m <= 0.1 for m in means) / len(means):7.1f}% {max(means):8.3f} "
                      f"{statistics.median(r['hausdorff'] for r in rows.values()):13.3f}")
            else:
                print(f"{name:28} {0:8d}")
            results[name] = rows
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
