"""Runs inside the ParaView GUI's Python shell, last event of run_gui_test.py --print-part (the plan is the
JSON file named by $GEOLATTICE_GUI_PLAN), after the model was opened, Filters > GeoLattice > GL Print
Part was applied once (Fit Size and Orient typed into its panel first) and Filters > GeoLattice > GL
Toolpath Replay was applied to its Toolpath output. The events run _gl_pp_first(), _gl_pp_capture(<workbench
png>) (the whole screen by xwd, after the GUI repainted), _gl_pp_second(). Checks:

- the Summary table (shown in a spreadsheet view) holds the numbers of the command line's report.json
  `summary` for the same model and parameters, and the Verdict text (shown as a text annotation in
  the render view) is that summary's verdict;
- the replay plays: at animation step k the shown toolpath is the points with PointIndex <= its last
  printed point round(p (N - 1)), every point kept, the PointIndex colour range that of the whole print
  at every step; by layer, one step per LayerId (seconds per step recorded, not asserted);
- three screenshots (workbench layout, summary, replay at mid-print) that are not blank.

Writes {"failures": [...], "outputs": {...}} to plan["check_result"]."""
import json
import os
import sys
import time
import traceback

from paraview import servermanager, simple


def _geolattice_png_spread(path):
    from paraview.vtk.vtkIOImage import vtkPNGReader
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    image = png.GetOutput()
    scalars = image.GetPointData().GetScalars()
    spread = [scalars.GetRange(c) for c in range(min(3, scalars.GetNumberOfComponents()))] if scalars else []
    return list(image.GetDimensions()[:2]), spread


_GL_PP = {}  # what the stages share: they run as separate events, so the GUI repaints in between


def _gl_pp_save():
    with open(_GL_PP["plan"]["check_result"], "w") as f:
        json.dump({"failures": _GL_PP["failures"], "outputs": _GL_PP["outputs"]}, f, indent=1)


def _gl_pp_capture(name):
    """The whole screen (the ParaView window: panels, render view, spreadsheet) as docs/images shows it."""
    import subprocess
    sys.path.insert(0, os.path.dirname(_GL_PP["plan"]["check_script"]))
    from xwd_to_png import xwd_to_png
    try:
        dump = os.path.join(os.path.dirname(_GL_PP["plan"]["check_result"]), "screen.xwd")
        subprocess.run(["xwd", "-root", "-silent", "-out", dump], check=True, timeout=60)
        xwd_to_png(dump, os.path.join(_GL_PP["plan"]["screenshot_dir"], name))
    except Exception:
        _GL_PP["failures"].append("screen capture %s: %s" % (name, traceback.format_exc()))
    _gl_pp_save()


def _gl_pp_maximize_summary(maximize=True):
    """Maximizes the summary's spreadsheet view in its layout (as its "maximize" button does), or restores it."""
    spreadsheets = [v for v in simple.GetViews() if v.GetXMLName() == "SpreadSheetView"]
    if not spreadsheets:
        _GL_PP["failures"].append("no spreadsheet view to show the summary in")
        return
    layout = simple.GetLayout(spreadsheets[0])
    if maximize:
        layout.MaximizeCell(layout.GetViewLocation(spreadsheets[0]))
    else:
        layout.RestoreMaximizedState()


def _gl_pp_first():
    """The summary and the verdict; sets the workbench up for its screenshot."""
    with open(os.environ["GEOLATTICE_GUI_PLAN"]) as f:
        plan = json.load(f)
    failures, outputs = [], {}
    _GL_PP.update(plan=plan, failures=failures, outputs=outputs)
    try:
        part = simple.FindSource("GLPrintPart1")
        replay = simple.FindSource("GLToolpathReplay1")
        if part is None or replay is None:
            raise RuntimeError("GLPrintPart1 / GLToolpathReplay1 were not created from Filters > GeoLattice "
                               "(found %s)" % sorted(k[0] for k in simple.GetSources()))
        for name, value in plan["parameters"].items():
            got = part.SMProxy.GetProperty(name).GetElement(0)
            if got != value:
                failures.append("GL Print Part's %s is %r after Apply, not the %r typed in" % (name, got, value))
        render_views = simple.GetViews("RenderView")
        view = render_views[0]
        spreadsheets = [v for v in simple.GetViews() if v.GetXMLName() == "SpreadSheetView"]
        outputs["views"] = sorted(v.GetXMLName() for v in simple.GetViews())

        # The summary against the command line's report.json.
        with open(plan["report"]) as f:
            report = json.load(f)["summary"]
        table = servermanager.Fetch(part, idx=1)
        rows = {table.GetValueByName(r, "Key").ToString(): table.GetValueByName(r, "Value").ToDouble()
                for r in range(table.GetNumberOfRows())}
        compared = 0
        for key, want in sorted(report.items()):
            if key == "seconds" or not isinstance(want, (int, float)):
                continue
            got = rows.get(key)
            compared += 1
            if got is None or abs(got - want) > 1e-9 * max(1.0, abs(want)):
                failures.append("summary %s: GUI %s, command line %s" % (key, got, want))
        outputs["summary_compared_keys"] = compared
        outputs["summary"] = {k: rows.get(k) for k in ("layers", "subgraphs", "points", "retractions",
                                                       "print_time_min", "filament_g", "collision_free")}
        if compared < 12:
            failures.append("only %d numeric summary keys compared" % compared)
        if not any(servermanager.GetRepresentation(simple.OutputPort(part, 1), v) is not None for v in spreadsheets):
            failures.append("the Summary output is not shown in a spreadsheet view")

        # The verdict in words: a text annotation in the render view.
        text = servermanager.Fetch(part, idx=5).GetColumnByName("Text").GetValue(0)
        outputs["verdict_text"] = text
        words = text.replace(";\n", "; ").replace("):\n", "): ").replace("\n(", " (", 1)
        if not words.startswith("GeoLattice: " + report["verdict"]):
            failures.append("verdict text %r, report.json verdict %r" % (text, report["verdict"]))
        verdict_rep = servermanager.GetRepresentation(simple.OutputPort(part, 5), view)
        if verdict_rep is None or verdict_rep.GetXMLName() != "TextSourceRepresentation" or not verdict_rep.Visibility:
            failures.append("the Verdict is not a visible text annotation in the render view (%s)"
                            % (verdict_rep.GetXMLName() if verdict_rep else None))

        # The workbench: the toolpath by LayerId (as Apply showed it), the part translucent, the verdict.
        toolpath_rep = servermanager.GetRepresentation(simple.OutputPort(part, 0), view)
        if toolpath_rep is None:
            failures.append("the Toolpath output is not shown in the render view")
        else:
            for rep in view.Representations:  # the legends Apply added (MoveKind): LayerId's only
                if rep.GetXMLName() == "ScalarBarWidgetRepresentation":
                    rep.Visibility = 0
            toolpath_rep.Visibility = 1  # GL Toolpath Replay's Apply hid its input
            simple.ColorBy(toolpath_rep, ("POINTS", "LayerId"))
            toolpath_rep.RescaleTransferFunctionToDataRange(True, False)
            toolpath_rep.SetScalarBarVisibility(view, True)
        for port in (2, 3, 4):  # shown on request only (View hints "None")
            if servermanager.GetRepresentation(simple.OutputPort(part, port), view) is not None:
                failures.append("Apply showed GL Print Part's output %d; only the toolpath, the verdict and the "
                                "summary are shown at first" % port)
        replay_rep = servermanager.GetRepresentation(replay, view)
        if replay_rep is not None:
            replay_rep.Visibility = 0
        view.ResetCamera()
        camera = view.GetActiveCamera()
        camera.SetViewUp(0, 0, 1)
        focal, distance = camera.GetFocalPoint(), camera.GetDistance()
        camera.SetPosition(focal[0] - 0.5 * distance, focal[1] - distance, focal[2] + 0.4 * distance)
        view.ResetCamera()
        simple.Render(view)
        _GL_PP.update(part=part, replay=replay, view=view, rows=rows, toolpath_rep=toolpath_rep)
    except Exception:
        failures.append(traceback.format_exc())
    _gl_pp_save()


def _gl_pp_second():
    """The replay by points and by layers, its screenshot; then every screenshot checked."""
    plan, failures, outputs = _GL_PP["plan"], _GL_PP["failures"], _GL_PP["outputs"]

    def shots(name):
        return os.path.join(plan["screenshot_dir"], name)

    try:
        part, replay, view, rows = _GL_PP["part"], _GL_PP["replay"], _GL_PP["view"], _GL_PP["rows"]
        toolpath_rep = _GL_PP["toolpath_rep"]
        part_rep = simple.Show(simple.OutputPort(part, 4), view)  # for the replay's screenshot
        part_rep.Representation = "Surface"
        part_rep.Opacity = 0.25
        simple.ColorBy(part_rep, None)
        # The replay: colour by PointIndex, step through the animation by points, then by layers.
        # Timed with the replay and the verdict shown (what Apply leaves plus the replay); the
        # part is added for the screenshot only (a translucent tet mesh is slow to render here,
        # without a GPU).
        if toolpath_rep is not None:
            toolpath_rep.Visibility = 0
        part_rep.Visibility = 0
        for rep in view.Representations:
            if rep.GetXMLName() == "ScalarBarWidgetRepresentation":
                rep.Visibility = 0
        replay_rep = simple.Show(replay, view)
        simple.ColorBy(replay_rep, ("POINTS", "PointIndex"))
        replay_rep.RescaleTransferFunctionToDataRange(True, False)
        replay_rep.SetScalarBarVisibility(view, True)
        lut = simple.GetColorTransferFunction("PointIndex")
        scene = simple.GetAnimationScene()
        scene.UpdateAnimationUsingDataTimeSteps()
        times = list(replay.TimestepValues)
        whole = servermanager.Fetch(part, idx=0).GetNumberOfPoints()
        seconds, filter_seconds, render_seconds, ranges, cells = [], [], [], set(), []
        picks = sorted(set([1, len(times) // 4, len(times) // 2, (3 * len(times)) // 4, len(times) - 1]))
        for k in picks:
            start = time.time()
            replay.UpdatePipeline(times[k])  # the filter alone
            filter_seconds.append(round(time.time() - start, 3))
            start = time.time()
            scene.AnimationTime = times[k]  # what a step of Play does: every view updated ...
            updated = time.time()
            simple.Render(view)  # ... and the render view drawn
            seconds.append(round(time.time() - start, 3))
            render_seconds.append(round(time.time() - updated, 3))
            data = servermanager.Fetch(replay)
            last = int(data.GetFieldData().GetArray("ReplayLastPoint").GetValue(0))
            want = int(times[k] * (whole - 1) + 0.5)
            if last != want:
                failures.append("replay step %d (t %g) shows up to point %d, not %d" % (k, times[k], last, want))
            index = data.GetPointData().GetArray("PointIndex")
            used = data.GetLines().GetConnectivityArray().GetRange()
            if index is None or data.GetNumberOfPoints() != whole:
                failures.append("replay step %d keeps %d of %d points" % (k, data.GetNumberOfPoints(), whole))
            elif used[1] > last or index.GetValue(int(used[1])) > last:
                failures.append("replay step %d shows PointIndex %d > its last printed point %d"
                                % (k, index.GetValue(int(used[1])), last))
            ranges.add(tuple(lut.RGBPoints[i] for i in (0, len(lut.RGBPoints) - 4)))
            cells.append(data.GetNumberOfCells())
        if len(ranges) != 1 or cells != sorted(cells):
            failures.append("replay: colour ranges %s while playing (one expected), cells per step %s" % (ranges, cells))
        outputs["replay"] = {"time_steps": len(times), "steps_checked": picks, "cells": cells,
                             "colour_range": sorted(ranges), "seconds_per_step": seconds,
                             "filter_seconds": filter_seconds, "render_seconds": render_seconds}
        scene.AnimationTime = times[len(times) // 2]
        part_rep.Visibility = 1
        simple.Render(view)
        simple.SaveScreenshot(shots("gui_replay_bunny.png"), view, ImageResolution=[1200, 900])
        replay.SetPropertyWithName("StepBy", 1)  # Layers
        replay.UpdatePipelineInformation()
        scene.UpdateAnimationUsingDataTimeSteps()
        layer_times = list(replay.TimestepValues)
        layers = int(rows.get("layers", -1))
        if len(layer_times) < layers:
            failures.append("replay by layer has %d steps for %d layers" % (len(layer_times), layers))
        start = time.time()
        scene.AnimationTime = layer_times[len(layer_times) // 2]
        simple.Render(view)
        outputs["replay"]["layer_steps"] = len(layer_times)
        outputs["replay"]["seconds_per_layer_step"] = round(time.time() - start, 3)

        for name in ("gui_workbench_bunny.png", "gui_summary_bunny.png", "gui_replay_bunny.png"):
            if not os.path.isfile(shots(name)):
                failures.append("no screenshot %s" % shots(name))
                continue
            size, spread = _geolattice_png_spread(shots(name))
            outputs[name] = {"size": size}
            if not spread or all(hi - lo < 32 for lo, hi in spread):
                failures.append("screenshot %s looks blank (channel ranges %s)" % (shots(name), spread))
    except Exception:
        failures.append(traceback.format_exc())
    _gl_pp_save()
