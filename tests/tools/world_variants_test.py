#!/usr/bin/env python3
"""tools/gen_world_variants.py stress on the 3D BAG tile: in the turned variants (rot, all) every
building is turned as a rigid body, including the vertices it shares with a neighbour (a shared
wall), and no two buildings share a vertex any more.

usage: world_variants_test.py SOURCE_DIR
"""
import json, math, os, subprocess, sys, tempfile


sys.path.insert(0, os.path.join(sys.argv[1], "tools"))
from gen_world_variants import vertex_refs  # noqa: E402  (the generator's own walk of boundaries)


def buildings(d):
    """Per top-level object: its and its children's vertex references in file order (repeats
    kept, so that a building's references line up with its copy's in a variant)."""
    cos = d["CityObjects"]
    for oid, o in cos.items():
        if not o.get("parents"):
            refs = []
            for k in [oid] + o.get("children", []):
                for g in cos.get(k, {}).get("geometry", []):
                    vertex_refs(g.get("boundaries", []), refs)
            yield oid, refs


def coords(d):
    t = d.get("transform", {"scale": [1, 1, 1], "translate": [0, 0, 0]})
    return [[v[k] * t["scale"][k] + t["translate"][k] for k in range(3)] for v in d["vertices"]]


def main():
    src = sys.argv[1]
    tile = os.path.join(src, "datasets", "3dbag", "3dbag_5910.city.json")
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([sys.executable, os.path.join(src, "tools", "gen_world_variants.py"), "stress", tile, out,
                        "--seed", "13"], check=True, stdout=subprocess.DEVNULL)
        d0 = json.load(open(tile))
        v0 = coords(d0)
        shared_before = set()
        owner = {}
        for oid, refs in buildings(d0):
            for i in set(refs):
                if i in owner and owner[i] != oid:
                    shared_before.add(oid)
                owner.setdefault(i, oid)
        assert shared_before, "the tile has buildings sharing vertices: the case under test"
        for tag, tol in (("rot", 2e-3), ("all", 2.5e-2)):  # 1 mm grid; 1 cm grid and 0.4 mm jitter
            d = json.load(open(os.path.join(out, f"3dbag_5910.{tag}.city.json")))
            v = coords(d)
            seen, worst, worst_id = {}, 0.0, None
            for (oid, a), (oid2, b) in zip(buildings(d0), buildings(d)):
                assert oid == oid2 and len(a) == len(b), oid
                for i in set(b):
                    assert seen.setdefault(i, oid) == oid, f"{tag}: vertex {i} shared by {seen[i]} and {oid}"
                # Rigid: every vertex keeps its distance to the building's first vertex.
                for i, j in zip(a, b):
                    d_in = math.dist(v0[i], v0[a[0]])
                    d_out = math.dist(v[j], v[b[0]])
                    if abs(d_in - d_out) > worst:
                        worst, worst_id = abs(d_in - d_out), oid
            assert worst <= tol, f"{tag}: {worst_id} deformed by {worst:.3f} m"
            print(f"{tag}: every building rigid within {worst * 1000:.2f} mm; {len(shared_before)} buildings shared vertices")
    return 0


if __name__ == "__main__":
    sys.exit(main())
