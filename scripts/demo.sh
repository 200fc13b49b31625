#!/usr/bin/env bash
# Fresh Debian 12 machine -> installed packages, built GeoLattice, and the whole pipeline run on
# the bundled default model (testdata/bunny.obj scaled to 80 mm), results in out/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
# As placed, the bunny's nozzle meets the build plate at 13 % of the toolpath stations (the
# collision gate, exit 4, writes no program); the orientation search and a 30° axis tilt make it
# collision-free (tests/cli/test_demo.py runs this line).
"$root/build/bin/geolattice" run "$root/testdata/bunny.obj" --fit-size 80 --orient auto -o "$root/out"
cat <<MSG

Done. Outputs are in $root/out:
  tets.vtu       the tetrahedral mesh of the part
  fields.vtu     the mesh with the geodesic fields Gamma, Alpha, Beta (point data)
  layers.vtp     the curved layers (colour by LayerId)
  lattice.vtp    the lattice infill of every layer (colour by SubgraphId or PrintOrder)
  skeleton.vtp   the skeleton tree of the lattice pieces, sequence.csv the printing order
  toolpath.vtp   the printing path (colour by MoveKind or AxisTilt); toolpath.pvd replays the print
  print_part*.script  the UR5 program (URScript; split into numbered files at air moves)
  toolpath.gcode the 5-axis G-code (A-C table), waypoints.csv every point with its axis
  report.json    per-stage timings, counts and the collision checks (toolpath.collision_free)
Open them in ParaView:  paraview $root/out/toolpath.pvd   (press Play)
or load the filters into ParaView (Tools > Manage Plugins > Load New):
  $root/build/lib/paraview-5.11/plugins/GeoLattice/GeoLattice.so
MSG
