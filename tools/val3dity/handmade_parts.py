#!/usr/bin/env python3
"""Writes small CityJSON files, each one Building with one or two morphcut parts (BuildingParts
with `morphcut_level`), one file per way `morphcut-city validate` and val3dity could read a part
differently: vertices about one snap distance (1 mm) apart, an edge used twice in one direction,
T-junctions, faces that collapse when snapped, holes touching their outer ring, inward shells,
thin overlaps between parts. tools/val3dity/crosscheck.py runs both validators on them
(docs/reliability.md, "val3dity and validate agree").

usage: handmade_parts.py OUTDIR

Coordinates are integers on a grid of 1 mm (0.1 mm where a case needs sub-millimetre offsets)
with a Lambert-93-like translate, as a French CityGML file's parts would be written.
"""

import json
import os
import sys

LAMBERT = [652417.613, 6862291.337, 35.21]
S = 10000  # 10 m at 1 mm


def box(x0, y0, z0, x1, y1, z1):
    """Outward faces of an axis-aligned box: bottom, top, -y, +x, +y, -x."""
    def p(i, j, k):
        return ((x0, x1)[i], (y0, y1)[j], (z0, z1)[k])
    return [[[p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0)]], [[p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)]],
            [[p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)]], [[p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)]],
            [[p(1, 1, 0), p(0, 1, 0), p(0, 1, 1), p(1, 1, 1)]], [[p(0, 1, 0), p(0, 0, 0), p(0, 0, 1), p(0, 1, 1)]]]


def pit(hole, depth):
    """Walls and floor of a square pit below a hole (clockwise seen from above) of a top face."""
    faces = []
    for i in range(len(hole)):
        a, b = hole[i], hole[(i + 1) % len(hole)]
        faces.append([[b, a, (a[0], a[1], a[2] - depth), (b[0], b[1], b[2] - depth)]])
    faces.append([[(v[0], v[1], v[2] - depth) for v in reversed(hole)]])
    return faces


def pyramid(hole, depth):
    """A pit below a hole ending in one apex below the hole's centre."""
    c = (sum(v[0] for v in hole) // len(hole), sum(v[1] for v in hole) // len(hole), hole[0][2] - depth)
    return [[[hole[(i + 1) % len(hole)], hole[i], c]] for i in range(len(hole))]


def with_top(faces, top):
    return faces[:1] + [top] + faces[2:]


def moved(faces, face, old, new):
    """`faces` with vertex `old` of face `face` replaced by `new` (the other faces keep `old`)."""
    out = [f for f in faces]
    out[face] = [[new if v == old else v for v in ring] for ring in faces[face]]
    return out


def reverse(faces):
    return [[list(reversed(r)) for r in f] for f in faces]


def cases():
    b = box(0, 0, 0, S, S, S)
    T = 10 * S  # 10 m at 0.1 mm
    bt = box(0, 0, 0, T, T, T)
    yield "ok_box", [b], {}
    yield "touching_parts", [b, box(S, 0, 0, 2 * S, S, S)], {}
    # A top corner 1 mm off the sides' corner: one vertex for val3dity, or two, as the coordinates round.
    yield "step_1mm_lambert", [moved(b, 1, (S, 0, S), (S + 1, 0, S))], {}
    yield "step_1mm_origin", [moved(b, 1, (S, 0, S), (S + 1, 0, S))], {"translate": [0.0, 0.0, 0.0]}
    yield "step_1mm_round", [moved(b, 1, (S, 0, S), (S + 1, 0, S))], {"translate": [652417.0, 6862291.0, 35.0]}
    for tenths in (9, 10, 11):
        yield f"step_{tenths}_tenths_mm", [moved(bt, 1, (T, 0, T), (T + tenths, 0, T))], {"scale": 0.0001}
    # A corner split into two 1.8 mm apart and one face using their midpoint (0.9 mm from each).
    r1, r2, p = (T + 9, 0, T), (T - 9, 0, T), (T, 0, T)
    yield "snap_two_candidates", [[bt[0], bt[4], bt[5], moved(bt, 2, p, r1)[2], moved(bt, 3, p, r2)[3], bt[1]]], \
        {"scale": 0.0001}
    yield "face_reversed", [with_top(b, reverse([b[1]])[0])], {}
    yield "shell_inward", [reverse(b)], {}
    yield "open_box", [b[1:]], {}
    # T-junctions: a vertex in the middle of a neighbour's edge, or 0.5 mm beside it.
    yield "t_junction", [with_top(b, [[(0, 0, S), (S // 2, 0, S), (S, 0, S), (S, S, S), (0, S, S)]])], {}
    yield "t_junction_near", [with_top(bt, [[(0, 0, T), (T // 2, 5, T), (T, 0, T), (T, T, T), (0, T, T)]])], \
        {"scale": 0.0001}
    # Faces that collapse when snapped: a quad with two vertices 0.5 mm apart, a 4-point ring of
    # two points, a top tilted by 0.5 mm.
    quad = with_top(bt, [[(0, 0, T), (T, 0, T), (T, T, T), (5, T, T), (0, T, T)]])
    quad[4] = [[(T, T, 0), (0, T, 0), (0, T, T), (5, T, T), (T, T, T)]]
    yield "ring_repeat_after_snap", [quad], {"scale": 0.0001}
    yield "two_point_face", [b + [[[(S, 0, 0), (S, 0, S), (S, 0, S), (S, 0, 0)]]]], {}
    tilted = with_top(bt, [[(0, 0, T), (T, 0, T), (T, T, T + 5), (0, T, T + 5)]])
    tilted[3] = [[(T, 0, 0), (T, T, 0), (T, T, T + 5), (T, 0, T)]]
    tilted[4] = [[(T, T, 0), (0, T, 0), (0, T, T + 5), (T, T, T + 5)]]
    tilted[5] = [[(0, T, 0), (0, 0, 0), (0, 0, T), (0, T, T + 5)]]
    yield "tilted_top_sub_mm", [tilted], {"scale": 0.0001}
    # Holes.
    hole = [(2000, 2000, S), (2000, 6000, S), (6000, 6000, S), (6000, 2000, S)]  # clockwise from above
    yield "hole_ok", [with_top(b, [b[1][0], hole]) + pit(hole, 3000)], {}
    diamond = [(4000, 0, S), (2000, 2000, S), (4000, 4000, S), (6000, 2000, S)]
    yield "hole_touches_edge", [with_top(b, [b[1][0], diamond]) + pyramid(diamond, 3000)], {}
    outer = [(0, 0, S), (4000, 0, S), (S, 0, S), (S, S, S), (0, S, S)]
    walls = with_top(b, [outer, diamond])
    walls[2] = [[(0, 0, 0), (S, 0, 0), (S, 0, S), (4000, 0, S), (0, 0, S)]]
    yield "hole_touches_vertex", [walls + pyramid(diamond, 3000)], {}
    outer2 = [(0, 0, S), (4000, 0, S), (S, 0, S), (S, S, S), (4000, S, S), (0, S, S)]
    across = [(4000, 0, S), (2000, S // 2, S), (4000, S, S), (6000, S // 2, S)]
    w2 = with_top(b, [outer2, across])
    w2[2] = [[(0, 0, 0), (S, 0, 0), (S, 0, S), (4000, 0, S), (0, 0, S)]]
    w2[4] = [[(S, S, 0), (0, S, 0), (0, S, S), (4000, S, S), (S, S, S)]]
    yield "hole_splits_face", [w2 + pyramid(across, 3000)], {}
    beside = [(S + 2000, 2000, S), (S + 2000, 6000, S), (S + 6000, 6000, S), (S + 6000, 2000, S)]
    yield "hole_outside", [with_top(b, [b[1][0], beside])], {}
    h1 = [(1000, 1000, S), (1000, 8000, S), (8000, 8000, S), (8000, 1000, S)]
    h2 = [(3000, 3000, S), (3000, 5000, S), (5000, 5000, S), (5000, 3000, S)]
    yield "hole_nested", [with_top(b, [b[1][0], h1, h2]) + pit(h1, 3000)], {}
    yield "hole_twice", [with_top(b, [b[1][0], hole, hole]) + pit(hole, 3000)], {}
    ha = [(2000, 2000, S), (2000, 4000, S), (4000, 4000, S), (4000, 2000, S)]
    hb = [(4000, 4000, S), (4000, 6000, S), (6000, 6000, S), (6000, 4000, S)]
    hc = [(4000, 2000, S), (4000, 4000, S), (6000, 4000, S), (6000, 2000, S)]
    yield "holes_touch_once", [with_top(b, [b[1][0], ha, hb]) + pyramid(ha, 1000) + pyramid(hb, 1000)], {}
    yield "holes_share_edge", [with_top(b, [b[1][0], ha, hc]) + pyramid(ha, 1000) + pyramid(hc, 1000)], {}
    # Shells that are not one 2-manifold.
    yield "two_boxes_edge", [b + box(S, S, 0, 2 * S, 2 * S, S)], {}
    yield "two_boxes_vertex", [b + box(S, S, S, 2 * S, 2 * S, 2 * S)], {}
    yield "two_boxes_apart", [b + box(2 * S, 0, 0, 3 * S, S, S)], {}
    # Non-planar tops: a corner 5, 15 and 40 mm up (val3dity's 0.01 m from the fitted plane).
    for dz in (5, 15, 40):
        yield f"bent_top_{dz}mm", [[[[(S, S, S + dz) if v == (S, S, S) else v for v in r] for r in f] for f in b]], {}
    # Parts overlapping by 0.5 mm x 10 m x 10 m and 1 mm x 1 m x 1 m.
    yield "overlap_sliver", [bt, box(T - 5, 0, 0, 2 * T, T, T)], {"scale": 0.0001}
    yield "overlap_tiny", [b, box(S - 1, 0, 0, S + 1000, 1000, 1000)], {}


def write(path, parts, scale=0.001, translate=None):
    verts, index = [], {}

    def vid(v):
        if v not in index:
            index[v] = len(verts)
            verts.append(list(v))
        return index[v]

    building = {"type": "Building", "children": [], "geometry": [],
                "attributes": {"morphcut_status": "ok", "morphcut_levels": [0.1], "morphcut_parts": [len(parts)]}}
    objects = {"B": building}
    for i, faces in enumerate(parts):
        pid = f"B-mc0-{i}"
        building["children"].append(pid)
        objects[pid] = {"type": "BuildingPart", "parents": ["B"], "attributes": {"morphcut_level": 0.1},
                        "geometry": [{"type": "Solid", "lod": "2.2",
                                      "boundaries": [[[[vid(v) for v in ring] for ring in f] for f in faces]]}]}
    doc = {"type": "CityJSON", "version": "2.0",
           "transform": {"scale": [scale] * 3, "translate": translate or LAMBERT},
           "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/2154"},
           "CityObjects": objects, "vertices": verts}
    with open(path, "w", encoding="utf-8") as f:
        json.dump(doc, f)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    os.makedirs(sys.argv[1], exist_ok=True)
    n = 0
    for name, parts, opts in cases():
        write(os.path.join(sys.argv[1], name + ".city.json"), parts, **opts)
        n += 1
    print(f"{n} files in {sys.argv[1]}")


if __name__ == "__main__":
    main()
