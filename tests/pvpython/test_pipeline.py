"""pvpython end-to-end test: load the GeoLattice plugin, run reader -> placement -> meshing ->
geodesic fields on a test model, check array names (taken from filters/vtkGLArrayNames.h, not
retyped) and ranges, save with the pipeline script's writer and read the file back."""
import os
import re
import shutil
import sys
import tempfile
import unittest

SOURCE_DIR = os.environ["GEOLATTICE_SOURCE_DIR"]
sys.path.insert(0, os.path.join(SOURCE_DIR, "pvpython"))

import geolattice_pipeline as pipeline  # noqa: E402
from paraview import simple, servermanager  # noqa: E402


def array_names():
    """The constants of filters/vtkGLArrayNames.h as a dict: C++ name -> array name."""
    with open(os.path.join(SOURCE_DIR, "filters", "vtkGLArrayNames.h")) as f:
        return dict(re.findall(r'constexpr const char\*\s+(\w+)\s*=\s*"([^"]+)"', f.read()))


NAMES = array_names()


class PipelineTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        pipeline.load_plugin()
        cls.out = tempfile.mkdtemp(prefix="geolattice-pvpython-")
        model = os.path.join(SOURCE_DIR, "testdata", "bunny.obj")
        cls.proxies = pipeline.build_pipeline(model, fit_size=40.0, edge_length=2.5, base_tolerance=0.5)
        cls.proxies["fields"].UpdatePipeline()
        cls.fields = servermanager.Fetch(cls.proxies["fields"])

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.out, ignore_errors=True)

    def test_fields_have_named_arrays_and_sane_ranges(self):
        f = self.fields
        self.assertGreater(f.GetNumberOfCells(), 1000)
        pd, cd = f.GetPointData(), f.GetCellData()
        for key in ("Gamma", "Alpha", "Beta", "HeatSource"):
            self.assertIsNotNone(pd.GetArray(NAMES[key]), key)
        for key in ("GammaGradient", "AlphaDirection", "BetaDirection"):
            a = cd.GetArray(NAMES[key])
            self.assertIsNotNone(a, key)
            self.assertEqual(a.GetNumberOfComponents(), 3)
        gamma = pd.GetArray(NAMES["Gamma"]).GetRange()
        bounds = f.GetBounds()
        height = bounds[5] - bounds[4]
        self.assertEqual(gamma[0], 0.0)
        # Geodesic distance from the base is at least the height and not much more for a bunny.
        self.assertGreater(gamma[1], 0.95 * height)
        self.assertLess(gamma[1], 1.6 * height)
        for key in ("Alpha", "Beta"):
            lo, hi = pd.GetArray(NAMES[key]).GetRange()
            self.assertAlmostEqual(lo, 0.0, places=9)
            self.assertGreater(hi, 10.0)
        self.assertAlmostEqual(bounds[4], 0.0, places=9)  # base on the platform
        self.assertAlmostEqual(max(bounds[1] - bounds[0], bounds[3] - bounds[2], height), 40.0, places=6)
        fd = f.GetFieldData()
        for key in ("GammaRange", "GdfTimings", "OrthogonalityDeg", "SourceCount"):
            self.assertIsNotNone(fd.GetArray(NAMES[key]), key)

    def test_layers_follow_the_count_formula(self):
        self.proxies["layers"].UpdatePipeline()
        layers = servermanager.Fetch(self.proxies["layers"])
        gamma_max = self.fields.GetPointData().GetArray(NAMES["Gamma"]).GetRange()[1]
        expected = int((gamma_max - 0.6) // 0.6) + 1
        self.assertEqual(layers.GetFieldData().GetArray(NAMES["LayerValues"]).GetNumberOfTuples(), expected)
        ids = layers.GetCellData().GetArray(NAMES["LayerId"]).GetRange()
        self.assertEqual(ids, (0.0, expected - 1.0))
        self.assertIsNotNone(layers.GetPointData().GetArray(NAMES["Normals"]))

    def test_curved_layers_need_less_support_than_planar(self):
        self.proxies["overhang"].UpdatePipeline()
        surface = servermanager.Fetch(self.proxies["overhang"])
        fd = surface.GetFieldData()
        planar = fd.GetArray(NAMES["OverhangPlanarFraction"]).GetValue(0)
        curved = fd.GetArray(NAMES["OverhangCurvedFraction"]).GetValue(0)
        self.assertGreater(planar, 0.05)
        self.assertLess(curved, 0.5 * planar)
        for key in ("OverhangPlanar", "OverhangCurved"):
            self.assertIsNotNone(surface.GetCellData().GetArray(NAMES[key]), key)

    def test_lattice_has_documented_arrays(self):
        self.proxies["lattice"].UpdatePipeline()
        lattice = servermanager.Fetch(self.proxies["lattice"])
        self.assertGreater(lattice.GetNumberOfCells(), 100)
        for key in ("VertexKind", "Degree", "NozzleAxis", "Gamma"):
            self.assertIsNotNone(lattice.GetPointData().GetArray(NAMES[key]), key)
        # Not the active normals: ParaView would light the lines with them (layers facing away
        # from the camera render black).
        self.assertIsNone(lattice.GetPointData().GetNormals())
        for key in ("EdgeKind", "LayerId", "SubgraphId"):
            self.assertIsNotNone(lattice.GetCellData().GetArray(NAMES[key]), key)
        fd = lattice.GetFieldData()
        self.assertGreater(fd.GetArray(NAMES["LatticeCrossings"]).GetValue(0), 0)
        self.assertEqual(fd.GetArray(NAMES["LatticeEdges"]).GetValue(0), lattice.GetNumberOfCells())

    def test_skeleton_sequence_and_collision_check(self):
        self.proxies["verifier"].UpdatePipeline()
        lattice = servermanager.Fetch(self.proxies["lattice"])
        skeleton = servermanager.Fetch(self.proxies["skeleton"])
        subgraphs = int(lattice.GetFieldData().GetArray(NAMES["LatticeSubgraphs"]).GetValue(0))
        self.assertGreater(subgraphs, 10)
        self.assertEqual(skeleton.GetNumberOfPoints(), subgraphs)
        self.assertGreater(skeleton.GetNumberOfCells(), 0)
        for key in ("NodeId", "LayerId", "SubgraphId", "Gamma", "SubgraphLength", "LowerCount", "UpperCount"):
            self.assertIsNotNone(skeleton.GetPointData().GetArray(NAMES[key]), key)
        for key in ("SkeletonRoots", "SkeletonFloatingNodes", "SkeletonMergeNodes", "SkeletonSplitNodes",
                    "SkeletonSeconds", "LayerValues"):
            self.assertIsNotNone(skeleton.GetFieldData().GetArray(NAMES[key]), key)
        self.assertGreaterEqual(skeleton.GetFieldData().GetArray(NAMES["SkeletonSplitNodes"]).GetValue(0), 1)  # ears

        sequencer = self.proxies["sequencer"]
        sequenced = servermanager.Fetch(sequencer, idx=0)
        nodes = servermanager.Fetch(sequencer, idx=1)
        order = servermanager.Fetch(sequencer, idx=2)
        self.assertEqual(sequenced.GetNumberOfCells(), lattice.GetNumberOfCells())
        self.assertIsNotNone(sequenced.GetCellData().GetArray(NAMES["PrintOrder"]))
        self.assertIsNotNone(sequenced.GetPointData().GetArray(NAMES["PrintOrder"]))
        positions = nodes.GetPointData().GetArray(NAMES["PrintOrder"])
        self.assertEqual(sorted(int(positions.GetValue(i)) for i in range(subgraphs)), list(range(subgraphs)))
        self.assertEqual(order.GetNumberOfPoints(), subgraphs)
        retraction = order.GetCellData().GetArray(NAMES["Retraction"])
        self.assertEqual(order.GetNumberOfCells(), subgraphs - 1)
        for data in (sequenced, nodes, order):
            fd = data.GetFieldData()
            self.assertEqual(fd.GetAbstractArray(NAMES["SequenceStrategy"]).GetValue(0), "best")
            for key in ("SequenceRetractions", "SequenceAirLength", "SequenceForcedSteps", "SequenceSeconds",
                        "SequencePcgPairs", "SequencePcgSeconds", "SequenceUnavoidablePairs", "NozzleAngleDeg",
                        "SequenceOrder", "SequenceStart", "SequenceEnd", "SkeletonEdges"):
                self.assertIsNotNone(fd.GetArray(NAMES[key]), key)
        fd = order.GetFieldData()
        self.assertEqual(sum(retraction.GetValue(i) for i in range(retraction.GetNumberOfTuples())),
                         fd.GetArray(NAMES["SequenceRetractions"]).GetValue(0))
        self.assertEqual(fd.GetArray(NAMES["SequenceStart"]).GetNumberOfComponents(), 3)
        self.assertGreater(fd.GetArray(NAMES["SequencePcgPairs"]).GetValue(0), 0)

        collisions = servermanager.Fetch(self.proxies["verifier"])
        cfd = collisions.GetFieldData()
        for key in ("CollisionFree", "CollisionOrderFree", "CollisionStations", "CollisionViolatingStations",
                    "CollisionUnavoidableStations", "CollisionSeconds"):
            self.assertIsNotNone(cfd.GetArray(NAMES[key]), key)
        self.assertGreater(cfd.GetArray(NAMES["CollisionStations"]).GetValue(0), lattice.GetNumberOfPoints())
        # The independent verifier (same nozzle, same samples) agrees with A4: no avoidable collision exactly
        # when no step had to be forced. On this small bunny the nozzle over curved layers reaches material
        # of skeleton ancestors (unavoidable in every order), so the strict CollisionFree is 0.
        forced = fd.GetArray(NAMES["SequenceForcedSteps"]).GetValue(0)
        order_free = cfd.GetArray(NAMES["CollisionOrderFree"]).GetValue(0)
        self.assertEqual(order_free == 1, forced == 0,
                         "CollisionOrderFree %d with %d forced steps" % (order_free, forced))
        violating = cfd.GetArray(NAMES["CollisionViolatingStations"]).GetValue(0)
        unavoidable = cfd.GetArray(NAMES["CollisionUnavoidableStations"]).GetValue(0)
        self.assertEqual(order_free == 1, violating == unavoidable)
        self.assertEqual(cfd.GetArray(NAMES["CollisionFree"]).GetValue(0) == 1, violating == 0)
        self.assertEqual(collisions.GetNumberOfPoints() == 0, violating == 0)

    def test_depth_priority_at_a_wide_nozzle_shows_violations(self):
        sequencer = simple.GLPrintSequencer(Input=self.proxies["lattice"], Skeleton=self.proxies["skeleton"],
                                            Strategy="DPT", NozzleAngle=80.0)
        verifier = simple.GLCollisionVerifier(Input=simple.OutputPort(sequencer, 0), NozzleAngle=80.0)
        verifier.UpdatePipeline()
        collisions = servermanager.Fetch(verifier)
        fd = collisions.GetFieldData()
        self.assertEqual(fd.GetArray(NAMES["CollisionFree"]).GetValue(0), 0)
        self.assertEqual(fd.GetArray(NAMES["CollisionOrderFree"]).GetValue(0), 0)  # DPT ignores collisions
        self.assertGreater(fd.GetArray(NAMES["CollisionViolatingStations"]).GetValue(0),
                           fd.GetArray(NAMES["CollisionUnavoidableStations"]).GetValue(0))
        self.assertEqual(collisions.GetNumberOfPoints(), 2 * collisions.GetNumberOfCells())
        self.assertEqual(collisions.GetNumberOfCells(), 20)  # MaxReported
        for key in ("ViolationIndex", "Role", "Height", "Radial", "Unavoidable"):
            self.assertIsNotNone(collisions.GetPointData().GetArray(NAMES[key]), key)
        self.assertEqual(collisions.GetPointData().GetArray(NAMES["Role"]).GetRange(), (0.0, 1.0))
        bad = simple.GLPrintSequencer(Input=self.proxies["lattice"], Skeleton=self.proxies["skeleton"],
                                      NozzleAngle=90.0)
        bad.UpdatePipeline()
        self.assertEqual(servermanager.Fetch(bad, idx=0).GetNumberOfCells(), 0)

    def test_toolpath_and_its_replay(self):
        toolpath = self.proxies["toolpath"]
        toolpath.UpdatePipeline(1.0)
        path = servermanager.Fetch(toolpath)
        n = path.GetNumberOfPoints()
        self.assertGreater(n, 1000)
        self.assertGreater(path.GetNumberOfCells(), 10)
        pd, cd, fd = path.GetPointData(), path.GetCellData(), path.GetFieldData()
        for key in ("NozzleAxis", "Thickness", "Width", "Extrusion", "FeedRate", "MoveKind", "LayerId", "SubgraphId",
                    "PathIndex", "PointIndex"):
            self.assertIsNotNone(pd.GetArray(NAMES[key]), key)
            self.assertEqual(pd.GetArray(NAMES[key]).GetNumberOfTuples(), n, key)
        for key in ("MoveKind", "PathIndex", "LayerId", "SubgraphId"):
            self.assertIsNotNone(cd.GetArray(NAMES[key]), key)
        for key in ("ToolpathPrintLength", "ToolpathPerimeterLength", "ToolpathAirLength", "ToolpathRetractions",
                    "ToolpathTours", "ToolpathCrossings", "ToolpathSplitSubgraphs", "ToolpathFilament",
                    "ToolpathVolume", "ToolpathThicknessDeviation", "ToolpathThicknessDeviationPerLayer",
                    "ToolpathRotationSteps", "ToolpathSeconds", "SkeletonEdges"):
            self.assertIsNotNone(fd.GetArray(NAMES[key]), key)
        kinds = pd.GetArray(NAMES["MoveKind"]).GetRange()
        self.assertEqual(kinds[0], 0)  # print moves
        self.assertEqual(kinds[1], 2)  # air moves
        self.assertEqual(pd.GetArray(NAMES["PointIndex"]).GetRange(), (0.0, n - 1.0))
        self.assertEqual(fd.GetArray(NAMES["ToolpathCrossings"]).GetValue(0), 0)
        self.assertGreater(fd.GetArray(NAMES["ToolpathPrintLength"]).GetValue(0), 100)
        self.assertEqual(fd.GetArray(NAMES["ToolpathThicknessDeviationPerLayer"]).GetNumberOfComponents(), 3)
        # The planner has no time (Apply shows the whole path); GL Toolpath Replay has time steps 0..1
        # of print progress (the TimestepValues information property); a time gives the part printed by
        # then, with every point kept (colour ranges of the whole print), from the same plan.
        toolpath.UpdatePipeline(0.0)
        self.assertEqual(servermanager.Fetch(toolpath).GetNumberOfPoints(), n)  # time 0: the whole path too
        replay = self.proxies["replay"]
        steps = list(replay.TimestepValues)
        self.assertEqual(len(steps), 200)
        self.assertEqual((steps[0], steps[-1]), (0.0, 1.0))
        time_range = replay.GetProperty("TimeRange")  # information only, not a Python attribute
        self.assertEqual([time_range[0], time_range[1]], [0.0, 1.0])
        replay.UpdatePipeline(0.5)
        half = servermanager.Fetch(replay)
        self.assertEqual(half.GetNumberOfPoints(), n)
        self.assertEqual(half.GetFieldData().GetArray(NAMES["ReplayLastPoint"]).GetValue(0), int(0.5 * (n - 1) + 0.5))
        self.assertLess(half.GetNumberOfCells(), path.GetNumberOfCells())
        self.assertEqual(half.GetFieldData().GetArray(NAMES["ToolpathSeconds"]).GetValue(0),
                         fd.GetArray(NAMES["ToolpathSeconds"]).GetValue(0))
        replay.UpdatePipeline(0.0)
        self.assertEqual(servermanager.Fetch(replay).GetNumberOfCells(), 0)
        replay.StepBy = "Layers"
        replay.UpdatePipelineInformation()
        layer_steps = list(replay.TimestepValues)
        layer_ids = pd.GetArray(NAMES["LayerId"]).GetRange()
        self.assertEqual((layer_steps[0], layer_steps[-1]), (max(layer_ids[0], 0.0), layer_ids[1]))
        replay.UpdatePipeline(layer_steps[1])
        shown = servermanager.Fetch(replay).GetCellData().GetArray(NAMES["LayerId"]).GetRange()
        self.assertEqual(shown, (layer_steps[0], layer_steps[1]))
        replay.StepBy = "Points"
        # GL Print Summary: a table keyed like report.json's "summary", with the verifier's strict verdict.
        self.proxies["summary"].UpdatePipeline()
        table = servermanager.Fetch(self.proxies["summary"])
        rows = pipeline.summary_values(table)
        self.assertEqual(rows["points"], n)
        self.assertEqual(rows["stations"], n)
        self.assertGreater(rows["print_time_min"], 0)
        self.assertEqual(rows["filament_m"] * 1000, fd.GetArray(NAMES["ToolpathFilament"]).GetValue(0))
        toolpath.UpdatePipeline()
        saved = os.path.join(self.out, "toolpath.vtp")
        pipeline.save_binary(toolpath, saved)
        back = simple.XMLPolyDataReader(FileName=[saved])
        back.UpdatePipeline()
        self.assertEqual(servermanager.Fetch(back).GetNumberOfPoints(), n)
        # The verifier on the toolpath: every point a station.
        self.proxies["toolpath_verifier"].UpdatePipeline(1.0)
        cfd = servermanager.Fetch(self.proxies["toolpath_verifier"]).GetFieldData()
        self.assertEqual(cfd.GetArray(NAMES["CollisionStations"]).GetValue(0), n)
        # Bad parameter: empty output.
        bad = simple.GLToolpathPlanner(Input=simple.OutputPort(self.proxies["sequencer"], 0),
                                       Skeleton=self.proxies["skeleton"], FlowCorrection=1.5)
        bad.UpdatePipeline(1.0)
        self.assertEqual(servermanager.Fetch(bad).GetNumberOfPoints(), 0)

    def test_programs_saved_with_the_writer_proxies(self):
        toolpath = self.proxies["toolpath"]
        toolpath.UpdatePipeline(1.0)
        n = servermanager.Fetch(toolpath).GetNumberOfPoints()
        # The animation time in the middle of the replay: the writers still write the whole path.
        toolpath.UpdatePipeline(0.5)
        out = os.path.join(self.out, "program")
        os.makedirs(out)
        # This coarse, wide-nozzle toolpath collides: the writers refuse it (nothing written) ...
        collision_free = servermanager.Fetch(toolpath).GetFieldData().GetArray(NAMES["ToolpathCollisionFree"])
        self.assertEqual(collision_free.GetValue(0), 0)
        simple.SaveData(os.path.join(out, "bunny.script"), toolpath, MaxFileBytes=500000, Robot="ur5e")
        simple.SaveData(os.path.join(out, "bunny.gcode"), toolpath)
        self.assertEqual(os.listdir(out), [])
        # ... unless Allow Collisions is on. .script -> GL URScript Writer (the writer factory picks
        # it by extension).
        simple.SaveData(os.path.join(out, "bunny.script"), toolpath, MaxFileBytes=500000, Robot="ur5e",
                        AllowCollisions=1)
        scripts = sorted(f for f in os.listdir(out) if f.endswith(".script"))
        self.assertGreater(len(scripts), 1)
        self.assertEqual(scripts, sorted(["bunny.script"] + ["bunny_%d.script" % k for k in range(1, len(scripts))]))
        movels = 0
        for name in scripts:
            with open(os.path.join(out, name)) as f:
                text = f.read()
            self.assertLessEqual(len(text), 500000)
            self.assertTrue(text.startswith("def %s():\n" % name[:-len(".script")]), text[:40])
            self.assertTrue(text.endswith("\nend\n"))
            movels += text.count("\n  movel(p[")
            # Waypoints between points where the wrist passes near its singularity.
            movels -= sum(int(k) for k in re.findall(r"\n  # (\d+) waypoint\(s\) between toolpath points", text))
        self.assertEqual(movels, n - 1)
        # .gcode -> GL GCode Writer; the waypoint CSV writer by name (ParaView's CSV writer owns .csv).
        simple.SaveData(os.path.join(out, "bunny.gcode"), toolpath, Kinematics=1, AllowCollisions=1)
        with open(os.path.join(out, "bunny.gcode")) as f:
            gcode = f.read()
        self.assertIn("B-C tilting-rotary table", gcode)
        self.assertEqual(len(re.findall(r"^G[01] X", gcode, re.M)), n)
        csv = servermanager.writers.GLWaypointCSVWriter(Input=toolpath, FileName=os.path.join(out, "bunny.csv"),
                                                        AllowCollisions=1)
        csv.UpdatePipeline()
        with open(os.path.join(out, "bunny.csv")) as f:
            rows = f.read().splitlines()
        self.assertEqual(rows[0], "x,y,z,nx,ny,nz,e,kind,layer")
        self.assertEqual(len(rows), n + 1)
        # A cell that cannot reach: an error, nothing written.
        simple.SaveData(os.path.join(out, "far.script"), toolpath, NozzleTipmm=[5000.0, 0.0, 0.0], AllowCollisions=1)
        self.assertEqual(sorted(f for f in os.listdir(out) if f.startswith("far") or f.startswith(".")), [])

    def test_saved_file_reads_back(self):
        path = os.path.join(self.out, "fields.vtu")
        pipeline.save_binary(self.proxies["fields"], path)
        self.assertEqual([n for n in os.listdir(self.out) if n.startswith(".tmp")], [])
        back = simple.XMLUnstructuredGridReader(FileName=[path])
        back.UpdatePipeline()
        data = servermanager.Fetch(back)
        self.assertEqual(data.GetNumberOfCells(), self.fields.GetNumberOfCells())
        self.assertIsNotNone(data.GetPointData().GetArray(NAMES["Gamma"]))

    def test_bad_parameter_gives_empty_output(self):
        bad = simple.GLGeodesicDistanceFields(Input=self.proxies["tets"], TimeFactor=0.0)
        bad.UpdatePipeline()
        self.assertEqual(servermanager.Fetch(bad).GetNumberOfCells(), 0)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
