#!/usr/bin/env bash
# Fresh Debian 12 machine -> installed packages, built GeoLattice, and the whole pipeline run on
# the bundled default model (testdata/bunny.obj scaled to 80 mm), results in out/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
"$root/build/bin/geolattice" run "$root/testdata/bunny.obj" --fit-size 80 --base-tolerance 1 -o "$root/out"
cat <<MSG

Done. Outputs are in $root/out:
  tets.vtu     the tetrahedral mesh of the part
  fields.vtu   the mesh with the geodesic fields Gamma, Alpha, Beta (point data)
  report.json  per-stage timings and counts
Open them in ParaView:  paraview $root/out/fields.vtu
or load the filters into ParaView (Tools > Manage Plugins > Load New):
  $root/build/lib/paraview-5.11/plugins/GeoLattice/GeoLattice.so
MSG
