#!/usr/bin/env bash
# Checks that every tracked C++ file is formatted by .clang-format (clang-format 14, Debian 12).
# With --fix, formats them instead. Called by scripts/test.sh (so by .ci/run).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mapfile -t files < <(git ls-files '*.cpp' '*.cxx' '*.h' 2>/dev/null || find core filters apps tests bench -name '*.cpp' -o -name '*.cxx' -o -name '*.h')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
if ! clang-format --dry-run --Werror "${files[@]}" 2> /tmp/geolattice-format.$$; then
  grep -m 20 "error:" /tmp/geolattice-format.$$ >&2 || true
  rm -f /tmp/geolattice-format.$$
  echo "check-format: files above are not formatted; run scripts/check-format.sh --fix" >&2
  exit 1
fi
rm -f /tmp/geolattice-format.$$
echo "check-format: ${#files[@]} C++ files formatted"
