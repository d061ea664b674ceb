#!/usr/bin/env python3
"""Derives test data for inputs from the rest of the world from the public CityJSON files: the same
buildings in geographic coordinates, and stress variants for the output grid.

usage: tools/gen_world_variants.py geographic IN.city.json OUT_DIR [--bin morphcut-city] [--from EPSG:n]
       tools/gen_world_variants.py stress IN.city.json OUT_DIR [--seed S]
       tools/gen_world_variants.py plateau IN.city.json OUT.gml [--bin morphcut-city] [--count N]

geographic  IN reprojected with `morphcut-city reproject` (PROJ, horizontal; heights kept) to
            EPSG:4979 (WGS 84 latitude/longitude/ellipsoidal height) and to EPSG:6697 (JGD2011
            latitude/longitude + JGD2011 height, PLATEAU's CRS), both on a 1e-9 degree grid
            (about 0.1 mm). Written as NAME.epsg4979.city.json and NAME.epsg6697.city.json.
stress      seeded variants (random.Random(seed), buildings in file order):
              rot     every building turned about the vertical through its own centre by an angle
                      in [0, 360) and moved to coordinates around 1e6-1e7 (one offset per file)
              cm      the input snapped to a 1 cm grid, the file's transform scale 0.01 m
              jitter  every vertex moved by up to +-0.4 mm on each axis (scale 1e-4 m to hold it)
              all     rot, then jitter, then the 1 cm grid (scale 0.01)
            In rot and all, a vertex two buildings share (a shared wall) is copied, so that each
            building turns with all of its own vertices. Written as NAME.<variant>.city.json.
plateau     a PLATEAU-like CityGML 2.0 file (EPSG:6697, gml:posList latitude first, bldg:
            WallSurface/RoofSurface/GroundSurface with lod2MultiSurface, a lod1Solid box and a
            lod2Solid of xlinks to the boundary surfaces, an uro: ADE element in every building)
            from the first N (default 12) buildings of IN with a LoD 2 Solid with semantics.
"""
import argparse, json, math, os, random, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def load(path):
    d = json.load(open(path))
    t = d.get("transform", {"scale": [1, 1, 1], "translate": [0, 0, 0]})
    s, tr = t["scale"], t["translate"]
    verts = [[v[0] * s[0] + tr[0], v[1] * s[1] + tr[1], v[2] * s[2] + tr[2]] for v in d["vertices"]]
    return d, verts


def save(d, verts, path, scale):
    lo = [min(v[i] for v in verts) for i in range(3)] if verts else [0, 0, 0]
    tr = [math.floor(lo[0]), math.floor(lo[1]), math.floor(lo[2])]
    d["transform"] = {"scale": [scale] * 3, "translate": tr}
    d["vertices"] = [[round((v[i] - tr[i]) / scale) for i in range(3)] for v in verts]
    if "metadata" in d:
        d["metadata"].pop("geographicalExtent", None)
    json.dump(d, open(path, "w"), separators=(",", ":"))


def vertex_refs(node, out):
    if isinstance(node, list):
        for x in node:
            vertex_refs(x, out)
    elif isinstance(node, int):
        out.append(node)


def buildings(d):
    """Top-level objects (no parents) with every vertex index of them and their descendants."""
    cos = d["CityObjects"]
    for oid, o in cos.items():
        if o.get("parents"):
            continue
        refs, stack = [], [oid]
        while stack:
            c = cos.get(stack.pop())
            if not c:
                continue
            for g in c.get("geometry", []):
                vertex_refs(g.get("boundaries", []), refs)
            stack.extend(c.get("children", []))
        yield oid, sorted(set(refs))


def own_vertices(d0, v0):
    """A copy of d0 in which no two buildings share a vertex: a building's references to a vertex
    an earlier building (file order) uses go to a new copy of it, appended."""
    d = json.loads(json.dumps(d0))
    verts = [list(v) for v in v0]
    cos = d["CityObjects"]
    taken = set()

    def remap(node, to):
        if isinstance(node, list):
            return [remap(x, to) for x in node]
        return to.get(node, node) if isinstance(node, int) else node

    for oid, refs in list(buildings(d)):
        to = {}
        for i in refs:
            if i in taken:
                to[i] = len(verts)
                verts.append(list(v0[i]))
        taken.update(refs)
        if not to:
            continue
        stack = [oid]
        while stack:
            c = cos.get(stack.pop())
            if not c:
                continue
            for g in c.get("geometry", []):
                g["boundaries"] = remap(g.get("boundaries", []), to)
            stack.extend(c.get("children", []))
    return d, verts


def stress(args):
    d0, v0 = load(args.input)
    name = os.path.basename(args.input).split(".")[0]
    os.makedirs(args.out, exist_ok=True)
    rnd = random.Random(args.seed)
    # One rotation per building, one offset for the file (drawn first: the same for every variant).
    angles = {oid: rnd.uniform(0, 2 * math.pi) for oid, _ in buildings(d0)}
    offset = [rnd.uniform(1e6, 1e7), rnd.uniform(1e6, 1e7), 0.0]
    jit = [[rnd.uniform(-4e-4, 4e-4) for _ in range(3)] for _ in v0]

    # Turned buildings get their own copy of every vertex they share with an earlier building (a
    # shared wall): turned with the first, the vertex would stand metres off the second one's shape.
    d_own, v_own = own_vertices(d0, v0)
    jit += [[rnd.uniform(-4e-4, 4e-4) for _ in range(3)] for _ in range(len(v_own) - len(v0))]

    def rotated(verts):
        out = list(verts)
        for oid, refs in buildings(d_own):
            if not refs:
                continue
            cx = sum(verts[i][0] for i in refs) / len(refs)
            cy = sum(verts[i][1] for i in refs) / len(refs)
            c, s = math.cos(angles[oid]), math.sin(angles[oid])
            for i in refs:
                x, y, z = verts[i]
                out[i] = [cx + c * (x - cx) - s * (y - cy), cy + s * (x - cx) + c * (y - cy), z]
        return [[v[0] + offset[0], v[1] + offset[1], v[2]] for v in out]

    def jittered(verts):
        return [[v[k] + jit[i][k] for k in range(3)] for i, v in enumerate(verts)]

    variants = {"rot": (d_own, rotated(v_own), 0.001), "cm": (d0, v0, 0.01), "jitter": (d0, jittered(v0), 0.0001),
                "all": (d_own, jittered(rotated(v_own)), 0.01)}
    for tag, (src, verts, scale) in variants.items():
        d = json.loads(json.dumps(src))
        path = os.path.join(args.out, f"{name}.{tag}.city.json")
        save(d, verts, path, scale)
        print(path)


def geographic(args):
    name = os.path.basename(args.input).split(".")[0]
    os.makedirs(args.out, exist_ok=True)
    for code in ("4979", "6697"):
        path = os.path.join(args.out, f"{name}.epsg{code}.city.json")
        subprocess.run([args.bin, "reproject", args.input, "-o", path, "--to", f"EPSG:{code}", "--scale", "1e-9"] +
                       (["--from", args.source_crs] if args.source_crs else []), check=True, stderr=subprocess.DEVNULL)
        print(path)


GML_HEAD = """<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:brid="http://www.opengis.net/citygml/bridge/2.0" xmlns:tran="http://www.opengis.net/citygml/transportation/2.0" xmlns:frn="http://www.opengis.net/citygml/cityfurniture/2.0" xmlns:wtr="http://www.opengis.net/citygml/waterbody/2.0" xmlns:sch="http://www.ascc.net/xml/schematron" xmlns:veg="http://www.opengis.net/citygml/vegetation/2.0" xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:tun="http://www.opengis.net/citygml/tunnel/2.0" xmlns:tex="http://www.opengis.net/citygml/texturedsurface/2.0" xmlns:gml="http://www.opengis.net/gml" xmlns:app="http://www.opengis.net/citygml/appearance/2.0" xmlns:gen="http://www.opengis.net/citygml/generics/2.0" xmlns:dem="http://www.opengis.net/citygml/relief/2.0" xmlns:luse="http://www.opengis.net/citygml/landuse/2.0" xmlns:uro="https://www.geospatial.jp/iur/uro/2.0" xmlns:xAL="urn:oasis:names:tc:ciq:xsdschema:xAL:2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:smil20="http://www.w3.org/2001/SMIL20/" xmlns:pbase="http://www.opengis.net/citygml/profiles/base/2.0" xmlns:smil20lang="http://www.w3.org/2001/SMIL20/Language" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xmlns:grp="http://www.opengis.net/citygml/cityobjectgroup/2.0" xmlns:core="http://www.opengis.net/citygml/2.0">
<gml:boundedBy><gml:Envelope srsName="http://www.opengis.net/def/crs/EPSG/0/6697" srsDimension="3">
<gml:lowerCorner>{lo}</gml:lowerCorner><gml:upperCorner>{hi}</gml:upperCorner></gml:Envelope></gml:boundedBy>
"""
KINDS = {"WallSurface", "RoofSurface", "GroundSurface"}


def plateau(args):
    # The buildings in EPSG:6697 first (longitude first, as CityJSON writes them).
    tmp = args.out + ".tmp6697.city.json"
    subprocess.run([args.bin, "reproject", args.input, "-o", tmp, "--to", "EPSG:6697", "--scale", "1e-9"],
                   check=True, stderr=subprocess.DEVNULL)
    d, verts = load(tmp)
    os.remove(tmp)
    cos = d["CityObjects"]

    def pos(i):  # latitude first, as GML writes EPSG:6697
        x, y, z = verts[i]
        return f"{y:.10f} {x:.10f} {z:.3f}"

    out, used, n = [], [], 0
    for oid, o in cos.items():
        if n >= args.count or o.get("type") != "Building":
            continue
        solid = None
        for c in [oid] + o.get("children", []):
            for g in cos.get(c, {}).get("geometry", []):
                if g.get("type") == "Solid" and str(g.get("lod")).startswith("2") and "semantics" in g:
                    solid = g
        if not solid:
            continue
        n += 1
        bid = f"bldg_{n:04d}"
        sem = solid["semantics"]
        surfaces, members, ring_pts = [], [], []
        for k, face in enumerate(solid["boundaries"][0]):
            kind = sem["surfaces"][sem["values"][0][k]]["type"] if sem["values"][0][k] is not None else "WallSurface"
            kind = kind if kind in KINDS else "WallSurface"
            pid = f"{bid}_poly_{k}"
            rings = []
            for r, ring in enumerate(face):
                ring_pts.extend(ring)
                coords = " ".join(pos(i) for i in ring + ring[:1])
                tag = "exterior" if r == 0 else "interior"
                rings.append(f"<gml:{tag}><gml:LinearRing><gml:posList>{coords}</gml:posList></gml:LinearRing></gml:{tag}>")
            surfaces.append(f"<bldg:boundedBy><bldg:{kind} gml:id=\"{bid}_surf_{k}\"><bldg:lod2MultiSurface><gml:MultiSurface>"
                            f"<gml:surfaceMember><gml:Polygon gml:id=\"{pid}\">{''.join(rings)}</gml:Polygon></gml:surfaceMember>"
                            f"</gml:MultiSurface></bldg:lod2MultiSurface></bldg:{kind}></bldg:boundedBy>")
            members.append(f"<gml:surfaceMember xlink:href=\"#{pid}\"/>")
        used.extend(ring_pts)
        # LoD 1: the box of the building's points, as PLATEAU's lod1Solid is an extruded footprint.
        xs = [verts[i] for i in set(ring_pts)]
        lo = [min(v[a] for v in xs) for a in range(3)]
        hi = [max(v[a] for v in xs) for a in range(3)]
        c = [[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]]

        def p(x, y, z):
            return f"{y:.10f} {x:.10f} {z:.3f}"

        def face(pts):
            coords = " ".join(p(*q) for q in pts + pts[:1])
            return (f"<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>{coords}"
                    f"</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>")

        bottom = [(x, y, lo[2]) for x, y in c][::-1]
        top = [(x, y, hi[2]) for x, y in c]
        sides = [[(c[i][0], c[i][1], lo[2]), (c[(i + 1) % 4][0], c[(i + 1) % 4][1], lo[2]),
                  (c[(i + 1) % 4][0], c[(i + 1) % 4][1], hi[2]), (c[i][0], c[i][1], hi[2])] for i in range(4)]
        lod1 = "".join(face(f) for f in [bottom, top] + sides)
        out.append(
            f"<core:cityObjectMember><bldg:Building gml:id=\"{bid}\">"
            f"<gen:stringAttribute name=\"source\"><gen:value>{oid}</gen:value></gen:stringAttribute>"
            f"<bldg:measuredHeight uom=\"m\">{hi[2] - lo[2]:.2f}</bldg:measuredHeight>"
            f"<bldg:lod1Solid><gml:Solid srsName=\"http://www.opengis.net/def/crs/EPSG/0/6697\" srsDimension=\"3\">"
            f"<gml:exterior><gml:CompositeSurface>{lod1}</gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod1Solid>"
            f"<bldg:lod2Solid><gml:Solid srsName=\"http://www.opengis.net/def/crs/EPSG/0/6697\" srsDimension=\"3\">"
            f"<gml:exterior><gml:CompositeSurface>{''.join(members)}</gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>"
            f"{''.join(surfaces)}"
            f"<uro:buildingDetailAttribute><uro:BuildingDetailAttribute><uro:surveyYear>2022</uro:surveyYear>"
            f"<uro:buildingRoofEdgeArea uom=\"m2\">0</uro:buildingRoofEdgeArea></uro:BuildingDetailAttribute>"
            f"</uro:buildingDetailAttribute>"
            f"</bldg:Building></core:cityObjectMember>")
    pts = [verts[i] for i in set(used)]
    lo = " ".join(f"{v:.10f}" for v in (min(q[1] for q in pts), min(q[0] for q in pts), min(q[2] for q in pts)))
    hi = " ".join(f"{v:.10f}" for v in (max(q[1] for q in pts), max(q[0] for q in pts), max(q[2] for q in pts)))
    with open(args.out, "w") as f:
        f.write(GML_HEAD.format(lo=lo, hi=hi))
        f.write("\n".join(out))
        f.write("\n</core:CityModel>\n")
    print(args.out, n, "buildings")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mode", choices=["geographic", "stress", "plateau"])
    ap.add_argument("input")
    ap.add_argument("out")
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "tools", "morphcut-city"))
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=12)
    ap.add_argument("--from", dest="source_crs", default="",
                    help="the input's CRS when the file does not say it (cjio's rotterdam_subset: EPSG:7415)")
    args = ap.parse_args()
    {"geographic": geographic, "stress": stress, "plateau": plateau}[args.mode](args)


if __name__ == "__main__":
    sys.exit(main())
