#!/usr/bin/python3
"""Check the arm's capsules (core/robot/ArmCapsules.h) against the manufacturer's meshes.

Usage: scripts/check-arm-capsules.py DESCRIPTION_DIR [POSES]

DESCRIPTION_DIR is a checkout of Universal Robots' ROS 2 description
(github.com/UniversalRobots/Universal_Robots_ROS2_Description; checked at 2221ec0, 2024-10-14).
For the UR5 and the UR5e it places every vertex of the collision meshes
(meshes/<model>/collision/*.stl) by the description's kinematics and mesh offsets
(config/<model>/default_kinematics.yaml, physical_parameters.yaml, visual_parameters.yaml) at
POSES random joint vectors (default 200, the first all zero), builds the capsules from the
shape in core/robot/URKinematics.cpp at the same joints, and prints per link how far inside its
capsules the outermost vertex lies (mm; positive: some vertex is outside, the check fails and
the exit status is 1). The meshes are not bundled (Universal Robots' terms); nothing here runs
in CI.
"""
import math
import os
import re
import struct
import sys

import numpy as np
import yaml

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LINKS = ["base", "shoulder", "upperarm", "forearm", "wrist1", "wrist2", "wrist3"]


def shape_from_source(model):
    """The ArmShape members set in <model>Model() in URKinematics.cpp, and its DH values."""
    text = open(os.path.join(SOURCE, "core", "robot", "URKinematics.cpp")).read()
    body = re.search(r"RobotModel %sModel\(\) \{(.*?)\n\}" % model, text, re.S).group(1)
    shape = {m.group(1): float(m.group(2)) for m in re.finditer(r"s\.(\w+) = ([-\d.e]+);", body)}
    shape["radius"] = [float(v) for v in re.search(r"s\.radius = \{([^}]*)\}", body).group(1).split(",")]
    return shape


def read_stl(path):
    data = open(path, "rb").read()
    if data[:5] == b"solid" and b"facet" in data[:300]:
        return np.array([[float(v) for v in line.split()[1:4]]
                         for line in data.decode().splitlines() if line.strip().startswith("vertex")])
    count = struct.unpack("<I", data[80:84])[0]
    rows = np.frombuffer(data[84:84 + 50 * count],
                         dtype=np.dtype([("n", "<3f4"), ("v", "<9f4"), ("a", "<u2")]))
    return rows["v"].reshape(-1, 3).astype(float)


def rotation(roll, pitch, yaw):
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
                              math.cos(yaw), math.sin(yaw))
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def transform(rot=np.eye(3), xyz=(0, 0, 0)):
    t = np.eye(4)
    t[:3, :3] = rot
    t[:3, 3] = xyz
    return t


def segment_distance(points, a, b):
    d = b - a
    t = np.clip((points - a) @ d / (d @ d), 0, 1) if d @ d > 0 else np.zeros(len(points))
    return np.linalg.norm(points - (a + t[:, None] * d), axis=1)


def capsules(shape, origins):
    """ArmCapsules.cpp's armCapsules, in numpy."""
    o = origins
    u = (o[3] - o[2]) / np.linalg.norm(o[3] - o[2])
    j5 = (o[4] - o[3]) / np.linalg.norm(o[4] - o[3])
    j6 = (o[5] - o[4]) / np.linalg.norm(o[5] - o[4])
    s = shape
    ends = [(np.zeros(3), np.array([0, 0, o[0][2] + s["baseTop"]])),
            (o[0] + s["shoulderFrom"] * u, o[0] + s["shoulderTo"] * u),
            (o[0] + s["shoulderOffset"] * u, o[1] + s["shoulderOffset"] * u),
            (o[1] + s["elbowFrom"] * u, o[1] + s["elbowTo"] * u),
            (o[1] + s["forearmOffset"] * u, o[2] + s["forearmOffset"] * u),
            (o[2] + s["wrist1From"] * u, o[3] + s["wrist1Past"] * u),
            (o[3] - s["wrist2Behind"] * j5, o[4]),
            (o[4] - s["wrist3Behind"] * j6, o[5])]
    return [(a, b, r) for (a, b), r in zip(ends, s["radius"])]


def check(description, model, poses):
    config = os.path.join(description, "config", model)
    kin = yaml.safe_load(open(os.path.join(config, "default_kinematics.yaml")))["kinematics"]
    offsets = yaml.safe_load(open(os.path.join(config, "physical_parameters.yaml")))["offsets"]
    visual = yaml.safe_load(open(os.path.join(config, "visual_parameters.yaml")))["mesh_files"]
    shape = shape_from_source(model)
    # Each link's collision mesh in its link frame (the description's ur_macro.xacro origins).
    half = math.pi / 2
    mesh_origin = {
        "base": ((0, 0, 0), (0, 0, math.pi)),
        "shoulder": ((0, 0, 0), (0, 0, math.pi)),
        "upperarm": ((0, 0, offsets["shoulder_offset"]), (half, 0, -half)),
        "forearm": ((0, 0, offsets["elbow_offset"]), (half, 0, -half)),
        "wrist1": ((0, 0, visual["wrist_1"]["visual_offset"]), (half, 0, 0)),
        "wrist2": ((0, 0, visual["wrist_2"]["visual_offset"]), (0, 0, 0)),
        "wrist3": ((0, 0, visual["wrist_3"]["visual_offset"]), (half, 0, 0)),
    }
    meshes = {}
    for link in LINKS:
        xyz, rpy = mesh_origin[link]
        v = read_stl(os.path.join(description, "meshes", model, "collision", link + ".stl"))
        meshes[link] = v @ rotation(*rpy).T + np.array(xyz)
    joints = ["shoulder", "upper_arm", "forearm", "wrist_1", "wrist_2", "wrist_3"]
    rng = np.random.default_rng(1)
    worst = {link: -math.inf for link in LINKS}
    for pose in range(poses):
        q = rng.uniform(-math.pi, math.pi, 6) if pose else np.zeros(6)
        frames, t = [], np.eye(4)
        for k, joint in enumerate(joints):
            j = kin[joint]
            t = t @ transform(rotation(j["roll"], j["pitch"], j["yaw"]), (j["x"], j["y"], j["z"]))
            t = t @ transform(rotation(0, 0, q[k]))
            frames.append(t.copy())
        # The link frames' origins are the DH origins, except the upper arm's (the shoulder's)
        # and the forearm's (the elbow's): wrist 1's DH origin is on the DH plane.
        o = [frames[1][:3, 3], frames[2][:3, 3],
             (frames[2] @ np.array([kin["wrist_1"]["x"], 0, 0, 1]))[:3],
             frames[3][:3, 3], frames[4][:3, 3], frames[5][:3, 3]]
        caps = capsules(shape, o)
        for link, frame in zip(LINKS, [np.eye(4)] + frames):
            v = meshes[link] @ frame[:3, :3].T + frame[:3, 3]
            outside = np.min([segment_distance(v, a, b) - r for a, b, r in caps], axis=0)
            worst[link] = max(worst[link], outside.max())
    return worst


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    poses = int(sys.argv[2]) if len(sys.argv) > 2 else 200
    failed = False
    for model in ["ur5", "ur5e"]:
        worst = check(sys.argv[1], model, poses)
        print(model + ": outermost vertex per link (mm, negative: inside) " +
              ", ".join("%s %.1f" % (link, 1000 * w) for link, w in worst.items()))
        failed = failed or max(worst.values()) > 0
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
