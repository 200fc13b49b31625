"""Renders the robot cell at one moment of a real print (needs an X server, like render_docs.py):

    xvfb-run -a -s "-screen 0 1280x1024x24" pvpython pvpython/render_cell.py OUTDIR [PNG] \
        [--moment F] [--size W H]

OUTDIR is the output of `geolattice run` (print_part*.script, toolpath.vtp, report.json); PNG
defaults to docs/images/ur5_cell.png. The moment is the `movej` of the program whose waypoint is
nearest to F (default 0.5) of the print: a `movej` restates the joints of the point the robot is
at, i.e. the waypoint reached by the preceding `movel` (the i-th `movel`, counted over all files
in order, goes to toolpath point i; the first `movej` to point 0).

The robot is drawn from those joints by forward kinematics with the same DH convention as
core/robot/URKinematics.cpp; the part (toolpath printed so far, coloured by LayerId; the rest
faint) is placed by flange pose * part-on-flange (the program's set_tcp) * 0.001 (mm -> m). The
script checks that the current toolpath point lands on the nozzle tip (distance printed, must be
< 1e-3 m) and that FK * TCP reproduces the program's movel pose; it exits with 1 otherwise.
"""
import argparse
import glob
import json
import math
import os
import re

import numpy as np
from paraview import simple
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import (vtkArrowSource, vtkConeSource, vtkCubeSource, vtkCylinderSource,
                                          vtkSphereSource)
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from geolattice_view import white_view

HERE = os.path.dirname(os.path.abspath(__file__))

# Standard DH tables (metres, rad), as ur5Model() / ur5eModel() in core/robot/URKinematics.cpp.
ROBOTS = {
    "ur5": dict(d=[0.089159, 0, 0, 0.10915, 0.09465, 0.0823], a=[0, -0.425, -0.39225, 0, 0, 0]),
    "ur5e": dict(d=[0.1625, 0, 0, 0.1333, 0.0997, 0.0996], a=[0, -0.425, -0.3922, 0, 0, 0]),
}
ALPHA = [math.pi / 2, 0, 0, math.pi / 2, -math.pi / 2, 0]
TIP_TOLERANCE = 1e-3  # m

GREY = [0.62, 0.64, 0.67]
DARK = [0.25, 0.27, 0.30]


# --- kinematics -------------------------------------------------------------------------------

def dh(theta, d, a, alpha):
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    return np.array([[ct, -st * ca, st * sa, a * ct],
                     [st, ct * ca, -ct * sa, a * st],
                     [0, sa, ca, d],
                     [0, 0, 0, 1.0]])


def forward_frames(robot, q):
    """Frames 0..6 of the DH chain (4x4, base frame); frame 6 is the flange."""
    frames = [np.eye(4)]
    for i in range(6):
        frames.append(frames[-1] @ dh(q[i], robot["d"][i], robot["a"][i], ALPHA[i]))
    return frames


def pose_matrix(p):
    """URScript pose p[x, y, z, rx, ry, rz] (rotation vector) -> 4x4."""
    t = np.eye(4)
    rv = np.asarray(p[3:], float)
    angle = np.linalg.norm(rv)
    if angle > 1e-12:
        k = rv / angle
        kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
        t[:3, :3] = np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * kx @ kx
    t[:3, 3] = p[:3]
    return t


# --- the program --------------------------------------------------------------------------------

NUMBERS = r"\[([^\]]*)\]"


def program_files(outdir, report):
    names = (report.get("program") or {}).get("files")
    if names:
        return [os.path.join(outdir, n) for n in names]

    def number(path):
        m = re.search(r"_(\d+)\.script$", path)
        return int(m.group(1)) if m else 0
    return sorted(glob.glob(os.path.join(outdir, "print_part*.script")), key=number)


def parse_program(files):
    """movej's as (waypoint index, joints, file), movel poses by waypoint index, the TCP pose."""
    movej, movel, tcp = [], [None], None
    for path in files:
        with open(path) as f:
            for line in f:
                s = line.strip()
                if s.startswith("movel("):
                    movel.append([float(v) for v in re.search(NUMBERS, s).group(1).split(",")])
                elif s.startswith("movej("):
                    q = [float(v) for v in re.search(NUMBERS, s).group(1).split(",")]
                    movej.append((len(movel) - 1, q, os.path.basename(path)))
                elif s.startswith("set_tcp(") and tcp is None:
                    tcp = [float(v) for v in re.search(NUMBERS, s).group(1).split(",")]
    if not movej or tcp is None:
        raise SystemExit("render_cell: no movej / set_tcp in %s" % ", ".join(files))
    return movej, movel, tcp


# --- geometry (base frame, metres) ------------------------------------------------------------

def transformed(source, matrix):
    t = vtkTransform()
    t.SetMatrix(np.asarray(matrix, float).ravel().tolist())
    f = vtkTransformPolyDataFilter()
    f.SetInputConnection(source.GetOutputPort())
    f.SetTransform(t)
    f.Update()
    out = vtkPolyData()
    out.DeepCopy(f.GetOutput())
    return out


def frame_along(axis, origin):
    """4x4 whose y column is the unit axis (vtkCylinderSource's axis), placed at origin."""
    y = np.asarray(axis, float) / np.linalg.norm(axis)
    helper = np.array([1.0, 0, 0]) if abs(y[0]) < 0.9 else np.array([0, 0, 1.0])
    x = np.cross(helper, y)
    x /= np.linalg.norm(x)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = x, y, np.cross(x, y), origin
    return m


def cylinder(p0, p1, radius, sides=40):
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    src = vtkCylinderSource()
    src.SetResolution(sides)
    src.SetRadius(radius)
    src.SetHeight(np.linalg.norm(p1 - p0))
    return transformed(src, frame_along(p1 - p0, (p0 + p1) / 2))


def joint_housing(origin, axis, radius, length):
    axis = np.asarray(axis, float)
    return cylinder(origin - axis * length / 2, origin + axis * length / 2, radius)


def sphere(center, radius):
    src = vtkSphereSource()
    src.SetCenter(*center)
    src.SetRadius(radius)
    src.SetThetaResolution(32)
    src.SetPhiResolution(24)
    src.Update()
    return src.GetOutput()


def cone(apex, axis, height, radius):
    """Cone with its apex at `apex`, its body along `axis` (unit)."""
    axis = np.asarray(axis, float)
    src = vtkConeSource()
    src.SetResolution(48)
    src.SetHeight(height)
    src.SetRadius(radius)
    src.SetCenter(*(np.asarray(apex) + axis * height / 2))
    src.SetDirection(*(-axis))  # vtkConeSource points its apex along Direction
    src.Update()
    return src.GetOutput()


def box(bounds, matrix):
    src = vtkCubeSource()
    src.SetBounds(*bounds)
    return transformed(src, matrix)


def arrow(origin, axis, length):
    src = vtkArrowSource()
    src.SetShaftRadius(0.025)
    src.SetTipRadius(0.07)
    src.SetTipLength(0.2)
    src.SetShaftResolution(24)
    src.SetTipResolution(24)
    x = np.asarray(axis, float)
    helper = np.array([0, 0, 1.0]) if abs(x[2]) < 0.9 else np.array([1.0, 0, 0])
    y = np.cross(helper, x)
    y /= np.linalg.norm(y)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = x * length, y * length, np.cross(x, y) * length, origin
    return transformed(src, m)


def merged(pieces):
    app = vtkAppendPolyData()
    for p in pieces:
        app.AddInputData(p)
    app.Update()
    return app.GetOutput()


def polyline_data(points, segments, cell_arrays):
    """Line cells between consecutive points listed in `segments` (index of the segment's end)."""
    pd = vtkPolyData()
    pts = vtkPoints()
    pts.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(points), deep=1))
    pd.SetPoints(pts)
    conn = np.column_stack([segments - 1, segments]).ravel().astype(np.int64)
    offsets = np.arange(0, 2 * len(segments) + 1, 2, dtype=np.int64)
    lines = vtkCellArray()
    lines.SetData(numpy_support.numpy_to_vtkIdTypeArray(offsets, deep=1),
                  numpy_support.numpy_to_vtkIdTypeArray(conn, deep=1))
    pd.SetLines(lines)
    for name, values in cell_arrays.items():
        arr = numpy_support.numpy_to_vtk(np.ascontiguousarray(values[segments]), deep=1)
        arr.SetName(name)
        pd.GetCellData().AddArray(arr)
    return pd


# --- ParaView display ---------------------------------------------------------------------------

def producer(polydata):
    p = simple.PVTrivialProducer()
    p.GetClientSideObject().SetOutput(polydata)
    p.UpdatePipeline()
    return p


def show_solid(source, view, color, opacity=1.0, specular=0.25):
    rep = simple.Show(source, view)
    rep.ColorArrayName = ["POINTS", ""]  # solid colour
    rep.DiffuseColor = color
    rep.AmbientColor = color
    rep.Specular = specular
    rep.Opacity = opacity
    return rep


def label(view, text, size=16, bold=False, color=(0, 0, 0), corner="Upper Left Corner", at=None,
          justification="Left", backdrop=False):
    """2D text in a corner, or next to a 3D point: at = (camera, point, (dx, dy) pixels)."""
    t = simple.Text(Text=text)
    rep = simple.Show(t, view)
    rep.FontSize = size
    rep.Bold = int(bold)
    rep.Color = list(color)
    if at is None:
        rep.WindowLocation = corner
    else:
        cam, point, offset = at
        x, y = cam.project(point)
        rep.WindowLocation = "Any Location"
        rep.Position = [x + offset[0] / cam.size[0], y + offset[1] / cam.size[1]]
    if justification:
        rep.Justification = justification
    if backdrop:
        rep.BackgroundColor = [1, 1, 1, 0.8]
        rep.ShowBorder = "Always"
        rep.BorderColor = [1, 1, 1]
    return rep


def view_for(size):
    view = white_view(size, axes=False)
    view.EnableRenderOnInteraction = 0
    return view


class Camera:
    """A perspective camera looking from `position` at `focal` with +z up; projects points to
    normalized viewport coordinates (0..1, origin lower left) for the labels."""

    def __init__(self, view, focal, position, size, angle=30.0):
        self.focal, self.position, self.size, self.angle = (np.asarray(focal, float), np.asarray(position, float),
                                                            size, angle)
        cam = view.GetActiveCamera()
        cam.SetFocalPoint(*self.focal)
        cam.SetPosition(*self.position)
        cam.SetViewUp(0, 0, 1)
        cam.SetViewAngle(angle)
        f = self.focal - self.position
        self.forward = f / np.linalg.norm(f)
        r = np.cross(self.forward, [0, 0, 1.0])
        self.right = r / np.linalg.norm(r)
        self.up = np.cross(self.right, self.forward)

    def project(self, point):
        v = np.asarray(point, float) - self.position
        depth = v @ self.forward
        t = math.tan(math.radians(self.angle) / 2)
        aspect = self.size[0] / self.size[1]
        return 0.5 + 0.5 * (v @ self.right) / (depth * t * aspect), 0.5 + 0.5 * (v @ self.up) / (depth * t)


# --- main ---------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("outdir", help="output directory of `geolattice run` (full pipeline)")
    ap.add_argument("png", nargs="?", default=os.path.join(HERE, "..", "docs", "images", "ur5_cell.png"))
    ap.add_argument("--moment", type=float, default=0.5,
                    help="fraction of the print: the movej nearest to it is drawn (default 0.5)")
    ap.add_argument("--size", type=int, nargs=2, default=[1200, 900], metavar=("W", "H"))
    args = ap.parse_args()

    report_path = os.path.join(args.outdir, "report.json")
    report = json.load(open(report_path)) if os.path.exists(report_path) else {}
    prog = report.get("program") or {}
    robot_name = prog.get("robot", "ur5")
    robot = ROBOTS[robot_name]
    tip = np.array(prog.get("nozzle_tip_mm", [0.0, -400.0, 300.0]), float) / 1000.0  # m
    nozzle_axis = np.array(prog.get("nozzle_axis", [0.0, 0.0, 1.0]), float)
    nozzle_axis /= np.linalg.norm(nozzle_axis)
    scale = 0.001  # toolpath mm -> m (RobotCell::partScale)

    files = program_files(args.outdir, report)
    movej, movel, tcp = parse_program(files)

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(args.outdir, "toolpath.vtp"))
    reader.Update()
    toolpath = reader.GetOutput()
    pts_mm = numpy_support.vtk_to_numpy(toolpath.GetPoints().GetData()).astype(float)
    pd = toolpath.GetPointData()
    kind = numpy_support.vtk_to_numpy(pd.GetArray("MoveKind")).astype(int)
    layer = numpy_support.vtk_to_numpy(pd.GetArray("LayerId")).astype(float)
    normals = numpy_support.vtk_to_numpy(pd.GetArray("NozzleAxis") or pd.GetArray("Normals")).astype(float)
    n_points = len(pts_mm)
    if len(movel) != n_points:
        raise SystemExit("render_cell: %d movel + start in the program but %d toolpath points: different runs?"
                         % (len(movel), n_points))

    # The moment: the movej nearest to the requested fraction of the print.
    target = args.moment * (n_points - 1)
    index, q, script = min(movej, key=lambda m: abs(m[0] - target))

    frames = forward_frames(robot, q)
    flange = frames[6]
    part = flange @ pose_matrix(tcp)  # part (platform) frame in the base frame
    base_pts = (part[:3, :3] @ (scale * pts_mm).T).T + part[:3, 3]

    # Checks: the point being printed is at the nozzle tip with its axis along the nozzle, and
    # FK * TCP is the movel pose of this waypoint.
    tip_distance = float(np.linalg.norm(base_pts[index] - tip))
    n_base = part[:3, :3] @ (normals[index] / np.linalg.norm(normals[index]))
    axis_error = math.degrees(math.acos(max(-1.0, min(1.0, float(n_base @ nozzle_axis)))))
    print("render_cell: %s, movej in %s at waypoint %d of %d (%.0f%% of the print)"
          % (robot_name, script, index, n_points, 100.0 * index / (n_points - 1)))
    print("render_cell: joints (deg) %s" % ", ".join("%.1f" % math.degrees(v) for v in q))
    print("render_cell: toolpath point %d -> base (%.6f, %.6f, %.6f) m; nozzle tip (%.3f, %.3f, %.3f) m"
          % ((index,) + tuple(base_pts[index]) + tuple(tip)))
    print("render_cell: tip distance %.3e m (tolerance %.0e), point axis vs nozzle axis %.4f deg"
          % (tip_distance, TIP_TOLERANCE, axis_error))
    ok = tip_distance < TIP_TOLERANCE
    if movel[index] is not None:
        pose_error = float(np.abs(part - pose_matrix(movel[index]))[:3, :].max())
        print("render_cell: FK * TCP vs the program's movel pose of that waypoint: max entry difference %.2e"
              % pose_error)
        ok = ok and pose_error < 1e-4
    if not ok:
        raise SystemExit("render_cell: the pose does not put the toolpath point at the nozzle tip: "
                         "FK or frame convention is wrong")

    # --- scene ---------------------------------------------------------------------------------
    origins = [f[:3, 3] for f in frames]
    axes = [f[:3, 2] for f in frames]  # joint i + 1 turns about z_i through origin i
    robot_pieces = [cylinder([0, 0, 0], [0, 0, 0.06], 0.075)]  # base
    housings = {1: (0.060, 0.15), 2: (0.050, 0.12), 3: (0.042, 0.10), 4: (0.042, 0.10), 5: (0.042, 0.09)}
    for i, (radius, length) in housings.items():  # joints 2..6 (sizes roughly as on the UR5)
        robot_pieces.append(joint_housing(origins[i], axes[i], radius, length))
    links = [joint_housing(origins[0] + [0, 0, 0.09], axes[0], 0.055, 0.10)]  # joint 1
    for i in range(6):
        if np.linalg.norm(origins[i + 1] - origins[i]) > 1e-6:
            r = 0.045 if i < 3 else 0.036
            links.append(cylinder(origins[i], origins[i + 1], r))
    joint_balls = [sphere(o, 0.028) for o in origins[1:6]]
    flange_disc = cylinder(origins[6] - 0.008 * axes[6], origins[6], 0.0315)

    # Platform: a 5 mm plate under the part frame's z = 0, around the toolpath's footprint, and the
    # adapter that holds it 40 mm in front of the flange.
    lo, hi = pts_mm.min(axis=0), pts_mm.max(axis=0)
    margin = 12.0
    plate_bounds = [scale * (lo[0] - margin), scale * (hi[0] + margin), scale * (lo[1] - margin),
                    scale * (hi[1] + margin), -0.005, 0.0]
    plate = box(plate_bounds, part)
    part_origin = part[:3, 3]
    adapter = cylinder(origins[6], part_origin - 0.005 * part[:3, 2], 0.02)

    # Fixed nozzle: cone apex at the tip, body up along the nozzle axis, heater block above, and a
    # bracket to a post that stands on the floor.
    top = tip + nozzle_axis * 0.056
    nozzle = [cone(tip, nozzle_axis, 0.008, 0.005),                                             # nozzle
              cylinder(tip + nozzle_axis * 0.008, tip + nozzle_axis * 0.020, 0.011),             # heater block
              cylinder(tip + nozzle_axis * 0.020, tip + nozzle_axis * 0.026, 0.004),             # heat break
              cylinder(tip + nozzle_axis * 0.026, top, 0.011)]                                   # heat sink
    post_xy = tip[:2] + np.array([0.35, -0.25])
    bracket = [cylinder([post_xy[0], post_xy[1], 0], [post_xy[0], post_xy[1], top[2] + 0.02], 0.025),
               cylinder([post_xy[0], post_xy[1], top[2] - 0.01], top - [0, 0, 0.01], 0.008),
               cylinder([post_xy[0], post_xy[1], -0.01], [post_xy[0], post_xy[1], 0], 0.08)]

    # Toolpath printed so far (coloured by LayerId) and the rest (faint).
    seg = np.arange(1, n_points)
    arrays = {"LayerId": layer, "MoveKind": kind.astype(float)}
    done = seg[(seg <= index) & (kind[seg] != 2)]
    rest = seg[(seg > index) & (kind[seg] != 2)]
    printed = polyline_data(base_pts, done, arrays)
    remaining = polyline_data(base_pts, rest, arrays)

    floor = box([-0.40, 0.55, -0.85, 0.25, -0.012, -0.010], np.eye(4))

    # Cameras: a 3/4 view of the cell from the nozzle's open side, and a close-up of nozzle, part
    # and platform looking along the part's y axis (the toolpath's thin direction), from that side.
    def right_of(direction):
        r = np.cross([0, 0, 1.0], direction)
        return r / np.linalg.norm(r)

    main_dir = np.array([-1.0, -1.3, 0.8])
    main_dir /= np.linalg.norm(main_dir)
    main_focal = np.array([0.10, -0.33, 0.26]) + 0.02 * right_of(main_dir)
    part_y = part[:3, 1] if part[:3, 1] @ main_dir > 0 else -part[:3, 1]
    zoom_dir = part_y + [0, 0, 0.2]
    zoom_dir /= np.linalg.norm(zoom_dir)
    zoom_focal = part_origin + part[:3, :3] @ [scale * (lo[0] + hi[0]) / 2, 0, scale * hi[2] / 2]

    # --- views ---------------------------------------------------------------------------------
    W, H = args.size
    split = 0.62
    main_view = view_for([int(W * split), H])
    zoom_view = view_for([W - int(W * split), H])

    srcs = dict(robot=producer(merged(robot_pieces)), links=producer(merged(links)),
                balls=producer(merged(joint_balls)), flange=producer(merged([flange_disc, adapter])),
                plate=producer(plate), nozzle=producer(merged(nozzle)), bracket=producer(merged(bracket)),
                printed=producer(printed), remaining=producer(remaining), floor=producer(floor))
    rgb = ([0.85, 0.1, 0.1], [0.1, 0.6, 0.1], [0.1, 0.25, 0.9])
    base_axes = [producer(arrow([0, 0, 0], e, 0.25)) for e in np.eye(3)]
    part_axes = [producer(arrow(part_origin, part[:3, i], 0.03)) for i in range(3)]

    printing = kind != 2  # air moves have LayerId -1
    layer_range = [float(layer[printing].min()), float(layer[printing].max())]
    # In the close-up the arm is translucent: it is behind and below the part.
    for view, line_width, axes_srcs, arm in ((main_view, 2.0, base_axes, 1.0), (zoom_view, 3.0, part_axes, 0.3)):
        show_solid(srcs["robot"], view, DARK, opacity=arm)
        show_solid(srcs["links"], view, GREY, opacity=arm)
        show_solid(srcs["balls"], view, [0.45, 0.47, 0.50], opacity=arm)
        show_solid(srcs["flange"], view, [0.35, 0.45, 0.60])
        show_solid(srcs["plate"], view, [0.80, 0.72, 0.55])
        show_solid(srcs["nozzle"], view, [0.85, 0.33, 0.10], specular=0.5)
        show_solid(srcs["bracket"], view, [0.55, 0.40, 0.30])
        show_solid(srcs["floor"], view, [0.93, 0.93, 0.93], specular=0.0)
        rest_rep = show_solid(srcs["remaining"], view, [0.55, 0.55, 0.55], opacity=0.3)
        rest_rep.LineWidth = 1.0
        rep = simple.Show(srcs["printed"], view)
        simple.ColorBy(rep, ("CELLS", "LayerId"))
        lut = simple.GetColorTransferFunction("LayerId")
        lut.ApplyPreset("Turbo", True)
        lut.RescaleTransferFunction(*layer_range)
        rep.LineWidth = line_width
        rep.RenderLinesAsTubes = 1
        for src, color in zip(axes_srcs, rgb):
            show_solid(src, view, color)

    bar = simple.GetScalarBar(simple.GetColorTransferFunction("LayerId"), zoom_view)
    bar.Title = "LayerId (printed so far)"
    bar.ComponentTitle = ""
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Horizontal"
    bar.Position = [0.12, 0.04]
    bar.ScalarBarLength = 0.76
    bar.AutomaticLabelFormat = 0
    bar.LabelFormat = "%.0f"
    bar.RangeLabelFormat = "%.0f"
    bar.AddRangeLabels = 0
    bar.Visibility = 1

    deg = ", ".join("%.0f" % math.degrees(v) for v in q)
    label(main_view, "%s holds the part; the nozzle is fixed" % robot_name.upper(), size=22, bold=True)
    label(main_view,
          "base frame (m): nozzle tip (%.2f, %.2f, %.2f), nozzle axis (%g, %g, %g)\n"
          "part frame = flange * p[%s]  (set_tcp)\n"
          "toolpath mm x 0.001; waypoint %d of %d (movej in %s)\n"
          "joints (deg): %s\n"
          "toolpath point to nozzle tip: %.1e m"
          % (tuple(tip) + tuple(nozzle_axis) + (", ".join("%g" % v for v in tcp), index, n_points, script, deg,
                                                 tip_distance)),
          size=13, corner="Lower Left Corner", justification="Left")
    main_cam = Camera(main_view, main_focal, main_focal + main_dir * 2.15, main_view.ViewSize)
    zoom_cam = Camera(zoom_view, zoom_focal, zoom_focal + zoom_dir * 0.40, zoom_view.ViewSize)
    for i, name in enumerate("xyz"):
        label(main_view, name, size=16, color=rgb[i], at=(main_cam, 0.27 * np.eye(3)[i], (4, 4)))
    label(main_view, "robot base (0, 0, 0)", size=14, at=(main_cam, [0, 0, 0], (-60, -70)))
    label(main_view, "fixed nozzle", size=14, at=(main_cam, top, (12, 22)), backdrop=True)
    label(main_view, "part on the platform\n(close-up on the right)", size=14, at=(main_cam, part_origin, (-175, 8)),
          backdrop=True)

    label(zoom_view, "close-up at the nozzle", size=18, bold=True)
    label(zoom_view, "nozzle tip", size=14, at=(zoom_cam, tip, (22, 8)))
    label(zoom_view, "printed so far\n(the rest faint)", size=14, at=(zoom_cam, base_pts[index], (-200, -110)))
    label(zoom_view, "platform = part frame\nx y z: red green blue", size=14, at=(zoom_cam, part_origin, (-215, -150)))
    label(zoom_view, "flange + %g mm adapter" % round(1000 * np.linalg.norm(tcp[:3]), 1), size=14, at=(zoom_cam, origins[6], (-150, -60)), backdrop=True)

    layout = simple.CreateLayout("cell")
    layout.SplitHorizontal(0, split)
    layout.AssignView(1, main_view)
    layout.AssignView(2, zoom_view)
    layout.SetSize(W, H)
    os.makedirs(os.path.dirname(os.path.abspath(args.png)), exist_ok=True)
    simple.SaveScreenshot(args.png, layout, ImageResolution=[W, H], SeparatorWidth=2, SeparatorColor=[0.6, 0.6, 0.6])
    print("render_cell: wrote %s" % os.path.abspath(args.png))


if __name__ == "__main__":
    main()
