#!/usr/bin/env python3
"""The longest functions of the C++ sources (a top-level definition: a line at column 0 that opens
a brace and is not a namespace, class, struct or enum, up to its closing brace at column 0).

usage: tools/function_lengths.py [ROOT] [--top N]   (default: core io config massing output report
                                                       pipeline tools; the 15 longest)"""
import os, re, sys

args = sys.argv[1:]
top = 15
if "--top" in args:
    top = int(args[args.index("--top") + 1])
    del args[args.index("--top"):args.index("--top") + 2]
root = args[0] if args else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
dirs = ["core", "io", "config", "massing", "output", "report", "pipeline", "tools"]
skip = re.compile(r"^(namespace|class|struct|enum|union|extern|template\s*<[^>]*>\s*(class|struct))\b")
out = []
for d in dirs:
    for dp, _, files in os.walk(os.path.join(root, d)):
        for f in files:
            if not f.endswith(".cpp"):
                continue
            lines = open(os.path.join(dp, f), encoding="utf-8").read().split("\n")
            i = 0
            while i < len(lines):
                l = lines[i]
                if not l or l[0].isspace() or l.startswith(("#", "//", "}", "using", "static_assert")) or skip.match(l):
                    i += 1
                    continue
                # a declaration at column 0: read on to its '{' (a definition) or ';'
                j, sig = i, l
                while not sig.rstrip().endswith(("{", ";")) and j + 1 < len(lines) and j - i < 8:
                    j += 1
                    sig += " " + lines[j].strip()
                if sig.rstrip().endswith("{") and "(" in sig and "=" not in sig.split("(")[0]:
                    k = j + 1
                    while k < len(lines) and not lines[k].startswith("}"):
                        k += 1
                    name = re.search(r"([\w:~]+)\s*\(", sig)
                    out.append((k - i + 1, os.path.relpath(os.path.join(dp, f), root), name.group(1) if name else sig[:40]))
                    i = k
                i += 1
for n, f, name in sorted(out, reverse=True)[:top]:
    print(f"{n:5d}  {f}  {name}")
