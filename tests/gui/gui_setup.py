"""Runs inside the ParaView GUI's Python shell, first event of run_gui_test.py's playback (the plan is
the JSON file named by $GEOLATTICE_GUI_PLAN): checks that the plugin loaded at start-up defines every
GeoLattice proxy with its menu category, that an .off file opens with GL Mesh Reader through the reader
factory (File > Open's choice), and opens the model with GL Mesh Reader as the active source. Writes
{"failures": [...]} to plan["setup_result"]."""
import json
import os
import traceback

from paraview import servermanager, simple


def _geolattice_gui_setup():
    with open(os.environ["GEOLATTICE_GUI_PLAN"]) as f:
        plan = json.load(f)
    failures = []
    try:
        pxm = servermanager.ProxyManager()
        for name, category in sorted(plan["filters"].items()):
            prototype = pxm.GetPrototypeProxy("filters", name)
            if prototype is None:
                failures.append("the loaded plugin has no filter %s (plugin older than the source tree?)" % name)
                continue
            hints = prototype.GetHints()
            menu = hints.FindNestedElementByName("ShowInMenu") if hints else None
            got = menu.GetAttribute("category") if menu else None
            if got != category:
                failures.append("%s: menu category %r in the loaded plugin, %r in its XML" % (name, got, category))
        for name in plan["readers"]:
            if pxm.GetPrototypeProxy("sources", name) is None:
                failures.append("the loaded plugin has no reader %s" % name)

        off = simple.OpenDataFile(plan["off_file"])
        if off is None or off.GetXMLName() != "GLMeshReader":
            failures.append("%s opens with %s, not GLMeshReader" % (plan["off_file"], off and off.GetXMLName()))
        if off is not None:
            off.UpdatePipeline()
            if servermanager.Fetch(off).GetNumberOfCells() == 0:
                failures.append("GLMeshReader read nothing from %s" % plan["off_file"])
            simple.Delete(off)

        reader = simple.GLMeshReader(registrationName=plan["reader"], FileName=plan["model"])
        view = simple.GetActiveViewOrCreate("RenderView")
        simple.Show(reader, view)
        simple.SetActiveSource(reader)
        view.ResetCamera()
        simple.Render(view)
    except Exception:
        failures.append(traceback.format_exc())
    with open(plan["setup_result"], "w") as f:
        json.dump({"failures": failures}, f, indent=1)


_geolattice_gui_setup()
