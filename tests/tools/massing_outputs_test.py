#!/usr/bin/env python3
"""Massing outputs of a real run (docs/massing.md): morphcut-city on two 3D BAG buildings, then
  - OUT.morphcut.graph.jsonl loaded with networkx: one graph per building and level, nodes with
    role and geometry, edges with kind and shared area; cycles and edges match the building's
    morphcut_graph_* features; the CSV has the same features;
  - OUT.morphcut.gpkg read with ogrinfo: layers buildings and parts, feature counts, the CSV's
    columns, the source CRS;
  - a second run writes byte-identical graph and GeoPackage files.
Usage: massing_outputs_test.py BUILD_DIR SOURCE_DIR. Exit 77 when networkx or ogrinfo is missing."""
import csv
import filecmp
import json
import os
import shutil
import subprocess
import sys
import tempfile

ROLES = {"main", "wing", "annex", "podium", "tower", "setback", "rooftop"}
KINDS = {"stacked", "side", "inclined"}


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def main():
    build, source = sys.argv[1], sys.argv[2]
    try:
        import networkx as nx
    except ImportError:
        print("SKIPPED: python3-networkx is not installed")
        return 77
    if not shutil.which("ogrinfo"):
        print("SKIPPED: ogrinfo (gdal-bin) is not installed")
        return 77
    data = os.path.join(source, "datasets", "3dbag", "3dbag_b2.city.json")
    if not os.path.exists(data):
        print("SKIPPED: no", data)
        return 77
    cli = os.path.join(build, "tools", "morphcut-city")
    tmp = tempfile.mkdtemp(prefix="mc_massing_")
    try:
        outs = []
        for run in ("a", "b"):
            d = os.path.join(tmp, run)
            os.makedirs(d)
            out = os.path.join(d, "b2.city.json")
            r = subprocess.run([cli, data, "-o", out, "-q", "--no-html", "--threads", "1"], capture_output=True, text=True)
            if r.returncode not in (0, 1):
                fail(f"morphcut-city exited {r.returncode}: {r.stderr}")
            outs.append(os.path.join(d, "b2"))
        stem = outs[0]
        graph_path, gpkg_path, csv_path = stem + ".morphcut.graph.jsonl", stem + ".morphcut.gpkg", stem + ".morphcut.csv"
        for p in (graph_path, gpkg_path, csv_path):
            if not os.path.exists(p):
                fail(f"missing {p}")
        leftovers = [f for f in os.listdir(os.path.dirname(stem)) if ".tmp." in f]
        if leftovers:
            fail(f"temp files left: {leftovers}")

        rows = {r["id"]: r for r in csv.DictReader(open(csv_path, newline=""))}
        lines = [json.loads(line) for line in open(graph_path)]
        if len(lines) != len(rows):
            fail(f"{len(lines)} graph lines for {len(rows)} CSV rows")
        graphs = 0
        for b in lines:
            row = rows[b["id"]]
            if b["status"] not in ("ok", "partial"):
                continue
            feats = b["features"]
            if feats is None:
                fail(f"{b['id']}: no features")
            for k, v in feats.items():
                csv_v = row[k]
                want = str(v).lower() if isinstance(v, bool) else v
                if isinstance(v, float):
                    if abs(float(csv_v) - v) > 1e-6:
                        fail(f"{b['id']}: {k} {csv_v} in the CSV, {v} in the graph")
                elif str(want) != csv_v:
                    fail(f"{b['id']}: {k} {csv_v} in the CSV, {v} in the graph")
            for level in b["levels"]:
                g = nx.Graph()
                for n in level["nodes"]:
                    if n["role"] not in ROLES:
                        fail(f"{n['id']}: role {n['role']}")
                    if not (n["z_max"] > n["z_min"] and n["footprint_area"] > 0 and n["volume"] > 0):
                        fail(f"{n['id']}: bad geometry {n}")
                    g.add_node(n["id"], **n)
                for e in level["edges"]:
                    if e["kind"] not in KINDS or not e["shared_area"] > 0:
                        fail(f"bad edge {e}")
                    if e["source"] not in g or e["target"] not in g:
                        fail(f"edge to an unknown node {e}")
                    if e["kind"] == "stacked" and e.get("upper") not in (e["source"], e["target"]):
                        fail(f"stacked edge without its upper part {e}")
                    g.add_edge(e["source"], e["target"], kind=e["kind"], shared_area=e["shared_area"])
                mains = sum(1 for _, d in g.nodes(data=True) if d["role"] in ("main", "podium"))
                if mains < 1:
                    fail(f"{b['id']} level {level['threshold']}: no main or podium part")
                if level["threshold"] == feats["morphcut_massing_level"]:
                    if g.number_of_edges() != feats["morphcut_graph_edges"]:
                        fail(f"{b['id']}: {g.number_of_edges()} edges in networkx, {feats['morphcut_graph_edges']} reported")
                    cycles = len(nx.cycle_basis(g))
                    if cycles != feats["morphcut_graph_cycles"]:
                        fail(f"{b['id']}: {cycles} cycles in networkx, {feats['morphcut_graph_cycles']} reported")
                graphs += 1
        if graphs == 0:
            fail("no graph loaded")

        info = subprocess.run(["ogrinfo", "-ro", "-so", "-al", gpkg_path], capture_output=True, text=True)
        if info.returncode != 0:
            fail(f"ogrinfo failed: {info.stderr}")
        text = info.stdout
        for needle in ("Layer name: buildings", "Layer name: parts", f"Feature Count: {len(rows)}", "Amersfoort / RD New",
                       "morphcut_tiers: Integer64", "morphcut_courtyards", "lon: Real", "role: String",
                       "z_min: Real", "convexity: Real", "Geometry: Multi Polygon"):
            if needle not in text:
                fail(f"ogrinfo: no '{needle}' in\n{text}")
        parts = sum(len(n["nodes"]) for b in lines for n in b["levels"])
        if f"Feature Count: {parts}" not in text:
            fail(f"ogrinfo: parts layer should hold {parts} features:\n{text}")
        # Part values are written rounded as in the CityJSON attributes (output/rounding.hpp):
        # volumes to 1e-6 m³, convexities to 1e-9, so their last bits carry no noise.
        import sqlite3
        con = sqlite3.connect(gpkg_path)
        for part, volume, convexity in con.execute("SELECT part, volume, convexity FROM parts"):
            if abs(volume * 1e6 - round(volume * 1e6)) > 1e-3 or abs(convexity * 1e9 - round(convexity * 1e9)) > 1e-3:
                fail(f"GeoPackage part {part}: volume {volume!r} or convexity {convexity!r} not rounded")
        con.close()
        # Deterministic: the second run's files are the same bytes.
        for suffix in (".morphcut.graph.jsonl", ".morphcut.gpkg", ".morphcut.csv"):
            if not filecmp.cmp(outs[0] + suffix, outs[1] + suffix, shallow=False):
                fail(f"{suffix} differs between two runs")
        print(f"OK: {graphs} graphs loaded with networkx {nx.__version__}; GeoPackage with {len(rows)} buildings, {parts} parts")
        return 0
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
