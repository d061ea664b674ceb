#!/usr/bin/python3
"""tools/render-parts on a real run (docs/massing.md, "Rendering parts by role"):
morphcut-city on tests/tools/data/render_parts_3dbag.city.json, three buildings cut from
datasets/3dbag/3dbag_5910.city.json (the 3D BAG v21.09.08 tile 5910, CC BY 4.0 © 3D BAG / TU Delft;
see datasets/README.md) with their BuildingParts and vertices renumbered, nothing else changed:
  NL.IMBAG.Pand.0503100000031316  12 parts at 0.01: main, setback, rooftop (two slabs on a base)
  NL.IMBAG.Pand.0503100000021433   6 parts: main, wing, setback, rooftop
  NL.IMBAG.Pand.0503100000018410   4 parts: main, rooftop (a dormer), annex
then render-parts renders every building of the level-0.01 file (CityJSON, and the CityJSONSeq
run's), with the input as a ghost, and checks each PNG: present, 1600 x 1200, not blank, and in
its drawing panels (left of the legend and table) the legend colour of every role its parts have
and of no other role. Also: parts with morphcut_mass/morphcut_mass_role are coloured by mass role;
--random is random.Random(seed).sample(sorted ids) and repeatable; --min-parts filters; --sheet;
an unknown id exits 1.
Usage: render_parts_test.py BUILD_DIR SOURCE_DIR. Exit 77 when matplotlib is missing (run it with
Debian's python3, the tool's interpreter; python3-matplotlib, tools/setup-deps.sh)."""
import importlib.machinery
import importlib.util
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile

BUILDINGS = {
    "NL.IMBAG.Pand.0503100000031316": {"main", "setback", "rooftop"},
    "NL.IMBAG.Pand.0503100000021433": {"main", "wing", "setback", "rooftop"},
    "NL.IMBAG.Pand.0503100000018410": {"main", "rooftop", "annex"},
}
PRESENT_MIN = 150  # pixels of a role's exact colour (a label box alone is ~300 px in each panel)
ABSENT_MAX = 20  # stray antialiased pixels that happen to match


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def run(cmd, ok=(0,)):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode not in ok:
        fail(f"{' '.join(cmd)} exited {r.returncode}:\n{r.stdout}\n{r.stderr}")
    return r


def load_tool(path):
    loader = importlib.machinery.SourceFileLoader("render_parts", path)
    spec = importlib.util.spec_from_loader("render_parts", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


def roles_in_pixels(png, tool, sheet=False):
    """Roles whose exact legend colour covers >= PRESENT_MIN pixels of the drawing (a building's
    panels left of the legend and table; a sheet's thumbnails below its legend), and the roles
    with more than ABSENT_MAX but fewer such pixels; fails on a missing, wrong-sized or blank
    image."""
    import matplotlib.image as mpimg
    import numpy as np

    if not os.path.exists(png):
        fail(f"missing {png}")
    im = mpimg.imread(png)
    if sheet:
        px = np.round(im[int(tool.SHEET_HEAD_IN * tool.DPI) + 2 :, :, :3] * 255).astype(np.int16)
    else:
        if im.shape[:2] != (1200, 1600):
            fail(f"{png}: {im.shape[1]}x{im.shape[0]}, expected 1600x1200")
        px = np.round(im[:, : int(tool.PANELS_X1 * im.shape[1]), :3] * 255).astype(np.int16)
    nonwhite = float((px.min(axis=2) < 245).mean())
    colours = len(np.unique(px.reshape(-1, 3)[::7], axis=0))
    if nonwhite < 0.05 or colours < 50:
        fail(f"{png}: blank ({nonwhite:.1%} non-white pixels, {colours} colours)")
    found, stray = set(), {}
    for role, hexc in tool.ROLE_COLOURS.items():
        rgb = np.round(tool.hex_rgb(hexc) * 255).astype(np.int16)
        n = int((np.abs(px - rgb).max(axis=2) <= 2).sum())
        if n >= PRESENT_MIN:
            found.add(role)
        elif n > ABSENT_MAX:
            stray[role] = n
    return found, stray, nonwhite


def check_roles(png, tool, want, what):
    found, stray, nonwhite = roles_in_pixels(png, tool)
    if found != want or stray:
        fail(f"{png} ({what}): role colours {sorted(found)} (stray {stray}), expected {sorted(want)}")
    print(f"ok {os.path.basename(png)} ({what}): {sorted(found)}, {nonwhite:.0%} drawn")


def main():
    build, source = sys.argv[1], sys.argv[2]
    if importlib.util.find_spec("matplotlib") is None or importlib.util.find_spec("numpy") is None:
        print(f"SKIPPED: matplotlib is not installed for {sys.executable} (python3-matplotlib)")
        return 77
    tool_path = os.path.join(source, "tools", "render-parts")
    data = os.path.join(source, "tests", "tools", "data", "render_parts_3dbag.city.json")
    cli = os.path.join(build, "tools", "morphcut-city")
    tool = load_tool(tool_path)
    tmp = tempfile.mkdtemp(prefix="mc_render_parts_")
    try:
        # the pipeline, CityJSON and CityJSONSeq outputs
        stems = {}
        for kind, ext in (("json", ".city.json"), ("seq", ".city.jsonl")):
            d = os.path.join(tmp, kind)
            os.makedirs(d)
            run([cli, data, "-o", os.path.join(d, "r" + ext), "-q", "--no-html", "--no-gpkg", "--threads", "1"], ok=(0, 1))
            stems[kind] = (os.path.join(d, "r.level-0.01" + ext), os.path.join(d, "r" + ext))
        level, annotated = stems["json"]
        with open(level) as f:
            city = json.load(f)["CityObjects"]
        for bid, want in BUILDINGS.items():
            roles = {city[c]["attributes"]["morphcut_role"] for c in city[bid]["children"] if "-mc" in c}
            if roles != want:
                fail(f"{bid}: roles {sorted(roles)} at 0.01, the test expects {sorted(want)} (update BUILDINGS)")

        # every building, with the input ghost
        out = os.path.join(tmp, "png")
        r = run([tool_path, level, "--all", "--input", annotated, "--out", out])
        written = sorted(os.path.basename(p) for p in r.stdout.split())
        if written != sorted(b + ".png" for b in BUILDINGS):
            fail(f"--all wrote {written}")
        for bid, want in BUILDINGS.items():
            check_roles(os.path.join(out, bid + ".png"), tool, want, "CityJSON, ghost")

        # the CityJSONSeq level file gives the same pictures' colours
        out_seq = os.path.join(tmp, "png_seq")
        run([tool_path, stems["seq"][0], "--id", "NL.IMBAG.Pand.0503100000018410", "--input", stems["seq"][1], "--out", out_seq])
        check_roles(os.path.join(out_seq, "NL.IMBAG.Pand.0503100000018410.png"), tool, BUILDINGS["NL.IMBAG.Pand.0503100000018410"],
                    "CityJSONSeq")

        # masses: colour by mass role (tower and podium), not by the parts' roles
        bid = "NL.IMBAG.Pand.0503100000031316"
        with open(level) as f:
            doc = json.load(f)
        for c in doc["CityObjects"][bid]["children"]:
            a = doc["CityObjects"][c].get("attributes", {})
            if "morphcut_index" in a:
                grounded_low = a["morphcut_z_max"] < 5.0
                a["morphcut_mass"] = 1 if grounded_low else 0
                a["morphcut_mass_role"] = "podium" if grounded_low else "tower"
        mass_level = os.path.join(tmp, "mass.level-0.01.city.json")
        with open(mass_level, "w") as f:
            json.dump(doc, f)
        out_mass = os.path.join(tmp, "png_mass")
        run([tool_path, mass_level, "--id", bid, "--out", out_mass])
        check_roles(os.path.join(out_mass, bid + ".png"), tool, {"tower", "podium"}, "masses")

        # --random: random.Random(seed).sample(sorted ids, n), the same twice; --min-parts
        ids = sorted(BUILDINGS)
        r1 = run([tool_path, level, "--random", "2", "--seed", "7", "--out", os.path.join(tmp, "r1")]).stdout.split()
        r2 = run([tool_path, level, "--random", "2", "--seed", "7", "--out", os.path.join(tmp, "r2")]).stdout.split()
        want = [b + ".png" for b in random.Random(7).sample(ids, 2)]
        if [os.path.basename(p) for p in r1] != want or [os.path.basename(p) for p in r2] != want:
            fail(f"--random 2 --seed 7: {r1} then {r2}, expected {want}")
        r = run([tool_path, level, "--random", "3", "--seed", "1", "--min-parts", "5", "--sheet", "--out", os.path.join(tmp, "sheet")])
        sheet = r.stdout.split()
        if [os.path.basename(p) for p in sheet] != ["sheet.png"]:
            fail(f"--sheet wrote {sheet}")
        found, _, _ = roles_in_pixels(sheet[0], tool, sheet=True)
        # --min-parts 5 keeps 31316 and 21433 (18410 has 4 parts, the only annex)
        if found != BUILDINGS["NL.IMBAG.Pand.0503100000031316"] | BUILDINGS["NL.IMBAG.Pand.0503100000021433"]:
            fail(f"sheet with --min-parts 5: role colours {sorted(found)}")
        print(f"ok sheet: {sorted(found)}")

        r = run([tool_path, level, "--id", "no-such-building", "--out", os.path.join(tmp, "none")], ok=(1,))
        print("ok unknown id: exit 1")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print("render_parts: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
