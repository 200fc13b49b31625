#!/usr/bin/env python3
"""The robot program keeps the arm and the part above the floor it stands on. The bundled 30 mm
cube's path was followed in an IK branch with the elbow 225 mm below the robot's base plane
(reachable for the kinematics, not for a robot on a table). Every movej of the written program is
checked with forward kinematics written here from the UR5's published DH parameters, not the
solver's; every movel target (the TCP is the part's plate frame) with the whole part's bounding
box."""
import glob
import json
import math
import os
import re
import subprocess
import tempfile
import unittest

SOURCE = os.environ["GEOLATTICE_SOURCE_DIR"]
CLI = os.environ["GEOLATTICE_CLI"]

# UR5 (CB3), standard DH: d, a, alpha per joint (m, rad).
UR5_D = [0.089159, 0, 0, 0.10915, 0.09465, 0.0823]
UR5_A = [0, -0.425, -0.39225, 0, 0, 0]
UR5_ALPHA = [math.pi / 2, 0, 0, math.pi / 2, -math.pi / 2, 0]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def joint_heights(q):
    """Base-frame z of the origins of the DH frames 1..6."""
    t = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    heights = []
    for theta, d, a, alpha in zip(q, UR5_D, UR5_A, UR5_ALPHA):
        ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
        t = matmul(t, [[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st],
                       [0, sa, ca, d], [0, 0, 0, 1]])
        heights.append(t[2][3])
    return heights


def rotation(rx, ry, rz):
    """The rotation matrix of a UR rotation vector (axis times angle, rad)."""
    angle = math.sqrt(rx * rx + ry * ry + rz * rz)
    if angle < 1e-12:
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    x, y, z = rx / angle, ry / angle, rz / angle
    c, s, v = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return [[c + x * x * v, x * y * v - z * s, x * z * v + y * s],
            [y * x * v + z * s, c + y * y * v, y * z * v - x * s],
            [z * x * v - y * s, z * y * v + x * s, c + z * z * v]]


class RobotCellTest(unittest.TestCase):
    def test_the_arm_and_the_part_stay_above_the_floor(self):
        with tempfile.TemporaryDirectory() as out:
            result = subprocess.run([CLI, "run", os.path.join(SOURCE, "testdata", "cube.obj"),
                                     "--fit-size", "30", "-o", out, "-q"],
                                    capture_output=True, text=True, timeout=600)
            self.assertEqual(result.returncode, 0, result.stderr)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            program = report["program"]
            # The arm's lowest surface (core/robot/ArmCapsules.h: every joint origin below is
            # inside a capsule of 41 mm radius or more) and the part's stay 20 mm up.
            self.assertGreaterEqual(program["lowest_arm_height_mm"], 20.0)
            scripts = []
            for name in sorted(glob.glob(os.path.join(out, "print_part*.script"))):
                with open(name) as f:
                    scripts.append(f.read())
            movejs = [[float(v) for v in m.group(1).split(",")]
                      for text in scripts for m in re.finditer(r"movej\(\[([^\]]*)\]", text)]
            self.assertGreater(len(movejs), 10)
            lowest = min(min(joint_heights(q)[1:]) for q in movejs)
            self.assertGreaterEqual(lowest, 0.02 + 0.041 - 1e-6)
            self.assertGreaterEqual(lowest * 1000, program["lowest_arm_height_mm"] + 41 - 1e-3)
            # The part: the corners of its whole bounding box (mm, plate frame) at every movel
            # target. The solver holds the part printed so far, so this bound is the stricter.
            self.assertGreaterEqual(program["lowest_part_height_mm"], 20.0)
            x0, x1, y0, y1, z0, z1 = report["input"]["bounds_mm"]
            corners = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
            lowest_part = math.inf
            for text in scripts:
                for m in re.finditer(r"movel\(p\[([^\]]*)\]", text):
                    x, y, z, rx, ry, rz = (float(v) for v in m.group(1).split(","))
                    r = rotation(rx, ry, rz)
                    for c in corners:
                        height = z + sum(r[2][k] * c[k] / 1000 for k in range(3))
                        lowest_part = min(lowest_part, height)
            self.assertLess(lowest_part, math.inf)
            self.assertGreaterEqual(lowest_part, 0.02 - 1e-6)


if __name__ == "__main__":
    unittest.main()
