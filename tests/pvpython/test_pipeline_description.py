"""The pipeline is defined once: the pvpython module (pvpython/geolattice_pipeline.py, used by the
GUI and state scripts) builds the same stages, filter classes and connections as the C++ pipeline
the command-line tool runs (filters/GLPrintPipeline.h, `geolattice --describe-pipeline`)."""
import json
import os
import shutil
import tempfile
import subprocess
import sys
import unittest
import xml.etree.ElementTree as ET

SOURCE_DIR = os.environ["GEOLATTICE_SOURCE_DIR"]
CLI = os.environ["GEOLATTICE_CLI"]
sys.path.insert(0, os.path.join(SOURCE_DIR, "pvpython"))

import geolattice_pipeline as pipeline  # noqa: E402
from paraview import servermanager, simple  # noqa: E402

# Python key -> C++ stage name.
KEYS = {"reader": "read", "place": "place", "orient": "orient", "pedestal": "pedestal", "tets": "mesh", "fields": "fields", "layers": "layers",
        "overhang": "overhang", "lattice": "lattice", "skeleton": "skeleton", "sequencer": "sequence",
        "verifier": "sequence-verify", "toolpath": "toolpath", "toolpath_verifier": "toolpath-verify",
        "summary": "summary", "replay": "replay"}


class PipelineDescriptionTest(unittest.TestCase):
    def test_same_stages_classes_and_connections(self):
        cpp = {}
        out = subprocess.run([CLI, "--describe-pipeline"], capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            name, cls, *inputs = line.split("\t")
            cpp[name] = (cls, sorted(inputs))
        pipeline.load_plugin()
        p = pipeline.build_pipeline(os.path.join(SOURCE_DIR, "testdata", "cube.obj"))
        python = {}
        by_proxy = {}
        for key, proxy in p.items():
            by_proxy[proxy.SMProxy.GetGlobalIDAsString()] = KEYS[key]
        for key, proxy in p.items():
            inputs = []
            for port, (name, _) in enumerate(pipeline.STAGES[[s[0] for s in pipeline.STAGES].index(key)][2].items()):
                source = proxy.GetProperty(name)
                producer = source.GetData()
                producer_proxy = producer.Proxy if hasattr(producer, "Proxy") else producer
                index = producer.Port if hasattr(producer, "Port") else 0
                inputs.append("%d:%s.%d" % (port, by_proxy[producer_proxy.SMProxy.GetGlobalIDAsString()], index))
            python[KEYS[key]] = (proxy.SMProxy.GetVTKClassName(), sorted(inputs))
        self.assertEqual(sorted(python), sorted(cpp))
        for stage in cpp:
            with self.subTest(stage=stage):
                self.assertEqual(python[stage], cpp[stage])

    def test_shared_nozzle_parameters_reach_every_nozzle_filter(self):
        # The printhead (like the nozzle angle) is one keyword for the five filters with a nozzle.
        pipeline.load_plugin()
        head = os.path.join(SOURCE_DIR, "testdata", "printhead_slim.obj")
        p = pipeline.build_pipeline(os.path.join(SOURCE_DIR, "testdata", "cube.obj"), printhead=head,
                                    pedestal=5, split_rounds=2)
        for key in ("orient", "sequencer", "verifier", "toolpath", "toolpath_verifier"):
            with self.subTest(stage=key):
                self.assertEqual(p[key].PrintheadFile, head)
        self.assertEqual(pipeline.get_property(p["pedestal"], "Height"), 5)
        self.assertEqual(p["sequencer"].SplitRounds, 2)

    def test_the_filters_menu_lists_every_filter_once_in_pipeline_order(self):
        # plugin/GeoLatticeMenu.xml (Filters > GeoLattice, preserve_order) against the stages and the
        # plugin's filter proxies: a new filter must be placed in the menu too.
        menu = ET.parse(os.path.join(SOURCE_DIR, "plugin", "GeoLatticeMenu.xml")).getroot()
        listed = [p.get("name") for p in menu.iter("Proxy")]
        declared = set()
        for name in os.listdir(os.path.join(SOURCE_DIR, "plugin", "xml")):
            root = ET.parse(os.path.join(SOURCE_DIR, "plugin", "xml", name)).getroot()
            for group in root.iter("ProxyGroup"):
                if group.get("name") == "filters":
                    declared.update(proxy.get("name") for proxy in group if proxy.get("name"))
        in_stage_order = []
        for _, proxy, _ in pipeline.STAGES:
            if proxy in declared and proxy not in in_stage_order:
                in_stage_order.append(proxy)
        # Diagnostics, not stages: each just before the stage whose input it checks.
        for diagnostic, stage in (("GLSurfaceCheck", "GLTetrahedralizeSurface"),):
            in_stage_order.insert(in_stage_order.index(stage), diagnostic)
        self.assertEqual(listed, ["GLPrintPart"] + in_stage_order)  # the whole pipeline first
        self.assertEqual(set(listed), declared)
        self.assertEqual(menu.find("Category").get("preserve_order"), "1")

    def test_print_part_summary_equals_the_command_lines_report(self):
        # One Apply in ParaView (GL Print Part, defaults) and `geolattice run` (defaults) on the Y:
        # the same summary, value for value (issue 20's acceptance, without the GUI around it).
        model = os.path.join(SOURCE_DIR, "testdata", "y_shape.obj")
        out = tempfile.mkdtemp(prefix="geolattice-part-")
        try:
            subprocess.run([CLI, "run", model, "-o", out, "-q", "--until", "toolpath", "--replay-steps", "0"],
                           check=True, capture_output=True, text=True)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)["summary"]
        finally:
            shutil.rmtree(out, ignore_errors=True)
        pipeline.load_plugin()
        part = simple.GLPrintPart(Input=simple.GLMeshReader(FileName=model))
        part.UpdatePipeline()
        table = servermanager.Fetch(part, idx=1)
        rows = pipeline.summary_values(table)
        verdict = table.GetFieldData().GetAbstractArray("SummaryVerdict").GetValue(0)
        self.assertEqual(verdict, report.pop("verdict"))
        report.pop("seconds")  # the stage time the command line adds to every section
        self.assertEqual(sorted(rows), sorted(report))
        for key, value in report.items():
            with self.subTest(key=key):
                self.assertAlmostEqual(rows[key], value, delta=1e-9 * max(1.0, abs(value)))

    def test_the_command_lines_replay_plays_in_paraview(self):
        # toolpath.pvd opened by ParaView's own PVD reader: at each of its times the pieces show the path GL
        # Toolpath Replay shows at that progress (the same segments), and all pieces together hold the
        # toolpath once.
        model = os.path.join(SOURCE_DIR, "testdata", "cube.obj")
        out = tempfile.mkdtemp(prefix="geolattice-replay-")
        try:
            subprocess.run([CLI, "run", model, "-o", out, "-q", "--fit-size", "10", "--until", "toolpath",
                            "--replay-steps", "7"], check=True, capture_output=True, text=True)
            pipeline.load_plugin()
            pvd = simple.OpenDataFile(os.path.join(out, "toolpath.pvd"))
            self.assertEqual(pvd.GetXMLName(), "PVDReader")
            times = list(pvd.TimestepValues)
            self.assertEqual(len(times), 7)
            replay = simple.GLToolpathReplay(Input=simple.OpenDataFile(os.path.join(out, "toolpath.vtp")))

            def segments(data):
                lines = data.GetLines()
                return lines.GetNumberOfConnectivityIds() - lines.GetNumberOfCells()

            for t in times:
                with self.subTest(time=t):
                    pvd.UpdatePipeline(t)
                    blocks = servermanager.Fetch(pvd)
                    leaves = []
                    it = blocks.NewIterator()
                    it.InitTraversal()
                    while not it.IsDoneWithTraversal():
                        leaves.append(it.GetCurrentDataObject())
                        it.GoToNextItem()
                    self.assertEqual(len(leaves), 7)  # one per part, empty after the current step
                    shown = sum(segments(leaf) for leaf in leaves)
                    replay.UpdatePipeline(t)
                    self.assertEqual(shown, segments(servermanager.Fetch(replay)))
        finally:
            shutil.rmtree(out, ignore_errors=True)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
