#!/usr/bin/env pvpython
"""Example printhead for GeoLattice: a slim extended (volcano-style) nozzle as one closed mesh.

Usage:  pvpython scripts/make-printhead.py OUT.obj [--segments N] [--max-edge MM] [--outside]
        (/usr/bin/python3 works too when it can import vtkmodules and numpy)

Frame: the nozzle frame. The tip (centre of the orifice face) is the origin, the nozzle axis is
+z (from the tip up into the printhead), millimetres. The solid is a body of revolution about
the z axis with this profile (radius r at height z; r = 0 closes the profile on the axis):

  part                          r (mm)             z (mm)            notes
  orifice face                  0 -> 0.5           0                 flat face, diameter 1.0 mm
  tip cone                      0.5 -> 2.0         0 -> 1.788        40 deg half-angle: dz = 1.5 / tan 40
  nozzle barrel (hex, slim)     2.0                1.788 -> 8        diameter 4 (a slim extended nozzle)
  heat break / long barrel      3.0                8 -> 30           diameter 6 (flat step at z = 8)
  heater block                  10.0               30 -> 40          16 x 12 x 10 mm block, modelled by its
                                                                     circumscribed cylinder: r = sqrt(8^2 + 6^2)
  heat sink                     11.0               40 -> 70          diameter 22
  carriage / holder             28.284             70 -> 100         40 x 40 x 30 mm box, modelled by its
                                                                     circumscribed cylinder: r = 20 sqrt 2
  top face                      28.284 -> 0        100               flat

The two blocks are not round; replacing each by its circumscribed cylinder keeps the printhead a
single body of revolution (one closed, edge-manifold surface) and is conservative for collision
tests: the model contains the real block whatever its orientation about the axis. Widest cone
from the orifice rim (0.5, 0): the heater block corner (10, 30) is 17.6 deg off the axis, the
holder corner (28.284, 70) 21.6 deg, far inside a 45 deg nozzle cone.

Construction (no VTK filter needed, deterministic): the profile polyline is subdivided so that
no piece is longer than --max-edge (default 2 mm); every profile vertex off the axis becomes a
ring of --segments vertices (default 48) at angles 2 pi j / N (the first at +x), the two
on-axis profile ends become single pole vertices (the tip (0, 0, 0) and (0, 0, 100)), rings are
joined by two triangles per quad and the poles by triangle fans. Vertices lie on the true
circles (the polygonal section is inscribed: at most r (1 - cos(pi / N)) inside, 0.06 mm at the
holder for N = 48); --outside scales every ring by 1 / cos(pi / N) so that the mesh contains the
round solid instead (then the orifice face has radius 0.5 / cos(pi / N)). (vtkRotationalExtrusionFilter
would need vtkCleanPolyData to merge the seam and the axis copies and leaves collapsed quads
there; building the rings directly gives the same surface without that step.)

Verification (printed as a Markdown table; exit status 1 on failure): the written OBJ is read
back with vtkOBJReader; triangles, boundary and non-manifold edges (vtkFeatureEdges), connected
components (vtkPolyDataConnectivityFilter), inconsistently oriented edges, degenerate triangles,
volume (vtkMassProperties and the signed divergence-theorem volume; outward = positive; compared
with the exact volume of the polygonal solid of revolution), genus from V - E + F = 2 - 2g (0),
lowest point z = 0 on the axis and the radius of the face at z = 0 (0.5).
"""
import math
import os
import sys

import numpy as np

from surface_checks import check_obj, signed_volume

GENERATOR = "scripts/make-printhead.py (GeoLattice)"

TIP_FACE_RADIUS = 0.5
TIP_CONE_HALF_ANGLE_DEG = 40.0
NOZZLE_RADIUS = 2.0
NOZZLE_TOP = 8.0
BARREL_RADIUS = 3.0
BARREL_TOP = 30.0
HEATER_BLOCK = (16.0, 12.0, 10.0)     # x, y, z size (mm), centred on the axis, from z = BARREL_TOP
HEAT_SINK_RADIUS = 11.0
HEAT_SINK_TOP = 70.0
HOLDER_BOX = (40.0, 40.0, 30.0)       # x, y, z size (mm), centred on the axis, from z = HEAT_SINK_TOP


def profile():
    """Corner points (r, z) of the profile, from the tip on the axis to the top on the axis."""
    cone_top = (NOZZLE_RADIUS - TIP_FACE_RADIUS) / math.tan(math.radians(TIP_CONE_HALF_ANGLE_DEG))
    heater_r = math.hypot(HEATER_BLOCK[0] / 2, HEATER_BLOCK[1] / 2)
    heater_top = BARREL_TOP + HEATER_BLOCK[2]
    holder_r = math.hypot(HOLDER_BOX[0] / 2, HOLDER_BOX[1] / 2)
    top = HEAT_SINK_TOP + HOLDER_BOX[2]
    return [(0.0, 0.0), (TIP_FACE_RADIUS, 0.0), (NOZZLE_RADIUS, cone_top), (NOZZLE_RADIUS, NOZZLE_TOP),
            (BARREL_RADIUS, NOZZLE_TOP), (BARREL_RADIUS, BARREL_TOP), (heater_r, BARREL_TOP),
            (heater_r, heater_top), (HEAT_SINK_RADIUS, heater_top), (HEAT_SINK_RADIUS, HEAT_SINK_TOP),
            (holder_r, HEAT_SINK_TOP), (holder_r, top), (0.0, top)]


def subdivide(corners, max_edge):
    pts = [corners[0]]
    for (r0, z0), (r1, z1) in zip(corners[:-1], corners[1:]):
        n = max(1, int(math.ceil(math.hypot(r1 - r0, z1 - z0) / max_edge - 1e-9)))
        for k in range(1, n + 1):
            t = k / n
            pts.append((r0 + t * (r1 - r0), z0 + t * (z1 - z0)))
    return pts


def revolve(pts, n, outside):
    """Closed triangle mesh of the profile pts (first and last on the axis) revolved about z."""
    assert pts[0][0] == 0.0 and pts[-1][0] == 0.0 and all(r > 0 for r, _ in pts[1:-1])
    scale = 1.0 / math.cos(math.pi / n) if outside else 1.0
    ang = 2 * math.pi * np.arange(n) / n
    c, s = np.cos(ang), np.sin(ang)
    V = [np.array([[0.0, 0.0, pts[0][1]]])]
    for r, z in pts[1:-1]:
        V.append(np.stack([scale * r * c, scale * r * s, np.full(n, z)], axis=1))
    V.append(np.array([[0.0, 0.0, pts[-1][1]]]))
    V = np.concatenate(V)
    rings = len(pts) - 2
    top = len(V) - 1
    j = np.arange(n)
    jn = (j + 1) % n
    F = [np.stack([np.zeros(n, int), 1 + jn, 1 + j], axis=1)]          # bottom fan (normal -z)
    for i in range(rings - 1):
        a, b = 1 + i * n, 1 + (i + 1) * n
        F.append(np.stack([a + j, a + jn, b + jn], axis=1))
        F.append(np.stack([a + j, b + jn, b + j], axis=1))
    last = 1 + (rings - 1) * n
    F.append(np.stack([last + j, last + jn, np.full(n, top)], axis=1))  # top fan (normal +z)
    return V, np.concatenate(F).astype(np.int64)


def polygon_revolution_volume(pts, n, scale):
    """Exact volume of the profile revolved as an N-gon: (N/2) sin(2 pi/N) x the circular volume."""
    vol = 0.0
    for (r0, z0), (r1, z1) in zip(pts[:-1], pts[1:]):
        vol += math.pi * (z1 - z0) * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0  # frustum (signed by dz)
    return vol * scale * scale * n * math.sin(2 * math.pi / n) / (2 * math.pi), vol


def main(argv):
    args = list(argv)
    n, max_edge, outside = 48, 2.0, False
    if "--segments" in args:
        i = args.index("--segments")
        n = int(args[i + 1])
        del args[i:i + 2]
    if "--max-edge" in args:
        i = args.index("--max-edge")
        max_edge = float(args[i + 1])
        del args[i:i + 2]
    if "--outside" in args:
        outside = True
        args.remove("--outside")
    if len(args) != 1 or args[0].startswith("-") or n < 8 or not max_edge > 0:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    out = args[0]
    corners = profile()
    pts = subdivide(corners, max_edge)
    V, F = revolve(pts, n, outside)
    if signed_volume(V, F) < 0:  # cannot happen with the winding above; kept as a guard
        F = F[:, [0, 2, 1]]
    V = np.round(V, 6) + 0.0
    V[np.abs(V) < 5e-7] = 0.0
    if os.path.dirname(out):
        os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as f:
        f.write(f"# printhead (slim extended nozzle) generated by {GENERATOR}; nozzle frame: tip at the origin, "
                f"axis +z, mm.\n")
        f.write("# Profile corners (r, z) mm: " + " ".join(f"({r:.4g},{z:.4g})" for r, z in corners) + ".\n")
        f.write(f"# Parameters: tip face diameter {2 * TIP_FACE_RADIUS}, tip cone half-angle {TIP_CONE_HALF_ANGLE_DEG} deg, "
                f"nozzle d {2 * NOZZLE_RADIUS} to z {NOZZLE_TOP}, barrel d {2 * BARREL_RADIUS} to z {BARREL_TOP}, "
                f"heater block {HEATER_BLOCK} and holder box {HOLDER_BOX} as circumscribed cylinders, "
                f"heat sink d {2 * HEAT_SINK_RADIUS} to z {HEAT_SINK_TOP}; segments {n}, max profile edge {max_edge} mm, "
                f"rings {'circumscribed (--outside)' if outside else 'on the circles'}.\n")
        f.write(f"# {len(V)} vertices, {len(F)} triangles; closed, edge-manifold, outward, genus 0.\n")
        np.savetxt(f, V, fmt="v %.6f %.6f %.6f")
        np.savetxt(f, F + 1, fmt="f %d %d %d")

    # ---- verification of the written file
    c = check_obj(out)
    V, F, lo, hi = c["V"], c["F"], c["bbox"][0], c["bbox"][1]
    base = V[V[:, 2] == 0.0]
    face_r = float(np.hypot(base[:, 0], base[:, 1]).max())
    tip_on_axis = bool(np.any(np.all(base == 0.0, axis=1)))
    expected_vol, round_vol = polygon_revolution_volume(pts, n, 1.0 / math.cos(math.pi / n) if outside else 1.0)
    want_r = TIP_FACE_RADIUS / math.cos(math.pi / n) if outside else TIP_FACE_RADIUS
    svol = c["signed_volume"]
    ok = (c["boundary"] == 0 and c["nonmanifold"] == 0 and c["components"] == 1 and c["inconsistent"] == 0
          and c["degenerate"] == 0 and svol > 0 and c["genus"] == 0 and lo[2] == 0.0 and tip_on_axis and abs(face_r - want_r) < 1e-5
          and abs(svol - expected_vol) < 1e-6 * expected_vol)
    head = ["file", "triangles", "vertices", "bounding box (mm)", "volume vtk (mm^3)", "signed volume",
            "N-gon solid volume", "round solid volume", "V-E+F", "genus", "boundary e.", "non-manifold e.",
            "inconsistent e.", "degenerate", "components", "lowest z", "tip (0,0,0) on mesh",
            "face radius at z=0", "check"]
    row = [os.path.basename(out), len(F), len(V),
           f"[{lo[0]:.3f},{hi[0]:.3f}]x[{lo[1]:.3f},{hi[1]:.3f}]x[{lo[2]:.3f},{hi[2]:.3f}]",
           f"{c['vtk_volume']:.1f}", f"{svol:.1f}", f"{expected_vol:.1f}", f"{round_vol:.1f}", c["euler"],
           f"{c['genus']:g}", c["boundary"], c["nonmanifold"], c["inconsistent"], c["degenerate"],
           c["components"], f"{lo[2]:g}", "yes" if tip_on_axis else "no",
           f"{face_r:.6f}", "ok" if ok else "**FAIL**"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    print("| " + " | ".join(str(c) for c in row) + " |")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
