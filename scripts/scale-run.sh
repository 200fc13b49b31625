#!/usr/bin/env bash
# Scale run of issue 9: the whole pipeline (mesh .. program) on a ~1M-tet model, timed with
# /usr/bin/time -v. Prints the wall time, the peak resident memory, the seconds of every stage
# (from OUTDIR/report.json) and the main counts; results are recorded in docs/scale-run.md.
#
# Usage: scripts/scale-run.sh [OUTDIR] [extra geolattice run options ...]
#   OUTDIR defaults to /tmp/geolattice-scale (about 0.7-0.9 GB of output files).
#   GEOLATTICE_BIN selects the binary (default: build-scale/bin/geolattice, else build/bin/geolattice).
#   Build one that others' edits cannot disturb mid-run:
#     cmake -S . -B build-scale -G Ninja -DCMAKE_BUILD_TYPE=Release -DGEOLATTICE_BUILD_BENCHMARKS=ON
#     ninja -C build-scale -j1
#
# The case: testdata/bunny.obj scaled to 100 mm (largest side), TetGen aiming at 1,000,000 tets
# (automatic edge length, ~1.62 mm, radius-edge 1.414: 992,202 tets), 0.6 mm layers (the default
# bead: 0.6 mm wide), lattice width 5 mm (4 mm at 80 mm scaled to 100 mm), every other option at
# its default (best order, NA 45 deg, UR5 program, A-C G-code, 50 replay steps requested).
# Needs about 3.3 GB of memory and 1-1.5 minutes on the 2-core project machine (50-75 s measured
# at load averages 1-4.5; more when other jobs take both cores).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="${1:-/tmp/geolattice-scale}"
shift || true

BIN="${GEOLATTICE_BIN:-}"
if [[ -z "$BIN" ]]; then
  for candidate in "$ROOT/build-scale/bin/geolattice" "$ROOT/build/bin/geolattice"; do
    if [[ -x "$candidate" ]]; then
      BIN="$candidate"
      break
    fi
  done
fi
if [[ -z "$BIN" || ! -x "$BIN" ]]; then
  echo "scale-run: no geolattice binary (set GEOLATTICE_BIN or build build-scale, see the header of $0)" >&2
  exit 1
fi
if [[ ! -x /usr/bin/time ]]; then
  echo "scale-run: /usr/bin/time is missing (Debian package 'time')" >&2
  exit 1
fi

MODEL="$ROOT/testdata/bunny.obj"
ARGS=(run "$MODEL" -o "$OUT" -q
      --fit-size 100 --target-tets 1000000
      --layer-interval 0.6 --lattice-width 5)
ARGS+=("$@")

# OUTDIR is replaced, but only when it is empty or holds an earlier run (report.json).
if [[ -e "$OUT" && -n "$(ls -A "$OUT" 2>/dev/null)" && ! -f "$OUT/report.json" ]]; then
  echo "scale-run: $OUT is not empty and holds no report.json; not replacing it" >&2
  exit 1
fi
rm -rf "$OUT"
mkdir -p "$OUT"
TIMELOG="$OUT.time.txt"

echo "scale-run: binary  $BIN"
echo "scale-run: command $BIN ${ARGS[*]}"
echo "scale-run: load before: $(uptime)"
status=0
/usr/bin/time -v -o "$TIMELOG" "$BIN" "${ARGS[@]}" || status=$?
echo "scale-run: load after:  $(uptime)"
# Status 4 is the collision gate (the bunny as placed meets the build plate): every stage up to
# the toolpath ran and report.json has their times, so the table is printed; no program stage.
if [[ $status -eq 4 ]]; then
  echo "scale-run: the collision gate stopped the run after the toolpath (status 4): no program stage"
elif [[ $status -ne 0 ]]; then
  echo "scale-run: geolattice exited with status $status" >&2
  cat "$TIMELOG" >&2
  exit "$status"
fi

python3 - "$OUT/report.json" "$TIMELOG" "$OUT" <<'EOF'
import json, os, re, sys

report_path, time_path, out_dir = sys.argv[1:4]
with open(report_path) as f:
    r = json.load(f)
timelog = open(time_path).read()

def time_field(name):
    m = re.search(r"^\s*" + re.escape(name) + r": (.*)$", timelog, re.M)
    return m.group(1).strip() if m else "?"

def wall_seconds(text):
    parts = [float(p) for p in text.split(":")]
    seconds = 0.0
    for p in parts:
        seconds = seconds * 60 + p
    return seconds

wall = wall_seconds(time_field("Elapsed (wall clock) time (h:mm:ss or m:ss)"))
rss_kb = int(time_field("Maximum resident set size (kbytes)"))

rows = [
    ("input (read + place)", r["input"]["seconds"]),
    ("mesh (TetGen)", r["mesh"]["seconds"]),
    ("gdf", r["gdf"]["seconds"]),
    ("layers (+ statistics)", r["layers"]["seconds"]),
    ("overhang", r["overhang"]["seconds"]),
    ("lattice", r["lattice"]["seconds"]),
    ("skeleton", r["skeleton"]["seconds"]),
    ("sequence", r["sequence"]["seconds"]),
    ("sequence verify", r["sequence"]["verify_seconds"]),
    ("toolpath", r["toolpath"]["seconds"]),
    ("toolpath verify", r["toolpath"]["verify_seconds"]),
    ("program (URScript, G-code, CSV)", r["program"]["seconds"]),
]
stages = sum(s for _, s in rows)
print()
print("%-34s %9s" % ("stage", "seconds"))
for name, s in rows:
    print("%-34s %9.2f" % (name, s))
print("%-34s %9.2f" % ("sum of stages", stages))
print("%-34s %9.2f" % ("other (writing VTK files, setup)", wall - stages))
print("%-34s %9.2f" % ("total wall (/usr/bin/time)", wall))
print()
print("gdf split: assembly %.2f s, factorization %.2f s, solve %.2f s" % (
    r["gdf"]["assembly_seconds"], r["gdf"]["factorization_seconds"], r["gdf"]["solve_seconds"]))
print("peak RSS: %d kB = %.2f GiB (limit 4 GiB)" % (rss_kb, rss_kb / 1024.0 ** 2))
print("user %s s, system %s s, CPU %s" % (time_field("User time (seconds)"),
      time_field("System time (seconds)"), time_field("Percent of CPU this job got")))
print("tets %d, points %d, target edge %.3f mm, mean edge %.3f mm" % (
    r["mesh"]["tets"], r["mesh"]["points"], r["mesh"]["target_edge_length_mm"], r["mesh"]["mean_edge_length_mm"]))
print("layers %d (%d points, %d triangles)" % (r["layers"]["count"], r["layers"]["points"], r["layers"]["triangles"]))
print("lattice %d vertices, %d edges, %d sub-graphs" % (
    r["lattice"]["vertices"], r["lattice"]["edges"], r["lattice"]["subgraphs"]))
print("sequence: %d retractions, PCG pairs %d" % (r["sequence"]["retractions"], r["sequence"]["pcg_pairs"]))
t, prog = r["toolpath"], r["program"]
if prog.get("written", True):
    print("toolpath points %d, program waypoints %d, unreachable %d" % (
        t["points"], prog["waypoints"], prog["unreachable"]))
else:
    print("toolpath points %d, no program written (a gate stopped the run)" % t["points"])
print("toolpath collision-free (strict verifier): %s (%d violating stations, %d unavoidable); max axis tilt %s deg" % (
    "yes" if t.get("collision_free") else "no", t.get("violating_stations", -1), t.get("unavoidable_stations", -1),
    t.get("max_axis_tilt_deg", "n/a")))
print("UR5 program: max joint step %.1f deg, %d files; G-code written: %s" % (
    prog.get("max_joint_step_deg", float("nan")), len(prog.get("files", [])),
    "yes" if prog.get("gcode", {}).get("written") else "no"))
size = 0
for dirpath, _, files in os.walk(out_dir):
    size += sum(os.path.getsize(os.path.join(dirpath, f)) for f in files)
print("output files: %.0f MB in %s" % (size / 1e6, out_dir))
verdict = "within" if wall <= 40 and rss_kb <= 4 * 1024 ** 2 else "NOT within"
print("verdict: %s the target of issue 18 (40 s, 4 GiB)" % verdict)
EOF
