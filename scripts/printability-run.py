#!/usr/bin/env python3
"""Printability on every bundled model: model x nozzle {45° cone, example printhead} x orientation
{as placed, auto}, and the printhead auto-oriented on a 10 mm pedestal (docs/performance.md,
"Printability"; issue 14's table). Orientation tries (--orient-tries) are listed as rank: colliding
stations; after tries the stage seconds are those of the final pass (stages already run are read
from the pipeline's cache), the total is the whole run.

Runs `geolattice run MODEL -o OUT/... --until toolpath --replay-steps 0 -q` for each combination,
one after the other, and prints a Markdown table from report.json: colliding toolpath stations
(strict verifier, no exemption; of them at the build plate), the same toolpath judged by the
example printhead (`geolattice verify OUT --printhead`: the cone's paths against the real body;
a point apex cannot see contacts next to the tip), forced sequence steps, retractions,
air length, and the seconds of the orientation search, the sequence, the toolpath and the whole
run.

Usage: scripts/printability-run.py [OUTDIR] [--bin PATH] [--models a,b] [--extra ARGS...]
       (OUTDIR default /tmp/geolattice-printability; --extra passes the rest to every run)
"""
import json
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRINTHEAD = os.path.join(ROOT, "testdata", "printhead_slim.obj")
MODELS = [  # name, file, placement options
    ("bunny", "bunny.obj", ["--fit-size", "80"]),
    ("spot", "spot.obj", ["--fit-size", "80"]),
    ("knight", "decimated-knight.off", ["--fit-size", "80"]),
    ("topopt", "topopt_new4_surf.obj", []),
    ("Y", "y_shape.obj", []),
    ("three-branch", "three_branch_tree.obj", ["--scale", "1.5"]),
    ("cube", "cube.obj", ["--fit-size", "30"]),
    ("ring", "ring_surf.obj", []),
]
CONFIGS = [  # nozzle, orientation (and pedestal), options
    ("cone 45°", "as placed", []),
    ("cone 45°", "auto", ["--orient", "auto"]),
    ("printhead", "as placed", ["--printhead", PRINTHEAD]),
    ("printhead", "auto", ["--printhead", PRINTHEAD, "--orient", "auto"]),
    ("printhead", "auto + pedestal 10 mm", ["--printhead", PRINTHEAD, "--orient", "auto", "--pedestal", "10"]),
]


def colliding_with_printhead(binary, d):
    """Stations of d/toolpath.vtp with earlier material or the plate inside the example printhead."""
    p = subprocess.run([binary, "verify", d, "--printhead", PRINTHEAD], capture_output=True, text=True)
    m = re.search(r"(\d+) stations with earlier material", p.stderr + p.stdout)
    if m:
        return m.group(1)
    return "0" if "collision-free" in p.stderr + p.stdout else "?"


def main():
    args = sys.argv[1:]
    extra = []
    if "--extra" in args:
        i = args.index("--extra")
        extra = args[i + 1:]
        del args[i:]
    binary = os.path.join(ROOT, "build", "bin", "geolattice")
    if "--bin" in args:
        i = args.index("--bin")
        binary = args[i + 1]
        del args[i:i + 2]
    only = None
    if "--models" in args:
        i = args.index("--models")
        only = args[i + 1].split(",")
        del args[i:i + 2]
    out = args[0] if args else "/tmp/geolattice-printability"
    print("| model | nozzle | orientation | colliding stations (plate) | with the example printhead | of stations | forced steps "
          "| retractions | air (mm) | orient search s | orientation tries (rank: colliding) | sequence s "
          "| toolpath s | total s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, file, placement in MODELS:
        if only and name not in only:
            continue
        for nozzle, orient, config_args in CONFIGS:
            d = os.path.join(out, f"{name}-{nozzle.split()[0]}-{'-'.join(orient.split()[:3:2])}")
            os.makedirs(d, exist_ok=True)
            cmd = [binary, "run", os.path.join(ROOT, "testdata", file), "-o", d, "--until", "toolpath",
                   "--replay-steps", "0", "-q"] + placement + config_args + extra
            start = time.monotonic()
            p = subprocess.run(cmd, capture_output=True, text=True)
            wall = time.monotonic() - start
            try:
                r = json.load(open(os.path.join(d, "report.json")))
            except (OSError, ValueError):
                r = {}
            if p.returncode != 0 or "toolpath" not in r:
                err = (p.stderr.strip().splitlines() or ["?"])[0]
                print(f"| {name} | {nozzle} | {orient} | exit {p.returncode}: {err} ||||||||| {wall:.1f} |")
                continue
            t, s = r["toolpath"], r.get("sequence", {})
            o = r.get("orient", {})
            tries = ", ".join("%d: %d" % (x["rank"], x["colliding_stations"]) for x in o.get("tries", [])) or "–"
            judged = (str(t["violating_stations"]) if nozzle == "printhead"
                      else colliding_with_printhead(binary, d))
            # After orientation tries the stage seconds are the final pass's (cached stages: ~0).
            print(f"| {name} | {nozzle} | {orient} | {t['violating_stations']} ({t['plate_stations']}) | {judged} "
                  f"| {t['stations']} | {s.get('forced_steps')} | {t['retractions']} | {t['air_length_mm']:.0f} "
                  f"| {o.get('search_seconds', 0):.1f} | {tries} | {s.get('seconds', 0):.2f} | {t['seconds']:.2f} "
                  f"| {wall:.1f} |", flush=True)


if __name__ == "__main__":
    main()
