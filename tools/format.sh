#!/usr/bin/env bash
# Applies the project's style (.clang-format) to every C++ source, or with --check lists the files
# that differ from it and exits 1. The ctest `Style.SourcesAreFormatted` runs the check.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=apply
[ "${1:-}" = "--check" ] && mode=check
command -v clang-format >/dev/null || { echo "format.sh: clang-format is not installed (tools/setup-deps.sh)" >&2; exit 2; }
dirs=(core io config massing output report pipeline tools tests)
globs=()
for d in "${dirs[@]}"; do globs+=("$d/*.cpp" "$d/*.hpp"); done
mapfile -t files < <(git ls-files -- "${globs[@]}" 2>/dev/null ||
  find "${dirs[@]}" \( -name '*.cpp' -o -name '*.hpp' \))
if [ "$mode" = apply ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
bad=0
for f in "${files[@]}"; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then echo "not formatted: $f"; bad=1; fi
done
[ $bad = 0 ] && echo "format.sh: ${#files[@]} sources formatted"
exit $bad
