#!/usr/bin/env bash
# The installed tree (cmake/install.cmake): `cmake --install` into a temporary prefix, the tree
# moved elsewhere (relocatable), the installed morphcut-city run on the installed demo tile and
# its output validated, and a program outside the project built against the installed package
# (find_package(morphcut), morphcut::core) and run.
# usage: tests/install/run_install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$(cd "$1" && pwd)"
src="$(cd "$2" && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/mc-install.XXXXXX")"
trap 'rc=$?; if [ "$rc" -eq 0 ]; then rm -rf "$tmp"; else echo "work directory kept: $tmp"; fi' EXIT

cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log"
mv "$tmp/prefix" "$tmp/moved"  # relocatable: nothing refers to the install prefix
p="$tmp/moved"
for f in bin/morphcut-city bin/morphcut lib/libmc_core.a lib/cmake/morphcut/morphcutConfig.cmake \
         include/morphcut/core/decompose.hpp share/morphcut/lod.yaml share/morphcut/docs/algorithm.md \
         share/morphcut/datasets/3dbag_5910.city.json; do
  [ -e "$p/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done
"$p/bin/morphcut-city" --version | grep -q "0.3.0" || { echo "FAIL: --version"; exit 1; }

# The demo from the installed tree.
mkdir -p "$tmp/demo"
set +e
"$p/bin/morphcut-city" "$p/share/morphcut/datasets/3dbag_5910.city.json" -c "$p/share/morphcut/lod.yaml" \
  -o "$tmp/demo/demo.city.json" -q --threads 2
rc=$?
set -e
[ "$rc" -le 1 ] || { echo "FAIL: installed morphcut-city exited $rc"; exit 1; }
"$p/bin/morphcut-city" validate "$tmp/demo/demo.level-0.01.city.json" > "$tmp/demo/validate.txt" ||
  { tail -3 "$tmp/demo/validate.txt"; echo "FAIL: validate"; exit 1; }

# A consumer of the package.
cmake -S "$src/tests/install/consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$p" > "$tmp/consumer.log" 2>&1 ||
  { tail -20 "$tmp/consumer.log"; echo "FAIL: configuring the consumer"; exit 1; }
cmake --build "$tmp/consumer" -j 2 >> "$tmp/consumer.log" 2>&1 ||
  { tail -20 "$tmp/consumer.log"; echo "FAIL: building the consumer"; exit 1; }
"$tmp/consumer/consumer"
echo "PASS: installed tree relocated, demo run and validated, consumer built and run"
