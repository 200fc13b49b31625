#!/usr/bin/env pvpython
"""Hard, unseen test parts for GeoLattice: closed triangle surfaces written as OBJ files.

Usage:  pvpython scripts/make-test-shapes.py OUTDIR [--target-triangles N] [--only NAME[,NAME..]]
        (/usr/bin/python3 works too when it can import vtkmodules and numpy)

Every part is a solid in millimetres, +z up, lowest point at z = 0 (a flat base face on the
platform), centred roughly on the z axis. The parts are hard cases for a multi-axis printer whose
nozzle is a cone of half-angle 45 deg printing curved layers that grow from the base:

  arch.obj               semi-elliptic arch (tube r 7 -> 5 mm, centre line half-span 38 mm, 50 mm
                         high) on two round foot pads: two bases whose layers must merge at the top
  genus3_block.obj       rounded block 60 x 40 x 30 mm (edge radius 3) with three disjoint
                         filleted through-holes along z, y and x (genus 3; the x and y holes are
                         horizontal, i.e. 90 deg overhangs at their roofs)
  limbs.obj              figure ~90 mm tall: two legs on foot pads, torso, neck, head and two arms
                         sticking out sideways ~17 deg below horizontal (overhanging branches)
  overhang_branches.obj  small tree ~70 mm: tapered trunk and three branches leaning 65, 75 and
                         25 deg from vertical; the 25 deg branch forks again (60 and 10 deg twigs)
  mushroom.obj           thin stem (r 5, flared to 6.5 at the base) under a cap of radius ~15 mm
                         (3x the stem) with a flat underside at z = 33: a 90 deg overhang annulus
  handle_mug.obj         solid cylinder r 18 x 40 mm (edge radius 2) with a torus handle loop on
                         its side (genus 1; the handle's lower half overhangs)
  wrench.obj             flat ring spanner 100 x 20 x 6 mm (bar 80 x 10, a ring r 10 / hole r 5 at
                         each end, edges rounded 1 mm), lying flat (genus 2): its best print
                         orientation is the one written, flat on the plate (orientation search test)
  coil.obj               three-turn coil (tube r 3, coil radius 14, pitch 12 mm) rising from a
                         post on a disc (r 18, 3.5 mm thick): its first turn passes 4 mm over the
                         disc, a gap a 45 deg nozzle fits only if the disc under it is printed
                         first (print order test)
  two_rings.obj          two rings (tori R 10, r 3) lying flat side by side, touching: as written
                         they print, which the orientation search's coarse mesh does not see
                         (orientation search test)
  thin_plate.obj         flat plate 60 x 60 x 2 mm, edges rounded 0.5 mm, lying flat: thinner
                         than the orientation search's coarse elements, so the search misjudges
                         it as placed; it prints flat in 4 layers (orientation search test)
  hollow_ball.obj        ball r 20 mm with a sealed spherical void r 14 mm (two shells: the
                         void's faces inward), cut flat at the base: the layers closing over the
                         void's roof meet in a funnel the nozzle collides in; --fill-cavities
                         prints it solid (cavity test)
  column.obj             slender column 120 mm tall (r 6 -> 5 mm) on a round pad (r 14, 4 mm):
                         standing, its top layers need the UR5 cell's arm below the floor (the
                         cell prints 112 mm standing); it prints lying (orientation search test)

Method (deterministic, no random numbers):
  1. Each part is a signed distance function (SDF, < 0 inside) built from exact primitive SDFs
     (capsules / round cones, spheres, tori, rounded boxes and cylinders, infinite cylinders for
     holes, an approximate ellipsoid) combined with the polynomial smooth-min / smooth-max of
     Quilez (blend radius k, given per part). Parts that stand on feet are cut by the platform
     plane with a smooth max (blend 0.6 mm), so they have an exactly flat base at z = 0 and a
     slightly rounded rim.
  2. The SDF is sampled on a regular grid (padding 3 cells; the plane z = 0 lies half-way between
     two grid planes; samples with |f| < 0.02 h are pushed to +-0.02 h so that no iso-vertex
     falls on a grid point), contoured at 0 with vtkFlyingEdges3D and cleaned (vtkCleanPolyData,
     exact duplicates only). The spacing h is chosen per part from a coarse pass (h0 = 2 mm) so
     that the contour has about --target-triangles triangles (default 12000; marching-cubes
     triangle counts scale as 1/h^2), but never more than min_feature / 3 (so thin parts get
     more: 12k-20k triangles; TetGen then makes ~60k-170k tets at the automatic edge length).
  3. The marching-cubes triangles (many slivers near grid points) are improved by 20 rounds of
     tangential Laplacian relaxation (each vertex moves half-way towards the mean of its
     neighbours, within the tangent plane given by the SDF gradient) each followed by a Newton
     projection back onto f = 0 (x -= f grad f / |grad f|^2, 2 steps; 4 steps before and
     after; central-difference gradient; the tangent plane is the gradient of the last step). Connectivity is never changed, so the surface stays closed and edge-manifold;
     no decimation. Afterwards every triangle normal is checked against the SDF gradient
     (no fold-overs) and the vertices' |f| is reported.
  4. Triangles are oriented outward (positive signed volume), the part is translated so that its
     lowest point is at z = 0 exactly, and the OBJ is written (coordinates %.6f mm) with a
     comment header giving the generator, part, parameters and counts.
  5. Each written file is read back (vtkOBJReader) and verified: triangles, boundary edges and
     non-manifold edges (vtkFeatureEdges), connected components (vtkPolyDataConnectivityFilter),
     volume (vtkMassProperties and the signed divergence-theorem volume of the triangles),
     inconsistently oriented edges, degenerate triangles (area <= 1e-12 diag^2, as
     core/mesh/SurfaceCheck), the smallest triangle angle, genus from V - E + F = 2 - 2g, and the
     number of base vertices (z = 0). A Markdown table is printed; the exit status is 1 if any
     part fails (open, non-manifold, inconsistent, degenerate, not one component, volume <= 0,
     wrong genus or fold-overs).

Self-intersections are not tested here; `geolattice run PART -o DIR --until mesh` runs TetGen's
intersection test (-d) on a part.
"""
import math
import os
import sys
import time

import numpy as np

from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkFlyingEdges3D, vtkTriangleFilter
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

from surface_checks import check_obj, signed_volume

GENERATOR = "scripts/make-test-shapes.py (GeoLattice)"
BASE_BLEND = 0.6          # mm, smooth max with the platform half-space z >= 0
RELAX_ROUNDS = 20
RELAX_STEP = 0.5
NEWTON_STEPS = 4          # initial and final projection
RELAX_NEWTON_STEPS = 2    # projection after each relaxation round
COARSE_H = 2.0            # mm, spacing of the pass that calibrates h

# --------------------------------------------------------------------------------------------
# SDF primitives (p: (N, 3) array of points, mm). Exact distances unless noted.
# --------------------------------------------------------------------------------------------


def _len(v):
    return np.sqrt(np.einsum("...i,...i->...", v, v))


def _unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def sd_sphere(p, c, r):
    return _len(p - np.asarray(c, float)) - r


def sd_round_cone(p, a, b, r1, r2):
    """Capsule with end radii r1 (at a) and r2 (at b): the convex hull of the two spheres."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    ba = b - a
    l2 = ba @ ba
    rr = r1 - r2
    a2 = l2 - rr * rr
    il2 = 1.0 / l2
    pa = p - a
    y = pa @ ba
    z = y - l2
    w = pa * l2 - np.outer(y, ba)
    x2 = np.einsum("ij,ij->i", w, w)
    y2 = y * y * l2
    z2 = z * z * l2
    k = np.sign(rr) * rr * rr * x2
    d_end = np.sqrt(x2 + z2) * il2 - r2
    d_start = np.sqrt(x2 + y2) * il2 - r1
    d_side = (np.sqrt(np.maximum(x2 * a2 * il2, 0.0)) + y * rr) * il2 - r1
    return np.where(np.sign(z) * a2 * z2 > k, d_end, np.where(np.sign(y) * a2 * y2 < k, d_start, d_side))


def sd_round_box(p, c, half, r):
    """Axis-aligned box of half sizes `half` centred at c, edges rounded with radius r."""
    q = np.abs(p - np.asarray(c, float)) - (np.asarray(half, float) - r)
    return _len(np.maximum(q, 0.0)) + np.minimum(q.max(axis=1), 0.0) - r


def sd_round_cylinder_z(p, c, radius, half_height, r):
    """Cylinder along z centred at c, rim edges rounded with radius r."""
    d = p - np.asarray(c, float)
    q = np.stack([np.hypot(d[:, 0], d[:, 1]) - radius + r, np.abs(d[:, 2]) - half_height + r], axis=1)
    return np.minimum(q.max(axis=1), 0.0) + _len(np.maximum(q, 0.0)) - r


def sd_torus(p, c, axis, R, r):
    """Torus centred at c with the given axis, major radius R and tube radius r."""
    w = _unit(axis)
    d = p - np.asarray(c, float)
    h = d @ w
    radial = _len(d - np.outer(h, w))
    return np.hypot(radial - R, h) - r


def sd_line_cylinder(p, point, axis, r):
    """Infinite cylinder (a through-hole) of radius r around the line point + t axis."""
    w = _unit(axis)
    d = p - np.asarray(point, float)
    return _len(d - np.outer(d @ w, w)) - r


def sd_ellipsoid(p, c, radii):
    """Approximate (Quilez) ellipsoid distance: exact on the surface, smooth, sign-correct."""
    q = (p - np.asarray(c, float))
    rad = np.asarray(radii, float)
    k0 = _len(q / rad)
    k1 = np.maximum(_len(q / (rad * rad)), 1e-12)
    return k0 * (k0 - 1.0) / k1


def sd_extrude_z(d2, z, z0, z1, r):
    """Extrusion of a 2-D distance d2 between z0 and z1, all edges rounded with radius r."""
    half = 0.5 * (z1 - z0)
    wx = d2 + r
    wz = np.abs(z - 0.5 * (z0 + z1)) - (half - r)
    return np.minimum(np.maximum(wx, wz), 0.0) + np.hypot(np.maximum(wx, 0.0), np.maximum(wz, 0.0)) - r


def smin(a, b, k):
    """Polynomial smooth minimum (union) with blend radius k (k = 0: plain min)."""
    if k <= 0:
        return np.minimum(a, b)
    h = np.clip(0.5 + 0.5 * (b - a) / k, 0.0, 1.0)
    return b + (a - b) * h - k * h * (1.0 - h)


def smax(a, b, k):
    """Polynomial smooth maximum (intersection / subtraction) with blend radius k."""
    return -smin(-a, -b, k)


def union(ds, k):
    out = ds[0]
    for d in ds[1:]:
        out = smin(out, d, k)
    return out


def on_platform(d, p):
    """Cut by the platform: keep z >= 0, flat base face at z = 0."""
    return smax(d, -p[:, 2], BASE_BLEND)


def dir_lean(lean_deg, azimuth_deg):
    """Unit vector leaning lean_deg from +z towards azimuth_deg (from +x towards +y)."""
    t, a = math.radians(lean_deg), math.radians(azimuth_deg)
    return np.array([math.sin(t) * math.cos(a), math.sin(t) * math.sin(a), math.cos(t)])


# --------------------------------------------------------------------------------------------
# The parts. Each entry: sdf(p), bounds (xmin..zmax, the solid lies inside), smallest feature
# (mm, bounds the grid spacing), description and parameters for the OBJ header, expected genus
# (of each shell) and, where not 1, the number of shells (components).
# --------------------------------------------------------------------------------------------

ARCH = dict(half_span=38.0, height=50.0, r_foot=7.0, r_top=5.0, segments=36, blend=0.0,
            pad_radius=10.0, pad_height=4.0, pad_blend=3.0)


def arch_sdf(p):
    a = ARCH
    B = a["height"] - a["r_top"]
    n = a["segments"]
    t = np.linspace(-0.08, math.pi + 0.08, n + 1)  # a little below z = 0 at both feet
    xs, zs = a["half_span"] * np.cos(t), B * np.sin(t)
    rs = a["r_top"] + (a["r_foot"] - a["r_top"]) * (1.0 - np.clip(np.sin(t), 0.0, 1.0))
    ds = [sd_round_cone(p, (xs[i], 0, zs[i]), (xs[i + 1], 0, zs[i + 1]), rs[i], rs[i + 1]) for i in range(n)]
    tube = union(ds, a["blend"])
    half_h = 0.5 * (a["pad_height"] + 1.0)
    pads = [sd_round_cylinder_z(p, (sx * a["half_span"], 0, a["pad_height"] - half_h), a["pad_radius"], half_h, 1.5)
            for sx in (-1, 1)]
    return on_platform(union([tube] + pads, a["pad_blend"]), p)


BLOCK = dict(size=(60.0, 40.0, 30.0), edge_radius=3.0, fillet=1.5,
             hole_z=dict(x=-17.0, y=-6.0, r=5.5), hole_y=dict(x=14.0, z=9.5, r=4.5),
             hole_x=dict(y=8.0, z=21.5, r=4.0))


def block_sdf(p):
    b = BLOCK
    sx, sy, sz = b["size"]
    d = sd_round_box(p, (0, 0, sz / 2), (sx / 2, sy / 2, sz / 2), b["edge_radius"])
    hz, hy, hx = b["hole_z"], b["hole_y"], b["hole_x"]
    holes = [sd_line_cylinder(p, (hz["x"], hz["y"], 0), (0, 0, 1), hz["r"]),
             sd_line_cylinder(p, (hy["x"], 0, hy["z"]), (0, 1, 0), hy["r"]),
             sd_line_cylinder(p, (0, hx["y"], hx["z"]), (1, 0, 0), hx["r"])]
    for h in holes:
        d = smax(d, -h, b["fillet"])
    return d


LIMBS = dict(foot_half=(4.5, 8.0, 3.0), foot_x=9.0, foot_y=2.5, leg_r=(5.0, 6.0), hip=(7.0, 40.0),
             torso=((0, 0, 44.0), 10.5, (0, 0, 60.0), 11.0), neck=((0, 0, 68.0), (0, 0, 77.0), 4.0),
             head=((0, 0, 81.0), 8.0), shoulder=(9.0, 60.0), hand=(38.0, 51.0), arm_r=(4.5, 3.5),
             hand_r=4.5, blend=3.0)


def limbs_sdf(p):
    L = LIMBS
    parts = []
    for s in (-1, 1):
        fx = s * L["foot_x"]
        parts.append(sd_round_box(p, (fx, L["foot_y"], L["foot_half"][2] - 1.0), L["foot_half"], 1.5))
        parts.append(sd_round_cone(p, (fx, 0, 2.0), (s * L["hip"][0], 0, L["hip"][1]), *L["leg_r"]))
        sh = (s * L["shoulder"][0], 0, L["shoulder"][1])
        hd = (s * L["hand"][0], 0, L["hand"][1])
        parts.append(sd_round_cone(p, sh, hd, *L["arm_r"]))
        parts.append(sd_sphere(p, (s * (L["hand"][0] + 1.0), 0, L["hand"][1]), L["hand_r"]))
    ta, tra, tb, trb = L["torso"]
    parts.append(sd_round_cone(p, ta, tb, tra, trb))
    parts.append(sd_round_cone(p, L["neck"][0], L["neck"][1], L["neck"][2], L["neck"][2]))
    parts.append(sd_sphere(p, *L["head"]))
    return on_platform(union(parts, L["blend"]), p)


TREE = dict(trunk=((0, 0, -2.0), 7.0, (0, 0, 30.0), 5.0),
            # (start z on the trunk axis, lean deg, azimuth deg, length, r start, r end)
            branches=[(20.0, 65.0, 0.0, 30.0, 4.5, 3.0),
                      (27.0, 75.0, 140.0, 26.0, 4.0, 2.8),
                      (29.0, 25.0, 250.0, 26.0, 4.5, 3.5)],
            # twigs from the end of branch 2: (lean, azimuth, length, r start, r end)
            twigs=[(60.0, 330.0, 18.0, 3.2, 2.2), (10.0, 250.0, 14.0, 3.2, 2.2)], blend=2.5)


def tree_sdf(p):
    T = TREE
    a, ra, b, rb = T["trunk"]
    parts = [sd_round_cone(p, a, b, ra, rb)]
    ends = []
    for z0, lean, az, length, r0, r1 in T["branches"]:
        s = np.array([0.0, 0.0, z0])
        e = s + length * dir_lean(lean, az)
        parts.append(sd_round_cone(p, s, e, r0, r1))
        ends.append(e)
    for lean, az, length, r0, r1 in T["twigs"]:
        s = ends[2]
        parts.append(sd_round_cone(p, s, s + length * dir_lean(lean, az), r0, r1))
    return on_platform(union(parts, T["blend"]), p)


MUSHROOM = dict(stem=((0, 0, -2.0), 6.5, (0, 0, 34.0), 5.0), cap_centre=(0, 0, 36.0), cap_radii=(15.0, 15.0, 9.0),
                cap_underside_z=33.0, underside_blend=1.0, blend=2.0)


def mushroom_sdf(p):
    M = MUSHROOM
    a, ra, b, rb = M["stem"]
    stem = sd_round_cone(p, a, b, ra, rb)
    cap = smax(sd_ellipsoid(p, M["cap_centre"], M["cap_radii"]), M["cap_underside_z"] - p[:, 2], M["underside_blend"])
    return on_platform(smin(stem, cap, M["blend"]), p)


MUG = dict(radius=18.0, height=40.0, edge_radius=2.0, handle_centre=(22.0, 0.0, 21.0), handle_R=10.0,
           handle_r=3.5, blend=2.0)


def mug_sdf(p):
    M = MUG
    body = sd_round_cylinder_z(p, (0, 0, M["height"] / 2), M["radius"], M["height"] / 2, M["edge_radius"])
    handle = sd_torus(p, M["handle_centre"], (0, 1, 0), M["handle_R"], M["handle_r"])
    return smin(body, handle, M["blend"])


WRENCH = dict(ring_x=40.0, ring_r=10.0, hole_r=5.0, bar_half_width=5.0, thickness=6.0, edge_radius=1.0,
              blend=3.0)


def wrench_sdf(p):
    W = WRENCH
    x, y = p[:, 0], p[:, 1]
    qx = np.abs(x) - W["ring_x"]
    qy = np.abs(y) - W["bar_half_width"]
    bar = np.hypot(np.maximum(qx, 0), np.maximum(qy, 0)) + np.minimum(np.maximum(qx, qy), 0)
    rings = [np.hypot(x - s * W["ring_x"], y) - W["ring_r"] for s in (-1, 1)]
    holes = [np.hypot(x - s * W["ring_x"], y) - W["hole_r"] for s in (-1, 1)]
    d2 = union([bar] + rings, W["blend"])
    for h in holes:
        d2 = np.maximum(d2, -h)
    return sd_extrude_z(d2, p[:, 2], 0.0, W["thickness"], W["edge_radius"])


COIL = dict(turns=3, coil_radius=14.0, tube_radius=3.0, pitch=12.0, start_height=6.0, segments=90,
            disc_radius=18.0, disc_half_height=2.0, post_radii=(3.5, 3.0), blend=1.5)


def coil_sdf(p):
    c = COIL
    n = c["segments"]
    t = np.linspace(0, c["turns"] * 2 * math.pi, n + 1)
    R = c["coil_radius"]
    pts = np.stack([R * np.cos(t), R * np.sin(t), c["start_height"] + c["pitch"] * t / (2 * math.pi)], 1)
    tube = np.min(np.stack([sd_round_cone(p, pts[i], pts[i + 1], c["tube_radius"], c["tube_radius"])
                            for i in range(n)]), 0)
    disc = sd_round_cylinder_z(p, (0, 0, 1.5), c["disc_radius"], c["disc_half_height"], 1.0)
    post = sd_round_cone(p, (R, 0, 0), (R, 0, c["start_height"]), *c["post_radii"])
    return on_platform(union([tube, disc, post], c["blend"]), p)


TWO_RINGS = dict(major_radius=10.0, tube_radius=3.0, blend=2.0)


def two_rings_sdf(p):
    R = TWO_RINGS
    half = R["major_radius"] + R["tube_radius"]  # the rings touch at x = 0
    rings = [sd_torus(p, (s * half, 0, R["tube_radius"]), (0, 0, 1), R["major_radius"],
                      R["tube_radius"]) for s in (-1, 1)]
    return union(rings, R["blend"])


THIN_PLATE = dict(size=60.0, thickness=2.0, edge_radius=0.5)


def thin_plate_sdf(p):
    T = THIN_PLATE
    half = T["size"] / 2
    return sd_round_box(p, (0, 0, T["thickness"] / 2), (half, half, T["thickness"] / 2),
                        T["edge_radius"])


COLUMN = dict(height=115.0, radius_base=6.0, radius_top=5.0, pad_radius=14.0, pad_height=4.0,
              blend=2.0)


def column_sdf(p):
    C = COLUMN
    shaft = sd_round_cone(p, (0, 0, 0), (0, 0, C["height"]), C["radius_base"], C["radius_top"])
    pad = sd_round_cylinder_z(p, (0, 0, C["pad_height"] / 2), C["pad_radius"],
                              C["pad_height"] / 2, 1.0)
    return on_platform(union([shaft, pad], C["blend"]), p)


HOLLOW_BALL = dict(radius=20.0, void_radius=14.0, centre_height=18.0)


def hollow_ball_sdf(p):
    H = HOLLOW_BALL
    c = (0, 0, H["centre_height"])
    return on_platform(np.maximum(sd_sphere(p, c, H["radius"]), -sd_sphere(p, c, H["void_radius"])), p)


def _fmt(params):
    return ", ".join(f"{k} {v}" for k, v in params.items())


PARTS = {
    "arch": dict(sdf=arch_sdf, bounds=(-49, 49, -11, 11, -1, 51), feature=5.0, genus=0,
                 what="arch/bridge: semi-elliptic tube (foot radius -> top radius) on two round foot pads, flat bases at z = 0",
                 params=ARCH),
    "genus3_block": dict(sdf=block_sdf, bounds=(-31, 31, -21, 21, -1, 31), feature=4.0, genus=3,
                         what="rounded block with three disjoint filleted through-holes along z, y and x (genus 3)",
                         params=BLOCK),
    "limbs": dict(sdf=limbs_sdf, bounds=(-45, 45, -13, 13, -1, 90), feature=3.5, genus=0,
                  what="figure: two legs on foot pads, torso, neck, head, two arms sideways and ~17 deg down",
                  params=LIMBS),
    "overhang_branches": dict(sdf=tree_sdf, bounds=(-32, 36, -30, 30, -1, 71), feature=2.2, genus=0,
                              what="tree: tapered trunk, branches leaning 65/75/25 deg, the 25 deg branch forks (60/10 deg twigs)",
                              params=TREE),
    "mushroom": dict(sdf=mushroom_sdf, bounds=(-16, 16, -16, 16, -1, 46), feature=5.0, genus=0,
                     what="mushroom: thin flared stem, cap radius ~3x stem radius with a flat underside (90 deg overhang)",
                     params=MUSHROOM),
    "handle_mug": dict(sdf=mug_sdf, bounds=(-19, 36, -19, 19, -1, 41), feature=3.5, genus=1,
                       what="solid cylinder (not hollow) with a torus handle loop on its side (genus 1)",
                       params=MUG),
    "wrench": dict(sdf=wrench_sdf, bounds=(-51, 51, -11, 11, -1, 7), feature=3.0, genus=2,
                   what="flat ring spanner lying flat: bar with a ring at each end, edges rounded (genus 2)",
                   params=WRENCH),
    "coil": dict(sdf=coil_sdf, bounds=(-19, 19, -19, 19, -1, 45), feature=3.0, genus=0,
                 what="coil: three turns rising from a post on a disc, the first turn 4 mm over the disc",
                 params=COIL),
    "two_rings": dict(sdf=two_rings_sdf, bounds=(-27, 27, -14, 14, -1, 7), feature=3.0, genus=2,
                      what="two rings (tori) lying flat side by side, touching, blended 2 mm",
                      params=TWO_RINGS),
    "column": dict(sdf=column_sdf, bounds=(-15, 15, -15, 15, -1, 121), feature=3.0, genus=0,
                   what="slender column 120 mm tall on a round pad: taller than the robot cell prints standing",
                   params=COLUMN),
    "hollow_ball": dict(sdf=hollow_ball_sdf, bounds=(-21, 21, -21, 21, -1, 39), feature=3.0, genus=0,
                        components=2,
                        what="ball with a sealed spherical void (two shells, the void's inward), cut flat at the base",
                        params=HOLLOW_BALL),
    "thin_plate": dict(sdf=thin_plate_sdf, bounds=(-31, 31, -31, 31, -1, 3), feature=2.0, genus=0,
                       what="flat plate 60 x 60 x 2 mm lying flat, edges rounded 0.5 mm",
                       params=THIN_PLATE),
}

# --------------------------------------------------------------------------------------------
# Contouring, relaxation, orientation
# --------------------------------------------------------------------------------------------


def contour(sdf, bounds, h):
    """Sample sdf on a grid of spacing h (z = 0 half-way between grid planes), contour at 0."""
    pad = 3
    lo = np.array(bounds[0::2], float)
    hi = np.array(bounds[1::2], float)
    kz0 = math.floor(lo[2] / h - 0.5) - pad
    origin = np.array([lo[0] - pad * h, lo[1] - pad * h, (kz0 + 0.5) * h])
    dims = (np.ceil((hi - origin) / h).astype(int) + pad + 1)
    xs = origin[0] + h * np.arange(dims[0])
    ys = origin[1] + h * np.arange(dims[1])
    zs = origin[2] + h * np.arange(dims[2])
    vals = np.empty(int(np.prod(dims)))
    nxy = dims[0] * dims[1]
    gx, gy = np.meshgrid(xs, ys, indexing="xy")  # x fastest
    base = np.stack([gx.ravel(), gy.ravel(), np.zeros(nxy)], axis=1)
    for k, z in enumerate(zs):  # slice by slice: modest memory
        base[:, 2] = z
        vals[k * nxy:(k + 1) * nxy] = sdf(base)
    eps = 0.02 * h
    small = np.abs(vals) < eps
    vals[small] = np.where(vals[small] < 0, -eps, eps)
    img = vtkImageData()
    img.SetDimensions(*[int(d) for d in dims])
    img.SetOrigin(*origin)
    img.SetSpacing(h, h, h)
    arr = numpy_to_vtk(vals, deep=1)
    arr.SetName("sdf")
    img.GetPointData().SetScalars(arr)
    fe = vtkFlyingEdges3D()
    fe.SetInputData(img)
    fe.SetValue(0, 0.0)
    fe.ComputeNormalsOff()
    fe.ComputeGradientsOff()
    fe.ComputeScalarsOff()
    clean = vtkCleanPolyData()
    clean.SetInputConnection(fe.GetOutputPort())
    clean.PointMergingOn()
    clean.SetTolerance(0.0)
    tri = vtkTriangleFilter()
    tri.SetInputConnection(clean.GetOutputPort())
    tri.Update()
    pd = tri.GetOutput()
    V = vtk_to_numpy(pd.GetPoints().GetData()).astype(float)
    F = vtk_to_numpy(pd.GetPolys().GetConnectivityArray()).reshape(-1, 3).astype(np.int64)
    return V, F, dims


def gradient(sdf, V, e=1e-4):
    g = np.empty_like(V)
    for i in range(3):
        d = np.zeros(3)
        d[i] = e
        g[:, i] = (sdf(V + d) - sdf(V - d)) / (2 * e)
    return g


def project(sdf, V, steps=NEWTON_STEPS):
    """Newton steps onto f = 0; returns the points and the gradient at the last step's start."""
    for _ in range(steps):
        f = sdf(V)
        g = gradient(sdf, V)
        V = V - (f / np.maximum(np.einsum("ij,ij->i", g, g), 1e-12))[:, None] * g
    return V, g


def unique_edges(F):
    e = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    e.sort(axis=1)
    return np.unique(e, axis=0)


def relax(sdf, V, F):
    E = unique_edges(F)
    n = len(V)
    deg = np.bincount(E[:, 0], minlength=n) + np.bincount(E[:, 1], minlength=n)
    V, nrm = project(sdf, V)
    for _ in range(RELAX_ROUNDS):
        c = np.empty_like(V)
        for i in range(3):
            c[:, i] = (np.bincount(E[:, 0], V[E[:, 1], i], n) + np.bincount(E[:, 1], V[E[:, 0], i], n)) / deg
        nrm /= np.maximum(_len(nrm), 1e-12)[:, None]
        d = c - V
        d -= np.einsum("ij,ij->i", d, nrm)[:, None] * nrm
        V, nrm = project(sdf, V + RELAX_STEP * d, RELAX_NEWTON_STEPS)
    V, _ = project(sdf, V)
    return V


def triangle_stats(V, F):
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    cr = np.cross(b - a, c - a)
    area = 0.5 * _len(cr)
    angs = []
    for p, q, r in ((a, b, c), (b, c, a), (c, a, b)):
        u, v = q - p, r - p
        cosang = np.einsum("ij,ij->i", u, v) / np.maximum(_len(u) * _len(v), 1e-300)
        angs.append(np.degrees(np.arccos(np.clip(cosang, -1, 1))))
    return cr, area, np.min(np.stack(angs, 1), axis=1)


def make_part(name, spec, target):
    sdf = spec["sdf"]
    t0 = time.time()
    _, Fc, _ = contour(sdf, spec["bounds"], COARSE_H)
    h = COARSE_H * math.sqrt(len(Fc) / float(target))
    h = min(h, spec["feature"] / 3.0)
    h = round(h, 3)
    V, F, dims = contour(sdf, spec["bounds"], h)
    mc_volume = signed_volume(V, F)
    if mc_volume < 0:
        F = F[:, [0, 2, 1]]
    mc_min_angle = float(triangle_stats(V, F)[2].min())
    V = relax(sdf, V, F)
    if signed_volume(V, F) < 0:
        F = F[:, [0, 2, 1]]
    cr, area, minang = triangle_stats(V, F)
    cen = V[F].mean(axis=1)
    g = gradient(sdf, cen)
    foldovers = int(np.count_nonzero(np.einsum("ij,ij->i", cr, g) <= 0))
    residual = float(np.abs(sdf(V)).max())
    V[:, 2] -= V[:, 2].min()
    V = np.round(V, 6) + 0.0
    V[np.abs(V) < 5e-7] = 0.0
    info = dict(h=h, grid=f"{dims[0]}x{dims[1]}x{dims[2]}", foldovers=foldovers, residual=residual,
                seconds=time.time() - t0, mc_min_angle=mc_min_angle)
    return V, F, info


def write_obj(path, name, spec, V, F, info):
    with open(path, "w") as f:
        f.write(f"# {name} test part generated by {GENERATOR}, z up, mm, lowest point z = 0.\n")
        f.write(f"# What: {spec['what']}.\n")
        f.write(f"# Parameters: {_fmt(spec['params'])}; base blend {BASE_BLEND} mm.\n")
        f.write(f"# Method: SDF sampled at h = {info['h']} mm (grid {info['grid']}), vtkFlyingEdges3D, "
                f"{RELAX_ROUNDS} rounds of tangential relaxation + projection onto the SDF; no decimation.\n")
        shells = spec.get("components", 1)
        f.write(f"# {len(V)} vertices, {len(F)} triangles; closed, edge-manifold, outward; genus {spec['genus']}"
                + (f" ({shells} shells)" if shells > 1 else "") + ".\n")
        np.savetxt(f, V, fmt="v %.6f %.6f %.6f")
        np.savetxt(f, F + 1, fmt="f %d %d %d")


# --------------------------------------------------------------------------------------------
# Verification of a written file
# --------------------------------------------------------------------------------------------


def verify_obj(path):
    out = check_obj(path)
    V, F = out.pop("V"), out.pop("F")
    _, area, minang = triangle_stats(V, F)
    out["min_angle"] = float(minang.min())
    out["min_angle_p1"] = float(np.percentile(minang, 1))
    out["base_vertices"] = int(np.count_nonzero(V[:, 2] == 0.0))
    return out


def main(argv):
    args = list(argv)
    target = 12000
    only = None
    if "--target-triangles" in args:
        i = args.index("--target-triangles")
        target = int(args[i + 1])
        del args[i:i + 2]
    if "--only" in args:
        i = args.index("--only")
        only = args[i + 1].split(",")
        del args[i:i + 2]
    if len(args) != 1 or args[0].startswith("-"):
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    outdir = args[0]
    os.makedirs(outdir, exist_ok=True)
    rows = []
    ok_all = True
    for name, spec in PARTS.items():
        if only and name not in only:
            continue
        V, F, info = make_part(name, spec, target)
        path = os.path.join(outdir, name + ".obj")
        write_obj(path, name, spec, V, F, info)
        v = verify_obj(path)
        shells = spec.get("components", 1)
        # V - E + F = 2 shells - 2 genus (summed over the shells): genus per shell
        ok = (v["boundary"] == 0 and v["nonmanifold"] == 0 and v["components"] == shells
              and v["inconsistent"] == 0 and v["degenerate"] == 0 and v["signed_volume"] > 0
              and v["vtk_volume"] > 0 and v["euler"] == 2 * shells * (1 - spec["genus"])
              and info["foldovers"] == 0)
        ok_all &= ok
        lo, hi = v["bbox"]
        rows.append([name + ".obj", v["triangles"], v["vertices"],
                     f"{hi[0] - lo[0]:.1f} x {hi[1] - lo[1]:.1f} x {hi[2] - lo[2]:.1f}",
                     f"[{lo[0]:.1f},{hi[0]:.1f}]x[{lo[1]:.1f},{hi[1]:.1f}]x[{lo[2]:.1f},{hi[2]:.1f}]",
                     f"{v['vtk_volume']:.0f}", f"{v['signed_volume']:.0f}", f"{v['area']:.0f}",
                     v["euler"], f"{v['genus']:g}", v["boundary"], v["nonmanifold"], v["inconsistent"],
                     v["degenerate"], v["components"], f"{info['mc_min_angle']:.2f}",
                     f"{v['min_angle']:.1f} / {v['min_angle_p1']:.1f}",
                     info["foldovers"], f"{info['residual']:.1e}", v["base_vertices"], info["h"],
                     f"{info['seconds']:.1f}", "ok" if ok else "**FAIL**"])
        print(f"{name}: done ({info['seconds']:.1f} s)", file=sys.stderr)
    head = ["file", "triangles", "vertices", "size (mm)", "bounding box (mm)", "volume vtk (mm^3)",
            "signed volume", "area (mm^2)", "V-E+F", "genus", "boundary e.", "non-manifold e.",
            "inconsistent e.", "degenerate", "components", "MC min angle (deg)", "min angle / 1% (deg)", "fold-overs",
            "max abs(f) (mm)", "base vertices", "h (mm)", "s", "check"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        print("| " + " | ".join(str(c) for c in r) + " |")
    return 0 if ok_all else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
