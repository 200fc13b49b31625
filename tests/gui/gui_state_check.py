"""Runs inside the ParaView GUI's Python shell after the GUI loaded a state file saved by
pvpython/geolattice_state.py (`paraview --state=...`, the same loading code as File > Load State),
from run_gui_test.py --state: checks that every source of the state is there and non-empty, that the
four views are in one layout and show their coloured arrays, and saves a screenshot of the layout.
Writes {"failures": [...], "outputs": {...}} to plan["check_result"]."""
import json
import os
import sys
import traceback

from paraview import servermanager, simple


def _geolattice_gui_state_check():
    with open(os.environ["GEOLATTICE_GUI_PLAN"]) as f:
        plan = json.load(f)
    failures, outputs = [], {}
    try:
        sys.path.insert(0, plan["pvpython_dir"])
        import geolattice_state as state

        time_value = simple.GetAnimationScene().AnimationTime
        for key, name in sorted(state.NAMES.items()):
            source = simple.FindSource(name)
            if source is None:
                if key != "toolpath_verifier":
                    failures.append("the loaded state has no source %r" % name)
                continue
            source.UpdatePipeline(time_value)
            data = servermanager.Fetch(source)
            if data.IsA("vtkTable"):  # the summary: rows
                outputs[name] = {"rows": data.GetNumberOfRows()}
                if data.GetNumberOfRows() == 0:
                    failures.append("%s is empty after loading the state" % name)
                continue
            outputs[name] = {"points": data.GetNumberOfPoints(), "cells": data.GetNumberOfCells()}
            if data.GetNumberOfCells() == 0 and key not in ("verifier", "toolpath_verifier"):
                failures.append("%s is empty after loading the state" % name)
        layouts = list(simple.GetLayouts().values())
        if len(layouts) != 1:
            failures.append("%d layouts, expected 1" % len(layouts))
        for title, key, port, association, array in state.COLOURING:
            view = simple.FindView(title)
            if view is None:
                failures.append("no view %r" % title)
                continue
            rep = servermanager.GetRepresentation(simple.OutputPort(simple.FindSource(state.NAMES[key]), port), view)
            if rep is None or rep.Visibility != 1 or list(rep.ColorArrayName) != [association, array]:
                failures.append("view %r does not show %s coloured by %s" % (title, state.NAMES[key], array))
        if layouts:
            simple.SaveScreenshot(plan["screenshot"], layouts[0], ImageResolution=[1600, 1200])
            outputs["screenshot"] = plan["screenshot"]
    except Exception:
        failures.append(traceback.format_exc())
    with open(plan["check_result"], "w") as f:
        json.dump({"failures": failures, "outputs": outputs}, f, indent=1)


_geolattice_gui_state_check()
