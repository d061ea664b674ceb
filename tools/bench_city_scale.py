#!/usr/bin/env python3
"""City-scale benchmark of morphcut-city (docs/benchmarks.md, "City scale"). Python 3 standard
library only.

    tools/bench_city_scale.py [-n N | --sizes N1,N2,...] [--bin PATH] [--threads T]
                              [--formats json,jsonl] [--repeats R] [--work DIR]
                              [--baseline-bin PATH] [--baseline-args=ARGS]
                              [--candidate-args=ARGS] [--extra-args=ARGS]
                              [--all-outputs] [--keep-outputs] [--json OUT.json]
                              [--sources F1,F2,...] [--no-shared] [--generate-only] [--smoke]

1. Generation. A city of N buildings (default 20000) is made from public CityJSON 2.0 3D BAG data:
   the bundled tile datasets/3dbag/3dbag_5910.city.json (432 buildings) and every other file
   under ../shared/datasets/cityjson/3dbag/ that is CityJSON 2.0 (.city.json, or .city.jsonl
   whose header says 2.0), holds Buildings, has the bundled tile's CRS and is not a byte copy of
   a source already taken (files that do not qualify are listed with the reason; --no-shared
   uses the bundled tile only, --sources replaces the list). The sources are laid out as
   "slots" (slot k = source k mod S, all its buildings, until N buildings are placed; the last
   slot may be cut) on a square grid whose cell is larger than every source's x/y extent
   (extent + 100 m, rounded up to 100 m), so no two slots overlap; slot 0 stays where the
   bundled tile is. Every CityObject id gets the suffix -r<k> (k = the slot), and the
   children/parents references and each feature's id are rewritten the same way. Vertices are
   shifted (integer offsets in the common transform, which is the bundled tile's); a source with
   another transform is re-quantised to it (within half a unit, 0.5 mm for 3D BAG).
   Object-level geographicalExtent members are shifted too. Both forms are written:
     WORK/gen/N<N>-<key>/city.city.json    one CityJSON 2.0 file (CityObjects, then vertices)
     WORK/gen/N<N>-<key>/city.city.jsonl   CityJSONSeq: the header {"type":"CityJSON",...,
                                           "CityObjects":{},"vertices":[]} then one
                                           CityJSONFeature per building with local vertices
   Generation streams: one building at a time is made and written to both files (the .city.json
   vertex list goes to a scratch file and is appended at the end); it is deterministic (same
   bytes for the same N and sources). <key> hashes N, the generator version and every source's
   sha256; a directory with a complete manifest.json is reused (reruns skip generation).

2. Runs. morphcut-city (--bin, default build/tools/morphcut-city) runs on each generated file
   (--formats, default json,jsonl: both) as
     BIN INPUT -j THREADS -q -o WORK/runs/<tag>/out.city.json[l] --report .../out.report.json
         --summary .../out.csv --no-html --no-gpkg --no-graph   [--extra-args] [side args]
   (--all-outputs writes the HTML page, GeoPackage and graphs too) under /usr/bin/time -v. The
   written city files are deleted after each run unless --keep-outputs (they are 5x the input).
   Per run it records:
     wall s        wall time of the process (measured here; the report's own is kept in --json)
     cpu s         user + sys of the process (/usr/bin/time; without it getrusage of children)
     peak MB       maximum resident set size (/usr/bin/time; without it the report's peak_rss_mb)
     bldg/s        buildings / wall s
     eff           parallel efficiency = sum of buildings[].timings.cpu / (wall s x threads)
                   (threads as the report states them). timings.cpu is a job's CPU time over
                   every thread that worked for it (pipeline/job_cpu.hpp). Reports without it
                   (older binaries) use the job's wall time instead, marked "*": that undercounts
                   a building whose parallel steps other threads help with
     cpu%          CPU utilisation = cpu s / (wall s x threads). Job times are wall clock per
                   job: when their sum is well above the process CPU (marked "contended"), the
                   workers waited for a core (other load on the machine), which inflates the
                   job times; compare cpu s then
     job med/p99/max  of buildings[].timings.job over the buildings that are not skipped
                   (p99 = nearest rank)
     statuses      the report's counts: ok / partial / failed / skipped
   A run fails (exit status of this script non-zero) when morphcut-city exits with 2 or more or
   on a signal, or when its report is missing or does not count every building. Exit status 1
   of morphcut-city (some buildings partial or failed) is a completed run.

3. A/B. With --baseline-bin and/or --baseline-args (quote with =, e.g.
   --baseline-args=--no-fast-path) the baseline (baseline binary or --bin, plus the baseline
   args) and the candidate (--bin plus --candidate-args) run alternately on the same input:
   A B A B ... for --repeats pairs (default 1 pair). Printed: baseline/candidate ratios of wall s,
   cpu s and median job time (from the medians over the repeats; per pair in --json); > 1 means
   the candidate is faster. An option of the args that the binary's --help does not list (or
   that the binary rejects as unexpected) is reported as not accepted and that side is skipped.

4. Memory flatness. --sizes 2000,20000 runs every size (default: just -n) and prints per format
   the peak RSS per size and the ratio largest / smallest size next to the ratio of buildings:
   a ratio near 1 at 10x the buildings shows memory flat in the number of buildings.

5. Projection. From the candidate's largest run per format: buildings/s per thread (buildings/s
   / threads, so the measured parallel efficiency is included) gives the time for 10,000,000
   buildings on one 64-core node, assuming linear scaling per core at the measured efficiency,
   the same building mix (3D BAG LoD 2.2), one thread per core and I/O not limiting. The ideal
   (efficiency 1: sum of job times / 64) and the node-hours are printed beside it.

6. Output. A table on stdout; --json PATH writes every number (generation, runs, A/B, flatness,
   projection, machine load before and after each run).

--smoke: a small self-check for ctest (N = 100, one run): generates both files, checks them
   (N Buildings, unique ids with -r<k>, parents/children resolving, vertex references in range),
   runs the binary once on the .city.jsonl and checks that the output city, the level files, the
   report and the CSV exist and that the report's counts add up to N (and the CSV has N rows);
   the .city.json is read once with --lod 9 (nothing decomposed, every building skipped: a
   reader check of 0.2 s) and must also give N buildings. Exit 0 when all holds, else 1.
   --generate-only: only generates and prints the file names.
"""
import argparse
import hashlib
import json
import math
import os
import re
import resource
import shlex
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PRIMARY = os.path.join(ROOT, "datasets", "3dbag", "3dbag_5910.city.json")
SHARED_3DBAG = os.path.normpath(os.path.join(ROOT, "..", "shared", "datasets", "cityjson", "3dbag"))
GEN_VERSION = 1  # bump when the generated bytes change
PROJECT_BUILDINGS = 10_000_000
PROJECT_CORES = 64
DUMPS = dict(separators=(",", ":"), ensure_ascii=False)


def log(*a):
    print(*a, flush=True)


def sha256_file(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


# ---------------------------------------------------------------------------------------------
# Sources

class Unit:
    """One building of a source: its objects (root first) with boundaries re-indexed to `verts`,
    its vertices in the common transform's integers (source position, no grid shift)."""
    __slots__ = ("root", "objects", "verts")

    def __init__(self, root, objects, verts):
        self.root, self.objects, self.verts = root, objects, verts


class Source:
    def __init__(self, path):
        self.path = path
        self.name = os.path.basename(path)
        self.sha256 = sha256_file(path)
        self.units = []
        self.skipped_objects = 0
        self.header = None  # root members but CityObjects and vertices

    def bbox(self):
        """x/y/z min and max over the units' vertices (common integers)."""
        lo, hi = [math.inf] * 3, [-math.inf] * 3
        for u in self.units:
            for v in u.verts:
                for i in range(3):
                    if v[i] < lo[i]:
                        lo[i] = v[i]
                    if v[i] > hi[i]:
                        hi[i] = v[i]
        return lo, hi


def _walk_boundaries(node, fn):
    if isinstance(node, list):
        return [_walk_boundaries(c, fn) for c in node]
    return fn(node)


def _geometries(obj):
    """Every geometry-like member of a CityObject that indexes vertices."""
    for g in obj.get("geometry", []) or []:
        yield g
    addr = obj.get("address")
    if isinstance(addr, list):
        for a in addr:
            loc = a.get("location") if isinstance(a, dict) else None
            if isinstance(loc, dict) and "boundaries" in loc:
                yield loc


def read_source(path):
    """Reads a CityJSON 2.0 file (.city.json or .city.jsonl) into Units; raises ValueError with
    the reason when the file does not qualify."""
    src = Source(path)
    if path.endswith(".jsonl"):
        with open(path, encoding="utf-8") as f:
            first = f.readline()
            try:
                header = json.loads(first)
            except json.JSONDecodeError as e:
                raise ValueError(f"first line is not JSON ({e})")
            if header.get("type") != "CityJSON":
                raise ValueError("first line is not a CityJSON header")
            if str(header.get("version")) != "2.0":
                raise ValueError(f"version {header.get('version')}, not 2.0")
            groups = []
            for line in f:
                if not line.strip():
                    continue
                feat = json.loads(line)
                if feat.get("type") != "CityJSONFeature":
                    continue
                groups.append((feat.get("id"), feat.get("CityObjects", {}), feat.get("vertices", [])))
    else:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
        if doc.get("type") != "CityJSON":
            raise ValueError("not a CityJSON object")
        if str(doc.get("version")) != "2.0":
            raise ValueError(f"version {doc.get('version')}, not 2.0")
        header = {k: v for k, v in doc.items() if k not in ("CityObjects", "vertices")}
        objs = doc.get("CityObjects", {})
        groups = []
        for oid, o in objs.items():
            if o.get("parents"):
                continue
            # root + descendants, children lists first (DFS, file order), then stray parents links
            order, seen, stack = [], set(), [oid]
            while stack:
                cur = stack.pop()
                if cur in seen or cur not in objs:
                    continue
                seen.add(cur)
                order.append(cur)
                stack.extend(reversed(objs[cur].get("children", []) or []))
            for cid, c in objs.items():
                if cid not in seen and any(p in seen for p in c.get("parents", []) or []):
                    order.append(cid)
                    seen.add(cid)
            groups.append((oid, {k: objs[k] for k in order}, doc.get("vertices", [])))
    tr = header.get("transform")
    if not tr or "scale" not in tr or "translate" not in tr:
        raise ValueError("no transform")
    src.header = header
    src.groups = groups
    return src


def crs_of(header):
    md = header.get("metadata") or {}
    return md.get("referenceSystem")


def finish_source(src, common_tr):
    """Turns the raw groups into Units with vertices in the common transform's integers."""
    s_scale, s_tr = src.header["transform"]["scale"], src.header["transform"]["translate"]
    c_scale, c_tr = common_tr["scale"], common_tr["translate"]
    exact = []
    for i in range(3):
        d = (s_tr[i] - c_tr[i]) / c_scale[i]
        exact.append(s_scale[i] == c_scale[i] and abs(d - round(d)) < 1e-6)
    delta = [round((s_tr[i] - c_tr[i]) / c_scale[i]) for i in range(3)]

    def conv(v):
        out = []
        for i in range(3):
            if exact[i]:
                out.append(int(v[i]) + delta[i])
            else:
                out.append(int(round((v[i] * s_scale[i] + s_tr[i] - c_tr[i]) / c_scale[i])))
        return out

    src.requantised = not all(exact)
    for fid, objs, verts in src.groups:
        roots = [k for k, o in objs.items() if not o.get("parents")]
        root = fid if fid in objs and not objs[fid].get("parents") else (roots[0] if roots else None)
        if root is None or objs[root].get("type") != "Building" or len(roots) != 1:
            src.skipped_objects += len(objs)
            continue
        if any(g.get("type") == "GeometryInstance" for o in objs.values() for g in o.get("geometry", []) or []):
            src.skipped_objects += len(objs)
            continue
        local = {}
        lverts = []

        def remap(i):
            j = local.get(i)
            if j is None:
                j = local[i] = len(lverts)
                lverts.append(conv(verts[i]))
            return j

        # root first, then the others in the source's order
        order = [root] + [k for k in objs if k != root]
        new = {}
        for k in order:
            o = json.loads(json.dumps(objs[k]))  # own copy
            for g in _geometries(o):
                if "boundaries" in g:
                    g["boundaries"] = _walk_boundaries(g["boundaries"], remap)
            new[k] = o
        src.units.append(Unit(root, new, lverts))
    del src.groups


def discover_sources(args):
    """Returns (sources, notes): the primary tile and the qualifying shared 3D BAG files."""
    notes = []
    if args.sources:
        paths = [p for p in args.sources.split(",") if p]
    else:
        paths = [PRIMARY]
        if not args.no_shared and os.path.isdir(SHARED_3DBAG):
            for name in sorted(os.listdir(SHARED_3DBAG)):
                if name.endswith((".city.json", ".city.jsonl", ".json", ".jsonl")):
                    paths.append(os.path.join(SHARED_3DBAG, name))
        elif not args.no_shared:
            notes.append(f"{SHARED_3DBAG}: not found, bundled tile only")
    sources, hashes = [], set()
    for i, p in enumerate(paths):
        try:
            s = read_source(p)
        except (ValueError, OSError, json.JSONDecodeError) as e:
            if i == 0:
                raise SystemExit(f"bench_city_scale: {p}: {e}")
            notes.append(f"skipped {p}: {e}")
            continue
        if s.sha256 in hashes:
            notes.append(f"skipped {p}: same bytes as a source already taken")
            continue
        if sources and crs_of(s.header) != crs_of(sources[0].header):
            notes.append(f"skipped {p}: CRS {crs_of(s.header)} differs from {crs_of(sources[0].header)}")
            continue
        hashes.add(s.sha256)
        sources.append(s)
    common_tr = sources[0].header["transform"]
    kept = []
    for s in sources:
        finish_source(s, common_tr)
        if not s.units:
            notes.append(f"skipped {s.path}: no Building features")
            continue
        if s.requantised:
            notes.append(f"{s.name}: other transform, re-quantised to the common one")
        kept.append(s)
    return kept, notes, common_tr


# ---------------------------------------------------------------------------------------------
# Generation

def plan_slots(sources, n):
    """[(slot k, source index, buildings taken)] until n buildings."""
    slots, left, k = [], n, 0
    while left > 0:
        si = k % len(sources)
        take = min(left, len(sources[si].units))
        slots.append((k, si, take))
        left -= take
        k += 1
    return slots


def cache_key(sources, n):
    h = hashlib.sha256()
    h.update(json.dumps({"gen": GEN_VERSION, "n": n, "sources": [[s.name, s.sha256] for s in sources]}).encode())
    return h.hexdigest()[:12]


def _rename(objs, suffix, shift_m):
    out = {}
    for oid, o in objs.items():
        o = dict(o)
        for key in ("children", "parents"):
            if key in o:
                o[key] = [c + suffix for c in o[key]]
        ge = o.get("geographicalExtent")
        if isinstance(ge, list) and len(ge) == 6:
            o["geographicalExtent"] = [ge[0] + shift_m[0], ge[1] + shift_m[1], ge[2],
                                       ge[3] + shift_m[0], ge[4] + shift_m[1], ge[5]]
        out[oid + suffix] = o
    return out


def _offset_geoms(objs, base):
    """Copies of the objects whose geometry boundaries are shifted by `base` (new lists only
    where needed, the rest shared)."""
    if base == 0:
        return objs
    out = {}
    for oid, o in objs.items():
        if "geometry" not in o and "address" not in o:
            out[oid] = o
            continue
        o = dict(o)
        if "geometry" in o:
            gs = []
            for g in o["geometry"]:
                if "boundaries" in g:
                    g = dict(g)
                    g["boundaries"] = _walk_boundaries(g["boundaries"], lambda i: i + base)
                gs.append(g)
            o["geometry"] = gs
        if isinstance(o.get("address"), list):
            addrs = []
            for a in o["address"]:
                if isinstance(a, dict) and isinstance(a.get("location"), dict) and "boundaries" in a["location"]:
                    a = dict(a)
                    a["location"] = dict(a["location"])
                    a["location"]["boundaries"] = _walk_boundaries(a["location"]["boundaries"], lambda i: i + base)
                addrs.append(a)
            o["address"] = addrs
        out[oid] = o
    return out


def generate(sources, common_tr, n, work):
    """Writes (or reuses) the city of n buildings; returns the manifest dict."""
    key = cache_key(sources, n)
    gdir = os.path.join(work, "gen", f"N{n}-{key}")
    manifest_path = os.path.join(gdir, "manifest.json")
    if os.path.exists(manifest_path):
        with open(manifest_path) as f:
            m = json.load(f)
        if all(os.path.exists(m["files"][k]) for k in ("json", "jsonl")):
            m["cached"] = True
            return m
    os.makedirs(gdir, exist_ok=True)
    t0 = time.monotonic()
    scale, translate = common_tr["scale"], common_tr["translate"]
    slots = plan_slots(sources, n)
    boxes = [s.bbox() for s in sources]
    ext = max(max(hi[0] - lo[0], 0) * scale[0] for lo, hi in boxes)
    ext = max(ext, max(max(hi[1] - lo[1], 0) * scale[1] for lo, hi in boxes))
    cell_m = math.ceil((ext + 100.0) / 100.0) * 100.0
    cell = [round(cell_m / scale[0]), round(cell_m / scale[1])]
    grid = max(1, math.ceil(math.sqrt(len(slots))))
    origin = boxes[0][0]
    glo, ghi = [math.inf] * 3, [-math.inf] * 3
    slot_shift = {}
    for k, si, _ in slots:
        col, row = k % grid, k // grid
        lo, hi = boxes[si]
        sh = (origin[0] - lo[0] + col * cell[0], origin[1] - lo[1] + row * cell[1])
        slot_shift[k] = sh
        for i in range(3):
            d = sh[i] if i < 2 else 0
            glo[i] = min(glo[i], (lo[i] + d) * scale[i] + translate[i])
            ghi[i] = max(ghi[i], (hi[i] + d) * scale[i] + translate[i])
    md = {"identifier": f"morphcut-city-scale-N{n}",
          "title": f"{n} buildings: 3D BAG sources replicated on a {grid}x{grid} grid of {cell_m:.0f} m "
                   f"(tools/bench_city_scale.py)",
          "geographicalExtent": [round(x, 3) for x in glo + ghi]}
    if crs_of(sources[0].header):
        md["referenceSystem"] = crs_of(sources[0].header)
    head = {"type": "CityJSON", "version": "2.0", "transform": common_tr, "metadata": md}

    path_json = os.path.join(gdir, "city.city.json")
    path_jsonl = os.path.join(gdir, "city.city.jsonl")
    tmp_json, tmp_jsonl, tmp_verts = path_json + ".tmp", path_jsonl + ".tmp", path_json + ".vertices.tmp"
    base = 0
    buildings = objects = 0
    with open(tmp_json, "w", encoding="utf-8") as fj, open(tmp_jsonl, "w", encoding="utf-8") as fl, \
            open(tmp_verts, "w", encoding="utf-8") as fv:
        fj.write(json.dumps(head, **DUMPS)[:-1] + ',"CityObjects":{')
        seq_head = dict(head)
        seq_head["CityObjects"] = {}
        seq_head["vertices"] = []
        fl.write(json.dumps(seq_head, **DUMPS) + "\n")
        first_obj = first_vert = True
        for k, si, take in slots:
            suffix = f"-r{k}"
            dx, dy = slot_shift[k]
            shift_m = (dx * scale[0], dy * scale[1])
            for u in sources[si].units[:take]:
                objs = _rename(u.objects, suffix, shift_m)
                verts = [[v[0] + dx, v[1] + dy, v[2]] for v in u.verts]
                feat = {"type": "CityJSONFeature", "id": u.root + suffix, "CityObjects": objs, "vertices": verts}
                fl.write(json.dumps(feat, **DUMPS) + "\n")
                for oid, o in _offset_geoms(objs, base).items():
                    fj.write(("" if first_obj else ",") + json.dumps(oid, **DUMPS) + ":" + json.dumps(o, **DUMPS))
                    first_obj = False
                    objects += 1
                if verts:
                    s = json.dumps(verts, **DUMPS)[1:-1]
                    fv.write(("" if first_vert else ",") + s)
                    first_vert = False
                base += len(verts)
                buildings += 1
        fj.write('},"vertices":[')
        fv.flush()
        with open(tmp_verts, encoding="utf-8") as rv:
            shutil.copyfileobj(rv, fj, 1 << 20)
        fj.write("]}")
    os.unlink(tmp_verts)
    os.replace(tmp_json, path_json)
    os.replace(tmp_jsonl, path_jsonl)
    m = {"n": n, "key": key, "generator_version": GEN_VERSION, "dir": gdir,
         "files": {"json": path_json, "jsonl": path_jsonl},
         "bytes": {"json": os.path.getsize(path_json), "jsonl": os.path.getsize(path_jsonl)},
         "buildings": buildings, "objects": objects, "vertices": base,
         "slots": len(slots), "grid": grid, "cell_m": cell_m,
         "sources": [{"path": s.path, "sha256": s.sha256, "buildings": len(s.units),
                      "slots": sum(1 for _, si, _ in slots if si == i),
                      "requantised": s.requantised} for i, s in enumerate(sources)],
         "seconds": round(time.monotonic() - t0, 3)}
    with open(manifest_path + ".tmp", "w") as f:
        json.dump(m, f, indent=1)
    os.replace(manifest_path + ".tmp", manifest_path)
    m["cached"] = False
    return m


def check_generated(m):
    """Structural check of both generated files; returns a list of problems."""
    probs = []
    n = m["n"]
    suffix_re = re.compile(r"-r\d+$")
    # .city.json
    with open(m["files"]["json"], encoding="utf-8") as f:
        d = json.load(f)
    objs, nv = d["CityObjects"], len(d["vertices"])
    roots = [k for k, o in objs.items() if o.get("type") == "Building" and not o.get("parents")]
    if len(roots) != n:
        probs.append(f".city.json: {len(roots)} root Buildings, expected {n}")
    bad_ids = [k for k in objs if not suffix_re.search(k)]
    if bad_ids:
        probs.append(f".city.json: {len(bad_ids)} ids without -r<k>, e.g. {bad_ids[0]}")
    bad_refs = [k for k, o in objs.items() for c in (o.get("children", []) or []) + (o.get("parents", []) or [])
                if c not in objs]
    if bad_refs:
        probs.append(f".city.json: {len(bad_refs)} children/parents references that do not resolve")
    maxi = [-1]

    def see(i):
        if i > maxi[0]:
            maxi[0] = i
        return i
    for o in objs.values():
        for g in _geometries(o):
            _walk_boundaries(g.get("boundaries", []), see)
    if maxi[0] >= nv:
        probs.append(f".city.json: vertex index {maxi[0]} >= {nv} vertices")
    del d, objs
    # .city.jsonl
    ids, feats = set(), 0
    with open(m["files"]["jsonl"], encoding="utf-8") as f:
        head = json.loads(f.readline())
        if head.get("type") != "CityJSON" or head.get("CityObjects") != {} or head.get("vertices") != []:
            probs.append(".city.jsonl: first line is not a header with empty CityObjects and vertices")
        for line in f:
            ft = json.loads(line)
            feats += 1
            if ft.get("type") != "CityJSONFeature" or ft.get("id") not in ft.get("CityObjects", {}):
                probs.append(f".city.jsonl: feature {feats} has no CityJSONFeature type or its id is not an object")
                break
            nvl, top = len(ft["vertices"]), 0
            for oid, o in ft["CityObjects"].items():
                if oid in ids:
                    probs.append(f".city.jsonl: duplicate id {oid}")
                ids.add(oid)
                if not suffix_re.search(oid):
                    probs.append(f".city.jsonl: id without -r<k>: {oid}")
                if not o.get("parents"):
                    top += 1
                for c in (o.get("children", []) or []) + (o.get("parents", []) or []):
                    if c not in ft["CityObjects"]:
                        probs.append(f".city.jsonl: reference {c} of {oid} not in its feature")
                maxi[0] = -1
                for g in _geometries(o):
                    _walk_boundaries(g.get("boundaries", []), see)
                if maxi[0] >= nvl:
                    probs.append(f".city.jsonl: {oid} indexes vertex {maxi[0]} of {nvl}")
            if top != 1:
                probs.append(f".city.jsonl: feature {ft['id']} has {top} root objects")
            if len(probs) > 20:
                break
    if feats != n:
        probs.append(f".city.jsonl: {feats} features, expected {n}")
    return probs


# ---------------------------------------------------------------------------------------------
# Runs

def help_options(binary):
    try:
        p = subprocess.run([binary, "--help"], capture_output=True, text=True, timeout=60)
    except OSError as e:
        return None, str(e)
    return set(re.findall(r"(?<![\w-])(--?[A-Za-z][\w-]*)", p.stdout + p.stderr)), None


def unaccepted(binary, argv):
    """Options of argv that binary --help does not list."""
    opts, err = help_options(binary)
    if opts is None:
        return [f"({binary} --help failed: {err})"]
    bad = []
    for a in argv:
        if re.match(r"^--?[A-Za-z]", a):
            name = a.split("=", 1)[0]
            if name not in opts:
                bad.append(name)
    return bad


def parse_time_v(path):
    out = {}
    try:
        txt = open(path).read()
    except OSError:
        return out
    for key, pat in (("user", r"User time \(seconds\): ([\d.]+)"), ("sys", r"System time \(seconds\): ([\d.]+)"),
                     ("maxrss_kb", r"Maximum resident set size \(kbytes\): (\d+)"),
                     ("exit", r"Exit status: (\d+)")):
        mm = re.search(pat, txt)
        if mm:
            out[key] = float(mm.group(1))
    return out


def pct_nearest(sorted_vals, q):
    if not sorted_vals:
        return None
    i = max(0, math.ceil(q * len(sorted_vals)) - 1)
    return sorted_vals[i]


def run_once(binary, side_args, inp, fmt, run_dir, args, n, time_bin, lod9=False):
    """One morphcut-city run; returns the record (record['ok'] False on a failed run)."""
    if os.path.isdir(run_dir):
        shutil.rmtree(run_dir)
    os.makedirs(run_dir)
    ext = ".city.jsonl" if fmt == "jsonl" else ".city.json"
    out = os.path.join(run_dir, "out" + ext)
    report = os.path.join(run_dir, "out.report.json")
    csv_path = os.path.join(run_dir, "out.csv")
    cmd = [binary, inp, "-j", str(args.threads), "-q", "-o", out, "--report", report, "--summary", csv_path]
    if not args.all_outputs:
        cmd += ["--no-html", "--no-gpkg", "--no-graph"]
    if lod9:
        cmd += ["--lod", "9"]
    cmd += args.extra + side_args
    tfile = os.path.join(run_dir, "time.txt")
    full = ([time_bin, "-v", "-o", tfile] if time_bin else []) + cmd
    load0 = os.getloadavg()
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    with open(os.path.join(run_dir, "stderr.txt"), "w") as err:
        p = subprocess.run(full, cwd=run_dir, stdout=err, stderr=subprocess.STDOUT)
    wall = time.monotonic() - t0
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    rec = {"format": fmt, "input": inp, "command": " ".join(shlex.quote(c) for c in cmd),
           "exit_code": p.returncode, "wall_s": round(wall, 3), "threads": args.threads,
           "load_before": [round(x, 2) for x in load0], "load_after": [round(x, 2) for x in os.getloadavg()],
           "ok": True, "problems": []}
    tv = parse_time_v(tfile) if time_bin else {}
    if time_bin and "exit" in tv:
        rec["exit_code"] = int(tv["exit"])
    if "user" in tv:
        rec["cpu_s"] = round(tv["user"] + tv["sys"], 3)
        rec["cpu_source"] = "/usr/bin/time"
    else:
        rec["cpu_s"] = round((ru1.ru_utime - ru0.ru_utime) + (ru1.ru_stime - ru0.ru_stime), 3)
        rec["cpu_source"] = "getrusage(children)"
    if rec["exit_code"] >= 2 or rec["exit_code"] < 0 or p.returncode < 0:
        rec["ok"] = False
        tail = open(os.path.join(run_dir, "stderr.txt"), errors="replace").read()[-2000:]
        rec["problems"].append(f"morphcut-city exited with {rec['exit_code']}: {tail.strip()[-600:]}")
        rec["stderr_tail"] = tail
        return rec
    try:
        with open(report) as f:
            r = json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        rec["ok"] = False
        rec["problems"].append(f"no readable report {report}: {e}")
        return rec
    rec["threads"] = r.get("threads", args.threads)
    rec["report_wall_s"] = r.get("wall_seconds")
    rec["report_cpu_s"] = r.get("cpu_seconds")
    rec["report_peak_rss_mb"] = r.get("peak_rss_mb")
    rec["in_flight"] = r.get("in_flight")
    if "maxrss_kb" in tv:
        rec["peak_rss_mb"] = round(tv["maxrss_kb"] / 1024.0, 1)
        rec["rss_source"] = "/usr/bin/time"
    else:
        rec["peak_rss_mb"] = r.get("peak_rss_mb")
        rec["rss_source"] = "report peak_rss_mb"
    counts = r.get("counts", {})
    rec["counts"] = {k: counts.get(k, 0) for k in ("ok", "partial", "failed", "skipped")}
    blds = r.get("buildings", [])
    rec["buildings"] = r.get("building_count", len(blds))
    jobs_all = [b["timings"]["job"] for b in blds if isinstance(b.get("timings"), dict) and "job" in b["timings"]]
    jobs = sorted(b["timings"]["job"] for b in blds
                  if b.get("status") != "skipped" and isinstance(b.get("timings"), dict) and "job" in b["timings"])
    cpus = [b["timings"]["cpu"] for b in blds if isinstance(b.get("timings"), dict) and "cpu" in b["timings"]]
    outputs = r.get("outputs", {})
    del r, blds
    rec["job_sum_s"] = round(sum(jobs_all), 3)
    # efficiency from the jobs' CPU time where the report has it (see eff above), else their wall time
    rec["job_cpu_sum_s"] = round(sum(cpus), 3) if cpus and len(cpus) == len(jobs_all) else None
    rec["efficiency_basis"] = "job cpu" if rec["job_cpu_sum_s"] is not None else "job wall"
    rec["job_median_s"] = round(statistics.median(jobs), 4) if jobs else None
    rec["job_p99_s"] = round(pct_nearest(jobs, 0.99), 4) if jobs else None
    rec["job_max_s"] = round(jobs[-1], 4) if jobs else None
    rec["jobs_counted"] = len(jobs)
    thr = rec["threads"] or args.threads
    rec["buildings_per_s"] = round(rec["buildings"] / wall, 3) if wall > 0 else None
    eff_sum = rec["job_cpu_sum_s"] if rec["job_cpu_sum_s"] is not None else rec["job_sum_s"]
    rec["parallel_efficiency"] = round(eff_sum / (wall * thr), 4) if wall > 0 and thr else None
    rec["cpu_utilisation"] = round(rec["cpu_s"] / (wall * thr), 4) if wall > 0 and thr else None
    # job times are wall clock per job: well above the process CPU they mean the workers waited
    # for a core (other load on the machine), which inflates the job times and the efficiency
    rec["contended"] = bool(rec["job_sum_s"] > 1.15 * rec["cpu_s"] + 1.0)
    total = sum(rec["counts"].values())
    if rec["buildings"] != n or total != n:
        rec["ok"] = False
        rec["problems"].append(f"report counts {total} and building_count {rec['buildings']}, expected {n}")
    # outputs exist (checked before they are deleted)
    levels = [x.get("cityjson", "") if isinstance(x, dict) else x for x in outputs.get("levels", [])]
    files = [out, report, csv_path] + [os.path.join(run_dir, os.path.basename(x)) for x in levels if x]
    missing = [x for x in files if not os.path.exists(x)]
    if missing:
        rec["ok"] = False
        rec["problems"].append("missing outputs: " + ", ".join(missing))
    rec["level_files"] = len(levels)
    try:
        with open(csv_path, newline="") as f:
            import csv
            rec["csv_rows"] = sum(1 for _ in csv.reader(f)) - 1
    except OSError:
        rec["csv_rows"] = None
    if not args.keep_outputs:
        for x in files[:1] + files[3:]:
            if os.path.exists(x):
                os.unlink(x)
    return rec


# ---------------------------------------------------------------------------------------------
# Printing

HDR = (f"{'N':>7} {'fmt':<5} {'side':<9} {'rep':>3} {'bldgs':>7} {'wall s':>9} {'cpu s':>9} {'peak MB':>8} "
       f"{'bldg/s':>8} {'eff':>5} {'cpu%':>5} {'job med':>8} {'job p99':>8} {'job max':>8}  ok/part/fail/skip")


def row(r):
    if not r.get("ok") and "counts" not in r:
        return f"{r['n']:>7} {r['format']:<5} {r['side']:<9} {r['rep']:>3}  FAILED: {'; '.join(r['problems'])[:200]}"
    c = r["counts"]
    f = lambda v, fmt: (format(v, fmt) if v is not None else "-")
    s = (f"{r['n']:>7} {r['format']:<5} {r['side']:<9} {r['rep']:>3} {r['buildings']:>7} {f(r['wall_s'], '9.1f')} "
         f"{f(r['cpu_s'], '9.1f')} {f(r['peak_rss_mb'], '8.1f')} {f(r['buildings_per_s'], '8.2f')} "
         f"{f(r['parallel_efficiency'], '4.2f')}{'*' if r.get('efficiency_basis') == 'job wall' else ' '} {f(r['cpu_utilisation'], '5.2f')} {f(r['job_median_s'], '8.3f')} {f(r['job_p99_s'], '8.2f')} "
         f"{f(r['job_max_s'], '8.2f')}  {c['ok']}/{c['partial']}/{c['failed']}/{c['skipped']}")
    if r.get("contended"):
        s += "  (contended: job times sum > CPU)"
    if not r["ok"]:
        s += "  FAILED: " + "; ".join(r["problems"])
    return s


def med(vals):
    vals = [v for v in vals if v is not None]
    return statistics.median(vals) if vals else None


def fmt_h(seconds):
    return f"{seconds / 3600:.1f} h" if seconds >= 3600 else f"{seconds / 60:.1f} min"


# ---------------------------------------------------------------------------------------------

def parse_args(argv):
    ap = argparse.ArgumentParser(prog="bench_city_scale.py", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("-n", "--buildings", type=int, default=20000, help="buildings in the city (default 20000)")
    ap.add_argument("--sizes", help="comma-separated sizes to run, e.g. 2000,20000 (default: just -n)")
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "tools", "morphcut-city"),
                    help="morphcut-city binary of the candidate (default build/tools/morphcut-city)")
    ap.add_argument("--threads", "-j", type=int, default=2, help="-j passed to morphcut-city (default 2)")
    ap.add_argument("--formats", default="json,jsonl", help="json, jsonl or both (default json,jsonl)")
    ap.add_argument("--repeats", type=int, default=1, help="runs per side (A/B: pairs A B) per size and format (default 1)")
    ap.add_argument("--work", default=os.path.join(os.environ.get("TMPDIR") or "/tmp", "morphcut-city-scale"),
                    help="work dir: generated cities (gen/) and runs (runs/) (default ${TMPDIR:-/tmp}/morphcut-city-scale)")
    ap.add_argument("--baseline-bin", help="binary of the baseline side (A/B)")
    ap.add_argument("--baseline-args", default=None, help='extra morphcut-city args of the baseline, e.g. --baseline-args=--no-fast-path')
    ap.add_argument("--candidate-args", default="", help="extra morphcut-city args of the candidate only")
    ap.add_argument("--extra-args", default="", help="extra morphcut-city args of every run (e.g. --extra-args='--config F.yaml')")
    ap.add_argument("--all-outputs", action="store_true", help="also write the HTML page, GeoPackage and part graphs")
    ap.add_argument("--keep-outputs", action="store_true", help="keep the written city files of every run")
    ap.add_argument("--json", help="write every number to this JSON file")
    ap.add_argument("--sources", help="comma-separated source files instead of the default ones (the first sets transform and CRS)")
    ap.add_argument("--no-shared", action="store_true", help="bundled tile only (not ../shared/datasets/cityjson/3dbag)")
    ap.add_argument("--generate-only", action="store_true", help="generate the files and stop")
    ap.add_argument("--smoke", action="store_true", help="N=100 self-check for ctest (see above)")
    a = ap.parse_args(argv)
    a.extra = shlex.split(a.extra_args)
    a.cand = shlex.split(a.candidate_args)
    a.base = shlex.split(a.baseline_args) if a.baseline_args is not None else None
    a.fmts = [f.strip() for f in a.formats.split(",") if f.strip()]
    if any(f not in ("json", "jsonl") for f in a.fmts) or not a.fmts:
        ap.error("--formats takes json, jsonl or json,jsonl")
    a.size_list = [int(x) for x in a.sizes.split(",")] if a.sizes else [a.buildings]
    if any(s <= 0 for s in a.size_list) or a.repeats < 1 or a.threads < 0:
        ap.error("sizes and --repeats must be positive, --threads non-negative")
    return a


def smoke(args, sources, common_tr, time_bin):
    n = 100
    m = generate(sources, common_tr, n, args.work)
    how = "cached" if m["cached"] else f"{m['seconds']} s"
    log(f"smoke: generated N={n} in {m['dir']} ({how})")
    probs = check_generated(m)
    run_dir = os.path.join(args.work, "runs", f"smoke-N{n}")
    rec = run_once(args.bin, args.cand, m["files"]["jsonl"], "jsonl", run_dir, args, n, time_bin)
    rec.update(n=n, side="candidate", rep=1)
    log(HDR)
    log(row(rec))
    probs += rec["problems"]
    if rec.get("csv_rows") is not None and rec["csv_rows"] != n:
        probs.append(f"CSV has {rec['csv_rows']} rows, expected {n}")
    if rec.get("level_files", 0) < 1 and rec["ok"]:
        probs.append("report names no level files")
    rd = run_once(args.bin, [], m["files"]["json"], "json", run_dir + "-json-read", args, n, time_bin, lod9=True)
    if not rd["ok"]:
        probs += [".city.json read check: " + p for p in rd["problems"]]
    else:
        log(f"smoke: .city.json read check (--lod 9): {rd['buildings']} buildings, {rd['wall_s']:.2f} s")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"smoke": True, "generation": m, "run": rec, "json_read_check": rd, "problems": probs}, f, indent=1)
    if probs:
        for p in probs:
            log("FAIL:", p)
        return 1
    log(f"smoke: OK (N={n}: files consistent, outputs present, counts add up to {n})")
    return 0


def main(argv):
    args = parse_args(argv)
    args.bin = os.path.abspath(args.bin)
    if not (os.path.isfile(args.bin) and os.access(args.bin, os.X_OK)):
        log(f"bench_city_scale: {args.bin} is not an executable (build it, or pass --bin)")
        return 2
    time_bin = "/usr/bin/time" if os.access("/usr/bin/time", os.X_OK) else None
    if not time_bin:
        log("note: /usr/bin/time not found: CPU from getrusage, peak RSS from the report's peak_rss_mb")
    os.makedirs(args.work, exist_ok=True)
    sources, notes, common_tr = discover_sources(args)
    for s in sources:
        log(f"source: {s.path} ({len(s.units)} buildings, sha256 {s.sha256[:12]})")
    for nt in notes:
        log("note:", nt)
    if args.smoke:
        return smoke(args, sources, common_tr, time_bin)

    result = {"tool": "bench_city_scale.py", "date": time.strftime("%Y-%m-%d %H:%M:%S"),
              "machine": {"cpus": os.cpu_count(), "uname": " ".join(os.uname())},
              "bin": args.bin, "bin_sha256": sha256_file(args.bin), "threads": args.threads,
              "formats": args.fmts, "sizes": args.size_list, "repeats": args.repeats,
              "sources": [{"path": s.path, "sha256": s.sha256, "buildings": len(s.units)} for s in sources],
              "notes": notes, "generation": {}, "runs": [], "ab": None, "flatness": {}, "projection": {}}
    gens = {}
    for n in args.size_list:
        m = generate(sources, common_tr, n, args.work)
        gens[n] = m
        result["generation"][str(n)] = m
        log(f"city N={n}: {m['files']['json']} ({m['bytes']['json'] / 1e6:.1f} MB), "
            f"{m['files']['jsonl']} ({m['bytes']['jsonl'] / 1e6:.1f} MB); {m['slots']} slots on a "
            f"{m['grid']}x{m['grid']} grid of {m['cell_m']:.0f} m; "
            + ("cached" if m["cached"] else f"generated in {m['seconds']:.1f} s"))
    if args.generate_only:
        if args.json:
            with open(args.json, "w") as f:
                json.dump(result, f, indent=1)
        return 0

    # sides
    ab = args.baseline_bin is not None or args.base is not None
    sides = []
    base_bin = os.path.abspath(args.baseline_bin) if args.baseline_bin else args.bin
    cand_bad = unaccepted(args.bin, args.cand + args.extra)
    if cand_bad:
        log(f"bench_city_scale: {args.bin} does not accept {' '.join(cand_bad)} (not in its --help)")
        return 2
    if ab:
        base_args = args.base or []
        skip = None
        if not (os.path.isfile(base_bin) and os.access(base_bin, os.X_OK)):
            skip = f"baseline binary {base_bin} is not an executable"
        else:
            bad = unaccepted(base_bin, base_args + args.extra)
            if bad:
                skip = f"baseline binary {base_bin} does not accept {' '.join(bad)} (not in its --help)"
        result["ab"] = {"baseline_bin": base_bin, "baseline_args": base_args, "candidate_bin": args.bin,
                        "candidate_args": args.cand, "skipped": skip, "pairs": [], "ratios": {}}
        if skip:
            log(f"NOTE: A/B baseline side SKIPPED: {skip}; only the candidate runs")
            ab = False
        else:
            sides.append(("baseline", base_bin, base_args))
    sides.append(("candidate", args.bin, args.cand))

    log("")
    log(HDR)
    failed = False
    for n in args.size_list:
        for fmt in args.fmts:
            for rep in range(1, args.repeats + 1):
                for side, b, sargs in sides:
                    tag = f"N{n}-{fmt}-{side}-{rep}"
                    rec = run_once(b, sargs, gens[n]["files"][fmt], fmt, os.path.join(args.work, "runs", tag),
                                   args, n, time_bin)
                    if side == "baseline" and rec["exit_code"] == 2:
                        tail = rec.get("stderr_tail", "")
                        if re.search(r"not expected|unknown option|unrecognized", tail, re.I):
                            msg = f"baseline {b} rejected {' '.join(sargs)}: {tail.strip()[-200:]}"
                            log(f"NOTE: A/B baseline side SKIPPED: {msg}")
                            result["ab"]["skipped"] = msg
                            sides = [s for s in sides if s[0] != "baseline"]
                            ab = False
                            continue
                    rec.update(n=n, side=side, rep=rep, bin=b, side_args=sargs)
                    result["runs"].append(rec)
                    log(row(rec))
                    failed |= not rec["ok"]

    runs = [r for r in result["runs"] if r["ok"]]
    if any(r.get("efficiency_basis") == "job wall" for r in runs):
        log("* eff from the jobs' wall times: that report has no timings.cpu (an older binary)")

    def sel(n, fmt, side):
        return [r for r in runs if r["n"] == n and r["format"] == fmt and r["side"] == side]

    # A/B
    if ab:
        log("")
        log("A/B, baseline / candidate (> 1: the candidate is faster), medians over the repeats:")
        log(f"{'N':>7} {'fmt':<5} {'wall':>7} {'cpu':>7} {'job med':>8}  per pair (wall)")
        for n in args.size_list:
            for fmt in args.fmts:
                A, B = sel(n, fmt, "baseline"), sel(n, fmt, "candidate")
                if not A or not B:
                    continue
                rat = {}
                for key, name in (("wall_s", "wall"), ("cpu_s", "cpu"), ("job_median_s", "job_median")):
                    a, b = med([r[key] for r in A]), med([r[key] for r in B])
                    rat[name] = round(a / b, 4) if a and b else None
                pairs = []
                for ra, rb in zip(A, B):
                    pairs.append({"rep": ra["rep"], **{name: (round(ra[key] / rb[key], 4) if ra[key] and rb[key] else None)
                                                       for key, name in (("wall_s", "wall"), ("cpu_s", "cpu"),
                                                                         ("job_median_s", "job_median"))}})
                result["ab"]["ratios"][f"N{n}-{fmt}"] = rat
                result["ab"]["pairs"].append({"n": n, "format": fmt, "pairs": pairs})
                f = lambda v: f"{v:.3f}" if v is not None else "-"
                log(f"{n:>7} {fmt:<5} {f(rat['wall']):>7} {f(rat['cpu']):>7} {f(rat['job_median']):>8}  "
                    + " ".join(f(p["wall"]) for p in pairs))

    # memory flatness
    if len(args.size_list) > 1:
        log("")
        log("Memory flatness (candidate, peak RSS median over the repeats):")
        lo_n, hi_n = min(args.size_list), max(args.size_list)
        for fmt in args.fmts:
            per = {n: med([r["peak_rss_mb"] for r in sel(n, fmt, "candidate")]) for n in sorted(args.size_list)}
            if per.get(lo_n) and per.get(hi_n):
                ratio = per[hi_n] / per[lo_n]
                result["flatness"][fmt] = {"peak_rss_mb": {str(k): v for k, v in per.items()},
                                           "ratio": round(ratio, 4), "buildings_ratio": hi_n / lo_n}
                log(f"  {fmt:<5} " + ", ".join(f"N={k}: {v:.1f} MB" for k, v in per.items() if v)
                    + f"; {hi_n}/{lo_n} = {hi_n / lo_n:g}x the buildings -> {ratio:.3f}x the peak RSS")

    # projection
    hi_n = max(args.size_list)
    proj_lines = []
    for fmt in args.fmts:
        rs = sel(hi_n, fmt, "candidate")
        if not rs:
            continue
        bps = med([r["buildings_per_s"] for r in rs])
        thr = rs[0]["threads"] or args.threads
        eff = med([r["parallel_efficiency"] for r in rs])
        per_thread = bps / thr
        t_meas = PROJECT_BUILDINGS / (per_thread * PROJECT_CORES)
        mean_job = med([r["job_sum_s"] / r["buildings"] for r in rs])
        t_ideal = PROJECT_BUILDINGS * mean_job / PROJECT_CORES
        cpu_per_b = med([r["cpu_s"] / r["buildings"] for r in rs])
        result["projection"][fmt] = {
            "from_run": f"N{hi_n}-{fmt}-candidate", "buildings_per_s": bps, "threads": thr,
            "buildings_per_s_per_thread": round(per_thread, 4), "parallel_efficiency": eff,
            "buildings": PROJECT_BUILDINGS, "cores": PROJECT_CORES,
            "seconds_at_measured_efficiency": round(t_meas, 1), "seconds_at_efficiency_1": round(t_ideal, 1),
            "cpu_core_hours": round(PROJECT_BUILDINGS * cpu_per_b / 3600, 1),
            "assumption": "linear scaling per core at the measured parallel efficiency, same building mix, "
                          "one thread per core, I/O not limiting"}
        proj_lines.append(f"  {fmt:<5} {per_thread:.2f} buildings/s per thread (eff {eff:.2f}) -> "
                          f"{fmt_h(t_meas)} on {PROJECT_CORES} cores ({fmt_h(t_ideal)} at efficiency 1; "
                          f"{PROJECT_BUILDINGS * cpu_per_b / 3600:,.0f} CPU core-hours)")
    if proj_lines:
        log("")
        log(f"Projection to {PROJECT_BUILDINGS:,} buildings on one {PROJECT_CORES}-core node, from the "
            f"N={hi_n} candidate run(s). Assumption: linear scaling per core at the parallel efficiency "
            f"measured here (buildings/s / threads x {PROJECT_CORES}), the same building mix (3D BAG "
            f"LoD 2.2), one thread per core, I/O not limiting:")
        for line in proj_lines:
            log(line)

    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=1)
        log(f"\nJSON: {args.json}")
    if failed:
        log("bench_city_scale: at least one run FAILED (see above)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
