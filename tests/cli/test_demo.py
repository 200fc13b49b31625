#!/usr/bin/env python3
"""The README's first command ends with scripts/demo.sh's `geolattice run` line: it must give a
collision-free, reachable program on the bundled bunny (exit 0, the robot program and G-code
written). The line is read from demo.sh, so the test and the README cannot drift apart."""
import json
import os
import re
import shlex
import subprocess
import tempfile
import unittest

SOURCE = os.environ["GEOLATTICE_SOURCE_DIR"]
CLI = os.environ["GEOLATTICE_CLI"]


def demo_arguments(out):
    with open(os.path.join(SOURCE, "scripts", "demo.sh")) as f:
        line = next(l for l in f if re.match(r'\s*"\$root/build/bin/geolattice" run ', l))
    args = shlex.split(line.replace("$root", SOURCE))[1:]
    args[args.index("-o") + 1] = out
    return args


class DemoTest(unittest.TestCase):
    def test_the_demo_prints(self):
        with tempfile.TemporaryDirectory() as out:
            result = subprocess.run([CLI, *demo_arguments(out)], capture_output=True, text=True,
                                    timeout=600)
            self.assertEqual(result.returncode, 0, result.stderr)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            self.assertEqual(report["toolpath"]["violating_stations"], 0)
            self.assertEqual(report["toolpath"]["plate_stations"], 0)
            self.assertTrue(all(g["passed"] for g in report["gates"].values()), report["gates"])
            for name in ("print_part.script", "toolpath.gcode", "waypoints.csv"):
                self.assertTrue(os.path.exists(os.path.join(out, name)), name)
            # In the cell as given: the robot path solver's reconfiguration step keeps planning
            # while its plans find large joint steps at new places (this path: 1, 1, 6, 0), where
            # it once gave up after two plans and the cell layout search moved the part 30 mm.
            self.assertFalse(report["program"]["layout"]["changed"], report["program"]["layout"])


if __name__ == "__main__":
    unittest.main(verbosity=2)
