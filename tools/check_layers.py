#!/usr/bin/env python3
"""Checks the layering of the source tree (docs/design.md, "Layers"): a module's files include
only headers of the modules below it, never above or beside it.

    core  <-  io, config  <-  massing  <-  output  <-  report  <-  pipeline  <-  tools

usage: tools/check_layers.py [ROOT]     exit 0 when every #include "x/..." of every module is
allowed, 1 with the offending lines listed."""
import os, re, sys

ROOT = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# What each module may include (itself always).
ALLOWED = {
    "core": set(),
    "io": {"core"},
    "config": {"core"},
    "massing": {"core", "io"},
    "output": {"core", "io", "massing"},
    "report": {"core", "io", "config", "massing", "output"},
    "pipeline": {"core", "io", "config", "massing", "output", "report"},
    "tools": {"core", "io", "config", "massing", "output", "report", "pipeline", "tools"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')

bad = []
for module, allowed in ALLOWED.items():
    for dirpath, _, files in os.walk(os.path.join(ROOT, module)):
        for f in files:
            if not f.endswith((".cpp", ".hpp")):
                continue
            path = os.path.join(dirpath, f)
            for n, line in enumerate(open(path, encoding="utf-8"), 1):
                m = INCLUDE.match(line)
                if m and m.group(1) != module and m.group(1) not in allowed and m.group(1) in ALLOWED:
                    bad.append(f"{os.path.relpath(path, ROOT)}:{n}: {module} includes {m.group(1)}: {line.strip()}")
for b in bad:
    print(b)
print(f"layers: {'ok' if not bad else str(len(bad)) + ' includes against the layering'}")
sys.exit(1 if bad else 0)
