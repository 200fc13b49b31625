#!/usr/bin/env python3
"""Whole pipeline on every bundled test model (docs/performance.md, "Whole pipeline per test model").

Runs `geolattice run MODEL -o OUT/NN_NAME -q` with the default options, every file written (the
print replay's too; `--no-replay` adds `--replay-steps 0`, as the tables before 2026-12-04, late
night did), and the README's demo (the bunny with --orient auto), under
/usr/bin/time, one model after the other, and prints a Markdown table: stage seconds from
report.json, total wall and peak resident memory, toolpath points, the strict collision verdict
on the full toolpath, the UR5 program's largest joint step and the G-code outcome.

Usage: scripts/models-run.py [OUTDIR] [--bin PATH] [--no-replay]
       (OUTDIR default /tmp/geolattice-models)
"""
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODELS = [  # name, file, placement options
    ("cube 30 mm", "cube.obj", ["--fit-size", "30"]),
    ("knight 60 mm", "decimated-knight.off", ["--fit-size", "60"]),
    ("Y (52 mm)", "y_shape.obj", []),
    ("three-branch ×1.5 (81 mm)", "three_branch_tree.obj", ["--scale", "1.5"]),
    ("bunny 80 mm", "bunny.obj", ["--fit-size", "80"]),
    ("demo: bunny 80 mm, --orient auto", "bunny.obj", ["--fit-size", "80", "--orient", "auto"]),
    ("spot 80 mm", "spot.obj", ["--fit-size", "80"]),
    ("ring (tet input)", "ring.tet", []),
    ("topopt (genus 6)", "topopt_new4_surf.obj", []),
]


def main():
    args = sys.argv[1:]
    binary = os.path.join(ROOT, "build", "bin", "geolattice")
    if "--bin" in args:
        i = args.index("--bin")
        binary = args[i + 1]
        del args[i:i + 2]
    replay = []
    if "--no-replay" in args:
        args.remove("--no-replay")
        replay = ["--replay-steps", "0"]
    out = args[0] if args else "/tmp/geolattice-models"
    rows = []
    for k, (name, file, options) in enumerate(MODELS):
        d = os.path.join(out, "%02d_%s" % (k, file.split(".")[0]))
        os.makedirs(d, exist_ok=True)
        cmd = ["/usr/bin/time", "-f", "%e %M", binary, "run", os.path.join(ROOT, "testdata", file), "-o", d,
               "-q"] + replay + options
        p = subprocess.run(cmd, capture_output=True, text=True)
        wall, rss = p.stderr.strip().splitlines()[-1].split()
        if p.returncode != 0:
            print(f"{name}: exit {p.returncode}: {p.stderr.strip().splitlines()[0]}", file=sys.stderr)
        r = json.load(open(os.path.join(d, "report.json")))
        sec = lambda k: r.get(k, {}).get("seconds", float("nan"))
        t, prog = r.get("toolpath", {}), r.get("program", {})
        g = prog.get("gcode", {})
        layers = sec("layers") + sec("overhang")
        gcode = "yes" if g.get("written") else "no"
        rows.append([name, r["mesh"]["tets"] if "tets" in r.get("mesh", {}) else r["gdf"]["tets"], r["layers"]["count"],
                     r["lattice"]["subgraphs"], f"{sec('mesh'):.2f}", f"{sec('gdf'):.2f}", f"{layers:.2f}",
                     f"{sec('lattice'):.2f}", f"{sec('skeleton'):.2f}", f"{sec('sequence'):.2f}",
                     f"{sec('toolpath'):.2f}", f"{sec('program'):.2f}", t.get("points"),
                     "yes" if t.get("collision_free") else f"**no** ({t.get('violating_stations')})",
                     f"{t.get('max_axis_tilt_deg', 0):.1f}", prog.get("unreachable"),
                     f"{prog.get('max_joint_step_deg', float('nan')):.1f}", gcode, f"{float(wall):.1f}",
                     f"{int(rss) / 1024:.0f}"])
        print(f"{name}: done in {wall} s", file=sys.stderr)
    head = ["model", "tets", "layers", "sub-graphs", "mesh s", "GDF s", "layers s", "lattice s", "skeleton s",
            "sequence s", "toolpath s", "program s", "toolpath points", "toolpath collision-free (strict)",
            "max axis tilt °", "UR5 unreachable", "max joint step °", "G-code", "total wall s", "peak MB"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for row in rows:
        print("| " + " | ".join(str(c) for c in row) + " |")


if __name__ == "__main__":
    main()
