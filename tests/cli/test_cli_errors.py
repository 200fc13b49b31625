"""The geolattice CLI on bad input: each case must exit non-zero with exactly one line on stderr
that names the problem, and leave no partial or temporary file in the output directory."""
import json
import math
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

CLI = os.environ["GEOLATTICE_CLI"]
TESTDATA = os.environ["GEOLATTICE_TESTDATA"]


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def check_urscript(test, text, def_name, max_bytes):
    """The URScript rules of every program file: one def NAME(): ... end, statements indented inside
    it, pose literals p[...] of 6 numbers with at most 6 decimals, t= and r= numbers, short lines."""
    number = re.compile(r"-?[0-9]+(\.[0-9]{1,6})?$")
    test.assertLessEqual(len(text.encode()), max_bytes)
    lines = text.splitlines()
    test.assertEqual(lines[0], "def %s():" % def_name)
    test.assertEqual(lines[-1], "end")
    test.assertEqual(sum(1 for l in lines if l.startswith("def ")), 1)
    test.assertEqual(sum(1 for l in lines if l == "end"), 1)
    movels = 0
    for line in lines[1:-1]:
        test.assertTrue(line.startswith("  "), line)
        test.assertLessEqual(len(line), 200, line)
        for pose in re.findall(r"p\[([^\]]*)\]", line):
            parts = [x.strip() for x in pose.split(",")]
            test.assertEqual(len(parts), 6, line)
            for x in parts:
                test.assertRegex(x, number, line)
        for key in ("t=", "r="):
            if key in line:
                test.assertRegex(re.split(r"[,)]", line.split(key, 1)[1])[0], number, line)
        movels += line.startswith("  movel(")
    return movels


CUBE_OBJ = """v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1
f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8
"""


class CliErrorTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="geolattice-cli-")
        self.addCleanup(shutil.rmtree, self.tmp, True)
        self.out = os.path.join(self.tmp, "out")

    def run_cli(self, *args):
        return subprocess.run([CLI, "run", *args], capture_output=True, text=True, timeout=300)

    def expect_error(self, args, *words, out=None):
        result = self.run_cli(*args, "-o", out or self.out)
        self.assertNotEqual(result.returncode, 0, result.stdout)
        lines = [l for l in result.stderr.splitlines() if l.strip()]
        self.assertEqual(len(lines), 1, "stderr must be one line, got: %r" % result.stderr)
        for w in words:
            self.assertIn(w, lines[0])
        if os.path.isdir(self.out):
            leftovers = [n for n in os.listdir(self.out) if n.startswith(".") or n.endswith(".tmp")]
            self.assertEqual(leftovers, [], "temporary files left behind")
        return lines[0]

    def meshed_with_note(self, model, note, *extra, out=None):
        """Runs `model` through the mesh stage (with `extra`), expects success and `note` on
        stderr, and returns report.json."""
        out = out or self.out
        result = self.run_cli(model, "-o", out, "-q", "--until", "mesh", *extra)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn(note, result.stderr)
        with open(os.path.join(out, "report.json")) as f:
            report = json.load(f)
        self.assertGreater(report["mesh"]["tets"], 0)
        return report

    # Input files
    def test_missing_file(self):
        self.expect_error([os.path.join(self.tmp, "nope.stl")], "file not found")

    def test_unknown_extension(self):
        self.expect_error([write(os.path.join(self.tmp, "part.xyz"), "1 2 3\n")], "extension")

    def test_empty_mesh(self):
        self.expect_error([write(os.path.join(self.tmp, "empty.obj"), "")], "empty")

    def test_open_surface(self):
        open_box = "\n".join(CUBE_OBJ.splitlines()[:-2]) + "\n"  # drop two triangles
        model = write(os.path.join(self.tmp, "open.obj"), open_box)
        self.expect_error([model], "open surface", "--fill-holes")
        # Asked for, the hole is closed before the part is placed, and said.
        report = self.meshed_with_note(model, "1 hole of the surface closed", "--scale", "20", "--fill-holes")
        self.assertEqual(report["input"]["filled_holes"], 1)
        self.assertGreaterEqual(report["input"]["filled_hole_triangles"], 2)

    def test_non_manifold_surface(self):
        # The cube plus a fin: a third triangle on the edge (1,2).
        fin = CUBE_OBJ + "v 0.5 -1 0\nf 1 2 9\nf 2 1 9\n"
        model = write(os.path.join(self.tmp, "fin.obj"), fin)
        self.expect_error([model], "non-manifold", "--wrap 1")
        report = self.meshed_with_note(model, "replaced by its alpha wrap", "--scale", "20", "--wrap", "1")
        self.assertGreater(report["input"]["wrap_triangles"], 100)

    def test_self_intersecting_surface(self):
        # One body crossing itself: the cube's top face folded down through its bottom (a vertex
        # in the top face's middle pushed below the bottom).
        folded = CUBE_OBJ + "v 0.5 0.5 -0.3\n"
        folded = folded.replace("f 5 6 7\nf 5 7 8\n", "f 5 6 9\nf 6 7 9\nf 7 8 9\nf 8 5 9\n")
        model = write(os.path.join(self.tmp, "folded.obj"), folded)
        self.expect_error([model], "self-intersecting", "--wrap 1")
        # Asked for, the surface is replaced by its alpha wrap: closed, without crossing facets,
        # meshed.
        report = self.meshed_with_note(model, "replaced by its alpha wrap", "--scale", "20", "--wrap", "1")
        self.assertGreater(report["input"]["wrap_triangles"], 100)

    def test_overlapping_bodies_print_as_their_union(self):
        # Two closed cubes that overlap (an assembly exported as it is): meshed as one solid, said on
        # stderr and in report.json (it was "self-intersecting surface").
        second = "".join("v %g %g %g\n" % (x + 0.5, y + 0.5, z + 0.5) for x, y, z in
                         [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)])
        faces = "".join("f %d %d %d\n" % tuple(int(i) + 8 for i in line.split()[1:])
                        for line in CUBE_OBJ.splitlines() if line.startswith("f"))
        model = write(os.path.join(self.tmp, "two.obj"), CUBE_OBJ + second + faces)
        report = self.meshed_with_note(model, "bodies of the surface touch or cross each other", "--scale", "20")
        self.assertEqual(report["mesh"]["merged_bodies"], 1)

    def test_bodies_touching_along_a_face_print_as_their_union(self):
        # A post with a shelf touching its side, as an STL of two bodies gives it: the reader welds
        # the contact into an edge of four triangles (it was "non-manifold surface"). As placed the
        # mesh stage merges them; with --orient auto the search does, before it turns the part.
        def box(x0, y0, z0, x1, y1, z1, offset):
            v = "".join("v %g %g %g\n" % (x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1))
            f = "".join("f %d %d %d\n" % (a + offset, b + offset, c + offset) for a, b, c in
                        [(1, 3, 2), (2, 3, 4), (5, 6, 7), (6, 8, 7), (1, 2, 5), (2, 6, 5),
                         (3, 7, 4), (4, 7, 8), (1, 5, 3), (3, 5, 7), (2, 4, 6), (4, 8, 6)])
            return v, f
        post_v, post_f = box(0, 0, 0, 10, 20, 40, 0)
        shelf_v, shelf_f = box(10, 0, 30, 40, 20, 40, 8)
        model = write(os.path.join(self.tmp, "shelf.obj"), post_v + shelf_v + post_f + shelf_f)
        for extra in ([], ["--orient", "auto"]):
            report = self.meshed_with_note(model, "bodies of the surface touch or cross each other", *extra,
                                           out=self.out + "-".join(extra))
            self.assertEqual(report["mesh"]["merged_bodies"], 1)

    def test_doubled_and_flipped_faces_are_repaired(self):
        # The cube with two of its triangles written again (an STL exporter's doubled faces: their
        # edges had three triangles, "non-manifold surface"), and the cube with one triangle
        # flipped ("inconsistently oriented"): repaired, as placed by the mesh stage and with
        # --orient auto by the search, and said on stderr and in report.json.
        faces = [line for line in CUBE_OBJ.splitlines() if line.startswith("f")]
        doubled = write(os.path.join(self.tmp, "doubled.obj"), CUBE_OBJ + faces[0] + "\n" + faces[3] + "\n")
        a, b, c = faces[4].split()[1:]
        flipped = write(os.path.join(self.tmp, "flipped.obj"),
                        CUBE_OBJ.replace(faces[4] + "\n", "f %s %s %s\n" % (a, c, b)))
        for model, note, key in ((doubled, "2 triangles of the surface repeat another one", "duplicate_triangles"),
                                 (flipped, "1 triangle of the surface ran against its neighbours",
                                  "reoriented_triangles")):
            for extra in ([], ["--orient", "auto"]):
                report = self.meshed_with_note(model, note, "--scale", "20", *extra,
                                               out=self.out + os.path.basename(model) + "-".join(extra))
                self.assertEqual(report["mesh"][key], 2 if key == "duplicate_triangles" else 1)
                self.assertEqual(report["mesh"]["merged_bodies"], 0)

    def test_inverted_tet(self):
        tet = "4 vertices\n1 tets\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 2 1 3\n"
        self.expect_error([write(os.path.join(self.tmp, "inverted.tet"), tet)], "inverted")

    def test_zero_volume_tet(self):
        tet = "5 vertices\n2 tets\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 0\n4 0 1 2 3\n4 0 1 4 2\n"
        self.expect_error([write(os.path.join(self.tmp, "flat.tet"), tet)], "zero-volume")

    # Parameters
    def test_empty_source_set(self):
        # A tilted tet: no boundary face faces straight down.
        tet = "4 vertices\n1 tets\n0 0 0\n1 0 0.3\n0 1 0.2\n0.2 0.2 1\n4 0 1 2 3\n"
        self.expect_error([write(os.path.join(self.tmp, "tilted.tet"), tet), "--base", "faces", "--base-angle", "0.5"],
                          "empty source set")

    def test_negative_edge_length(self):
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--edge-length", "-1"], "edge length")

    def test_zero_time_factor(self):
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--time-factor", "0"],
                          "time factor")

    def test_zero_layer_interval(self):
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--layer-interval", "0"],
                          "interval")

    def test_zero_lattice_width(self):
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--lattice-width", "0"], "width")

    def test_runaway_work_is_bounded(self):
        # A 0.001 mm lattice on the bunny would be ~2 billion vertices and edges: refused from the
        # estimate, before anything is built (it used to grow to 24 GB).
        bunny = os.path.join(TESTDATA, "bunny.obj")
        line = self.expect_error([bunny, "--lattice-width", "0.001"], "lattice", "million vertices and edges",
                                 "limit of 40 million", "--max-elements")
        with open(os.path.join(self.out, "report.json")) as f:
            self.assertEqual(json.load(f)["failed"]["stage"], "lattice", line)
        # A 75 degree nozzle (it used to run the toolpath stage for more than 10 minutes): the run
        # finishes and the collision gate stops it. The bound is a guard against runaway work,
        # not a benchmark.
        start = time.monotonic()
        wide = self.run_cli(bunny, "--nozzle-angle", "75", "-o", self.out, "-q")
        self.assertEqual(wide.returncode, 4, wide.stderr)
        self.assertLess(time.monotonic() - start, 120)

    def test_ctrl_c_stops_the_running_stage(self):
        # A toolpath subdivided every 0.5 micrometres takes minutes: Ctrl-C stops it within
        # seconds, exit status 130, report.json names the stage, no program is written.
        cmd = [CLI, "run", os.path.join(TESTDATA, "bunny.obj"), "--max-segment", "0.0005", "-o", self.out]
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        seen = ""
        while "toolpath ..." not in seen:
            c = p.stdout.read(1)
            self.assertTrue(c, "the run ended before the toolpath stage: " + seen)
            seen += c
        time.sleep(1)
        p.send_signal(signal.SIGINT)
        # No time bound of our own (load makes it flaky): the stage would run for minutes, so
        # ending inside the communicate timeout with failed.stage "toolpath" shows it was stopped.
        _, err = p.communicate(timeout=60)
        self.assertEqual(p.returncode, 130, err)
        self.assertIn("toolpath stage was stopped by Ctrl-C", err)
        with open(os.path.join(self.out, "report.json")) as f:
            self.assertEqual(json.load(f)["failed"]["stage"], "toolpath")
        self.assertEqual(self.program_files(), [])

    def test_a_crash_names_its_signal_stage_and_call_stack(self):
        # A crash (here sent, as a fault would raise it) says on stderr which signal and stage,
        # with the call stack, and still ends the process by that signal.
        cmd = [CLI, "run", os.path.join(TESTDATA, "bunny.obj"), "--max-segment", "0.0005", "-o", self.out]
        no_core_dump = lambda: resource.setrlimit(resource.RLIMIT_CORE, (0, 0))  # ~700 MB each
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             preexec_fn=no_core_dump)
        seen = ""
        while "toolpath ..." not in seen:
            c = p.stdout.read(1)
            self.assertTrue(c, "the run ended before the toolpath stage: " + seen)
            seen += c
        p.send_signal(signal.SIGSEGV)
        _, err = p.communicate(timeout=60)
        self.assertEqual(p.returncode, -signal.SIGSEGV, err)
        self.assertIn("geolattice: crashed with SIGSEGV (invalid memory access) in stage toolpath; "
                      "call stack:\n", err)
        # Frames with their library and address (the signal went to one of the threads).
        self.assertRegex(err, r"call stack:\n(.*\(.*\)\[0x[0-9a-f]+\]\n)+")
        self.assertEqual(self.program_files(), [])

    def test_nozzle_angle_outside_range(self):
        for angle in ("0", "90", "-10"):
            self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--nozzle-angle", angle],
                              "nozzle angle")

    def test_unknown_strategy(self):
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--strategy", "fastest"], "--strategy")

    def test_unknown_stage(self):
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--until", "gcode"], "--until", "toolpath", "program")

    def test_bad_toolpath_option_values(self):
        cube = [os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10"]
        # Not numbers, or not a whole number of steps: usage errors before anything runs.
        for flag in ("--path-width", "--filament-diameter", "--flow", "--print-speed", "--air-speed",
                     "--thickness-cap", "--max-turn", "--safe-margin", "--lift", "--retraction", "--tooth-length"):
            self.expect_error(cube + [flag, "abc"], flag)
        for steps in ("-1", "2.5", "abc"):
            self.expect_error(cube + ["--replay-steps", steps], "--replay-steps")
        # Out of range: the planner's messages (as in ParaView), before the first stage runs.
        self.expect_error(cube + ["--path-width", "0"], "parameters", "path width must be > 0")
        self.expect_error(cube + ["--flow", "1.5"], "parameters", "flow correction mu must be in (0, 1]")
        self.expect_error(cube + ["--filament-diameter", "-1"], "parameters", "filament diameter must be > 0")
        self.expect_error(cube + ["--max-turn", "0"], "parameters", "maximum turn angle must be > 0")
        self.expect_error(cube + ["--retraction", "-1"], "parameters", "retraction must be >= 0")
        self.assertFalse(os.path.exists(os.path.join(self.out, "tets.vtu")))

    def test_parameters_fail_before_the_first_stage(self):
        # On the bunny meshing and the fields alone take seconds: a bad parameter of any stage the
        # run reaches must stop it in well under a second, naming the flag and its range.
        bunny = [os.path.join(TESTDATA, "bunny.obj"), "--fit-size", "80"]
        cases = [(["--layer-interval", "0"], "layer interval must be > 0"),
                 (["--lattice-width", "-1"], "lattice width must be > 0"),
                 (["--nozzle-angle", "95"], "nozzle angle"),
                 (["--max-tilt", "75"], "[0, 60]"),
                 (["--max-joint-step", "45"], "--max-joint-step must be in (0, 30]"),
                 (["--time-factor", "0"], "time factor"),
                 (["--sample-spacing", "0"], "sample spacing must be > 0"),
                 (["--edge-length", "-1"], "edge length")]
        for args, words in cases:
            start = time.monotonic()
            line = self.expect_error(bunny + args, "parameters", words)
            self.assertLess(time.monotonic() - start, 1.0, line)
            with open(os.path.join(self.out, "report.json")) as f:
                self.assertEqual(json.load(f)["failed"]["stage"], "parameters")
            self.assertFalse(os.path.exists(os.path.join(self.out, "tets.vtu")), line)
        # A stage the run does not reach is not checked.
        result = self.run_cli(*bunny, "--max-joint-step", "45", "--until", "mesh", "--edge-length", "8",
                              "-o", self.out, "-q")
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_bad_printhead_files_fail_before_the_first_stage(self):
        # A printhead mesh is read and validated with the parameters: missing, open, in metres,
        # or with its tip off the origin, the run stops in well under a second naming the file.
        bunny = [os.path.join(TESTDATA, "bunny.obj"), "--fit-size", "80"]
        cube_at = lambda dx, dz, scale=10.0: "".join(
            "v %g %g %g\n" % (scale * (float(x) - 0.5) + dx, scale * (float(y) - 0.5), scale * float(z) + dz)
            for x, y, z in (line.split()[1:] for line in CUBE_OBJ.splitlines() if line.startswith("v "))) + \
            "".join(line + "\n" for line in CUBE_OBJ.splitlines() if line.startswith("f"))
        cases = [(os.path.join(self.tmp, "nope.stl"), ["printhead file", "file not found"]),
                 (write(os.path.join(self.tmp, "open.obj"), "\n".join(cube_at(0, 0).splitlines()[:-2]) + "\n"),
                  ["printhead", "open.obj", "closed"]),
                 (write(os.path.join(self.tmp, "metres.obj"), cube_at(0, 0, 0.01)), ["metres"]),
                 (write(os.path.join(self.tmp, "lifted.obj"), cube_at(0, 3)), ["lowest point is at z = 3"]),
                 (write(os.path.join(self.tmp, "aside.obj"), cube_at(20, 0)), ["the origin is", "from its surface"]),
                 (write(os.path.join(self.tmp, "head.xyz"), "1 2 3\n"), ["printhead file", "extension"])]
        for path, words in cases:
            start = time.monotonic()
            line = self.expect_error(bunny + ["--printhead", path], "parameters", *words)
            self.assertLess(time.monotonic() - start, 1.0, line)
        # The same cube centred on the axis is a (blunt) printhead: the run gets past the parameters.
        good = write(os.path.join(self.tmp, "block.obj"), cube_at(0, 0))
        result = self.run_cli(*bunny, "--printhead", good, "--until", "mesh", "-o", self.out, "-q")
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_pedestal(self):
        # A bad height fails with the parameters; a tet mesh cannot be raised; the cube stands on a
        # column of its whole bottom face, 5 mm taller, and report.json says so.
        start = time.monotonic()
        self.expect_error([os.path.join(TESTDATA, "bunny.obj"), "--pedestal", "-1"], "parameters", "[0, 500]")
        self.assertLess(time.monotonic() - start, 1.0)
        self.expect_error([os.path.join(TESTDATA, "ring.tet"), "--pedestal", "5"], "surface model")
        result = self.run_cli(os.path.join(TESTDATA, "cube.obj"), "--fit-size", "30", "--pedestal", "5",
                              "--until", "mesh", "-o", self.out, "-q")
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.out, "report.json")) as f:
            report = json.load(f)
        self.assertEqual(report["pedestal"]["height_mm"], 5)
        self.assertAlmostEqual(report["pedestal"]["footprint_area_mm2"], 900, places=6)
        self.assertEqual(report["pedestal"]["footprint_loops"], 1)
        # 12 triangles of the cube (its bottom moved down) + one ring of 4 x 2 wall triangles.
        self.assertEqual(report["mesh"]["input_triangles"], 20)
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--pedestal", "tall"], "--pedestal")

    def test_orientation_stands_a_ball_on_a_pedestal(self):
        # A 30 mm ball has no side to stand on (0.3 mm deep its cap is 28 mm^2; --min-base-area
        # 50 asks for more): --orient auto puts it on a 10 mm pedestal reaching 1 mm into it, and
        # GL Pedestal builds that one; --pedestal 0 forbids it, and then no orientation stands.
        rings, segments, r = 24, 32, 15.0
        lines = ["v 0 0 0"]
        for i in range(1, rings):
            a = math.pi * i / rings
            for k in range(segments):
                b = 2 * math.pi * k / segments
                lines.append("v %.6f %.6f %.6f" % (r * math.sin(a) * math.cos(b), r * math.sin(a) * math.sin(b),
                                                   r - r * math.cos(a)))
        lines.append("v 0 0 %g" % (2 * r))
        ring = lambda i, k: 2 + (i - 1) * segments + k % segments
        top = 2 + (rings - 1) * segments
        for k in range(segments):
            lines.append("f 1 %d %d" % (ring(1, k + 1), ring(1, k)))
            for i in range(1, rings - 1):
                lines.append("f %d %d %d" % (ring(i, k), ring(i, k + 1), ring(i + 1, k + 1)))
                lines.append("f %d %d %d" % (ring(i, k), ring(i + 1, k + 1), ring(i + 1, k)))
            lines.append("f %d %d %d" % (top, ring(rings - 1, k), ring(rings - 1, k + 1)))
        ball = os.path.join(self.tmp, "ball.obj")
        with open(ball, "w") as f:
            f.write("\n".join(lines) + "\n")
        common = [ball, "--orient", "auto", "--min-base-area", "50", "--orient-candidates", "20", "--until", "mesh"]
        self.expect_error(common + ["--pedestal", "0"], "no orientation has a base contact area of 50")
        result = self.run_cli(*common, "-o", self.out, "-q")
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.out, "report.json")) as f:
            report = json.load(f)
        self.assertEqual(report["orient"]["pedestal_mm"], 10)
        self.assertEqual(report["pedestal"]["height_mm"], 10)
        self.assertGreaterEqual(report["pedestal"]["footprint_area_mm2"], 50)
        self.assertGreaterEqual(report["orient"]["refined_candidates"], 1)
        with open(os.path.join(self.out, "orientation.csv")) as f:
            header = f.readline().strip().split(",")
            first = dict(zip(header, f.readline().strip().split(",")))
        self.assertEqual(float(first["pedestal_mm"]), 10)
        self.assertEqual(first["refined"], "1")

    def test_unit_mistakes_fail_at_input(self):
        # A part exported in metres (0.05 across) and one with coordinates around 1e12.
        metres = "".join("v %g %g %g\n" % tuple(0.05 * float(x) for x in line.split()[1:])
                         for line in CUBE_OBJ.splitlines() if line.startswith("v "))
        metres += "".join(line + "\n" for line in CUBE_OBJ.splitlines() if line.startswith("f"))
        start = time.monotonic()
        self.expect_error([write(os.path.join(self.tmp, "metres.obj"), metres)], "0.05 mm", "metres",
                          "--scale 1000")
        self.assertLess(time.monotonic() - start, 1.0)
        huge = CUBE_OBJ.replace("v 1", "v 1e12")
        self.expect_error([write(os.path.join(self.tmp, "huge.obj"), huge)], "across", "--fit-size")

    def test_a_reference_along_the_build_direction_is_noted(self):
        # r of Eq. 3 along +z lies along the layers' normal in much of a cube: the lattice
        # directions there fall back to the neighbours', which the run says; the default does not.
        cube = write(os.path.join(self.tmp, "cube.obj"), CUBE_OBJ)
        notes = []
        for extra in (["--reference", "0,0,1"], []):
            out = os.path.join(self.tmp, "out%d" % len(notes))
            result = self.run_cli(cube, "-o", out, "-q", "--scale", "4", "--until", "gdf", *extra)
            self.assertEqual(result.returncode, 0, result.stderr)
            notes.append([line for line in result.stderr.splitlines() if "reference vector" in line])
        self.assertEqual(len(notes[0]), 1, notes)
        self.assertIn("--reference 0,0,1", notes[0][0])
        self.assertIn("gdf.reference_fallback_tets", notes[0][0])
        self.assertEqual(notes[1], [])

    def test_a_reference_along_a_horizontal_arm_is_turned(self):
        # An L: a 6 mm post 30 mm tall and an arm 34 mm long along x at its top (a figure's arm).
        # The layers' normal in the arm is +x, the default reference: it is turned across the
        # build direction (to y) and the run says so; given as --reference 1,0,0 it is kept.
        outline = [(0, 0), (6, 0), (6, 24), (40, 24), (40, 30), (0, 30)]  # x, z; counter-clockwise
        v = ["v %g %g %g" % (x, y, z) for y in (0, 6) for x, z in outline]
        n = len(outline)
        caps = [(0, 1, 2), (0, 2, 5), (2, 3, 4), (2, 4, 5)]  # the L as four triangles
        f = ["f %d %d %d" % (a + 1, c + 1, b + 1) for a, b, c in caps]  # y = 0 faces -y
        f += ["f %d %d %d" % (a + n + 1, b + n + 1, c + n + 1) for a, b, c in caps]
        for i in range(n):
            j = (i + 1) % n
            f += ["f %d %d %d" % (i + 1, j + 1, j + n + 1), "f %d %d %d" % (i + 1, j + n + 1, i + n + 1)]
        model = write(os.path.join(self.tmp, "arm.obj"), "\n".join(v + f) + "\n")
        reports, notes = [], []
        for extra in ([], ["--reference", "1,0,0"]):
            out = os.path.join(self.tmp, "arm%d" % len(notes))
            result = self.run_cli(model, "-o", out, "-q", "--until", "gdf", *extra)
            self.assertEqual(result.returncode, 0, result.stderr)
            notes.append([line for line in result.stderr.splitlines() if "reference vector" in line])
            with open(os.path.join(out, "report.json")) as fh:
                reports.append(json.load(fh)["gdf"])
        turned, kept = reports
        self.assertGreater(turned["given_reference_fallback_tets"], 0.05 * turned["tets"])
        self.assertEqual(turned["reference_fallback_tets"], 0)
        self.assertAlmostEqual(abs(turned["reference"][1]), 1.0, places=2)
        self.assertEqual(len(notes[0]), 1, notes)
        self.assertIn("was turned to", notes[0][0])
        self.assertNotIn("given_reference_fallback_tets", kept)
        self.assertEqual(kept["reference"], [1.0, 0.0, 0.0])
        self.assertEqual(kept["reference_fallback_tets"], turned["given_reference_fallback_tets"])
        self.assertIn("--reference auto turns it", notes[1][0])

    def test_non_finite_coordinates_named_at_read_time(self):
        for bad in ("nan", "inf", "-inf"):
            obj = CUBE_OBJ.replace("v 1 1 0", "v 1 %s 0" % bad)
            start = time.monotonic()
            line = self.expect_error([write(os.path.join(self.tmp, "bad.obj"), obj)], "input",
                                     "non-finite value for y", "bad.obj:3:")
            self.assertLess(time.monotonic() - start, 1.0, line)
        off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 nan 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"
        self.expect_error([write(os.path.join(self.tmp, "bad.off"), off)], "non-finite", "bad.off:5")

    def test_binary_stl_sanity(self):
        # Garbage named .stl (it used to abort the process allocating billions of triangles), a
        # truncated binary STL and a file shorter than the header: a clear error, exit status 1.
        garbage = os.path.join(self.tmp, "garbage.stl")
        with open(garbage, "wb") as f:
            f.write(bytes((i * 7919 + 13) % 256 for i in range(5000)))
        start = time.monotonic()
        result = self.run_cli(garbage, "-o", self.out)
        self.assertEqual(result.returncode, 1, result.stderr)
        self.assertIn("not a valid binary STL", result.stderr)
        self.assertLess(time.monotonic() - start, 1.0)
        # A real binary STL (the cube, 12 triangles), then cut short.
        import struct
        verts = [tuple(float(x) for x in l.split()[1:]) for l in CUBE_OBJ.splitlines() if l.startswith("v ")]
        faces = [tuple(int(i) - 1 for i in l.split()[1:]) for l in CUBE_OBJ.splitlines() if l.startswith("f")]
        data = b"binary cube".ljust(80, b" ") + struct.pack("<I", len(faces))
        for a, b, c in faces:
            data += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *verts[i]) for i in (a, b, c)) + b"\0\0"
        self.assertEqual(len(data), 84 + 50 * 12)
        truncated = os.path.join(self.tmp, "truncated.stl")
        with open(truncated, "wb") as f:
            f.write(data[:-30])
        self.expect_error([truncated], "12 triangles", "truncated")
        tiny = os.path.join(self.tmp, "tiny.stl")
        with open(tiny, "wb") as f:
            f.write(b"\x00\x01\x02")
        self.expect_error([tiny], "not an STL file", "has 3 bytes")  # its size, not -1
        good = os.path.join(self.tmp, "cube.stl")
        with open(good, "wb") as f:
            f.write(data)
        result = self.run_cli(good, "--fit-size", "10", "--until", "mesh", "-o", self.out, "-q")
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_replay_steps_replace_earlier_ones(self):
        cube = [os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "-o", self.out, "-q"]
        steps_dir = os.path.join(self.out, "toolpath")
        for steps in ("7", "3", "0"):
            result = self.run_cli(*cube, "--replay-steps", steps)
            self.assertEqual(result.returncode, 0, result.stderr)
            with open(os.path.join(self.out, "report.json")) as f:
                self.assertEqual(json.load(f)["toolpath"]["replay_steps"], int(steps))
            files = sorted(os.listdir(steps_dir)) if os.path.isdir(steps_dir) else []
            self.assertEqual(files, (["empty.vtp"] if steps != "0" else [])
                             + ["step_%04d.vtp" % k for k in range(1, int(steps) + 1)])
            self.assertEqual(os.path.isfile(os.path.join(self.out, "toolpath.pvd")), steps != "0")

    def test_lattice_wider_than_the_part_still_sequences(self):
        # No isoline crosses the layers: the sub-graphs are the layer boundaries, still printed in order.
        result = self.run_cli(os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--lattice-width", "1000",
                              "-o", self.out, "-q")
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.out, "report.json")) as f:
            report = json.load(f)
        self.assertEqual(report["lattice"]["isoline_edges"], 0)
        self.assertEqual(report["sequence"]["subgraphs"], report["lattice"]["subgraphs"])
        self.assertTrue(report["sequence"]["collision_free"])
        # Each sub-graph is a closed boundary loop: one tour each, nothing trimmed, no perimeter.
        self.assertEqual(report["toolpath"]["tours"], report["lattice"]["subgraphs"])
        self.assertEqual(report["toolpath"]["trimmed_edges"], 0)
        self.assertEqual(report["toolpath"]["perimeter_loops"], 0)
        self.assertEqual(report["toolpath"]["retractions"], report["lattice"]["subgraphs"] - 1)

    # Programs (the default last stage)
    def program_files(self):
        return sorted(n for n in os.listdir(self.out)
                      if n.endswith(".script") or n in ("toolpath.gcode", "waypoints.csv"))

    def test_unreachable_cell(self):
        # The nozzle 5 m from the robot: one line, the reachability gate (exit 5), no program file.
        line = self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--replay-steps", "0",
                                  "--nozzle-tip", "5000,0,0"], "program", "unreachable cell set-up")
        self.assertTrue(line.startswith("geolattice: stopped: program: "), line)
        self.assertEqual(self.program_files(), [])
        self.assertTrue(os.path.isfile(os.path.join(self.out, "toolpath.vtp")))  # the stages before

    def test_bad_program_options(self):
        cube = [os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--replay-steps", "0"]
        # Usage errors before anything runs.
        self.expect_error(cube + ["--robot", "ur10"], "--robot", "ur5 or ur5e")
        self.expect_error(cube + ["--nozzle-tip", "1,2"], "--nozzle-tip", "X,Y,Z")
        self.expect_error(cube + ["--nozzle-tip", "1,2,x"], "--nozzle-tip")
        self.expect_error(cube + ["--part-on-flange", "0,0,100"], "--part-on-flange", "X,Y,Z,RX,RY,RZ")
        self.expect_error(cube + ["--part-offset", "100", "--part-on-flange", "0,0,100,0,0,0"],
                          "--part-offset and --part-on-flange")
        self.expect_error(cube + ["--max-script-bytes", "5000"], "--max-script-bytes")
        self.expect_error(cube + ["--gcode", "xyz"], "--gcode", "ac, bc or none")
        self.expect_error(cube + ["--tilt-limits", "10"], "--tilt-limits", "MIN,MAX")
        self.assertFalse(os.path.exists(self.out))
        # Out of range: the writers' messages, before the first stage runs.
        self.expect_error(cube + ["--speed-factor", "0"], "parameters", "speed factor must be in (0, 1]")
        self.expect_error(cube + ["--max-filament-rate", "0"], "parameters", "maximum filament rate must be > 0")
        self.expect_error(cube + ["--nozzle-axis", "0,0,0"], "parameters", "nozzle axis")
        self.expect_error(cube + ["--tilt-limits", "30,-30"], "parameters", "tilt limits")
        # Without G-code its writer's parameters do not matter.
        result = self.run_cli(*cube, "--tilt-limits", "30,-30", "--gcode", "none", "-o", self.out, "-q")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("print_part.script", self.program_files())
        self.assertNotIn("toolpath.gcode", self.program_files())

    def test_gcode_out_of_tilt_limits_is_reported_not_fatal(self):
        # Flat layers need tilt 0; a table limited to 5..10 degrees cannot do it. The G-code is
        # an optional output: the run succeeds, writes no G-code and names the points.
        result = self.run_cli(os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--replay-steps", "0",
                              "--tilt-limits", "5,10", "-o", self.out, "-q")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("no G-code written", result.stdout)
        import json
        with open(os.path.join(self.out, "report.json")) as f:
            gcode = json.load(f)["program"]["gcode"]
        self.assertFalse(gcode["written"])
        self.assertGreater(gcode["out_of_limits"], 0)
        self.assertIn("first:", gcode["error"])
        self.assertFalse(os.path.exists(os.path.join(self.out, "toolpath.gcode")))
        self.assertTrue(any(n.endswith(".script") for n in os.listdir(self.out)))

    def test_program_files_split_and_replaced(self):
        cube = [os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--replay-steps", "0", "-o", self.out, "-q"]

        def report():
            with open(os.path.join(self.out, "report.json")) as f:
                return json.load(f)

        # Split below 200 kB: print_part.script, print_part_1.script, ... each with its def.
        result = self.run_cli(*cube, "--max-script-bytes", "200000", "--robot", "ur5e", "--part-offset", "50")
        self.assertEqual(result.returncode, 0, result.stderr)
        program = report()["program"]
        files = program["files"]
        self.assertGreater(len(files), 2)
        self.assertEqual(files, ["print_part.script"] + ["print_part_%d.script" % k for k in range(1, len(files))])
        self.assertEqual(self.program_files(), sorted(files + ["toolpath.gcode", "waypoints.csv"]))
        movels = 0
        for k, name in enumerate(files):
            with open(os.path.join(self.out, name)) as f:
                text = f.read()
            movels += check_urscript(self, text, name[:-len(".script")], 200000)
            self.assertIn("set_tcp(p[0, 0, 0.05, 0, 0, 0])", text)
        self.assertEqual(movels, program["moves"])
        self.assertEqual(program["moves"], program["waypoints"] - 1)
        self.assertEqual(program["robot"], "ur5e")
        self.assertEqual(program["part_on_flange"], [0, 0, 50, 0, 0, 0])  # mm, deg
        # One file again: the numbered files of the longer program are gone; no G-code wanted: the
        # earlier toolpath.gcode is removed too.
        result = self.run_cli(*cube, "--gcode", "none")
        self.assertEqual(result.returncode, 0, result.stderr)
        program = report()["program"]
        self.assertEqual(program["files"], ["print_part.script"])
        self.assertEqual(program["gcode"], {"kinematics": "none"})
        self.assertEqual(self.program_files(), ["print_part.script", "waypoints.csv"])
        # --until toolpath: no program stage, no report section.
        shutil.rmtree(self.out)
        result = self.run_cli(*cube, "--until", "toolpath")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertNotIn("program", report())
        self.assertEqual(self.program_files(), [])

    def test_bad_option_value(self):
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--scale", "abc"], "--scale")

    def test_unwritable_output_directory(self):
        blocker = write(os.path.join(self.tmp, "a-file"), "x")
        self.expect_error([os.path.join(TESTDATA, "cube.obj")], "output directory",
                          out=os.path.join(blocker, "sub"))

    def test_a_file_that_cannot_be_written_fails_the_run(self):
        # A failed write fails the run with one line naming the file and keeps the files written
        # before it (complete: each is written to a temporary name and renamed).
        os.makedirs(os.path.join(self.out, "layers.vtp"))  # the rename onto it fails
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--until", "toolpath"],
                          "could not write", "layers.vtp")
        for name in ("tets.vtu", "fields.vtu"):
            self.assertGreater(os.path.getsize(os.path.join(self.out, name)), 0, name)
        self.assertFalse(os.path.exists(os.path.join(self.out, "toolpath.vtp")))

    def test_failure_keeps_earlier_results(self):
        # A good run, then a failing one into the same directory: the earlier files the failing run
        # did not write again are kept intact in previous/ (with their report.json), the new
        # report.json names the failing stage, and the directory holds only the new run's files.
        good = self.run_cli(os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--until", "gdf", "-o", self.out)
        self.assertEqual(good.returncode, 0, good.stderr)
        before = {n: os.path.getsize(os.path.join(self.out, n)) for n in os.listdir(self.out)}
        self.assertEqual(sorted(before), ["fields.vtu", "report.json", "tets.vtu"])
        self.expect_error([os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--time-factor", "0"], "time factor")
        previous = os.path.join(self.out, "previous")
        self.assertEqual(os.path.getsize(os.path.join(previous, "fields.vtu")), before["fields.vtu"])
        self.assertTrue(os.path.isfile(os.path.join(previous, "report.json")))
        self.assertFalse(os.path.exists(os.path.join(self.out, "fields.vtu")))
        with open(os.path.join(self.out, "report.json")) as f:
            report = json.load(f)
        self.assertEqual(report["failed"]["stage"], "parameters")
        self.assertIn("time factor", report["failed"]["message"])
        self.assertEqual(report["exit_status"], 1)
        self.assertEqual([f["file"] for f in report["files"]], [])


class CliGateTest(unittest.TestCase):
    """The safety gates: a colliding toolpath (4), unreachable points (5), a joint flip (6) stop the
    machine programs with exactly one line on stderr and every inspection output written; the
    overrides write the programs and keep the warning; a cell that flips is laid out anew."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="geolattice-gates-")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def run_cli(self, model, *args):
        out = os.path.join(self.tmp, "out")
        result = subprocess.run([CLI, "run", os.path.join(TESTDATA, model), "-o", out, "-q", "--replay-steps", "0",
                                 "--gcode", "none", *args], capture_output=True, text=True, timeout=600)
        path = os.path.join(out, "report.json")
        self.assertTrue(os.path.isfile(path), "no report.json: exit %d, stderr %r, stdout %r" %
                        (result.returncode, result.stderr, result.stdout[-2000:]))
        with open(path) as f:
            report = json.load(f)
        programs = sorted(n for n in os.listdir(out) if n.endswith((".script", ".gcode")) or n == "waypoints.csv")
        return result, report, programs, out

    def expect_gate(self, result, report, programs, out, status, gate, words):
        self.assertEqual(result.returncode, status, result.stderr)
        lines = [l for l in result.stderr.splitlines() if l.strip()]
        self.assertEqual(len(lines), 1, result.stderr)
        self.assertTrue(lines[0].startswith("geolattice: stopped: "), lines[0])
        for w in words:
            self.assertIn(w, lines[0])
        self.assertEqual(programs, [])
        for name in ("fields.vtu", "lattice.vtp", "toolpath.vtp", "toolpath_collisions.vtp"):
            self.assertTrue(os.path.isfile(os.path.join(out, name)), name)
        self.assertFalse(report["gates"][gate]["passed"])
        self.assertEqual(report["gates"][gate]["stopped"], ["program"])
        self.assertEqual(report["exit_status"], status)

    def test_a_small_base_is_warned_of(self):
        # spot as placed touches the plate at points: it may come loose while printing. The
        # run goes on (the user placed it so) with a warning that holds even with -q; the cube
        # stands on a whole face: no warning.
        result, report, programs, out = self.run_cli("spot.obj", "--fit-size", "80", "--until", "layers")
        self.assertEqual(result.returncode, 0, result.stderr)
        lines = [l for l in result.stderr.splitlines() if l.strip()]
        self.assertEqual(len(lines), 1, result.stderr)
        self.assertIn("warning: the part touches the plate on", lines[0])
        self.assertIn("--min-base-area 10", lines[0])
        self.assertIn("--orient auto", lines[0])
        self.assertTrue(report["overhang"]["small_base"])
        self.assertLess(report["overhang"]["base_contact_mm2"], 10)
        result, report, programs, out = self.run_cli("cube.obj", "--fit-size", "30", "--until", "layers")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stderr, "")
        self.assertFalse(report["overhang"]["small_base"])
        # The contact is the one the orientation search asks of a side (faces facing down within
        # half a first layer, 0.3 mm, of the lowest point), not the layers' base (0.05 mm and the
        # 0.6 mm flat band): topopt's uneven underside has 10.8 mm^2 so (its orientation.csv row
        # "keep"), almost none within 0.05 mm, more within the band. It used to be warned of as
        # placed, and when --orient auto chose it.
        result, report, programs, out = self.run_cli("topopt_new4_surf.obj", "--until", "layers")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stderr, "")
        self.assertFalse(report["overhang"]["small_base"])
        self.assertGreaterEqual(report["overhang"]["base_contact_mm2"], 10)
        overhang = report["overhang"]
        self.assertGreater(overhang["base_area_mm2"], overhang["base_contact_mm2"])
        result, report, programs, out = self.run_cli("topopt_new4_surf.obj", "--until", "layers",
                                                     "--base-flat-band", "0")
        self.assertEqual(result.stderr, "")
        self.assertLess(report["overhang"]["base_area_mm2"], 10)

    def test_a_closed_cavity_is_named_in_the_collision_gate(self):
        # A 20 mm cube with a closed 12 mm cavity (an inward shell): the layers over the void
        # collide; the stop line says the part has a cavity no nozzle can enter, report.json counts it.
        cube = [line.split() for line in CUBE_OBJ.splitlines()]
        points = [[float(x) for x in c[1:]] for c in cube if c[0] == "v"]
        faces = [[int(i) for i in c[1:]] for c in cube if c[0] == "f"]
        text = "".join("v %g %g %g\n" % tuple(20 * x for x in p) for p in points)
        text += "".join("v %g %g %g\n" % tuple(4 + 12 * x for x in p) for p in points)
        text += "".join("f %d %d %d\n" % tuple(f) for f in faces)
        text += "".join("f %d %d %d\n" % (f[0] + 8, f[2] + 8, f[1] + 8) for f in faces)  # inward
        model = write(os.path.join(self.tmp, "hollow_cube.obj"), text)
        result, report, programs, out = self.run_cli(model)
        self.expect_gate(result, report, programs, out, 4, "collision",
                         ["the part has 1 closed inner cavity",
                          "fill it with --fill-cavities or open it"])
        self.assertEqual(report["mesh"]["cavities"], 1)

    def test_the_bunny_keeps_the_printhead_out_of_the_plate(self):
        # Issue 15's acceptance for the bunny: with the example printhead on a 10 mm pedestal, no
        # station and no air move of the 80 mm bunny (as placed) has the printhead in the build
        # plate (the strict verifier counts plate stations separately), and the run is written.
        result, report, programs, out = self.run_cli(
            "bunny.obj", "--fit-size", "80", "--printhead", os.path.join(TESTDATA, "printhead_slim.obj"),
            "--pedestal", "10", "--until", "toolpath")
        self.assertEqual(result.returncode, 0, result.stderr)
        t = report["toolpath"]
        self.assertEqual(t["plate_stations"], 0)
        self.assertGreater(t["stations"], 200000)
        self.assertLess(t["violating_stations"], 100)  # 34 measured: beads at the face's rim
        self.assertEqual(report["pedestal"]["height_mm"], 10)

    def test_the_bunny_auto_oriented_prints_with_the_default_nozzle(self):
        # Issue 14's acceptance for the bunny: --orient auto with the default 45 degree cone finds
        # a side (here on a 10 mm pedestal) where the strict verifier passes the whole toolpath,
        # no station or air move in the build plate, and the programs are written.
        result, report, programs, out = self.run_cli("bunny.obj", "--fit-size", "80", "--orient", "auto")
        self.assertEqual(result.returncode, 0, result.stderr)
        t = report["toolpath"]
        self.assertTrue(t["collision_free"])
        self.assertEqual(t["violating_stations"], 0)
        self.assertEqual(t["plate_stations"], 0)
        self.assertGreater(t["stations"], 200000)
        self.assertTrue(any(p.endswith(".script") for p in programs), programs)
        self.assertLess(report["orient"]["after"]["colliding_stations"],
                        report["orient"]["before"]["colliding_stations"])

    def test_other_orientations_and_taller_pedestals_are_tried_through_the_toolpath(self):
        # The knight's best candidate collides, so the next ones of the search are run through the
        # toolpath; the least colliding of them is kept. It stands on the search's 10 mm pedestal
        # and its toolpath still meets the build plate (its lowest layers overhang far and the
        # nozzle tilts down under them), so taller pedestals are run through the toolpath too; the
        # one printed (and reported, and gated) is the least colliding of those.
        result, report, programs, out = self.run_cli("decimated-knight.off", "--fit-size", "80", "--orient", "auto")
        orient = report["orient"]
        tries = orient["tries"]
        self.assertGreaterEqual(len(tries), 2, tries)
        self.assertEqual([t["rank"] for t in tries], list(range(len(tries))))
        least = min(tries, key=lambda t: (t["colliding_stations"], t["rank"]))
        self.assertEqual(orient["chosen_rank"], least["rank"])
        self.assertGreater(least["colliding_stations"], 0)
        pedestals = orient["pedestal_tries"]
        self.assertEqual(pedestals[0]["height_mm"], least["pedestal_mm"])
        self.assertEqual(pedestals[0]["colliding_stations"], least["colliding_stations"])
        self.assertGreater(pedestals[0]["plate_stations"], 0)
        self.assertEqual([p["height_mm"] for p in pedestals],
                         [least["pedestal_mm"] * (i + 1) for i in range(len(pedestals))])
        chosen = min(pedestals, key=lambda p: (p["colliding_stations"], p["height_mm"]))
        self.assertEqual(report["pedestal"]["height_mm"], chosen["height_mm"])
        t = report["toolpath"]
        self.assertEqual(t["violating_stations"], chosen["colliding_stations"])
        self.assertEqual(t["stations"], chosen["stations"])
        # Measured: 82 stations (79 at the plate) on 10 mm, none on 20 mm: the collision gate
        # passes. The UR5 in the default cell follows it with the arm off the nozzle (the
        # tenth session's fixed 3 refinement passes left 97 points unreachable; the eleventh's
        # go on while they make progress: 4).
        self.assertEqual(t["violating_stations"], 0)
        self.assertTrue(report["gates"]["collision"]["passed"])
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("print_part.script", programs)
        program = report["program"]
        self.assertEqual(program["unreachable"], 0)
        self.assertGreaterEqual(program["min_link_nozzle_distance_mm"], 35.0 - 1e-6)
        self.assertGreaterEqual(program["min_link_part_distance_mm"], 15.0 - 1e-6)
        self.assertGreaterEqual(program["lowest_part_height_mm"], 20.0 - 1e-6)
        self.assertGreaterEqual(program["lowest_arm_height_mm"], 20.0 - 1e-6)
        with open(os.path.join(out, "orientation.csv")) as f:
            self.assertGreater(len(f.readlines()), 100)

    def test_the_knight_under_the_example_printhead_stays_out_of_the_plate(self):
        # Issue 15: no station or air move of the knight with the nozzle in the build plate. With
        # the default unbounded 45° cone its overhang stations (axes below the horizon under the
        # head) reach the plate slab and the gate stops it (test above); the real printhead ends,
        # and the auto-oriented knight's toolpath has every station (air moves included) clear of
        # the plate and the part: the collision gate passes, and the program is written.
        result, report, programs, out = self.run_cli(
            "decimated-knight.off", "--fit-size", "80", "--orient", "auto", "--printhead",
            os.path.join(TESTDATA, "printhead_slim.obj"))
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("print_part.script", programs)
        t = report["toolpath"]
        self.assertGreater(t["stations"], 100000)
        self.assertEqual(t["stations"], t["points"])  # every point a station, air moves included
        self.assertEqual(t["plate_stations"], 0)
        self.assertEqual(t["violating_stations"], 0)
        self.assertTrue(report["gates"]["collision"]["passed"])

    def test_a_wide_tilt_limit_still_tilts_the_least(self):
        # The Y under the example printhead: 33 stations collide along the layer normal, each is
        # cleared by a tilt below 11 degrees. With the 30 degree limit the projection off one
        # obstacle used to stop at a needless 30 degree tilt whose sweep hit the neighbours (31
        # stations left); the least tilt is searched first, so the limit changes nothing.
        result, report, programs, out = self.run_cli(
            "y_shape.obj", "--printhead", os.path.join(TESTDATA, "printhead_slim.obj"), "--until", "toolpath")
        self.assertEqual(result.returncode, 0, result.stderr)
        t = report["toolpath"]
        self.assertEqual(t["max_tilt_deg"], 30)
        self.assertEqual(t["violating_stations"], 0)
        self.assertGreater(t["colliding_stations_along_normal"], 0)
        self.assertLess(t["max_axis_tilt_deg"], 15)

    def test_split_sub_graphs_are_printed_as_pieces(self):
        # The knight as placed under the example printhead has sub-graphs that block each other
        # (58 forced steps measured); with --split-rounds some are cut into pieces (5 sub-graphs,
        # 55 forced steps): fewer forced steps, the lattice carries PieceId, and the toolpath
        # prints every piece (the gate decides as usual).
        result, report, programs, out = self.run_cli(
            "decimated-knight.off", "--fit-size", "80", "--printhead",
            os.path.join(TESTDATA, "printhead_slim.obj"), "--split-rounds", "3", "--until", "toolpath")
        self.assertEqual(result.returncode, 0, result.stderr)
        s = report["sequence"]
        self.assertGreater(s["split_for_order"], 0)
        self.assertGreater(s["pieces"], s["subgraphs"])
        self.assertLess(s["forced_steps"], s["forced_steps_before_split"])
        self.assertEqual(s["split_rounds"], 3)
        with open(os.path.join(out, "lattice.vtp"), "rb") as f:
            self.assertIn(b'Name="PieceId"', f.read())
        # Every piece printed: one tour per piece at least, one retraction fewer than tours.
        self.assertGreaterEqual(report["toolpath"]["tours"], s["pieces"])
        self.assertEqual(report["toolpath"]["retractions"], report["toolpath"]["tours"] - 1)

    def test_collision_gate_and_its_override(self):
        args = ["--edge-length", "2", "--strategy", "dpt", "--nozzle-angle", "75"]
        result, report, programs, out = self.run_cli("y_shape.obj", *args)
        self.expect_gate(result, report, programs, out, 4, "collision",
                         ["toolpath collides at", "stations", "see toolpath_collisions.vtp", "--allow-collisions"])
        self.assertGreater(report["toolpath"]["violating_stations"], 0)
        # The stations left are those no tilt within 30° clears: the stop suggests a larger limit.
        self.assertIn("--max-tilt 45", result.stderr)
        result, report, programs, out = self.run_cli("y_shape.obj", *args, "--allow-collisions")
        self.assertEqual(result.returncode, 0, result.stderr)
        lines = [l for l in result.stderr.splitlines() if l.strip()]
        self.assertEqual(len(lines), 1, result.stderr)
        self.assertIn("warning: toolpath collides at", lines[0])
        self.assertIn("print_part.script", programs)
        self.assertIn("waypoints.csv", programs)
        self.assertTrue(report["gates"]["collision"]["overridden"])

    def test_unreachable_gate_and_its_override(self):
        # The nozzle beyond the edge of the UR5's reach, 900 mm out and 400 mm up: no IK branch
        # reaches the path (until the eleventh session 880 mm left 14 points between coarse
        # samples out of reach; the plan on 2,000 samples now reaches them all, so a partly
        # reachable path is the filter test's: vtkGLURScriptWriter.UnreachablePointsAreReported
        # NotSkipped). (At 100 mm, below the shoulder, only branches with the elbow under the
        # robot's base reached it: since they are barred, the whole cell is unreachable.)
        args = ["--fit-size", "30", "--nozzle-tip", "900,0,400", "--no-layout-search"]
        result, report, programs, out = self.run_cli("cube.obj", *args)
        self.expect_gate(result, report, programs, out, 5, "reachability",
                         ["unreachable cell set-up", "15 mm off the part it holds"])
        self.assertIn("or try --orient auto", result.stderr)  # the part kept as placed
        self.assertEqual(report["program"]["unreachable"], report["toolpath"]["points"])
        # The program stage's own seconds (the writer ran before the gate), not the summary's.
        self.assertNotEqual(report["program"]["seconds"], report["summary"]["seconds"])
        # A cell that reaches no part of the path is not overridden: nothing to simulate.
        result, report, programs, out = self.run_cli("cube.obj", *args, "--allow-unreachable")
        self.expect_gate(result, report, programs, out, 5, "reachability", ["unreachable cell set-up"])

    def test_joint_gate_and_the_cell_layout_search(self):
        # The nozzle tip at the edge of the UR5's reach (860 mm out, 400 mm up): the Y's path as
        # laid out winds a joint to its limit when the whole path keeps one IK branch (steps 1-3
        # of the path solver, on 500 and on 2,000 samples).
        result, report, programs, out = self.run_cli("y_shape.obj", "--nozzle-tip", "860,0,400",
                                                     "--no-layout-search", "--no-reconfiguration")
        self.assertEqual(result.returncode, 6, result.stderr)
        lines = [l for l in result.stderr.splitlines() if l.strip()]
        self.assertEqual(len([l for l in lines if l.startswith("geolattice: stopped: ")]), 1, result.stderr)
        self.assertIn("jumps by", result.stderr)
        self.assertIn("wound to its limit", result.stderr)
        self.assertIn("reconfiguration, off here, turns it back at an air move", result.stderr)
        self.assertIn("or try --orient auto", result.stderr)  # the part kept as placed
        self.assertNotIn("raise", result.stderr)  # no advice to raise the bound
        self.assertEqual(programs, [])
        self.assertFalse(report["gates"]["joints"]["passed"])
        self.assertFalse(report["program"]["reconfigure"])
        # With reconfiguration (the default), step 4 turns the wound joint back a full turn at
        # the last air move before it, in the same IK branch (twelfth session; until then it
        # was refused the same way).
        result, report, programs, out = self.run_cli("y_shape.obj", "--nozzle-tip", "860,0,400",
                                                     "--no-layout-search")
        self.assertEqual(result.returncode, 0, result.stderr)
        program = report["program"]
        self.assertLessEqual(program["max_joint_step_deg"], 20.0)
        self.assertEqual(program["unreachable"], 0)
        unwinds = [r for r in program["reconfigurations"] if r["from_branch"] == r["to_branch"]]
        self.assertGreaterEqual(len(unwinds), 1, program["reconfigurations"])
        scripts = ""
        for name in programs:
            if name.endswith(".script"):
                with open(os.path.join(out, name)) as f:
                    scripts += f.read()
        self.assertIn("turned back a full turn", scripts)
        # The bound is not the way out: above 30 degrees it is refused.
        r = subprocess.run([CLI, "run", os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "-o",
                            os.path.join(self.tmp, "bound"), "-q", "--max-joint-step", "360"],
                           capture_output=True, text=True, timeout=300)
        self.assertEqual(r.returncode, 1)
        self.assertIn("--max-joint-step must be in (0, 30]", r.stderr)
        # The nozzle pointing along the robot's +x axis. With the arm checked as its body
        # (twelfth session: core/robot/ArmCapsules.h) one IK branch over the whole path steps a
        # joint by 24 degrees twice in the cell as given: the joint gate stops it ...
        cell = ["--nozzle-tip", "0,-400,350", "--nozzle-axis", "1,0,0", "--allow-collisions"]
        result, report, programs, out = self.run_cli("y_shape.obj", *cell, "--no-layout-search",
                                                     "--no-reconfiguration")
        self.assertEqual(result.returncode, 6, result.stderr)
        self.assertIn("jumps by", result.stderr)
        self.assertEqual(programs, [])
        # ... and the cell layout search finds a mounting of the part on the flange that one
        # branch follows (measured: turned 225 degrees about the flange's z axis, 60 mm further
        # out), and writes the program for it, saying so.
        result, report, programs, out = self.run_cli("y_shape.obj", *cell, "--no-reconfiguration")
        self.assertEqual(result.returncode, 0, result.stderr)
        layout = report["program"]["layout"]
        self.assertTrue(layout["searched"])
        self.assertTrue(layout["changed"])
        self.assertGreater(layout["layouts_tried"], 1)
        self.assertNotEqual((layout["rotation_about_flange_z_deg"], layout["offset_added_mm"]),
                            (0.0, 0.0))
        self.assertLessEqual(report["program"]["max_joint_step_deg"], 20.0)
        self.assertEqual(report["program"]["unreachable"], 0)
        self.assertEqual(report["program"]["reconfigurations"], [])
        with open(os.path.join(out, "print_part.script")) as f:
            self.assertIn("# cell layout: the platform turned by", f.read())
        # With the defaults (step 4: one IK branch per stretch, flips barred, reconfigurations at
        # air moves where needed) the path is followed in the cell as given; where the wrist
        # passes near its singularity the program has waypoints between points.
        result, report, programs, out = self.run_cli("y_shape.obj", *cell)
        self.assertEqual(result.returncode, 0, result.stderr)
        program = report["program"]
        self.assertFalse(program["layout"]["changed"])
        self.assertTrue(program["reconfigure"])
        self.assertLessEqual(program["max_joint_step_deg"], 20.0)
        self.assertEqual(program["large_joint_steps"], 0)
        self.assertEqual(program["unreachable"], 0)
        self.assertIn("print_part.script", programs)
        seams = sum(1 for r in program["reconfigurations"] if r["at_seam"])
        self.assertGreater(program["via_segments"], 0)
        scripts = ""  # every program file of the split program
        for name in programs:
            if name.endswith(".script"):
                with open(os.path.join(out, name)) as f:
                    scripts += f.read()
        self.assertEqual(scripts.count("# reconfiguration "), len(program["reconfigurations"]))
        self.assertEqual(scripts.count(" waypoint(s) between toolpath points "), program["via_segments"])
        # A change at an air move replaces one move by two; a seam adds two.
        self.assertEqual(scripts.count("\n  movel(p["),
                         program["waypoints"] - 1 + program["via_waypoints"] +
                         len(program["reconfigurations"]) + seams)
        for r in program["reconfigurations"]:
            self.assertGreaterEqual(r["clearance_mm"], 20.0 - 1e-6)
            self.assertGreater(r["retreat_mm"], 0)


class CliVerifyTest(unittest.TestCase):
    """`geolattice verify OUTDIR`: exit 0 when collision-free, 3 on a collision, 1 on an error."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="geolattice-verify-")
        cls.out = os.path.join(cls.tmp, "y")
        run = subprocess.run([CLI, "run", os.path.join(TESTDATA, "y_shape.obj"), "-o", cls.out, "--edge-length", "2",
                              "--strategy", "dpt", "--nozzle-angle", "75", "--allow-collisions", "-q"], capture_output=True, text=True,
                             timeout=600)
        assert run.returncode == 0, run.stderr

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def verify(self, *args):
        return subprocess.run([CLI, "verify", *args], capture_output=True, text=True, timeout=300)

    def test_outputs_of_the_sequence_stage(self):
        for name in ("skeleton.vtp", "sequence.vtp", "sequence.csv", "collisions.vtp", "lattice.vtp"):
            self.assertTrue(os.path.isfile(os.path.join(self.out, name)), name)
        with open(os.path.join(self.out, "sequence.csv")) as f:
            rows = f.read().splitlines()
        self.assertEqual(rows[0].split(",")[:3], ["order", "subgraph", "layer"])
        with open(os.path.join(self.out, "report.json")) as f:
            seq = json.load(f)["sequence"]
        self.assertEqual(len(rows) - 1, seq["subgraphs"])
        self.assertIsInstance(seq["collision_free"], bool)
        for key in ("strategy", "nozzle_angle_deg", "retractions", "air_length_mm", "seconds"):
            self.assertIn(key, seq)

    def test_outputs_of_the_toolpath_stage(self):
        with open(os.path.join(self.out, "report.json")) as f:
            report = json.load(f)
        tp = report["toolpath"]
        for key in ("print_length_mm", "perimeter_length_mm", "air_length_mm", "retractions", "tours", "crossings",
                    "split_subgraphs", "thickness_dev_min", "thickness_dev_max", "filament_mm", "volume_mm3",
                    "seconds", "verify_seconds", "points", "path_width_mm", "replay_steps", "stations",
                    "violating_stations", "unavoidable_stations"):
            self.assertIn(key, tp)
        self.assertIsInstance(tp["collision_free"], bool)
        self.assertIsInstance(tp["order_collision_free"], bool)
        self.assertGreater(tp["print_length_mm"], 0)
        self.assertGreater(tp["filament_mm"], 0)
        self.assertEqual(tp["crossings"], 0)
        self.assertGreaterEqual(tp["tours"], report["sequence"]["subgraphs"])
        self.assertEqual(tp["stations"], tp["points"])  # every toolpath point is a nozzle station
        self.assertLessEqual(tp["thickness_dev_min"], tp["thickness_dev_max"])
        # GL Print Summary's table (what the GUI's spreadsheet shows) agrees with the stage's report.
        summary = report["summary"]
        self.assertEqual(summary["points"], tp["points"])
        self.assertEqual(summary["tours"], tp["tours"])
        self.assertEqual(summary["retractions"], tp["retractions"])
        self.assertTrue(0 < summary["layers"] <= report["layers"]["count"])
        self.assertAlmostEqual(summary["filament_m"] * 1000, tp["filament_mm"], places=6)
        self.assertAlmostEqual(summary["air_length_mm"], tp["air_length_mm"], delta=1e-6 * tp["air_length_mm"])
        self.assertEqual(bool(summary["collision_free"]), tp["collision_free"])
        self.assertEqual(summary["stations"], tp["stations"])
        self.assertEqual(summary["colliding_stations"], tp["violating_stations"])
        self.assertEqual(summary["plate_stations"], tp["plate_stations"])
        self.assertGreater(summary["print_time_min"], tp["print_length_mm"] / tp["print_speed_mm_s"] / 60 * 0.99)
        self.assertGreater(summary["filament_g"], 0)
        self.assertIsInstance(summary["verdict"], str)
        # Each section's seconds are its own stage's (they once took the toolpath check's).
        self.assertNotEqual(summary["seconds"], tp["verify_seconds"])
        for name in ("toolpath.vtp", "toolpath.pvd", "toolpath_collisions.vtp"):
            self.assertTrue(os.path.isfile(os.path.join(self.out, name)), name)

        def points_in(path):
            with open(path, "rb") as f:
                head = f.read(100000).decode("latin-1")
            return int(re.search(r'<Piece NumberOfPoints="(\d+)"', head).group(1))

        self.assertEqual(points_in(os.path.join(self.out, "toolpath.vtp")), tp["points"])
        # The replay: at time k / S the pieces 1..k (parts 0..k-1; the others the empty file), piece k the
        # points printed between progress (k - 1) / S and k / S, its first one shared with piece k - 1.
        import xml.etree.ElementTree as ET
        sets = ET.parse(os.path.join(self.out, "toolpath.pvd")).getroot().findall("./Collection/DataSet")
        steps = tp["replay_steps"]
        self.assertTrue(1 <= steps <= 50)
        self.assertEqual(len(sets), steps * steps)
        self.assertEqual(sorted(os.listdir(os.path.join(self.out, "toolpath"))),
                         ["empty.vtp"] + ["step_%04d.vtp" % k for k in range(1, steps + 1)])
        self.assertEqual(points_in(os.path.join(self.out, "toolpath", "empty.vtp")), 0)
        pieces = [points_in(os.path.join(self.out, "toolpath", "step_%04d.vtp" % k)) for k in range(1, steps + 1)]
        self.assertEqual(sum(pieces), tp["points"] + steps - 1)  # the toolpath once, not once per step
        times = sorted({float(d.get("timestep")) for d in sets})
        self.assertEqual(len(times), steps)
        self.assertEqual(times[-1], 1.0)
        for k, t in enumerate(times, start=1):
            listed = [d for d in sets if float(d.get("timestep")) == t]
            self.assertEqual(sorted(int(d.get("part")) for d in listed), list(range(steps)))
            shown = sum(points_in(os.path.join(self.out, d.get("file"))) for d in listed)
            # GL Toolpath Replay's rule, std::llround: halves away from zero (Python's round() takes
            # them to the even neighbour)
            self.assertEqual(shown - (k - 1), math.floor(t * (tp["points"] - 1) + 0.5) + 1)

    def test_outputs_of_the_program_stage(self):
        with open(os.path.join(self.out, "report.json")) as f:
            report = json.load(f)
        program = report["program"]
        for key in ("waypoints", "unreachable", "unreachable_first", "files", "max_joint_step_deg",
                    "via_segments", "via_waypoints", "min_singularity", "max_joint_speed_deg_s", "duration_s", "seconds", "robot", "nozzle_tip_mm",
                    "part_on_flange", "gcode", "csv"):
            self.assertIn(key, program)
        self.assertEqual(program["waypoints"], report["toolpath"]["points"])
        self.assertEqual(program["unreachable"], 0)
        self.assertEqual(program["unreachable_first"], [])
        self.assertEqual(sorted(program["min_singularity"]), ["elbow", "shoulder_m", "wrist"])
        self.assertGreater(program["min_singularity"]["wrist"], 0)
        self.assertGreater(program["max_joint_step_deg"], 0)
        self.assertLessEqual(program["max_joint_speed_deg_s"], 90 + 1e-6)  # half the 180 deg/s limits
        self.assertGreater(program["duration_s"], 0)
        self.assertEqual(program["files"][0], "print_part.script")
        movels = 0
        for name in program["files"]:
            with open(os.path.join(self.out, name)) as f:
                movels += check_urscript(self, f.read(), name[:-len(".script")], program["max_script_bytes"])
        self.assertEqual(movels, program["waypoints"] - 1)
        with open(os.path.join(self.out, "waypoints.csv")) as f:
            rows = f.read().splitlines()
        self.assertEqual(rows[0], "x,y,z,nx,ny,nz,e,kind,layer")
        self.assertEqual(len(rows) - 1, program["waypoints"])
        self.assertEqual(program["gcode"]["file"], "toolpath.gcode")
        with open(os.path.join(self.out, "toolpath.gcode")) as f:
            gcode = f.read().splitlines()
        self.assertEqual(sum(1 for l in gcode if re.match(r"G[01] X", l)), program["waypoints"])
        self.assertEqual(gcode[-2:], ["G94", "M2"])
        print("\n[cli program] Y: %d waypoints, %d file(s), max joint step %.2f deg, unreachable %d, "
              "%.0f s of printing" % (program["waypoints"], len(program["files"]), program["max_joint_step_deg"],
                                     program["unreachable"], program["duration_s"]))

    def test_verify_checks_the_newer_of_toolpath_and_lattice(self):
        toolpath = self.verify(self.out, "--nozzle-angle", "5")
        self.assertEqual(toolpath.returncode, 0, toolpath.stdout + toolpath.stderr)
        self.assertIn("verify: toolpath.vtp", toolpath.stdout)
        stations = int(re.search(r"(\d+) nozzle stations", toolpath.stdout).group(1))
        with open(os.path.join(self.out, "report.json")) as f:
            self.assertEqual(stations, json.load(f)["toolpath"]["points"])
        # A copy whose lattice.vtp is newer (as after a later `run --until sequence`).
        copy = os.path.join(self.tmp, "lattice-newer")
        shutil.copytree(self.out, copy)
        later = os.path.getmtime(os.path.join(copy, "toolpath.vtp")) + 10
        os.utime(os.path.join(copy, "lattice.vtp"), (later, later))
        lattice = self.verify(copy, "--nozzle-angle", "5")
        self.assertEqual(lattice.returncode, 0, lattice.stdout + lattice.stderr)
        self.assertIn("verify: lattice.vtp", lattice.stdout)
        # Only a toolpath: it is checked.
        os.remove(os.path.join(copy, "lattice.vtp"))
        only = self.verify(copy, "--nozzle-angle", "5")
        self.assertEqual(only.returncode, 0, only.stdout + only.stderr)
        self.assertIn("verify: toolpath.vtp", only.stdout)

    def test_depth_first_collides_and_slender_nozzle_does_not(self):
        # Depth first on the Y: one branch is finished before the other starts; a 75° nozzle on
        # the second branch reaches the first one.
        wide = self.verify(self.out)
        self.assertEqual(wide.returncode, 3, wide.stdout + wide.stderr)
        self.assertIn("stations with earlier material inside the nozzle", wide.stdout)
        slim = self.verify(self.out, "--nozzle-angle", "5")
        self.assertEqual(slim.returncode, 0, slim.stdout + slim.stderr)
        self.assertIn("collision-free", slim.stdout)

    def test_errors(self):
        missing = self.verify(os.path.join(self.tmp, "nowhere"))
        self.assertEqual(missing.returncode, 1)
        self.assertIn("not found", missing.stderr)
        self.assertIn("toolpath.vtp", missing.stderr)
        bad = self.verify(self.out, "--nozzle-angle", "90")
        self.assertEqual(bad.returncode, 1)
        self.assertEqual(len(bad.stderr.strip().splitlines()), 1)
        self.assertIn("nozzle angle", bad.stderr)
        usage = self.verify()
        self.assertEqual(usage.returncode, 2)
        # A lattice without PrintOrder (the lattice stage only).
        early = os.path.join(self.tmp, "early")
        run = subprocess.run([CLI, "run", os.path.join(TESTDATA, "cube.obj"), "--fit-size", "10", "--until",
                              "lattice", "-o", early, "-q"], capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stderr)
        no_order = self.verify(early)
        self.assertEqual(no_order.returncode, 1)
        self.assertIn("PrintOrder", no_order.stderr)


class CliProgressTest(unittest.TestCase):
    """One progress line per stage on stdout ("geolattice: STAGE ... done (S s)"), with the filter's
    progress as 25% 50% 75% on the long stages; -q prints nothing."""

    STAGES = ["input", "mesh", "gdf", "layers", "overhang", "lattice", "skeleton", "sequence", "verify", "toolpath",
              "verify toolpath", "summary", "program"]
    WITH_PERCENT = {"mesh", "gdf", "lattice", "sequence", "toolpath", "program"}

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="geolattice-progress-")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def run_cube(self, *extra):
        return subprocess.run([CLI, "run", os.path.join(TESTDATA, "cube.obj"), "--fit-size", "20", "-o",
                               os.path.join(self.tmp, "out"), *extra], capture_output=True, text=True, timeout=300)

    def test_a_line_per_stage_with_percentages_on_the_long_ones(self):
        run = self.run_cube()
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        lines = [l for l in run.stdout.splitlines() if l.startswith("geolattice: ") and " ... " in l]
        self.assertEqual([l[len("geolattice: "):l.index(" ... ")] for l in lines], self.STAGES, run.stdout)
        for stage, line in zip(self.STAGES, lines):
            percent = " 25% 50% 75%" if stage in self.WITH_PERCENT else ""
            self.assertRegex(line, r"^geolattice: %s \.\.\.%s done \([0-9.e-]+ s\)$" % (re.escape(stage), percent))

    def test_quiet_prints_nothing(self):
        run = self.run_cube("-q", "--until", "lattice")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(run.stdout, "")
        self.assertEqual(run.stderr, "")


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
