#!/usr/bin/env python3
"""Open-model test data: seeded variants of real CityJSON files with surfaces removed,
and small synthetic open models with their closed references. Python 3 standard library only.

    python3 tools/gen_open_variants.py INPUT.city.json OUTDIR [--seed N] [--variants a,b,c,d,e]
                                       [--lod 2.2|highest]
    python3 tools/gen_open_variants.py --synthetic OUTDIR

Inputs meant (../shared/datasets/cityjson, read its README.md): the 3D BAG tile
upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.json (= datasets/3dbag/3dbag_5910.city.json;
the 1.1 original 3dbag/3dbag_v210908_fd2cee53_5910.city.json works as well), the Rotterdam subset
cjio/rotterdam/rotterdam_subset.json and DH_01_subs upgraded-2.0/DH_01_subs.v20.city.json
(= datasets/edge/DH_01_subs.v20.city.json; or the 1.1 original cjio/DH_01_subs.city.json).

Output, per variant V: OUTDIR/<stem>.<V>.city.json, same CityJSON version as the input, with
metadata, transform, appearance, every city object and attribute kept. Only the building geometry
the project decomposes changes: per Building (a CityObject of type Building without parents), the
geometries of the Building and its BuildingPart descendants (through "children") at the chosen LoD
- "highest" exactly as io/cityjson_building.cpp extract_building picks it (the first geometry's
LoD, replaced by any numerically greater one; every geometry numerically equal is taken) - of type
Solid, MultiSurface, CompositeSurface, MultiSolid or CompositeSolid are each replaced, in place, by
a MultiSurface at the same "lod" holding every surface of every shell, minus the removed ones.
Semantics, materials and textures follow the surfaces (values flattened to one per surface; the
"surfaces" array is kept unchanged). GeometryInstances are left alone. Vertices are only appended
(clipped points, quantised with the file's transform, reused when an identical vertex exists);
none is removed, so the removed surfaces' vertices stay unused. A geometry left with no surface is
dropped from its object. Plus OUTDIR/<stem>.variants.json: seed, rules, per-variant totals and per
building and variant the surfaces removed / clipped (0 where nothing applied).

Surface class: the semantic type when the surface has one (WallSurface -> wall, RoofSurface -> roof,
GroundSurface -> ground; any other semantic type is "other" and never touched). Without semantics
(no "semantics" or a null value) from the outer ring's Newell normal n (unit): |n_z| < 0.17 wall;
n_z < -0.9 and mean height within 0.5 m of the building's lowest vertex ground; else roof. A ring
with < 3 distinct points or zero area is "other".

Variants (the closed input is the reference for every one):
 a  party walls removed. A wall W of building A is a party wall when some wall V of another
    building B (a different top-level Building) is parallel (angle between the planes <= 5 deg,
    either orientation), coplanar (each polygon's vertex mean lies within 0.05 m of the other's
    plane) and overlaps W in area: both are projected onto W's plane and clipped against each
    other (holes respected, exact signed-triangle decomposition), overlap >= 0.05 m^2. Candidate
    pairs come from a 10 m grid of the walls' bounding boxes (grown by 0.05 m). The whole wall
    polygon is removed, also when only a part of it is shared.
 b  every wall removed (roof + ground + other remain).
 c  every ground surface removed.
 d  round(0.3 * walls) walls of each building removed, drawn with random.Random seeded from
    sha256("<seed>:<building id>") over the walls in file order (independent of other buildings).
 e  the lowest 0.3 m of every wall removed: each wall polygon (holes included) is clipped against
    the plane z = z_min + 0.3 (z_min: the lowest vertex of the building's chosen geometries) and
    the part above kept - possibly several pieces, each a surface with the wall's semantics,
    material and texture (uv interpolated along the cut edge). Walls wholly below are removed.
    This leaves a 0.3 m gap between the walls and the ground.
Measured (seed 19): the Rotterdam subset has no party walls to remove - its adjacent buildings
share 16 footprint edges but no walls there, it is already open that way - and the DH_01_subs
buildings stand >= 67 m apart, so (a) only re-encodes those two files as MultiSurface.

Every file written is checked (JSON, vertex indices in range, semantics/material/texture value
lengths) and, for CityJSON 2.0 files, validated with the project's ajv (build/node_tools) against
../shared/datasets/cityjson/schemas/2.0/cityjson.min.schema.json when both are there. --no-ajv skips it.

--synthetic OUTDIR writes CityJSON 2.0 files (transform 1 mm, MultiSurface with semantics) and the
closed reference <name>.closed.city.json of each: terraced_row (five terraced houses without party
walls: roof, ground, front and back walls, the two end houses also their gable end wall),
gable_roof_only (two roof planes; reference with four walls and ground), l_shape_roof_only (an
L-shaped house: gabled main block and a flat-roofed annex, roofs only), tower_inclined_prisms (six
storeys, each a closed sheared triangular prism, glued face to face - every inter-storey triangle
twice - plus a horizontal floor sheet at mid-height of each storey; reference: the outer shell
only). The closed references are checked to be closed and outward oriented (every edge used once
in each direction, positive volume).
"""
import argparse
import hashlib
import json
import math
import os
import random
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, ".."))
AJV = os.path.join(REPO, "build", "node_tools", "node_modules", ".bin", "ajv")
SCHEMA = os.path.normpath(os.path.join(REPO, "..", "shared", "datasets", "cityjson", "schemas", "2.0",
                                       "cityjson.min.schema.json"))

VARIANTS = "abcde"
SURFACE_GEOMS = ("MultiSurface", "CompositeSurface", "Solid", "MultiSolid", "CompositeSolid")
NESTING = {"MultiSurface": 0, "CompositeSurface": 0, "Solid": 1, "MultiSolid": 2, "CompositeSolid": 2}
SEM_CLASS = {"WallSurface": "wall", "RoofSurface": "roof", "GroundSurface": "ground"}

WALL_NZ = 0.17          # |n_z| below: wall
GROUND_NZ = -0.9        # n_z below (and near the lowest height): ground
GROUND_NEAR = 0.5       # m above the building's lowest vertex
PARTY_ANGLE = 5.0       # degrees
PARTY_DIST = 0.05       # m
PARTY_MIN_AREA = 0.05   # m^2
GRID = 10.0             # m
RANDOM_FRACTION = 0.3
GAP = 0.3               # m


# ---------------------------------------------------------------------------------------------
# small vector helpers

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def newell(pts):
    """Area vector (normal * area) of a 3D ring, computed relative to its first point."""
    if len(pts) < 3:
        return (0.0, 0.0, 0.0)
    o = pts[0]
    nx = ny = nz = 0.0
    n = len(pts)
    for i in range(n):
        a = sub(pts[i], o)
        b = sub(pts[(i + 1) % n], o)
        nx += (a[1] - b[1]) * (a[2] + b[2])
        ny += (a[2] - b[2]) * (a[0] + b[0])
        nz += (a[0] - b[0]) * (a[1] + b[1])
    return (nx * 0.5, ny * 0.5, nz * 0.5)


def area2(poly):
    """Signed area of a 2D ring."""
    s = 0.0
    n = len(poly)
    for i in range(n):
        x0, y0 = poly[i]
        x1, y1 = poly[(i + 1) % n]
        s += x0 * y1 - x1 * y0
    return 0.5 * s


def clip_convex(subject, clipper):
    """Sutherland-Hodgman: a 2D polygon clipped by a convex CCW polygon."""
    out = subject
    n = len(clipper)
    for i in range(n):
        if not out:
            break
        ax, ay = clipper[i]
        bx, by = clipper[(i + 1) % n]
        inp, out = out, []
        m = len(inp)
        for j in range(m):
            p = inp[j]
            q = inp[(j + 1) % m]
            sp = (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax)
            sq = (bx - ax) * (q[1] - ay) - (by - ay) * (q[0] - ax)
            if sp >= 0:
                out.append(p)
            if (sp >= 0) != (sq >= 0):
                t = sp / (sp - sq)
                out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def fan_triangles(rings):
    """Signed triangles (origin, p_k, p_k+1) of every ring edge; each as (sign, CCW triangle)."""
    out = []
    for ring in rings:
        n = len(ring)
        for k in range(n):
            p, q = ring[k], ring[(k + 1) % n]
            a = p[0] * q[1] - q[0] * p[1]
            if abs(a) < 1e-12:
                continue
            tri = [(0.0, 0.0), p, q] if a > 0 else [(0.0, 0.0), q, p]
            out.append((1.0 if a > 0 else -1.0, tri))
    return out


def overlap_area(rings_a, rings_b):
    """Area of the intersection of two 2D polygons with holes (outer CCW, holes CW):
    sum over pairs of signed origin-fan triangles of sign * sign * area(T_a & T_b)."""
    ta, tb = fan_triangles(rings_a), fan_triangles(rings_b)
    total = 0.0
    for sa, a in ta:
        ax0 = min(p[0] for p in a); ax1 = max(p[0] for p in a)
        ay0 = min(p[1] for p in a); ay1 = max(p[1] for p in a)
        for sb, b in tb:
            if max(p[0] for p in b) <= ax0 or min(p[0] for p in b) >= ax1:
                continue
            if max(p[1] for p in b) <= ay0 or min(p[1] for p in b) >= ay1:
                continue
            c = clip_convex(a, b)
            if len(c) >= 3:
                total += sa * sb * area2(c)
    return total


# ---------------------------------------------------------------------------------------------
# reading the model

def lod_string(lod):
    if isinstance(lod, str):
        return lod
    if isinstance(lod, bool) or lod is None:
        return ""
    if isinstance(lod, (int, float)):
        return json.dumps(lod)
    return ""


def lod_value(lod):
    try:
        v = float(lod)
    except (TypeError, ValueError):
        return -math.inf
    return v if math.isfinite(v) or v == -math.inf else -math.inf


def building_objects(objs, bid):
    out, seen, i = [bid], {bid}, 0
    while i < len(out):
        o = objs.get(out[i])
        i += 1
        if not isinstance(o, dict) or not isinstance(o.get("children"), list):
            continue
        for c in o["children"]:
            if isinstance(c, str) and isinstance(objs.get(c), dict) and objs[c].get("type") == "BuildingPart" \
                    and c not in seen:
                seen.add(c)
                out.append(c)
    return out


def top_level_buildings(objs):
    out = []
    for k, o in objs.items():
        if not isinstance(o, dict) or o.get("type") != "Building":
            continue
        parents = o.get("parents")
        if isinstance(parents, list) and any(isinstance(p, str) and p in objs for p in parents):
            continue
        out.append(k)
    return out


def chosen_geometries(objs, bid, lod):
    """[(object id, geometry index)] taken for building `bid`, and the chosen LoD string."""
    cands = []
    for oid in building_objects(objs, bid):
        geoms = objs[oid].get("geometry")
        if not isinstance(geoms, list):
            continue
        for gi, g in enumerate(geoms):
            if isinstance(g, dict) and g.get("type") in SURFACE_GEOMS:
                cands.append((oid, gi, lod_string(g.get("lod"))))
    chosen = lod
    if lod == "highest":
        chosen, best = "", -math.inf
        for _, _, l in cands:
            if chosen == "" or lod_value(l) > best:
                best, chosen = lod_value(l), l
    take = []
    for oid, gi, l in cands:
        if lod == "highest":
            ok = l == chosen or (lod_value(l) == lod_value(chosen) and math.isfinite(lod_value(chosen)))
        else:
            ok = l == chosen
        if ok:
            take.append((oid, gi))
    return take, chosen


def flatten(node, levels):
    """Surfaces of a boundary / value array nested `levels` deep above the surface level."""
    if levels == 0:
        return list(node) if isinstance(node, list) else []
    out = []
    for x in node if isinstance(node, list) else []:
        out.extend(flatten(x, levels - 1))
    return out


def flatten_values(values, levels, n):
    """Per-surface values (semantics / material) aligned with `n` flattened surfaces."""
    if values is None:
        return [None] * n
    flat = flatten(values, levels)
    flat = flat + [None] * (n - len(flat))
    return flat[:n]


class Model:
    def __init__(self, doc):
        self.doc = doc
        self.objs = doc["CityObjects"]
        t = doc.get("transform")
        self.scale = tuple(t["scale"]) if t else None
        self.translate = tuple(t["translate"]) if t else None
        self.verts = doc.setdefault("vertices", [])
        self.index = None  # quantised vertex -> index, built on the first append
        app = doc.get("appearance") or {}
        self.uv = app.get("vertices-texture")

    def point(self, i):
        v = self.verts[i]
        if self.scale:
            return (v[0] * self.scale[0] + self.translate[0], v[1] * self.scale[1] + self.translate[1],
                    v[2] * self.scale[2] + self.translate[2])
        return (float(v[0]), float(v[1]), float(v[2]))

    def vertex_for(self, p):
        """Index of the vertex at p (quantised with the transform), appended when new."""
        if self.scale:
            q = tuple(int(round((p[k] - self.translate[k]) / self.scale[k])) for k in range(3))
        else:
            q = tuple(float(x) for x in p)
        if self.index is None:
            self.index = {}
            for i, v in enumerate(self.verts):
                self.index.setdefault(tuple(v), i)
        i = self.index.get(q)
        if i is None:
            i = len(self.verts)
            self.verts.append(list(q))
            self.index[q] = i
        return i

    def uv_for(self, uv):
        if self.uv is None:
            return None
        self.uv.append([round(uv[0], 7), round(uv[1], 7)])
        return len(self.uv) - 1


class Surface:
    __slots__ = ("rings", "sem", "mat", "tex", "cls", "normal", "key")

    def __init__(self, rings, sem, mat, tex):
        self.rings, self.sem, self.mat, self.tex = rings, sem, mat, tex
        self.cls, self.normal, self.key = "other", None, None


class Building:
    def __init__(self, bid):
        self.id = bid
        self.geoms = []     # (object id, geometry index, geometry, [Surface])
        self.lod = ""
        self.zmin = math.inf

    def surfaces(self):
        for _, _, _, ss in self.geoms:
            for s in ss:
                yield s

    def walls(self):
        return [s for s in self.surfaces() if s.cls == "wall"]


def ring_ok(ring, nverts):
    return isinstance(ring, list) and all(isinstance(i, int) and not isinstance(i, bool) and 0 <= i < nverts
                                          for i in ring)


def load_buildings(model, lod):
    objs = model.objs
    out = []
    for bid in top_level_buildings(objs):
        b = Building(bid)
        take, b.lod = chosen_geometries(objs, bid, lod)
        for oid, gi in take:
            g = objs[oid]["geometry"][gi]
            lv = NESTING[g["type"]]
            surfs = flatten(g.get("boundaries", []), lv)
            n = len(surfs)
            sem = g.get("semantics") if isinstance(g.get("semantics"), dict) else None
            semv = flatten_values(sem.get("values") if sem else None, lv, n)
            mats = {}
            for th, m in (g.get("material") or {}).items():
                mats[th] = ("value", m["value"]) if "value" in m else ("values", flatten_values(m.get("values"), lv, n))
            texs = {}
            for th, t in (g.get("texture") or {}).items():
                texs[th] = flatten_values(t.get("values"), lv, n)
            ss = []
            for k, rings in enumerate(surfs):
                s = Surface(rings, semv[k],
                            {th: (m[1][k] if m[0] == "values" else None) for th, m in mats.items()},
                            {th: t[k] for th, t in texs.items()})
                ss.append(s)
                if isinstance(rings, list):
                    for r in rings:
                        if ring_ok(r, len(model.verts)):
                            for i in r:
                                b.zmin = min(b.zmin, model.point(i)[2])
            b.geoms.append((oid, gi, g, ss))
        classify(model, b)
        for gk, (_, _, _, ss) in enumerate(b.geoms):
            for sk, s in enumerate(ss):
                s.key = (gk, sk)
        out.append(b)
    return out


def classify(model, b):
    for _, _, g, ss in b.geoms:
        sem = g.get("semantics") if isinstance(g.get("semantics"), dict) else None
        labels = sem.get("surfaces") if sem and isinstance(sem.get("surfaces"), list) else []
        for s in ss:
            if not isinstance(s.rings, list) or not s.rings or not ring_ok(s.rings[0], len(model.verts)):
                continue
            pts = [model.point(i) for i in s.rings[0]]
            nv = newell(pts)
            ln = length(nv)
            s.normal = mul(nv, 1.0 / ln) if ln > 1e-9 else None
            v = s.sem
            if isinstance(v, int) and not isinstance(v, bool) and 0 <= v < len(labels) \
                    and isinstance(labels[v], dict):
                s.cls = SEM_CLASS.get(labels[v].get("type"), "other")
                continue
            if s.normal is None or len(set(s.rings[0])) < 3:
                s.cls = "other"
            elif abs(s.normal[2]) < WALL_NZ:
                s.cls = "wall"
            elif s.normal[2] < GROUND_NZ and sum(p[2] for p in pts) / len(pts) <= b.zmin + GROUND_NEAR:
                s.cls = "ground"
            else:
                s.cls = "roof"


# ---------------------------------------------------------------------------------------------
# variant (a): party walls

def plane_frame(n):
    ref = (0.0, 0.0, 1.0) if abs(n[2]) < 0.9 else (1.0, 0.0, 0.0)
    e1 = cross(ref, n)
    e1 = mul(e1, 1.0 / length(e1))
    e2 = cross(n, e1)
    return e1, e2


def project_rings(model, rings, origin, e1, e2):
    out = []
    for r in rings:
        if not ring_ok(r, len(model.verts)):
            continue
        pr = []
        for i in r:
            d = sub(model.point(i), origin)
            q = (dot(d, e1), dot(d, e2))
            if not pr or pr[-1] != q:
                pr.append(q)
        while len(pr) > 1 and pr[-1] == pr[0]:
            pr.pop()
        if len(pr) >= 3:
            out.append(pr)
    if not out:
        return []
    # outer ring CCW, holes CW (fan decomposition needs consistent orientation)
    fixed = []
    for k, r in enumerate(out):
        a = area2(r)
        if (k == 0 and a < 0) or (k > 0 and a > 0):
            r = r[::-1]
        fixed.append(r)
    return fixed


def party_walls(model, buildings):
    """{surface key: count of touching walls} per building id; plus statistics."""
    walls = []   # (building index, surface, centroid, bbox, unit normal)
    for bi, b in enumerate(buildings):
        for s in b.walls():
            if s.normal is None or not ring_ok(s.rings[0], len(model.verts)):
                continue
            pts = [model.point(i) for r in s.rings if ring_ok(r, len(model.verts)) for i in r]
            outer = [model.point(i) for i in s.rings[0]]
            c = mul(outer[0], 0.0)
            for p in outer:
                c = add(c, p)
            c = mul(c, 1.0 / len(outer))
            lo = tuple(min(p[k] for p in pts) - PARTY_DIST for k in range(3))
            hi = tuple(max(p[k] for p in pts) + PARTY_DIST for k in range(3))
            walls.append((bi, s, c, lo, hi))
    grid = {}
    for wi, (_, _, _, lo, hi) in enumerate(walls):
        for gx in range(int(math.floor(lo[0] / GRID)), int(math.floor(hi[0] / GRID)) + 1):
            for gy in range(int(math.floor(lo[1] / GRID)), int(math.floor(hi[1] / GRID)) + 1):
                grid.setdefault((gx, gy), []).append(wi)
    cos_tol = math.cos(math.radians(PARTY_ANGLE))
    pairs = set()
    for cell in sorted(grid):
        ids = grid[cell]
        for x in range(len(ids)):
            for y in range(x + 1, len(ids)):
                i, j = ids[x], ids[y]
                if walls[i][0] != walls[j][0]:
                    pairs.add((min(i, j), max(i, j)))
    party = {}
    stats = {"candidate_pairs": len(pairs), "touching_pairs": 0, "same_facing_pairs": 0}
    for i, j in sorted(pairs):
        bi, si, ci, loi, hii = walls[i]
        bj, sj, cj, loj, hij = walls[j]
        if any(hii[k] < loj[k] or hij[k] < loi[k] for k in range(3)):
            continue
        cosang = dot(si.normal, sj.normal)
        if abs(cosang) < cos_tol:
            continue
        if abs(dot(sub(cj, ci), si.normal)) > PARTY_DIST or abs(dot(sub(ci, cj), sj.normal)) > PARTY_DIST:
            continue
        e1, e2 = plane_frame(si.normal)
        ra = project_rings(model, si.rings, ci, e1, e2)
        rb = project_rings(model, sj.rings, ci, e1, e2)
        if not ra or not rb:
            continue
        if overlap_area(ra, rb) < PARTY_MIN_AREA:
            continue
        stats["touching_pairs"] += 1
        if cosang > 0:
            stats["same_facing_pairs"] += 1
        party.setdefault(buildings[bi].id, set()).add(si.key)
        party.setdefault(buildings[bj].id, set()).add(sj.key)
    return party, stats


# ---------------------------------------------------------------------------------------------
# variant (e): clipping walls against z = zc

def clip_above(model, s, zc):
    """The part of surface s with z >= zc: None if s is wholly above (unchanged), else a list of
    pieces, each a list of rings, each a list of (vertex index, {theme: (tex index, uv index)})."""
    rings = [r for r in s.rings if ring_ok(r, len(model.verts))]
    if not rings:
        return None
    # per ring point records: (xyz, vertex index, {theme: (uv or None)})
    tex_idx = {}
    recs = []
    for rk, r in enumerate(rings):
        rr = []
        for pk, vi in enumerate(r):
            uvs = {}
            for th, tv in s.tex.items():
                ring_t = tv[rk] if isinstance(tv, list) and rk < len(tv) else None
                if isinstance(ring_t, list) and ring_t and ring_t[0] is not None and len(ring_t) == len(r) + 1 \
                        and model.uv is not None:
                    tex_idx[th] = ring_t[0]
                    uvs[th] = tuple(model.uv[ring_t[pk + 1]])
                else:
                    uvs[th] = None
            rr.append((model.point(vi), vi, uvs))
        recs.append(rr)
    above = [[p[0][2] >= zc for p in rr] for rr in recs]
    if all(all(a) for a in above):
        return None
    if not any(any(a) for a in above):
        return []
    n = s.normal
    if n is None:
        return None
    d = cross((0.0, 0.0, 1.0), n)   # horizontal direction in the plane
    if length(d) < 1e-9:
        return None
    d = mul(d, 1.0 / length(d))
    # orient the working frame (u = p.d, v = z) so that the outer ring is CCW
    def uv2(p):
        return (dot(p, d), p[2])
    sign = 1.0 if area2([uv2(p[0]) for p in recs[0]]) >= 0 else -1.0
    for rk in range(1, len(recs)):   # holes CW in the working frame
        a = area2([uv2(p[0]) for p in recs[rk]]) * sign
        if a > 0:
            recs[rk] = recs[rk][::-1]
            above[rk] = above[rk][::-1]

    def cut(a, b):
        t = (zc - a[0][2]) / (b[0][2] - a[0][2])
        p = add(a[0], mul(sub(b[0], a[0]), t))
        p = (p[0], p[1], zc)
        uvs = {}
        for th in a[2]:
            ua, ub = a[2][th], b[2][th]
            uvs[th] = (ua[0] + t * (ub[0] - ua[0]), ua[1] + t * (ub[1] - ua[1])) if ua and ub else None
        return (p, None, uvs)

    chains, free = [], []
    crossings = []   # (position along the line, chain index, 'in'/'out')
    for rk, rr in enumerate(recs):
        ab = above[rk]
        m = len(rr)
        if all(ab):
            free.append(rr)
            continue
        if not any(ab):
            continue
        start = next(k for k in range(m) if not ab[k] and ab[(k + 1) % m])   # entry edge
        k = start
        cur = None
        for _ in range(m):
            a, b = rr[k], rr[(k + 1) % m]
            aa, bb = ab[k], ab[(k + 1) % m]
            if not aa and bb:
                x = cut(a, b)
                cur = [x]
                crossings.append((sign * dot(x[0], d), len(chains), "in"))
            if bb:
                cur.append(b)
            if aa and not bb:
                x = cut(a, b)
                cur.append(x)
                crossings.append((sign * dot(x[0], d), len(chains), "out"))
                chains.append(cur)
                cur = None
            k = (k + 1) % m
    crossings.sort(key=lambda c: (c[0], c[1], c[2]))
    if len(crossings) % 2:
        return None
    nxt = {}
    for k in range(0, len(crossings), 2):
        c0, c1 = crossings[k], crossings[k + 1]
        if {c0[2], c1[2]} != {"in", "out"}:
            return None   # inconsistent ring orientation: leave the wall as it is
        out_c, in_c = (c0, c1) if c0[2] == "out" else (c1, c0)
        nxt[out_c[1]] = in_c[1]
    cycles, used = [], set()
    for ci in range(len(chains)):
        if ci in used:
            continue
        cyc, k = [], ci
        while k not in used:
            used.add(k)
            cyc.extend(chains[k])
            k = nxt.get(k)
            if k is None:
                return None
        cycles.append(cyc)
    # free rings: CCW ones (in the working frame) are outer pieces, CW ones holes
    outers, holes = list(cycles), []
    for rr in free:
        a = sign * area2([uv2(p[0]) for p in rr])
        (outers if a > 0 else holes).append(rr)
    pieces = [[o] for o in outers]
    for h in holes:
        q = uv2(h[0][0])
        for pc in pieces:
            poly = [uv2(p[0]) for p in pc[0]]
            if point_in(q, poly):
                pc.append(h)
                break
    # to vertex indices and texture values
    result = []
    for pc in pieces:
        out_rings = []
        for rr in pc:
            ring, tex = [], {th: [] for th in s.tex}
            for p, vi, uvs in rr:
                if vi is None:
                    vi = model.vertex_for(p)
                if ring and ring[-1] == vi:
                    continue
                ring.append(vi)
                for th in s.tex:
                    tex[th].append(uvs[th])
            while len(ring) > 1 and ring[-1] == ring[0]:
                ring.pop()
                for th in s.tex:
                    tex[th].pop()
            if len(set(ring)) < 3:
                continue
            out_rings.append((ring, tex))
        if out_rings:
            result.append(out_rings)
    return _with_uv_indices(model, s, result, tex_idx)


def _with_uv_indices(model, s, pieces, tex_idx):
    out = []
    for pc in pieces:
        rings, tex = [], {th: [] for th in s.tex}
        for ring, t in pc:
            rings.append(ring)
            for th in s.tex:
                uvs = t[th]
                if th in tex_idx and all(u is not None for u in uvs):
                    tex[th].append([tex_idx[th]] + [model.uv_for(u) for u in uvs])
                else:
                    tex[th].append([None])
        out.append((rings, tex))
    return out


def point_in(q, poly):
    inside = False
    n = len(poly)
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        if (a[1] > q[1]) != (b[1] > q[1]):
            x = a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if x > q[0]:
                inside = not inside
    return inside


# ---------------------------------------------------------------------------------------------
# writing a variant

def seeded_rng(seed, bid):
    h = hashlib.sha256(("%d:%s" % (seed, bid)).encode("utf-8")).digest()
    return random.Random(int.from_bytes(h[:8], "big"))


def plan(model, buildings, variant, seed, party):
    """{building id: {surface key: 'remove' | [pieces]}} and per building counts."""
    actions, counts = {}, {}
    for b in buildings:
        act = {}
        walls = b.walls()
        if variant == "a":
            for k in sorted(party.get(b.id, ())):
                act[k] = "remove"
        elif variant == "b":
            for s in walls:
                act[s.key] = "remove"
        elif variant == "c":
            for s in b.surfaces():
                if s.cls == "ground":
                    act[s.key] = "remove"
        elif variant == "d":
            k = int(math.floor(RANDOM_FRACTION * len(walls) + 0.5))
            for i in sorted(seeded_rng(seed, b.id).sample(range(len(walls)), k)):
                act[walls[i].key] = "remove"
        elif variant == "e":
            zc = b.zmin + GAP
            for s in walls:
                r = clip_above(model, s, zc)
                if r is None:
                    continue
                act[s.key] = "remove" if not r else r
        removed = sum(1 for v in act.values() if v == "remove")
        clipped = sum(1 for v in act.values() if v != "remove")
        counts[b.id] = {"removed": removed, "clipped": clipped,
                        "pieces": sum(len(v) for v in act.values() if v != "remove")}
        actions[b.id] = act
    return actions, counts


def rebuild(b, act):
    """New MultiSurface geometries of building b: [(object id, geometry index, geometry or None)]."""
    out = []
    for gk, (oid, gi, g, ss) in enumerate(b.geoms):
        bnd, semv, mats, texs = [], [], {}, {}
        for th, m in (g.get("material") or {}).items():
            mats[th] = {"value": m["value"]} if "value" in m else {"values": []}
        for th in (g.get("texture") or {}):
            texs[th] = {"values": []}

        def emit(rings, s, tex):
            bnd.append(rings)
            semv.append(s.sem)
            for th in mats:
                if "values" in mats[th]:
                    mats[th]["values"].append(s.mat.get(th))
            for th in texs:
                texs[th]["values"].append(tex[th])

        for sk, s in enumerate(ss):
            a = act.get((gk, sk))
            if a == "remove":
                continue
            if a is None:
                emit(s.rings, s, {th: s.tex.get(th) if s.tex.get(th) is not None else [[None]] for th in texs})
            else:
                for rings, tex in a:
                    emit(rings, s, tex)
        if not bnd:
            out.append((oid, gi, None))
            continue
        ng = {"type": "MultiSurface", "lod": g.get("lod"), "boundaries": bnd}
        if isinstance(g.get("semantics"), dict):
            ng["semantics"] = {"surfaces": g["semantics"].get("surfaces", []), "values": semv}
        if mats:
            ng["material"] = mats
        if texs:
            ng["texture"] = texs
        out.append((oid, gi, ng))
    return out


def stem_of(path):
    name = os.path.basename(path)
    for ext in (".city.json", ".json"):
        if name.endswith(ext):
            return name[: -len(ext)]
    return name


def make_variants(args):
    with open(args.input, encoding="utf-8") as f:
        text = f.read()
    base = json.loads(text)
    probe = Model(base)
    buildings = load_buildings(probe, args.lod)
    party, pstats = party_walls(probe, buildings) if "a" in args.variants else ({}, {})
    os.makedirs(args.outdir, exist_ok=True)
    stem = stem_of(args.input)
    report = {"input": os.path.relpath(os.path.abspath(args.input), REPO), "seed": args.seed, "lod": args.lod,
              "generator": "tools/gen_open_variants.py", "rules": RULES,
              "buildings_total": len(buildings),
              "buildings_with_geometry": sum(1 for b in buildings if b.geoms),
              "variants": {}, "buildings": {}}
    if pstats:
        report["party_wall_search"] = pstats
    files = []
    for v in args.variants:
        doc = json.loads(text)          # a fresh copy: vertex appends stay per variant
        model = Model(doc)
        bl = load_buildings(model, args.lod)
        actions, counts = plan(model, bl, v, args.seed, party)
        dropped = 0
        for b in bl:
            for oid, gi, ng in rebuild(b, actions[b.id]):
                if ng is None:
                    doc["CityObjects"][oid]["geometry"][gi] = None
                    dropped += 1
                else:
                    doc["CityObjects"][oid]["geometry"][gi] = ng
        for o in doc["CityObjects"].values():
            if isinstance(o.get("geometry"), list) and any(g is None for g in o["geometry"]):
                o["geometry"] = [g for g in o["geometry"] if g is not None]
        out = os.path.join(args.outdir, "%s.%s.city.json" % (stem, v))
        with open(out, "w", encoding="utf-8") as f:
            json.dump(doc, f, separators=(",", ":"))
            f.write("\n")
        files.append(out)
        touched = sorted(bid for bid, c in counts.items() if c["removed"] or c["clipped"])
        report["variants"][v] = {
            "file": os.path.basename(out),
            "buildings_touched": len(touched),
            "surfaces_removed": sum(c["removed"] for c in counts.values()),
            "surfaces_clipped": sum(c["clipped"] for c in counts.values()),
            "pieces_from_clipping": sum(c["pieces"] for c in counts.values()),
            "geometries_dropped_empty": dropped,
            "vertices_appended": len(doc["vertices"]) - len(base.get("vertices", [])),
        }
        for b in bl:
            e = report["buildings"].setdefault(b.id, {
                "lod": b.lod, "surfaces": sum(1 for _ in b.surfaces()),
                "walls": len(b.walls()), "roofs": sum(1 for s in b.surfaces() if s.cls == "roof"),
                "grounds": sum(1 for s in b.surfaces() if s.cls == "ground")})
            c = counts[b.id]
            e[v] = {"removed": c["removed"], "clipped": c["clipped"]} if v == "e" else c["removed"]
    rep = os.path.join(args.outdir, "%s.variants.json" % stem)
    with open(rep, "w", encoding="utf-8") as f:
        json.dump(report, f, indent=1, sort_keys=True)
        f.write("\n")
    print("%s: %d buildings (%d with geometry at LoD %s), seed %d" % (
        args.input, report["buildings_total"], report["buildings_with_geometry"], args.lod, args.seed))
    if pstats:
        print("  party-wall search: %(candidate_pairs)d grid pairs, %(touching_pairs)d touching wall pairs "
              "(%(same_facing_pairs)d facing the same way)" % pstats)
    for v in args.variants:
        r = report["variants"][v]
        print("  %s: %d buildings touched, %d surfaces removed, %d clipped (%d pieces), +%d vertices -> %s" % (
            v, r["buildings_touched"], r["surfaces_removed"], r["surfaces_clipped"], r["pieces_from_clipping"],
            r["vertices_appended"], r["file"]))
    print("  report -> %s" % rep)
    return files


RULES = {
    "classes": "semantic type when present (Wall/Roof/GroundSurface; other types untouched); else normal: "
               "|n_z| < %.2f wall, n_z < %.1f and mean z within %.1f m of the building's lowest vertex ground, "
               "else roof" % (WALL_NZ, GROUND_NZ, GROUND_NEAR),
    "a": "walls parallel (<= %g deg) and coplanar (vertex means within %g m of the other plane) to a wall of "
         "another Building, overlap on the shared plane >= %g m^2 (10 m bbox grid); whole polygon removed"
         % (PARTY_ANGLE, PARTY_DIST, PARTY_MIN_AREA),
    "b": "all walls removed",
    "c": "all ground surfaces removed",
    "d": "round(%g * walls) walls per building, random.Random(sha256('seed:building id'))" % RANDOM_FRACTION,
    "e": "walls clipped at z = z_min(building) + %g m, part above kept (pieces), wholly-below walls removed" % GAP,
}


# ---------------------------------------------------------------------------------------------
# checks

def check_file(path, closed=False):
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    errs = []
    if doc.get("type") != "CityJSON":
        errs.append("type is not CityJSON")
    nv = len(doc.get("vertices", []))
    app = doc.get("appearance") or {}
    nuv = len(app.get("vertices-texture", []))
    nmat = len(app.get("materials", []))
    ntex = len(app.get("textures", []))
    counts = {"objects": len(doc.get("CityObjects", {})), "vertices": nv, "geometries": 0, "surfaces": 0}
    for oid, o in doc.get("CityObjects", {}).items():
        for g in o.get("geometry", []) or []:
            t = g.get("type")
            if t not in NESTING:
                continue
            counts["geometries"] += 1
            lv = NESTING[t]
            surfs = flatten(g.get("boundaries"), lv)
            counts["surfaces"] += len(surfs)
            if not surfs:
                errs.append("%s: empty %s" % (oid, t))
            for s in surfs:
                if not isinstance(s, list) or not s:
                    errs.append("%s: surface without rings" % oid)
                    continue
                for r in s:
                    if not ring_ok(r, nv) or not r:
                        errs.append("%s: ring with a vertex index out of range" % oid)
            sem = g.get("semantics")
            if isinstance(sem, dict):
                vals = flatten(sem.get("values"), lv)
                nsurf = len(sem.get("surfaces", []))
                if len(vals) != len(surfs):
                    errs.append("%s: %d semantic values for %d surfaces" % (oid, len(vals), len(surfs)))
                if any(v is not None and not (0 <= v < nsurf) for v in vals):
                    errs.append("%s: semantic value out of range" % oid)
            for th, m in (g.get("material") or {}).items():
                if "values" in m:
                    vals = flatten(m["values"], lv)
                    if len(vals) != len(surfs) or any(v is not None and not 0 <= v < nmat for v in vals):
                        errs.append("%s: material values do not match" % oid)
            for th, tx in (g.get("texture") or {}).items():
                vals = flatten(tx.get("values"), lv)
                if len(vals) != len(surfs):
                    errs.append("%s: %d texture values for %d surfaces" % (oid, len(vals), len(surfs)))
                    continue
                for s, tv in zip(surfs, vals):
                    for rk, rt in enumerate(tv if isinstance(tv, list) else []):
                        if not rt or rt[0] is None:
                            continue
                        if not 0 <= rt[0] < ntex or len(rt) != len(s[rk]) + 1 or \
                                any(not 0 <= u < nuv for u in rt[1:]):
                            errs.append("%s: texture ring does not match" % oid)
    if closed:
        errs.extend(closure_errors(doc))
    return doc, counts, errs


def closure_errors(doc):
    """Each Building's MultiSurface: every directed edge once and its reverse once; volume > 0."""
    errs = []
    verts = doc["vertices"]
    for oid, o in doc["CityObjects"].items():
        for g in o.get("geometry", []):
            edges = {}
            vol = 0.0
            for s in flatten(g["boundaries"], NESTING[g["type"]]):
                for r in s:
                    for k in range(len(r)):
                        e = (r[k], r[(k + 1) % len(r)])
                        edges[e] = edges.get(e, 0) + 1
                    p0 = verts[r[0]]
                    for k in range(1, len(r) - 1):
                        a, b = verts[r[k]], verts[r[k + 1]]
                        vol += dot(p0, cross(a, b)) / 6.0
            bad = [e for e, c in edges.items() if c != 1 or edges.get((e[1], e[0])) != 1]
            if bad:
                errs.append("%s: %d edges not paired (e.g. %s)" % (oid, len(bad), bad[0]))
            if vol <= 0:
                errs.append("%s: volume %g <= 0" % (oid, vol))
    return errs


def run_ajv(paths):
    v20 = [p for p in paths if json.load(open(p, encoding="utf-8")).get("version") == "2.0"]
    if len(v20) < len(paths):
        print("  schema check: %d file(s) not CityJSON 2.0, structure check only" % (len(paths) - len(v20)))
    paths = v20
    if not paths:
        return True
    if not (os.path.exists(AJV) and os.path.exists(SCHEMA)):
        print("schema check skipped: %s or %s missing" % (AJV, SCHEMA))
        return True
    cmd = [AJV, "validate", "--strict=false", "--all-errors=false", "-c", "ajv-formats", "-s", SCHEMA]
    for p in paths:
        cmd += ["-d", p]
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    ok = True
    for p in paths:
        valid = (p + " valid") in r.stdout
        ok = ok and valid
        print("  schema 2.0: %s %s" % (os.path.basename(p), "valid" if valid else "INVALID"))
    if not ok:
        print(r.stdout[:4000])
    return ok


def check_all(paths, closed=()):
    ok = True
    for p in paths:
        _, c, errs = check_file(p, p in closed)
        print("  %s: %d objects, %d geometries, %d surfaces, %d vertices, %s%s" % (
            os.path.basename(p), c["objects"], c["geometries"], c["surfaces"], c["vertices"],
            "OK" if not errs else "%d ERRORS" % len(errs), " (closed, outward)" if p in closed and not errs else ""))
        for e in errs[:10]:
            print("    " + e)
        ok = ok and not errs
    return ok


# ---------------------------------------------------------------------------------------------
# synthetic models

class Synth:
    def __init__(self, title):
        self.title = title
        self.verts, self.index, self.objs = [], {}, {}

    def vid(self, p):
        q = tuple(int(round(c * 1000)) for c in p)
        if q not in self.index:
            self.index[q] = len(self.verts)
            self.verts.append(list(q))
        return self.index[q]

    def building(self, bid, faces, attributes=None):
        """faces: [(semantic type, [points], outward direction)]; each ring is turned so that its
        normal points along the outward direction."""
        types = []
        bnd, vals = [], []
        for t, pts, outward in faces:
            if dot(newell(pts), outward) < 0:
                pts = pts[::-1]
            if t not in types:
                types.append(t)
            bnd.append([[self.vid(p) for p in pts]])
            vals.append(types.index(t))
        o = {"type": "Building", "attributes": dict(attributes or {}),
             "geometry": [{"type": "MultiSurface", "lod": "2.2", "boundaries": bnd,
                           "semantics": {"surfaces": [{"type": t} for t in types], "values": vals}}]}
        self.objs[bid] = o

    def write(self, path):
        doc = {"type": "CityJSON", "version": "2.0",
               "transform": {"scale": [0.001, 0.001, 0.001], "translate": [0.0, 0.0, 0.0]},
               "metadata": {"title": self.title},
               "CityObjects": self.objs, "vertices": self.verts}
        with open(path, "w", encoding="utf-8") as f:
            json.dump(doc, f, separators=(",", ":"))
            f.write("\n")


def gable_house(x0, x1, depth, eaves, ridge, sides=(True, True), front_back=True, ground=True):
    """Faces of a gable house on [x0,x1] x [0,depth], ridge along x at y = depth/2."""
    ym = depth / 2.0
    f = [("RoofSurface", [(x0, 0, eaves), (x1, 0, eaves), (x1, ym, ridge), (x0, ym, ridge)], (0, -1, 1)),
         ("RoofSurface", [(x0, ym, ridge), (x1, ym, ridge), (x1, depth, eaves), (x0, depth, eaves)], (0, 1, 1))]
    if front_back:
        f.append(("WallSurface", [(x0, 0, 0), (x1, 0, 0), (x1, 0, eaves), (x0, 0, eaves)], (0, -1, 0)))
        f.append(("WallSurface", [(x0, depth, 0), (x1, depth, 0), (x1, depth, eaves), (x0, depth, eaves)], (0, 1, 0)))
    for on, x, out in ((sides[0], x0, -1), (sides[1], x1, 1)):
        if on:
            f.append(("WallSurface", [(x, 0, 0), (x, depth, 0), (x, depth, eaves), (x, ym, ridge), (x, 0, eaves)],
                      (out, 0, 0)))
    if ground:
        f.append(("GroundSurface", [(x0, 0, 0), (x1, 0, 0), (x1, depth, 0), (x0, depth, 0)], (0, 0, -1)))
    return f


def synth_terraced(closed):
    s = Synth("Synthetic: a row of five terraced houses" + (" (closed reference)" if closed else
                                                            " without party walls"))
    w, depth, eaves, ridge = 5.5, 9.0, 5.8, 9.0
    for i in range(5):
        sides = (True, True) if closed else (i == 0, i == 4)
        s.building("terrace_%d" % (i + 1), gable_house(i * w, (i + 1) * w, depth, eaves, ridge, sides),
                   {"house": i + 1})
    return s


def synth_gable(closed):
    s = Synth("Synthetic: gable house" + (" (closed reference)" if closed else ", roof only"))
    faces = gable_house(0.0, 10.0, 7.0, 5.0, 8.0, sides=(closed, closed), front_back=closed, ground=closed)
    s.building("gable_house", faces)
    return s


def synth_l_shape(closed):
    s = Synth("Synthetic: L-shaped house, gabled main block with a flat-roofed annex" +
              (" (closed reference)" if closed else ", roofs only"))
    f = [("RoofSurface", [(0, 0, 6), (10, 0, 6), (10, 3, 9), (0, 3, 9)], (0, -1, 1)),
         ("RoofSurface", [(0, 3, 9), (10, 3, 9), (10, 6, 6), (0, 6, 6)], (0, 1, 1)),
         ("RoofSurface", [(0, 6, 3), (4, 6, 3), (4, 10, 3), (0, 10, 3)], (0, 0, 1))]
    if closed:
        f += [("WallSurface", [(0, 0, 0), (10, 0, 0), (10, 0, 6), (0, 0, 6)], (0, -1, 0)),
              ("WallSurface", [(0, 0, 0), (0, 0, 6), (0, 3, 9), (0, 6, 6), (0, 6, 3), (0, 6, 0)], (-1, 0, 0)),
              ("WallSurface", [(10, 0, 0), (10, 6, 0), (10, 6, 6), (10, 3, 9), (10, 0, 6)], (1, 0, 0)),
              ("WallSurface", [(0, 6, 3), (4, 6, 3), (4, 6, 0), (10, 6, 0), (10, 6, 6), (0, 6, 6)], (0, 1, 0)),
              ("WallSurface", [(0, 6, 0), (0, 10, 0), (0, 10, 3), (0, 6, 3)], (-1, 0, 0)),
              ("WallSurface", [(0, 10, 0), (4, 10, 0), (4, 10, 3), (0, 10, 3)], (0, 1, 0)),
              ("WallSurface", [(4, 6, 0), (4, 10, 0), (4, 10, 3), (4, 6, 3)], (1, 0, 0)),
              ("GroundSurface", [(0, 0, 0), (10, 0, 0), (10, 6, 0), (4, 6, 0), (4, 10, 0), (0, 10, 0), (0, 6, 0)],
               (0, 0, -1))]
    s.building("l_house", f)
    return s


def synth_tower(closed):
    s = Synth("Synthetic: tower of six inclined triangular prisms" +
              (" (closed reference: outer shell)" if closed else
               ", storeys as glued closed shells plus interior floor sheets"))
    tri = [(0.0, 0.0), (12.0, 0.0), (4.0, 9.0)]
    storeys, h, shift = 6, 3.2, (0.8, 0.5)
    cx = sum(p[0] for p in tri) / 3.0
    cy = sum(p[1] for p in tri) / 3.0

    def ring(level, frac=0.0):
        z = (level + frac) * h
        dx, dy = shift[0] * (level + frac), shift[1] * (level + frac)
        return [(x + dx, y + dy, z) for x, y in tri]

    f = []
    for i in range(storeys):
        lo, hi = ring(i), ring(i + 1)
        if i == 0:
            f.append(("GroundSurface", lo, (0, 0, -1)))
        elif not closed:
            f.append(("FloorSurface", lo, (0, 0, -1)))       # bottom of storey i: glued to the one below
        if i == storeys - 1:
            f.append(("RoofSurface", hi, (0, 0, 1)))
        elif not closed:
            f.append(("CeilingSurface", hi, (0, 0, 1)))      # top of storey i
        for k in range(3):
            a, b = lo[k], lo[(k + 1) % 3]
            c, d = hi[(k + 1) % 3], hi[k]
            mid = mul(add(add(a, b), add(c, d)), 0.25)
            centre = (cx + shift[0] * (i + 0.5), cy + shift[1] * (i + 0.5), mid[2])
            f.append(("WallSurface", [a, b, c, d], sub(mid, centre)))
        if not closed:
            f.append(("FloorSurface", ring(i, 0.5), (0, 0, 1)))  # interior sheet at mid-storey
    s.building("tower", f, {"storeys": storeys})
    return s


SYNTHETIC = [("terraced_row", synth_terraced), ("gable_roof_only", synth_gable),
             ("l_shape_roof_only", synth_l_shape), ("tower_inclined_prisms", synth_tower)]


def make_synthetic(outdir):
    os.makedirs(outdir, exist_ok=True)
    files, closed = [], []
    for name, fn in SYNTHETIC:
        for c in (False, True):
            p = os.path.join(outdir, name + (".closed" if c else "") + ".city.json")
            fn(c).write(p)
            files.append(p)
            if c:
                closed.append(p)
    return files, closed


# ---------------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("input", nargs="?")
    ap.add_argument("outdir", nargs="?")
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--variants", default="a,b,c,d,e")
    ap.add_argument("--lod", default="highest")
    ap.add_argument("--synthetic", metavar="OUTDIR")
    ap.add_argument("--no-ajv", action="store_true", help="skip the schema check")
    args = ap.parse_args()
    ok = True
    if args.synthetic:
        files, closed = make_synthetic(args.synthetic)
        print("synthetic models -> %s" % args.synthetic)
        ok = check_all(files, set(closed)) and ok
        if not args.no_ajv:
            ok = run_ajv(files) and ok
    if args.input:
        if not args.outdir:
            ap.error("OUTDIR is required with INPUT")
        args.variants = [v.strip() for v in args.variants.split(",") if v.strip()]
        bad = [v for v in args.variants if v not in VARIANTS]
        if bad:
            ap.error("unknown variant(s) %s (choose from a,b,c,d,e)" % ",".join(bad))
        files = make_variants(args)
        ok = check_all(files) and ok
        if not args.no_ajv:
            ok = run_ajv(files) and ok
    if not args.synthetic and not args.input:
        ap.error("give INPUT OUTDIR or --synthetic OUTDIR")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
