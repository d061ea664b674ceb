#!/usr/bin/env python3
"""The labelled set of real buildings that judges the massing analytics (docs/massing.md, "The
labelled set"; tests/data/massing_labels.json).

usage: tools/massing_labels.py sample   --out DIR [--bin B] [--seed S]     draw the buildings, render them
       tools/massing_labels.py evaluate LABELS [--bin B] [--work DIR] [--min-roles R] [--min-buildings F]
       tools/massing_labels.py collect  --manifest M --out LABELS FILE... [--review FILE]
       tools/massing_labels.py agree    LABELS                              two people's labels compared

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
collect   joins the people's label files (each {"buildings": [label...]}) with the manifest's part
          geometry into one LABELS file (tests/data/massing_labels.json): seed, level, how the
          buildings were drawn and rendered, the guide, and the second labeller's labels as "review".
agree     compares the primary labels with the second labeller's (LABELS["review"], made blind on a
          third of the buildings): masses with the same parts and role, parts with the same role,
          buildings with every feature equal, and Cohen's kappa over the parts' roles.
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
            "index": a["morphcut_index"], "id": k, "width": plan_width(pts),
            "centroid": [round(sum(p[j] for p in pts) / len(pts), 4) for j in range(3)],
            "box": [[round(x, 4) for x in lo], [round(x, 4) for x in hi]],
            "volume": a.get("volume"), "role": a.get("morphcut_role"),
            "mass": a.get("morphcut_mass"), "mass_role": a.get("morphcut_mass_role"),
        })
    for v in out.values():
        v.sort(key=lambda p: p["index"])
    return out


def plan_width(pts):
    """The smallest caliper width of the points' plan (2D convex hull), metres."""
    q = sorted({(round(p[0], 6), round(p[1], 6)) for p in pts})
    if len(q) < 3:
        return 0.0
    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    lower, upper = [], []
    for p in q:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(q):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    hull = lower[:-1] + upper[:-1]
    best = float("inf")
    for i in range(len(hull)):
        a, b = hull[i], hull[(i + 1) % len(hull)]
        L = ((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2) ** 0.5
        if L > 0:
            best = min(best, max(abs(cross(a, b, c)) / L for c in hull))
    return 0.0 if best == float("inf") else best


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
    by_source = collections.defaultdict(lambda: collections.defaultdict(collections.Counter))
    slivers = 0  # tool masses of role annex or wing made only of parts thinner than 1 m
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
            by_source[key][m["role"]][predicted] += 1
            s = per_source[key]
            s[0] += predicted == m["role"]
            s[1] += 1
            if args.verbose and predicted != m["role"]:
                print(f"  role {key} {b['id']}: parts {m['parts']} person {m['role']}, tool {predicted}")
        tool_masses = collections.defaultdict(list)
        for cp in current:
            tool_masses[cp["mass"] if cp["mass"] is not None else ("part", cp["index"])].append(cp)
        for ps in tool_masses.values():
            if (ps[0]["mass_role"] or ps[0]["role"]) in ("annex", "wing") and all(cp["width"] < 1.0 for cp in ps):
                slivers += 1
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
        if args.verbose and not right:
            tool = collections.defaultdict(list)
            for cp in current:
                tool[(cp["mass"], cp["mass_role"] or cp["role"])].append(cp["index"])
            print(f"- {key} {b['id']}: person " + "; ".join(f"{m['role']} {m['parts']}" for m in b["masses"])
                  + " | tool " + "; ".join(f"{r} {ps}" for (_, r), ps in sorted(tool.items(), key=lambda t: t[1]))
                  + " | " + ", ".join(f"{f} {b['features'][f]}/{attrs.get('morphcut_' + f)}" for f in FEATURES
                                       if (bool(b['features'][f]) != bool(attrs.get('morphcut_' + f)) if f == 'tower_on_podium'
                                           else b['features'][f] != attrs.get('morphcut_' + f))))
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
    print(f"annex or wing masses made only of parts under 1 m wide: {slivers}")
    roles = ROLES + sorted({r for c in confusion.values() for r in c} - set(ROLES))
    def table(title, conf):
        print(f"{title} (rows: person, columns: tool)")
        print(f"{'':9}" + "".join(f"{r[:7]:>8}" for r in roles))
        for r in ROLES:
            if conf[r]:
                print(f"{r:9}" + "".join(f"{conf[r][c] or '.':>8}" for c in roles))
    table("confusion, all sources", confusion)
    if args.per_source:
        for k in sorted(by_source):
            table(f"confusion, {k}", by_source[k])
    ok = masses_right >= args.min_roles * masses and buildings_right >= args.min_buildings * buildings
    return 0 if ok else 1


def collect(args):
    manifest = json.load(open(args.manifest))
    by_key = {(b["source"], b["id"]): b for b in manifest["buildings"]}
    labels = {}
    for f in args.files:
        for lab in json.load(open(f))["buildings"]:
            labels[(lab["source"], lab["id"])] = lab
    out = {
        "about": "Massing labels of real buildings judged by a person (docs/massing.md, 'The labelled set'; "
                 "guide: docs/massing-labelling-guide.md)",
        "drawn": f"tools/massing_labels.py sample --seed {manifest['seed']}: random.Random(seed).sample of 100 "
                 "among the 3D BAG tile's buildings with 2-40 parts at level 0.01, every such building of the "
                 "other sources",
        "rendered": "tools/render-parts OUT.level-0.01.city.json --neutral --input OUT.city.json --id ID",
        "seed": manifest["seed"], "level": manifest["level"], "buildings": [], "review": []}
    for key, b in by_key.items():
        if key not in labels:
            continue
        lab = labels[key]
        out["buildings"].append({"source": b["source"], "file": b["file"], "id": b["id"], "parts": b["parts"],
                                 "masses": lab["masses"], "features": lab["features"],
                                 "confidence": lab.get("confidence"), "notes": lab.get("notes", "")})
    if args.review:
        for lab in json.load(open(args.review))["buildings"]:
            out["review"].append({k: lab.get(k) for k in ("source", "id", "masses", "features", "confidence", "notes")})
    json.dump(out, open(args.out, "w"), indent=1)
    print(f"{len(out['buildings'])} buildings labelled of {len(by_key)}; {len(out['review'])} reviewed")
    return 0


def agree(args):
    data = json.load(open(args.labels))
    primary = {(b["source"], b["id"]): b for b in data["buildings"]}
    review = data.get("review", [])
    same_mass = masses = same_part = parts = same_feat = 0
    mass_major = [0, 0]
    feat_eq = collections.Counter()
    pairs = []
    for r in review:
        b = primary.get((r["source"], r["id"]))
        if not b:
            continue
        def part_role(lab):
            return {i: (m["role"], tuple(sorted(m["parts"]))) for m in lab["masses"] for i in m["parts"]}
        pa, pb = part_role(b), part_role(r)
        vol = {pp["index"]: pp.get("volume") or 0 for pp in b.get("parts", [])}
        for m in b["masses"]:  # as `evaluate` scores the tool: the volume-weighted majority role
            w = collections.Counter()
            for i in m["parts"]:
                w[pb.get(i, ("?",))[0]] += vol.get(i, 0)
            mass_major[0] += (w.most_common(1)[0][0] if w else "?") == m["role"]
            mass_major[1] += 1
        sa = {(t, role) for role, t in pa.values()}
        sb = {(t, role) for role, t in pb.values()}
        masses += len(sa)
        same_mass += len(sa & sb)
        for i in pa:
            parts += 1
            same_part += pb.get(i, ("?",))[0] == pa[i][0]
            pairs.append((pa[i][0], pb.get(i, ("?",))[0]))
        eq = True
        for f in FEATURES:
            e = bool(b["features"][f]) == bool(r["features"][f]) if f == "tower_on_podium" else b["features"][f] == r["features"][f]
            feat_eq[f] += e
            eq = eq and e
        same_feat += eq
    n = len(review)
    po = same_part / max(parts, 1)
    ca, cb = collections.Counter(a for a, _ in pairs), collections.Counter(b for _, b in pairs)
    pe = sum(ca[k] * cb[k] for k in ca) / max(len(pairs), 1) ** 2
    kappa = (po - pe) / (1 - pe) if pe < 1 else 1.0
    print(f"buildings reviewed: {n}")
    print(f"masses with the same parts and role: {same_mass}/{masses} ({100 * same_mass / max(masses, 1):.1f} %)")
    print(f"masses with the second person's role (volume-weighted majority of their parts, as evaluate scores the "
          f"tool): {mass_major[0]}/{mass_major[1]} ({100 * mass_major[0] / max(mass_major[1], 1):.1f} %)")
    print(f"parts with the same role: {same_part}/{parts} ({100 * po:.1f} %), Cohen's kappa {kappa:.2f}")
    print(f"buildings with every feature equal: {same_feat}/{n} ({100 * same_feat / max(n, 1):.1f} %)")
    print("per feature equal: " + ", ".join(f"{f} {feat_eq[f]}/{n}" for f in FEATURES))
    return 0


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
    e.add_argument("--per-source", action="store_true", help="a confusion table per source too")
    e.add_argument("--verbose", action="store_true", help="each building whose features differ: masses and counts")
    c = sub.add_parser("collect")
    c.add_argument("--manifest", required=True)
    c.add_argument("--out", required=True)
    c.add_argument("--review")
    c.add_argument("files", nargs="+")
    a = sub.add_parser("agree")
    a.add_argument("labels")
    for p in (s, e):
        p.add_argument("--bin", default=os.path.join(ROOT, "build", "tools", "morphcut-city"))
    args = ap.parse_args()
    return {"sample": sample, "evaluate": evaluate, "collect": collect, "agree": agree}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
