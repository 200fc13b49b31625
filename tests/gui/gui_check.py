"""Runs inside the ParaView GUI's Python shell, last event of run_gui_test.py's playback (the plan is the
JSON file named by $GEOLATTICE_GUI_PLAN), after every GeoLattice filter was created from the
Filters > GeoLattice menu and applied with the Apply button. Checks for each filter: it exists under its
default GUI name (<Filter>1), its second input is the one picked in the Select Input dialog, the GUI
shows it in the render view (Apply happened), its "no array" array selections (XML default = the
none string) are still unset after Apply, and every output port is non-empty (GL Collision Verifier:
its output carries the verdict in field data; its geometry is empty when nothing collides). Then colours
the part by Gamma and the sequenced lattice by PrintOrder, saves the screenshot and reads it back.
Writes {"failures": [...], "outputs": {...}} to plan["check_result"]."""
import json
import os
import sys
import time
import traceback

from paraview import servermanager, simple


def _geolattice_port_summary(data):
    if data.IsA("vtkTable"):  # GL Print Summary: rows and columns
        return {"class": data.GetClassName(), "points": data.GetNumberOfRows(), "cells": data.GetNumberOfColumns(),
                "arrays": data.GetNumberOfColumns()}
    n_arrays = sum(data.GetAttributes(a).GetNumberOfArrays() for a in (0, 1)) + data.GetFieldData().GetNumberOfArrays()
    return {"class": data.GetClassName(), "points": data.GetNumberOfPoints(), "cells": data.GetNumberOfCells(),
            "arrays": n_arrays}


def _geolattice_gui_check():
    with open(os.environ["GEOLATTICE_GUI_PLAN"]) as f:
        plan = json.load(f)
    failures, outputs = [], {}
    try:
        # The render view the filters were applied in (GL Print Summary opened a spreadsheet view beside it).
        render_views = simple.GetViews("RenderView")
        view = render_views[0] if render_views else simple.GetActiveViewOrCreate("RenderView")
        scene = simple.GetAnimationScene()
        scene.UpdateAnimationUsingDataTimeSteps()
        scene.AnimationTime = scene.EndTime  # the toolpath replay: last frame = the whole path

        reader = simple.FindSource(plan["reader"])
        reader.UpdatePipeline()
        outputs[plan["reader"]] = [_geolattice_port_summary(servermanager.Fetch(reader))]
        if outputs[plan["reader"]][0]["cells"] == 0:
            failures.append("GLMeshReader read nothing from %s" % plan["model"])

        for name, extra in plan["chain"]:
            src = simple.FindSource(name + "1")
            if src is None or src.GetXMLName() != name:
                failures.append("%s1 was not created from Filters > GeoLattice > %s" % (name, name))
                continue
            for prop, target in extra.items():
                got = getattr(src, prop)
                got_proxy = getattr(got, "SMProxy", None)
                want = simple.FindSource(target)
                if got_proxy is None or want is None or got_proxy != want.SMProxy:
                    failures.append("%s1.%s is %s, not %s (Select Input dialog)" % (
                        name, prop, got_proxy.GetXMLName() if got_proxy else None, target))
            for prop, none in plan["none_arrays"].get(name, {}).items():
                # Array selections whose XML default is "no array" must still be so after Apply: the GUI
                # must not pick the first array of the domain on its own (element 4 is the array name).
                chosen = src.SMProxy.GetProperty(prop).GetElement(4)
                if chosen not in ("", none):
                    failures.append(
                        "%s1.%s is %r after Apply in the GUI, but its XML default is %r: the GUI picked the first "
                        "array of the domain, so a GUI user gets a different result than pvpython. Fix in the "
                        "plugin XML: <Hints><NoDefault/></Hints> in that property" % (name, prop, chosen, none))
            if name == "GLPrintPart":
                # One Apply, five outputs, shown in whichever view was active (the spreadsheet here).
                if not any(servermanager.GetRepresentation(simple.OutputPort(src, port), v) is not None
                           for v in simple.GetViews() for port in range(5)):
                    failures.append("GLPrintPart1 is shown in no view (was Apply pressed?)")
            elif name == "GLPrintSummary":
                # A table: ParaView shows it in a spreadsheet view (the XML's View hint), not the render view.
                shown = [v for v in simple.GetViews() if v.GetXMLName() == "SpreadSheetView"
                         and servermanager.GetRepresentation(src, v) is not None]
                if not shown:
                    failures.append("GLPrintSummary1 is not shown in a spreadsheet view")
            elif servermanager.GetRepresentation(src, view) is None:
                failures.append("%s1 has no representation in the render view (was Apply pressed?)" % name)
            src.UpdatePipeline(scene.AnimationTime)
            ports = []
            for port in range(src.SMProxy.GetNumberOfOutputPorts()):
                data = servermanager.Fetch(src, idx=port)
                summary = _geolattice_port_summary(data)
                ports.append(summary)
                if name == "GLCollisionVerifier":
                    stations = data.GetFieldData().GetArray("CollisionStations")
                    if stations is None or stations.GetValue(0) <= 0:
                        failures.append("GLCollisionVerifier1 gave no verdict (no CollisionStations)")
                elif name == "GLSurfaceCheck":  # the Y is closed: no defect edges, the verdict says so
                    closed = data.GetFieldData().GetArray("SurfaceClosed")
                    if closed is None or closed.GetValue(0) != 1:
                        failures.append("GLSurfaceCheck1 does not find the Y closed")
                elif name == "GLAutoOrient" and port == 1:
                    pass  # the candidates: empty with Orient = Keep (the default)
                elif summary["points"] == 0 or summary["cells"] == 0:
                    failures.append("%s1 output port %d is empty: %s" % (name, port, summary))
            outputs[name] = ports

        # One Apply = the filters one by one: GL Print Part's summary equals GL Print Summary's on the chain
        # built from the menu (same model, same defaults).
        part, single = simple.FindSource("GLPrintPart1"), simple.FindSource("GLPrintSummary1")
        if part is not None and single is not None:
            def rows(table):
                return {table.GetValueByName(r, "Key").ToString(): table.GetValueByName(r, "Value").ToDouble()
                        for r in range(table.GetNumberOfRows())}
            a, b = rows(servermanager.Fetch(part, idx=1)), rows(servermanager.Fetch(single))
            for key in ("layers", "subgraphs", "points", "tours", "retractions", "print_time_min", "filament_g"):
                if a.get(key) != b.get(key):
                    failures.append("GL Print Part's %s is %s, the single filters' %s" % (key, a.get(key), b.get(key)))
            outputs["print_part_summary"] = {k: a.get(k) for k in ("layers", "points", "print_time_min", "collision_free")}

        # The replay plays: at each animation time the GUI shows the print so far (cells up to point
        # round(t (N - 1)), which ReplayLastPoint names), with every point kept, so the PointIndex range -
        # the colour map's - stays that of the whole print. Seconds per step recorded, not asserted.
        replay = simple.FindSource("GLToolpathReplay1")
        if replay is not None:
            simple.ColorBy(servermanager.GetRepresentation(replay, view), ("POINTS", "PointIndex"))
            ranges, seconds, cells = set(), [], []
            for t in (0.25, 0.5, 0.75, 1.0):
                start = time.time()
                scene.AnimationTime = t
                simple.Render(view)
                seconds.append(round(time.time() - start, 3))
                data = servermanager.Fetch(replay)
                n = data.GetNumberOfPoints()
                last = data.GetFieldData().GetArray("ReplayLastPoint").GetValue(0)
                if last != int(t * (n - 1) + 0.5):  # C++ llround: halves away from zero
                    failures.append("replay at %g shows up to point %d, not %d" % (t, last, int(t * (n - 1) + 0.5)))
                if data.GetLines().GetConnectivityArray().GetRange()[1] > last:
                    failures.append("replay at %g has cells beyond its last printed point %d" % (t, last))
                ranges.add(tuple(data.GetPointData().GetArray("PointIndex").GetRange()))
                cells.append(data.GetNumberOfCells())
            if len(ranges) != 1 or cells != sorted(cells):
                failures.append("replay: PointIndex ranges %s (one expected), cells per step %s" % (ranges, cells))
            outputs["replay_step_seconds"] = seconds

        # The picture: the part (surface of the fields' tet mesh) by Gamma, translucent, over the
        # sequenced lattice by PrintOrder.
        for src in simple.GetSources().values():
            simple.Hide(src, view)
        for rep in view.Representations:  # the colour legends the GUI added on Apply
            if rep.GetXMLName() == "ScalarBarWidgetRepresentation":
                rep.Visibility = 0
        part = simple.ExtractSurface(registrationName="PartSurface", Input=simple.FindSource("GLGeodesicDistanceFields1"))
        rep = simple.Show(part, view)
        simple.ColorBy(rep, ("POINTS", "Gamma"))
        rep.RescaleTransferFunctionToDataRange(True, False)
        rep.Opacity = 0.3
        rep.SetScalarBarVisibility(view, True)
        lattice = simple.OutputPort(simple.FindSource("GLPrintSequencer1"), 0)
        rep = simple.Show(lattice, view)
        simple.ColorBy(rep, ("CELLS", "PrintOrder"))
        rep.RescaleTransferFunctionToDataRange(True, False)
        simple.GetColorTransferFunction("PrintOrder").ApplyPreset("Turbo", True)
        rep.SetScalarBarVisibility(view, True)
        sys.path.insert(0, plan["pvpython_dir"])
        from geolattice_view import front_camera
        front_camera(view, elevation=20)
        simple.Render(view)
        simple.SaveScreenshot(plan["screenshot"], view, ImageResolution=[1200, 900])

        from paraview.vtk.vtkIOImage import vtkPNGReader
        png = vtkPNGReader()
        png.SetFileName(plan["screenshot"])
        png.Update()
        image = png.GetOutput()
        dims = image.GetDimensions()
        scalars = image.GetPointData().GetScalars()
        spread = [scalars.GetRange(c) for c in range(min(3, scalars.GetNumberOfComponents()))] if scalars else []
        outputs["screenshot"] = {"size": list(dims[:2]), "channel_ranges": spread}
        if list(dims[:2]) != [1200, 900]:
            failures.append("screenshot %s is %s, not 1200 x 900" % (plan["screenshot"], dims[:2]))
        elif not spread or all(hi - lo < 32 for lo, hi in spread):
            failures.append("screenshot %s looks blank (channel ranges %s)" % (plan["screenshot"], spread))
    except Exception:
        failures.append(traceback.format_exc())
    with open(plan["check_result"], "w") as f:
        json.dump({"failures": failures, "outputs": outputs}, f, indent=1)


_geolattice_gui_check()
