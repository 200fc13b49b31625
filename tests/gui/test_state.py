"""pvpython test of pvpython/geolattice_state.py: the state file it saves (in another pvpython process,
as a user would) loads with LoadState in a fresh session after the plugin, also with the model moved to
another directory (data_directory), and gives the whole pipeline back: every source non-empty, the four
views in one layout, each view coloured by its array (Gamma, LayerId, SubgraphId as categories,
PrintOrder), the cameras linked. No X server needed (nothing is rendered).

Environment: GEOLATTICE_PLUGIN, GEOLATTICE_SOURCE_DIR, PVPYTHON (default: pvpython on the PATH)."""
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

SOURCE_DIR = os.environ["GEOLATTICE_SOURCE_DIR"]
PLUGIN = os.environ["GEOLATTICE_PLUGIN"]
sys.path.insert(0, os.path.join(SOURCE_DIR, "pvpython"))

import geolattice_state as state  # noqa: E402
from paraview import servermanager, simple  # noqa: E402


class StateFileTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="geolattice-state-")
        cls.addClassCleanup(shutil.rmtree, cls.work, True)  # also when setUpClass fails
        cls.pvsm = os.path.join(cls.work, "geolattice_y_shape.pvsm")
        model = os.path.join(SOURCE_DIR, "testdata", "y_shape.obj")
        pvpython = os.environ.get("PVPYTHON") or shutil.which("pvpython")
        start = time.time()
        result = subprocess.run([pvpython, os.path.join(SOURCE_DIR, "pvpython", "geolattice_state.py"), model,
                                 "-o", cls.pvsm, "--plugin", PLUGIN], capture_output=True, text=True, timeout=300)
        print("geolattice_state.py: %.1f s, exit code %d\n%s%s" % (time.time() - start, result.returncode,
                                                                   result.stdout, result.stderr[-2000:]))
        assert result.returncode == 0 and os.path.isfile(cls.pvsm), "geolattice_state.py failed"
        # The model somewhere else: LoadState must find it by name under data_directory.
        cls.moved = os.path.join(cls.work, "moved")
        os.makedirs(cls.moved)
        shutil.copy(model, cls.moved)
        simple.LoadPlugin(PLUGIN, remote=False)
        start = time.time()
        simple.LoadState(cls.pvsm, data_directory=cls.moved)
        print("LoadState: %.1f s" % (time.time() - start))

    def test_model_was_relocated(self):
        reader = simple.FindSource(state.NAMES["reader"])
        self.assertIsNotNone(reader)
        self.assertEqual(os.path.dirname(os.path.abspath(reader.FileName)), self.moved)

    def test_every_source_is_back_and_non_empty(self):
        scene = simple.GetAnimationScene()
        time_value = scene.AnimationTime
        for key in ("reader", "place", "tets", "fields", "layers", "lattice", "skeleton", "sequencer", "verifier",
                    "overhang", "toolpath", "replay", "surface", "some_layers"):
            with self.subTest(key=key):
                source = simple.FindSource(state.NAMES[key])
                self.assertIsNotNone(source, state.NAMES[key])
                source.UpdatePipeline(time_value)
                for port in range(source.SMProxy.GetNumberOfOutputPorts()):
                    data = servermanager.Fetch(source, idx=port)
                    if key == "verifier":
                        self.assertIsNotNone(data.GetFieldData().GetArray("CollisionFree"))
                    else:
                        self.assertGreater(data.GetNumberOfCells(), 0, "%s port %d" % (key, port))
        replay = simple.FindSource(state.NAMES["replay"])
        self.assertAlmostEqual(time_value, max(replay.TimestepValues))  # the whole path

    def test_the_render_views_in_one_layout_coloured_by_their_arrays(self):
        layouts = simple.GetLayouts()
        self.assertEqual(len(layouts), 1)
        layout = list(layouts.values())[0]
        views = [simple.FindView(title) for title, *_ in state.COLOURING]
        for view in views:
            self.assertIsNotNone(view)
            self.assertGreaterEqual(layout.GetViewLocation(view), 0)
        for view, (title, key, port, association, array) in zip(views, state.COLOURING):
            with self.subTest(view=title):
                source = simple.OutputPort(simple.FindSource(state.NAMES[key]), port)
                rep = servermanager.GetRepresentation(source, view)
                self.assertIsNotNone(rep)
                self.assertEqual(rep.Visibility, 1)
                self.assertEqual(list(rep.ColorArrayName), [association, array])
                lut = rep.LookupTable
                self.assertIsNotNone(lut)
                lo, hi = lut.RGBPoints[0], lut.RGBPoints[-4]
                self.assertLess(lo, hi)
        lut = simple.GetColorTransferFunction("SubgraphId")
        self.assertEqual(lut.InterpretValuesAsCategories, 1)
        subgraphs = servermanager.Fetch(simple.FindSource(state.NAMES["lattice"])).GetFieldData().GetArray(
            "LatticeSubgraphs").GetValue(0)
        self.assertEqual(len(lut.Annotations) // 2, subgraphs)
        self.assertEqual(len(lut.IndexedColors) // 3, subgraphs)

    def test_the_summary_is_in_a_spreadsheet_view(self):
        sheet = simple.FindView(state.SUMMARY_VIEW)
        self.assertIsNotNone(sheet)
        self.assertEqual(sheet.GetXMLName(), "SpreadSheetView")
        summary = simple.FindSource(state.NAMES["summary"])
        self.assertIsNotNone(servermanager.GetRepresentation(summary, sheet))
        summary.UpdatePipeline()
        self.assertGreater(servermanager.Fetch(summary).GetNumberOfRows(), 10)

    def test_the_verdict_is_written_over_the_part(self):
        verdict = simple.FindSource(state.NAMES["verdict"])
        self.assertIsNotNone(verdict)
        view = simple.FindView(state.COLOURING[0][0])
        rep = servermanager.GetRepresentation(verdict, view)
        self.assertIsNotNone(rep)
        self.assertEqual(rep.Visibility, 1)
        verdict.UpdatePipeline()
        text = servermanager.Fetch(verdict).GetValue(0, 0).ToString()
        self.assertTrue(text.startswith("collision-free") or text.startswith("COLLIDES"), text)

    def test_every_coloured_view_has_a_legend(self):
        for title, key, port, association, array in state.COLOURING:
            with self.subTest(view=title):
                view = simple.FindView(title)
                rep = servermanager.GetRepresentation(
                    simple.OutputPort(simple.FindSource(state.NAMES[key]), port), view)
                self.assertTrue(rep.IsScalarBarVisible(view))

    def test_cameras_are_linked(self):
        pxm = servermanager.ProxyManager().SMProxyManager
        for i in range(1, len(state.COLOURING)):
            link = pxm.GetRegisteredLink(state.CAMERA_LINK % i)
            self.assertIsNotNone(link, state.CAMERA_LINK % i)
            self.assertEqual(link.GetClassName(), "vtkSMCameraLink")


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
