#!/usr/bin/env python3
"""The labelled set of real buildings that judges the massing analytics (docs/massing.md, "The
labelled set"; tests/data/massing_labels.json).

usage: tools/massing_labels.py sample   --out DIR [--bin B] [--seed S]     draw the buildings, render them
       tools/massing_labels.py evaluate LABELS [--bin B] [--work DIR] [--min-roles R] [--min-buildings F]

sample    runs morphcut-city on the public sources (the 3D BAG tile, cjio's Rotterdam subset, the Den
          Haag files, the Berlin CityGML sample), draws the buildings with 2-40 parts at level 0.01
          (random.Random(seed).sample over the sorted ids of each source; the tile QUOTA, every
          eligible building of the others), renders each with tools/render-parts --neutral (every part
          its own colour, no role shown) into DIR/png/<source>/<id>.png and writes DIR/manifest.json:
          per building its source, id and parts (index, centroid, box, volume, z range) at level 0.01.
          A person then labels each building: its masses (groups of part indices, each with a role)
          and its features (tiers, setbacks, wings, annexes, rooftop units, courtyards, tower on podium).
evaluate  runs morphcut-city on the sources again, maps each labelled part to the current part whose
          centroid is nearest (inside the labelled part's box grown by 0.5 m; parts the decomposition
          cut differently are matched by their centroids falling in the labelled part's box), and
          compares: a labelled mass is right when the role its parts get (volume-weighted majority of
          the current parts' mass roles) is the label's; a building is right when every feature count
          equals the label's. Prints the confusion table per role and per source; exit 1 below
          --min-roles (0.97) or --min-buildings (0.90).
"""
import argparse, collections, json, os, random, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(ROOT, "..", "shared", "datasets")
SOURCES = [  # name, path under datasets/, how many to draw (None = every eligible building)
    ("3dbag", "cityjson/3dbag/3dbag_v210908_fd2cee53_5910.city.json", 100),
    ("rotterdam", "cityjson/cjio/rotterdam/rotterdam_subset.json", None),
    ("denhaag_subs", "cityjson/cjio/DH_01_subs.city.json", None),
    ("denhaag_random", "cityjson/val3dity/denhaag_random_5.city.jsonl", None),
    ("denhaag_gml", "citygml/DenHaag_1BwBP.citygml1.0.gml", None),
    ("berlin", "citygml/berlin_open_data_sample_data.citygml1.0.gml", None),
]
LEVEL = "0.01"
ROLES = ["main", "wing", "annex", "podium", "tower", "setback", "roof", "rooftop"]
FEATURES = ["tiers", "setbacks", "wings", "annexes", "rooftop_units", "courtyards", "tower_on_podium"]


def run_source(binary, name, rel, work):
    src = os.path.join(SHARED, rel)
    ext = ".city.jsonl" if rel.endswith(".jsonl") else ".city.json"
    d = os.path.join(work, name)
    os.makedirs(d, exist_ok=True)
    out = os.path.join(d, "out" + ext)
    subprocess.run([binary, src, "-o", out, "--threads", "2", "-q", "--no-html", "--no-gpkg", "--no-graph",
                    "--no-summary"], check=False)
    return out, out.replace(ext, f".level-{LEVEL}{ext}")


def read_city(path):
    """CityObjects and real-world vertices of a CityJSON or CityJSONSeq file (feature-local vertices)."""
    objects, verts = {}, {}
    def add(doc, t):
        s, tr = (t["scale"], t["translate"]) if t else ([1, 1, 1], [0, 0, 0])
        vs = [[v[i] * s[i] + tr[i] for i in range(3)] for v in doc.get("vertices", [])]
        for k, o in doc["CityObjects"].items():
            objects[k] = o
            verts[k] = vs
    if path.endswith(".jsonl"):
        lines = open(path).read().splitlines()
        t = json.loads(lines[0]).get("transform")
        for l in lines[1:]:
            if l.strip():
                add(json.loads(l), t)
    else:
        d = json.load(open(path))
        add(d, d.get("transform"))
    return objects, verts


def parts_of(objects, verts):
    """building id -> [part record] of the morphcut parts of a level file."""
    out = collections.defaultdict(list)
    for k, o in objects.items():
        a = o.get("attributes", {})
        if o.get("type") != "BuildingPart" or "morphcut_level" not in a:
            continue
        vs = verts[k]
        idx = sorted({i for shell in o["geometry"][0]["boundaries"] for s in shell for r in s for i in r})
        pts = [vs[i] for i in idx]
        lo = [min(p[j] for p in pts) for j in range(3)]
        hi = [max(p[j] for p in pts) for j in range(3)]
        out[o["parents"][0]].append({
            "index": a["morphcut_index"], "id": k,
            "centroid": [round(sum(p[j] for p in pts) / len(pts), 4) for j in range(3)],
            "box": [[round(x, 4) for x in lo], [round(x, 4) for x in hi]],
            "volume": a.get("volume"), "role": a.get("morphcut_role"),
            "mass": a.get("morphcut_mass"), "mass_role": a.get("morphcut_mass_role"),
        })
    for v in out.values():
        v.sort(key=lambda p: p["index"])
    return out


def sample(args):
    work = os.path.join(args.out, "runs")
    rnd_seed = args.seed
    manifest = {"seed": rnd_seed, "level": float(LEVEL), "buildings": []}
    for name, rel, quota in SOURCES:
        main_out, level_out = run_source(args.bin, name, rel, work)
        objects, verts = read_city(level_out)
        parts = parts_of(objects, verts)
        eligible = sorted(b for b, p in parts.items() if 2 <= len(p) <= 40)
        chosen = eligible if quota is None or quota >= len(eligible) else random.Random(rnd_seed).sample(eligible, quota)
        png = os.path.join(args.out, "png", name)
        if chosen:
            cmd = ["/usr/bin/python3", os.path.join(HERE, "render-parts"), level_out, "--neutral", "--out", png, "-q",
                   "--input", main_out]
            for b in chosen:
                cmd += ["--id", b]
            subprocess.run(cmd, check=False)
        for b in chosen:
            manifest["buildings"].append({"source": name, "file": rel, "id": b,
                                          "png": os.path.relpath(os.path.join(png, safe(b) + ".png"), args.out),
                                          "parts": [{k: p[k] for k in ("index", "centroid", "box", "volume")}
                                                    for p in parts[b]]})
        print(f"{name}: {len(eligible)} eligible, {len(chosen)} drawn", file=sys.stderr)
    json.dump(manifest, open(os.path.join(args.out, "manifest.json"), "w"), indent=1)


def safe(oid):
    return "".join(c if c.isalnum() or c in "._-{}" else "_" for c in oid)


def match_parts(labelled, current):
    """labelled part index -> list of (current part, weight): the current parts whose centroid lies
    in the labelled part's box grown by 0.5 m, weighted by volume; else the nearest centroid."""
    out = {}
    for lp in labelled:
        lo = [x - 0.5 for x in lp["box"][0]]
        hi = [x + 0.5 for x in lp["box"][1]]
        inside = [cp for cp in current if all(lo[j] <= cp["centroid"][j] <= hi[j] for j in range(3))]
        if not inside:
            d = lambda cp: sum((cp["centroid"][j] - lp["centroid"][j]) ** 2 for j in range(3))
            inside = [min(current, key=d)]
        out[lp["index"]] = inside
    return out


def evaluate(args):
    labels = json.load(open(args.labels))
    work = args.work
    cache = {}
    confusion = collections.defaultdict(collections.Counter)  # label role -> predicted role
    per_source = collections.defaultdict(lambda: [0, 0, 0, 0])  # masses right, masses, buildings right, buildings
    feature_misses = collections.Counter()
    thin_counted = 0
    for b in labels["buildings"]:
        key = b["source"]
        if key not in cache:
            rel = next(r for n, r, _ in SOURCES if n == key)
            main_out, level_out = run_source(args.bin, key, rel, work)
            objects, verts = read_city(level_out)
            cache[key] = (objects, parts_of(objects, verts))
        objects, parts = cache[key]
        current = parts.get(b["id"], [])
        if not current:
            continue
        mapping = match_parts(b["parts"], current)
        for m in b["masses"]:
            weight = collections.Counter()
            for i in m["parts"]:
                for cp in mapping.get(i, []):
                    weight[cp["mass_role"] or cp["role"]] += cp["volume"] or 0
            predicted = weight.most_common(1)[0][0] if weight else "?"
            confusion[m["role"]][predicted] += 1
            s = per_source[key]
            s[0] += predicted == m["role"]
            s[1] += 1
        attrs = objects.get(b["id"], {}).get("attributes", {})
        right = True
        for f in FEATURES:
            want = b["features"][f]
            got = attrs.get("morphcut_" + f)
            if f == "tower_on_podium":
                got, want = bool(got), bool(want)
            if got != want:
                right = False
                feature_misses[f] += 1
        s = per_source[key]
        s[2] += right
        s[3] += 1
    masses = sum(s[1] for s in per_source.values())
    masses_right = sum(s[0] for s in per_source.values())
    buildings = sum(s[3] for s in per_source.values())
    buildings_right = sum(s[2] for s in per_source.values())
    print(f"masses with the person's role: {masses_right}/{masses} ({100 * masses_right / max(masses, 1):.1f} %)")
    print(f"buildings with every feature count equal: {buildings_right}/{buildings} "
          f"({100 * buildings_right / max(buildings, 1):.1f} %)")
    print("per source: " + ", ".join(f"{k} roles {s[0]}/{s[1]} buildings {s[2]}/{s[3]}" for k, s in sorted(per_source.items())))
    print("feature mismatches: " + ", ".join(f"{f} {n}" for f, n in feature_misses.most_common()))
    roles = ROLES + sorted({r for c in confusion.values() for r in c} - set(ROLES))
    print("confusion (rows: person, columns: tool)")
    print(f"{'':9}" + "".join(f"{r[:7]:>8}" for r in roles))
    for r in ROLES:
        if confusion[r]:
            print(f"{r:9}" + "".join(f"{confusion[r][c] or '.':>8}" for c in roles))
    ok = masses_right >= args.min_roles * masses and buildings_right >= args.min_buildings * buildings
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("sample")
    s.add_argument("--out", required=True)
    s.add_argument("--seed", type=int, default=35)
    e = sub.add_parser("evaluate")
    e.add_argument("labels")
    e.add_argument("--work", default=os.path.join(os.environ.get("TMPDIR", "/tmp"), "morphcut-massing-labels"))
    e.add_argument("--min-roles", type=float, default=0.97)
    e.add_argument("--min-buildings", type=float, default=0.90)
    for p in (s, e):
        p.add_argument("--bin", default=os.path.join(ROOT, "build", "tools", "morphcut-city"))
    args = ap.parse_args()
    return sample(args) if args.cmd == "sample" else evaluate(args)


if __name__ == "__main__":
    sys.exit(main())
