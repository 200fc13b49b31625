#!/usr/bin/env bash
# Configures (once) and builds GeoLattice in build/ (Release). Extra arguments go to cmake.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ ! -f "$root/build/build.ninja" ]; then
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
fi
cmake --build "$root/build" --parallel "$(nproc)"
