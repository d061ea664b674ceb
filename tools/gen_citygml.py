#!/usr/bin/env python3
"""Writes a CityGML file of N buildings for the streaming-memory tests and benchmarks.

The buildings of a template CityGML file (default: datasets/citygml/LOD2_Buildings_v200_first10.gml,
CityGML 2.0) are repeated on a grid: copy k is shifted by `--spacing` metres in x/y and every
gml:id / xlink:href gets the suffix "_k", so ids stay unique and xlinks stay inside their copy.
The template's envelope is kept as it is (its lower corner still bounds every copy, which is
what the reader's CityJSON transform is anchored at). The file is streamed out; memory does not
depend on N.

    python3 tools/gen_citygml.py 50000 /tmp/city_50k.gml
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_TEMPLATE = os.path.join(HERE, "..", "datasets", "citygml", "LOD2_Buildings_v200_first10.gml")
MEMBER = re.compile(r"<(?:\w+:)?cityObjectMember\b.*?</(?:\w+:)?cityObjectMember>", re.S)
COORDS = re.compile(r"(<(?:\w+:)?(?:posList|pos)\b[^>]*>)([^<]*)(</(?:\w+:)?(?:posList|pos)>)")
IDS = re.compile(r'((?:gml:id|xlink:href)="#?)([^"]+)(")')


def compile_member(text):
    """A member as literal pieces and coordinate lists; ids get a "\\0" placeholder for the copy index."""
    parts, at = [], 0
    for m in COORDS.finditer(text):
        parts.append(IDS.sub(lambda i: i.group(1) + i.group(2) + "_\0" + i.group(3), text[at:m.end(1)]))
        parts.append([float(v) for v in m.group(2).split()])
        at = m.start(3)
    parts.append(IDS.sub(lambda i: i.group(1) + i.group(2) + "_\0" + i.group(3), text[at:]))
    return parts


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("count", type=int, help="number of buildings to write")
    ap.add_argument("out", help="output .gml")
    ap.add_argument("--template", default=DEFAULT_TEMPLATE)
    ap.add_argument("--spacing", type=float, default=150.0, help="grid step between template copies (m)")
    args = ap.parse_args()

    # latin-1 maps bytes 1:1, so the template's own encoding declaration stays true.
    with open(args.template, "rb") as f:
        src = f.read().decode("latin-1")
    members = list(MEMBER.finditer(src))
    if not members:
        sys.exit(f"{args.template}: no cityObjectMember")
    head, tail = src[: members[0].start()], src[members[-1].end():]
    compiled = [compile_member(m.group(0)) for m in members]
    per_row = 100

    with open(args.out, "wb") as out:
        out.write(head.encode("latin-1"))
        for b in range(args.count):
            copy, member = divmod(b, len(compiled))
            dx, dy = (copy % per_row) * args.spacing, (copy // per_row) * args.spacing
            tag = str(copy)
            chunk = []
            for p in compiled[member]:
                if isinstance(p, str):
                    chunk.append(p.replace("\0", tag))
                else:
                    chunk.append(" ".join("%.3f" % (v + (dx if i % 3 == 0 else dy if i % 3 == 1 else 0.0))
                                          for i, v in enumerate(p)))
            chunk.append("\n  ")
            out.write("".join(chunk).encode("latin-1"))
        out.write(tail.encode("latin-1"))


if __name__ == "__main__":
    main()
