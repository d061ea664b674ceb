#!/usr/bin/env python3
"""The executables search no relative directory for shared libraries (cmake/install.cmake).

An RPATH or RUNPATH entry that is empty or relative is resolved against the caller's current
directory: every start would look there first for each shared library, and a library planted
there would be loaded. usage: library_paths_test.py BUILD_DIR
"""
import subprocess
import sys


def search_paths(binary):
    out = subprocess.run(["readelf", "-d", binary], check=True, capture_output=True, text=True).stdout
    paths = []
    for line in out.splitlines():
        if "(RPATH)" in line or "(RUNPATH)" in line:
            value = line.split("[", 1)[1].rsplit("]", 1)[0]
            paths.append(value)
    return paths


def main():
    build = sys.argv[1]
    bad = []
    for name in ("morphcut", "morphcut-city"):
        binary = f"{build}/tools/{name}"
        for value in search_paths(binary):
            relative = [e for e in value.split(":") if not e.startswith(("/", "$ORIGIN"))]
            if relative:
                bad.append(f"{name}: library search path {value!r} has {len(relative)} relative or empty "
                           "entries (an empty one is the current directory)")
    for b in bad:
        print(b)
    print("ok" if not bad else "FAILED")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
